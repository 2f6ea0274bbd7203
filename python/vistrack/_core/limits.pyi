"""
The valid range of every numeric input (vistrack/limits.hpp; README, Hardening): coordinates |v| <= MAX_COORDINATE m, lengths in [MIN_LENGTH, MAX_LENGTH] m, speeds in [MIN_SPEED, MAX_SPEED] m/s, angles |a| <= MAX_ANGLE rad, origin altitudes |alt| <= MAX_ALTITUDE m, volumes in (0, MAX_VOLUME] m^3, threads in [0, MAX_THREADS], the guidance gains beta in [MIN_GAIN, MAX_BETA] 1/m and k_psi in [MIN_GAIN, MAX_HEADING_GAIN] 1/s, and ODE tolerances rtol in [MIN_RTOL, MAX_RTOL] and atol in [MIN_ATOL, MAX_ATOL]; input files of at most MAX_INPUT_BYTES bytes; documents (JSON, YAML) nested at most MAX_DOCUMENT_DEPTH levels, YAML ones of at most MAX_DOCUMENT_NODES values (YAML aliases expanded); one planned piece of work (VVs, a loiter coverage matrix) of at most MAX_WORK_BYTES bytes, estimated before it starts.
"""
from __future__ import annotations
__all__: list[str] = ['MAX_ALTITUDE', 'MAX_ANGLE', 'MAX_ATOL', 'MAX_BETA', 'MAX_COORDINATE', 'MAX_DOCUMENT_DEPTH', 'MAX_DOCUMENT_NODES', 'MAX_HEADING_GAIN', 'MAX_INPUT_BYTES', 'MAX_LENGTH', 'MAX_RTOL', 'MAX_SPEED', 'MAX_THREADS', 'MAX_VOLUME', 'MAX_WORK_BYTES', 'MIN_ATOL', 'MIN_GAIN', 'MIN_LENGTH', 'MIN_RTOL', 'MIN_SPEED']
MAX_ALTITUDE: float = 100000.0
MAX_ANGLE: float = 1000000000.0
MAX_ATOL: float = 1000000.0
MAX_BETA: float = 1000.0
MAX_COORDINATE: float = 10000000.0
MAX_DOCUMENT_DEPTH: int = 100
MAX_DOCUMENT_NODES: int = 1000000
MAX_HEADING_GAIN: float = 1000000.0
MAX_INPUT_BYTES: int = 1073741824
MAX_LENGTH: float = 10000000.0
MAX_RTOL: float = 1.0
MAX_SPEED: float = 10000.0
MAX_THREADS: int = 1024
MAX_VOLUME: float = 1e+21
MAX_WORK_BYTES: float = 2000000000.0
MIN_ATOL: float = 1e-15
MIN_GAIN: float = 1e-09
MIN_LENGTH: float = 1e-06
MIN_RTOL: float = 1e-13
MIN_SPEED: float = 1e-06
