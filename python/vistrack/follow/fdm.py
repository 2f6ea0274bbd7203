"""Following a ground vehicle on a 6-DOF JSBSim aircraft (``vistrack.fdm``).

The planner is the kinematic run's (``FollowPlanner``: sinusoid and loiter modes with hysteresis,
offset point, wind compensation): every ``update_period`` it observes the vehicle and the aircraft and
hands the flight its planned path for the next seconds, which ``CurveL1`` follows (the scenario files'
``flight.guidance: l1``; the C++ run's loop, ``follow_run.cpp``, with the aircraft in place of the
kinematic vehicle). It starts where the kinematic run starts. The camera fraction is the kinematic
run's measure (the vehicle in the downward camera's footprint, the camera tilted by the bank flown,
each sample weighted by the time to the next) on the 6-DOF samples, from the altitude flown.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Optional, Sequence

import numpy as np

from .._core import Uav
from .._core import follow as _follow
from .._core.flight import CurveL1, Wind
from ..fdm import FdmTrajectory, FlightGuidanceLaw, fly

__all__ = ["FollowFdm", "fly_follow_fdm"]


@dataclass
class FollowFdm:
    """A 6-DOF follow run: the trajectory, the vehicle at its samples and whether the camera saw it."""

    trajectory: FdmTrajectory
    vehicle: np.ndarray  # (n, 2)
    in_view: np.ndarray  # (n,) bool

    @property
    def camera_fraction(self) -> float:
        t = self.trajectory.t
        weights = np.diff(t, append=t[-1])  # each sample holds until the next
        total = float(weights.sum()) or 1.0
        return float(weights @ self.in_view) / total

    def metrics(self) -> dict[str, Any]:
        """The 6-DOF run's scores under the kinematic run's keys, with the aircraft's errors."""
        traj = self.trajectory
        distance = np.hypot(traj.x - self.vehicle[:, 0], traj.y - self.vehicle[:, 1])
        return {"duration_s": float(traj.t[-1] - traj.t[0]), "camera_fraction": self.camera_fraction,
                "mean_vehicle_distance_m": float(np.mean(distance)),
                "altitude_error_max_m": traj.altitude_error_max, "airspeed_error_max_m_s": traj.airspeed_error_max}


def fly_follow_fdm(vehicle: Any, uav: Uav, parameters: Any, start: Sequence[float], *, aircraft: str,
                   wind: Optional[Wind] = None, wind_estimate: Optional[Sequence[float]] = None,
                   flight: Optional[Any] = None, camera: Optional[Any] = None) -> FollowFdm:
    """Fly the follow planner on ``aircraft`` from ``start`` = (x, y, psi) (the kinematic run's first state)
    for the vehicle's track (or ``flight.max_time``); the path follower is L1 with ``flight``'s period
    and damping. VistrackError for an offset schedule (not flown here)."""
    flight = flight or _follow.FollowFlight(guidance="l1")
    camera = camera or _follow.DownwardCamera()
    wind = wind or Wind()
    estimate = np.array(wind_estimate if wind_estimate is not None else (wind.east, wind.north), dtype=float)
    planner = _follow.FollowPlanner(parameters, uav, estimate, camera)  # threshold auto reads the camera
    t0 = vehicle.start_time
    duration = flight.max_time if flight.max_time > 0.0 else vehicle.end_time - t0
    period = parameters.update_period
    horizon = 3.0 * flight.l1_damping * flight.l1_period / math.pi + 2.0 * period
    pose = (float(start[0]), float(start[1]), float(start[2]))

    def observe(t: float, x: float, y: float, psi: float) -> np.ndarray:
        o = _follow.FollowObservation(vehicle_position=vehicle.position(t), vehicle_velocity=vehicle.velocity(t),
                                      vehicle_heading=vehicle.heading(t), uav_position=np.array([x, y]),
                                      uav_heading=psi)
        return np.asarray(planner.planned_path(planner.update(t, o), horizon, 0.25))

    law = CurveL1(uav.speed, observe(t0, *pose), flight.l1_period, flight.l1_damping)
    next_update = [t0 + period]

    def on_step(t: float, q: tuple[float, float, float]) -> None:
        if t < next_update[0] - 1e-9 or t >= vehicle.end_time - 1e-9:
            return
        law.set_path(observe(t, *q))
        while next_update[0] <= t + 1e-9:
            next_update[0] += period

    traj = fly(FlightGuidanceLaw(law, pose, t0), pose, speed=uav.speed, altitude=uav.altitude, duration=duration,
               turn_radius=uav.min_turn_radius, aircraft=aircraft, wind=wind, t0=t0, on_step=on_step)
    where = np.asarray(vehicle.sample(traj.t))
    in_view = np.array([_follow.camera_sees(camera, np.array([x, y, h]), psi, bank, np.array([g[0], g[1], 0.0]))
                        for x, y, h, psi, bank, g in zip(traj.x, traj.y, traj.altitude, traj.psi, traj.bank, where)],
                       dtype=bool)
    return FollowFdm(traj, where, in_view)
