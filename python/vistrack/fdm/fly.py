"""Fly a planner's lateral guidance on a JSBSim aircraft with vistrack's autopilot.

Three rates (the aircraft's ``rates``): JSBSim integrates at ``fdm_hz`` (120 Hz), the autopilot's
loops run at ``autopilot_hz`` (60 Hz), the planner's guidance at ``guidance_hz`` (20 Hz): it reads
(t, x, y, psi) and answers a turn rate, which the autopilot turns into the coordinated bank
atan(v r / g) at the plan's airspeed v. Altitude and airspeed are held at the plan's. The wind
(``vt.flight.Wind``, constant plus Dryden gusts) is the flight layer's ``WindField``, set into
JSBSim's atmosphere at every guidance step.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Callable, Optional, Protocol

import numpy as np

from .._core import VistrackError
from .._core.flight import FlightGuidance, Wind, WindField
from .aircraft import Aircraft
from .aircraft import aircraft as load_aircraft
from .autopilot import Autopilot
from .model import JsbsimModel
from .trim import Trim
from .trim import trim as trim_model


class Guidance(Protocol):
    """A lateral guidance: turn rate (rad/s) at (t, x, y, psi); ``advance`` after each guidance step."""

    def turn_rate(self, t: float, x: float, y: float, psi: float) -> float: ...

    def advance(self, t: float, x: float, y: float, psi: float) -> None: ...

    @property
    def done(self) -> bool: ...


class FlightGuidanceLaw:
    """A ``vt.flight.FlightGuidance`` (waypoint followers, DWN, path and curve followers) as a Guidance."""

    def __init__(self, guidance: FlightGuidance, start: tuple[float, float, float], t0: float = 0.0):
        self.guidance = guidance
        self.target_index = -1  # of the last command: the planner's waypoint index
        guidance.start(start, t0)

    def turn_rate(self, t: float, x: float, y: float, psi: float) -> float:
        rate, _target, self.target_index = self.guidance.command((x, y, psi), t)
        return float(rate)

    def advance(self, t: float, x: float, y: float, psi: float) -> None:
        self.guidance.advance((x, y, psi), t)

    @property
    def done(self) -> bool:
        return bool(self.guidance.done)


@dataclass
class FdmTrajectory:
    """One 6-DOF flight, sampled at the guidance rate (numpy arrays of length n; ``wind`` (n, 2))."""

    aircraft: str
    speed: float  # commanded airspeed, m/s
    altitude_command: float  # m
    trim: Trim
    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    psi: np.ndarray
    altitude: np.ndarray
    airspeed: np.ndarray
    bank: np.ndarray  # rad, the flight layer's sign: + for a left (counter-clockwise) turn
    bank_command: np.ndarray
    turn_rate_command: np.ndarray
    throttle: np.ndarray
    wind: np.ndarray
    target_index: np.ndarray  # the guidance's target (a waypoint index; -1: none) at each sample
    finished: bool = False
    seconds: float = 0.0  # wall-clock time of the flight (trim included)

    @property
    def altitude_error_max(self) -> float:
        """Largest |altitude - command|, m."""
        return float(np.max(np.abs(self.altitude - self.altitude_command)))

    @property
    def airspeed_error_max(self) -> float:
        """Largest |airspeed - command|, m/s."""
        return float(np.max(np.abs(self.airspeed - self.speed)))


def fly(guidance: Guidance, start: tuple[float, float, float], *, speed: float, altitude: float,
        duration: float, turn_radius: float, aircraft: str | Aircraft = "aerosonde", wind: Optional[Wind] = None,
        t0: float = 0.0, on_step: Optional[Callable[[float, tuple[float, float, float]], None]] = None,
        ) -> FdmTrajectory:
    """Fly ``guidance`` from ``start`` = (x, y, psi) at t0 for ``duration`` s (or until it is done) on the
    aircraft, trimmed level at ``speed`` (true airspeed, m/s) and ``altitude`` (m). ``turn_radius`` is the
    plan's: checked against the envelope with the speed (VistrackError naming value and limit)."""
    started = time.perf_counter()
    plane = aircraft if isinstance(aircraft, Aircraft) else load_aircraft(aircraft)
    plane.check_plan(speed, turn_radius)
    if not (math.isfinite(duration) and 0.0 < duration <= 1e6):
        raise VistrackError(f"duration = {duration!r} s: expected a positive number up to 1e6")
    if len(start) != 3 or not all(math.isfinite(float(v)) and abs(float(v)) <= 1e7 for v in start):
        raise VistrackError(f"start = {tuple(start)!r}: expected finite (x, y, psi), |x|, |y| <= 1e7 m")
    if not (math.isfinite(altitude) and 10.0 <= altitude <= 10000.0):
        raise VistrackError(f"uav.altitude = {altitude!r} m: expected 10-10000 m for a 6-DOF flight")
    rates = plane.rates
    per_guidance = rates.autopilot_hz // rates.guidance_hz
    per_autopilot = rates.fdm_hz // rates.autopilot_hz
    dt_ap = 1.0 / rates.autopilot_hz
    n = math.floor(duration * rates.guidance_hz + 1e-9) + 1
    times = t0 + np.arange(n) / rates.guidance_hz
    winds = WindField(wind, speed, t0, duration + 1.0).at(list(times)) if wind is not None else np.zeros((n, 2))

    model = JsbsimModel(plane, start, altitude)
    trimmed = trim_model(model, speed)
    model.start(speed, trimmed.alpha, (float(winds[0, 0]), float(winds[0, 1])),
                (0.0, trimmed.elevator, 0.0, trimmed.throttle))
    pilot = Autopilot(plane, trimmed, altitude, speed)
    s = model.state()
    sim_start = s.t  # one step after the initial condition: the flight's t0
    out = np.full((13, n), np.nan)
    k = 0
    finished = False
    for k in range(n):  # s: the state after the previous guidance step's autopilot steps
        t = t0 + (s.t - sim_start)
        x, y, psi = s.x, s.y, s.psi
        if wind is not None:  # calm air: start() set it, nothing changes
            model.set_wind(float(winds[k, 0]), float(winds[k, 1]))
        rate = guidance.turn_rate(t, x, y, psi)
        bank_c = pilot.bank_command(rate, s.alpha)
        out[:, k] = (t, x, y, psi, s.altitude, s.airspeed, -s.phi, -bank_c, rate, 0.0, winds[k, 0], winds[k, 1],
                     getattr(guidance, "target_index", -1))
        guidance.advance(t, x, y, psi)
        if on_step is not None:
            on_step(t, (x, y, psi))
        if guidance.done:
            finished = True
            break
        if k == n - 1:
            break
        for _ in range(per_guidance):
            controls = pilot.step(s, bank_c, dt_ap)
            model.set_controls(*controls)
            out[9, k] = controls[3]
            model.run(per_autopilot)
            s = model.state()
    m = k + 1
    rows = out[:, :m]
    return FdmTrajectory(
        aircraft=plane.name, speed=speed, altitude_command=altitude, trim=trimmed, t=rows[0], x=rows[1], y=rows[2],
        psi=np.unwrap(rows[3]), altitude=rows[4], airspeed=rows[5], bank=rows[6], bank_command=rows[7],
        turn_rate_command=rows[8], throttle=rows[9], wind=rows[10:12].T.copy(), target_index=rows[12].astype(int),
        finished=finished,
        seconds=time.perf_counter() - started)
