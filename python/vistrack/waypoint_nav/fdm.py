"""DWN and WN flown on a 6-DOF JSBSim aircraft (``vistrack.fdm``).

The guidance is the kinematic flight's own: ``DubinsWaypointGuidance`` (DWN's turning points over the
three-waypoint horizon) or ``WaypointFollower`` (WN), each leg by the law (5) (``LineFeedback``, its step
the aircraft's guidance period) or L1 line tracking, the same C++ objects ``waypoint_nav.fly`` flies. The
metrics (miss distances, reached, over- and undershoot, swirls) are ``navigate``'s, computed by the same
C++ function on the 6-DOF samples.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional, Sequence

import numpy as np

from .._core import waypoint_nav as _wn
from .._core.flight import Wind, paper_gains
from ..fdm import FdmTrajectory, FlightGuidanceLaw, aircraft, fly
from .navigation import (
    NavigationFlight,
    Points,
    default_start,
    flight_scores,
    navigation_guidance,
    navigation_time_limit,
    route_array,
)

__all__ = ["FdmNavigation", "fdm_flights", "fly_fdm", "roll_lead"]



def roll_lead(speed: float, turn_radius: float) -> float:
    """DWN "path"'s anticipation on an aircraft (s): the lag of the kinematic roll model that flies beside
    the 6-DOF flight (the default roll time constant 0.5 s and roll rate 70 deg/s, ``Options.roll_lag``);
    0.52 s for the Aerosonde at cruise. The Aerosonde's course trails a step of the commanded turn rate to
    v / R by 0.36 s at the rate it settles to, 0.59 s against v / R (``bench/fdm_waypoints.py --only-step``);
    its bank limit is the plan's turn, so the follower cannot tighten a late turn: leading by about that lag
    keeps the arc's error inside, where it can."""
    return float(_wn.Options(dynamics="roll", turn_radius=turn_radius, speed=speed).roll_lag())


@dataclass
class FdmNavigation:
    """One 6-DOF WN or DWN flight: the trajectory and navigate()'s metrics of it."""

    method: str
    waypoint_radius: Optional[float]  # WN's R_WP (None: DWN)
    turn_radius: float
    start: tuple[float, float, float]
    waypoints: np.ndarray
    trajectory: FdmTrajectory
    metrics: dict[str, Any]

    @property
    def miss_distances(self) -> np.ndarray:
        return np.asarray(self.metrics["miss_distances"])

    def summary(self) -> dict[str, Any]:
        """metrics.json's numbers of the flight (lengths also in R), with the aircraft's errors."""
        m = self.metrics
        return {"method": self.method, **flight_scores(
            self.turn_radius, self.miss_distances, m["reached"], self.trajectory.finished, m["swirls"], m["overshoot"],
            m["undershoot"], m["path_length"], m["duration"], m["fuel"])}


def fly_fdm(waypoints: Points, start: Optional[Sequence[float]] = None, *, method: str = "dwn",
            turn_radius: float, speed: float, altitude: float = 100.0, aircraft_name: str = "aerosonde",
            guidance: str = "l1", l1_period: float = 8.0, gains: Optional[tuple[float, float]] = None,
            waypoint_radius: Optional[float] = None, wind: Optional[Wind] = None, max_time: Optional[float] = None,
            weights: tuple[float, float] = (1.0, 1.0), wind_aware: bool = False,
            replan_interval: float = 0.0, dwn_tracking: str = "auto",
            path_anticipation: Optional[float] = None) -> FdmNavigation:
    """Fly the route (metres) on the aircraft with DWN (``method="dwn"``) or WN (``"wn"``, acceptance
    radius ``waypoint_radius``, None: R). ``start`` None: at the first waypoint heading to the second.
    ``guidance`` "l1" (period ``l1_period``) or "law5" (``gains``, None: ``paper_gains(R)``). ``max_time``
    None: 3 (route length + 2 pi R per waypoint) / v, as navigate(). ``wind_aware``: the leg law knows the
    constant part of ``wind`` (as navigate(wind_aware=True): DWN plans its turning points in the air mass);
    ``replan_interval``: DWN re-plans that often (s; 0: the paper's switch). ``dwn_tracking`` (beyond the
    paper) "path" ("auto", the default: an aircraft banks) follows each planned horizon path in closed loop
    (``DubinsWaypointGuidance.set_path_following``), its curvature read ``path_anticipation`` s ahead (None:
    ``roll_lead(speed, turn_radius)``); "paper": the leg law to each turning point. ``replan_interval`` and
    ``dwn_tracking`` "path" are DWN's: a WN flight refuses them, as navigate() does."""
    route = route_array(waypoints)
    if start is None:
        pose, flown = default_start(route), route[1:]
    else:
        pose, flown = (float(start[0]), float(start[1]), float(start[2])), route
    plane = aircraft(aircraft_name)  # fly() refuses a plan outside its envelope before flying
    # navigate()'s own guidance (C++ navigation_guidance), on the aircraft's guidance period; the law (5)'s
    # sign smoothed as in a continuous flight, and DWN "auto" following its paths with the roll model's lead.
    options = _wn.Options(method=method, turn_radius=turn_radius, speed=speed, dt=1.0 / plane.rates.guidance_hz,
                          gains=gains if gains is not None else paper_gains(turn_radius),
                          waypoint_radius=waypoint_radius, weights=weights, integration="continuous",
                          max_time=max_time, dynamics="roll", guidance=guidance, l1_period=l1_period,
                          wind_aware=wind_aware and wind is not None, replan_interval=replan_interval,
                          dwn_tracking=dwn_tracking, path_anticipation=path_anticipation)
    planner = navigation_guidance(flown, pose, options, wind)
    limit = navigation_time_limit(flown, pose, options)
    traj = fly(FlightGuidanceLaw(planner, pose), pose, speed=speed, altitude=altitude, duration=limit,
               turn_radius=turn_radius, aircraft=plane, wind=wind)
    metrics = _wn.navigation_metrics(list(traj.t), list(traj.x), list(traj.y), list(traj.turn_rate_command),
                                     [int(i) for i in traj.target_index], traj.finished, np.asarray(pose[:2]),
                                     flown, speed, turn_radius, weights)
    acceptance = None if method == "dwn" else (waypoint_radius if waypoint_radius is not None else turn_radius)
    return FdmNavigation(method, acceptance, float(turn_radius), pose, flown, traj, dict(metrics))


def fdm_flights(flights: Sequence[NavigationFlight], aircraft_name: str, wind: Optional[Wind], altitude: float,
                options: dict[str, Any]) -> list[FdmNavigation]:
    """Each DWN and WN flight of the kinematic vehicle flown again on the 6-DOF aircraft, same route, start,
    turn radius, leg law, wind and wind awareness (``options``: waypoint_nav.fly's keyword arguments the
    kinematic flights had)."""
    out = []
    for f in flights:
        dwn = f.method == "dwn"  # re-planning and the tracking choice are DWN's only
        out.append(fly_fdm(f.waypoints, f.start, method=f.method, turn_radius=f.turn_radius,
                           speed=options["speed"], altitude=altitude, aircraft_name=aircraft_name,
                           guidance=options["guidance"], l1_period=options["l1_period"], gains=options["gains"],
                           waypoint_radius=f.waypoint_radius, wind=wind,
                           wind_aware=bool(options.get("wind_aware", False)),
                           replan_interval=float(options.get("replan_interval", 0.0)) if dwn else 0.0,
                           dwn_tracking=str(options.get("dwn_tracking", "auto")) if dwn else "auto"))
    return out
