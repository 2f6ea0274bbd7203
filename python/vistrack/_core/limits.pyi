"""
The valid range of every numeric input (vistrack/limits.hpp; README, Hardening): coordinates |v| <= MAX_COORDINATE m, lengths in [MIN_LENGTH, MAX_LENGTH] m, speeds in [MIN_SPEED, MAX_SPEED] m/s, angles |a| <= MAX_ANGLE rad, volumes in (0, MAX_VOLUME] m^3, threads in [0, MAX_THREADS].
"""
from __future__ import annotations
__all__: list[str] = ['MAX_ANGLE', 'MAX_COORDINATE', 'MAX_LENGTH', 'MAX_SPEED', 'MAX_THREADS', 'MAX_VOLUME', 'MIN_LENGTH', 'MIN_SPEED']
MAX_ANGLE: float = 1000000000.0
MAX_COORDINATE: float = 10000000.0
MAX_LENGTH: float = 10000000.0
MAX_SPEED: float = 10000.0
MAX_THREADS: int = 1024
MAX_VOLUME: float = 1e+21
MIN_LENGTH: float = 1e-06
MIN_SPEED: float = 1e-06
