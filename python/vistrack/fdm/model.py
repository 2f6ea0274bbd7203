"""One JSBSim aircraft in vistrack's frame: load, place, trim, step, read and write.

The flight starts at latitude 0, longitude 0 and the project's local frame (x east, y north, z up,
heading counter-clockwise from east) is the tangent plane there: x = x0 + N dlon, y = y0 + M dlat
with the WGS84 radii of curvature at the equator (exact to the second order over a few km). The
wind of the flight layer is the air mass's velocity (east, north); it goes into JSBSim's
``atmosphere/wind-east-fps`` and ``wind-north-fps``, so the aircraft flies in the same air.
"""

from __future__ import annotations

import math
import os
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

from .._core import VistrackError
from .aircraft import Aircraft

FT = 0.3048  # m per ft
_EARTH_A = 6378137.0  # WGS84 semi-major axis, m
_EARTH_E2 = 6.69437999014e-3  # WGS84 first eccentricity squared
RADIUS_NORTH = _EARTH_A * (1.0 - _EARTH_E2)  # meridian radius of curvature at the equator, m
RADIUS_EAST = _EARTH_A  # prime-vertical radius at the equator, m


@dataclass
class AircraftState:
    """What the autopilot and the guidance read, SI and the project's frame."""

    t: float
    x: float
    y: float
    psi: float  # heading, counter-clockwise from east, rad
    altitude: float  # above sea level, m
    airspeed: float  # true airspeed, m/s
    phi: float  # bank, rad (+ right wing down)
    theta: float  # pitch, rad
    p: float
    q: float
    r: float  # body rates, rad/s
    beta: float  # sideslip, rad
    alpha: float  # angle of attack, rad


@contextmanager
def _quiet_stdout() -> Iterator[None]:
    """JSBSim prints a banner on the process's standard output when it starts: keep it off ours."""
    sys.stdout.flush()
    try:
        saved = os.dup(1)
    except OSError:  # no file descriptor 1: nothing to keep clean
        yield
        return
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, 1)
        yield
    finally:
        os.dup2(saved, 1)
        os.close(saved)
        os.close(devnull)


class JsbsimModel:
    """A loaded JSBSim aircraft, placed at (x0, y0) with heading psi0 at the given altitude."""

    def __init__(self, aircraft: Aircraft, start: tuple[float, float, float], altitude: float):
        self.aircraft = aircraft
        import jsbsim  # here: ``import vistrack`` does not load JSBSim

        with _quiet_stdout():
            fdm = jsbsim.FGFDMExec(jsbsim.get_default_root_dir(), None)
            fdm.set_debug_level(0)
            if aircraft.aircraft_path is not None:
                fdm.set_aircraft_path(str(aircraft.aircraft_path))
            loaded = fdm.load_model(aircraft.model)
        if not loaded:
            raise VistrackError(f"aircraft = {aircraft.name!r}: JSBSim could not load model {aircraft.model!r}")
        fdm.set_dt(1.0 / aircraft.rates.fdm_hz)
        self.fdm = fdm
        self.x0, self.y0 = float(start[0]), float(start[1])
        self.psi0 = float(start[2])
        self.altitude0 = float(altitude)
        self.wind = (0.0, 0.0)
        c = aircraft.controls
        self._elevator, self._aileron = c["elevator"], c["aileron"]
        self._rudder, self._throttle = c["rudder"], c["throttle"]

    def set_initial(self, airspeed: float, alpha: float = 0.0) -> None:
        """Level flight at the start: true airspeed (m/s) along the body's x-z plane at angle of attack
        ``alpha`` (rad), wings level, in the wind set now: the initial velocity over the ground is given in
        body axes (air velocity plus the wind rotated into the body), so JSBSim's own initial wind plays no
        part and the aircraft starts in the air mass it will fly in."""
        f = self.fdm
        f["ic/lat-geod-rad"] = 0.0
        f["ic/long-gc-rad"] = 0.0
        f["ic/h-sl-ft"] = self.altitude0 / FT
        f["ic/vw-mag-fps"] = 0.0
        heading = math.pi / 2.0 - self.psi0  # JSBSim: clockwise from north
        east, north = self.wind
        # wind in body axes for roll 0, pitch alpha, heading psi: NED -> heading frame -> pitched
        forward = north * math.cos(heading) + east * math.sin(heading)
        right = -north * math.sin(heading) + east * math.cos(heading)
        ca, sa = math.cos(alpha), math.sin(alpha)
        f["ic/phi-rad"] = 0.0
        f["ic/theta-rad"] = alpha
        f["ic/psi-true-rad"] = heading % (2.0 * math.pi)
        f["ic/u-fps"] = (airspeed * ca + forward * ca) / FT
        f["ic/v-fps"] = right / FT
        f["ic/w-fps"] = (airspeed * sa + forward * sa) / FT
        f["ic/p-rad_sec"] = f["ic/q-rad_sec"] = f["ic/r-rad_sec"] = 0.0

    def start(self, airspeed: float, alpha: float, wind: tuple[float, float], controls: tuple[float, ...]) -> None:
        """Start the flight from a calm-air trim (the trim of a constant wind is the same in the air mass):
        the same air velocity and attitude in ``wind`` (east, north; m/s), the trim's commands
        (aileron, elevator, rudder, throttle), one step flown so every output is current. JSBSim's
        ``run_ic`` writes its initial wind (none) into the atmosphere, so the wind is set after it."""
        self.wind = (float(wind[0]), float(wind[1]))
        self.set_initial(airspeed, alpha)
        self.set_controls(*controls)
        self.run_ic()
        self.set_wind(*self.wind)
        self.fdm.run()

    def run_ic(self) -> None:
        """Apply the initial conditions."""
        if not self.fdm.run_ic():
            raise VistrackError(f"aircraft = {self.aircraft.name!r}: JSBSim refused the initial conditions")

    def set_wind(self, east: float, north: float) -> None:
        """The air mass's velocity (m/s) from now on."""
        self.wind = (east, north)
        self.fdm["atmosphere/wind-east-fps"] = east / FT
        self.fdm["atmosphere/wind-north-fps"] = north / FT

    def set_controls(self, aileron: float, elevator: float, rudder: float, throttle: float) -> None:
        """Normalised commands in JSBSim's signs."""
        f = self.fdm
        f[self._aileron] = aileron
        f[self._elevator] = elevator
        f[self._rudder] = rudder
        f[self._throttle] = throttle

    def controls(self) -> tuple[float, float, float]:
        """(elevator, throttle, rudder) commands as set now (after a trim: the trim's)."""
        f = self.fdm
        return f[self._elevator], f[self._throttle], f[self._rudder]

    def run(self, steps: int) -> None:
        """Advance ``steps`` integration steps."""
        run = self.fdm.run
        for _ in range(steps):
            run()

    def accelerations(self) -> tuple[float, float, float]:
        """(udot, wdot, qdot) in ft/s^2 and rad/s^2: what a level trim zeroes."""
        f = self.fdm
        return f["accelerations/udot-ft_sec2"], f["accelerations/wdot-ft_sec2"], f["accelerations/qdot-rad_sec2"]

    def state(self) -> AircraftState:
        """The aircraft now, in the project's frame; VistrackError when the model has diverged."""
        f = self.fdm
        s = AircraftState(
            t=f["simulation/sim-time-sec"],
            x=self.x0 + RADIUS_EAST * f["position/long-gc-rad"],
            y=self.y0 + RADIUS_NORTH * f["position/lat-geod-rad"],
            psi=math.pi / 2.0 - f["attitude/psi-rad"],
            altitude=f["position/h-sl-meters"],
            airspeed=f["velocities/vt-fps"] * FT,
            phi=f["attitude/phi-rad"], theta=f["attitude/theta-rad"],
            p=f["velocities/p-rad_sec"], q=f["velocities/q-rad_sec"], r=f["velocities/r-rad_sec"],
            beta=f["aero/beta-rad"], alpha=f["aero/alpha-rad"])
        if not (math.isfinite(s.x) and math.isfinite(s.y) and math.isfinite(s.altitude)):
            raise VistrackError(f"aircraft = {self.aircraft.name!r}: the 6-DOF model diverged at t = {s.t:.2f} s")
        if s.altitude < 0.0:
            raise VistrackError(f"aircraft = {self.aircraft.name!r}: flew into the ground (altitude "
                                f"{s.altitude:.1f} m) at t = {s.t:.2f} s")
        return s
