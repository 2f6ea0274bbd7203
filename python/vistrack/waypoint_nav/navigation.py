"""Dubins waypoint navigation (DWN) and classical waypoint navigation (WN): the horizon's turning
point, flights of a route and the paper's comparisons (the API of ``vistrack.waypoint_nav``)."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Any, Optional, Sequence, Union

import numpy as np
from numpy.typing import ArrayLike

from .._core import VistrackError
from .._core import waypoint_nav as _wn
from ..flight import FlightTrajectory, Gusts, Wind
from ..georeference import Georeference
from ..mission.builder import MissionBuilder
from ..mission.model import Mission
from ..preview import preview

__all__ = [
    "CASES", "DEFAULTS", "METHODS", "PAPER_GUST_MODEL", "PAPER_RADII", "DubinsWaypointGuidance", "HorizonPath",
    "NavigationFlight", "Options", "TurningPoint", "air_mass_turning_point", "fly", "horizon_lengths", "horizon_path",
    "navigation_guidance", "navigation_metrics", "navigation_time_limit", "paper_flights", "paper_gusts",
    "reachability", "theta_against_weight", "turning_point", "turning_points",
]

# DWN, the paper's WN and (beyond the paper) WN switching as ArduPlane does.
METHODS: tuple[str, ...] = ("dwn", "wn", "wn_passed_line")
HorizonPath = _wn.HorizonPath
Options = _wn.Options
TurningPoint = _wn.TurningPoint
DubinsWaypointGuidance = _wn.DubinsWaypointGuidance
turning_point = _wn.turning_point
air_mass_turning_point = _wn.air_mass_turning_point  # wind-aware DWN: the horizon planned in the air mass
turning_points = _wn.turning_points  # batch: poses (n, 3), w_next, w_after (n, 2)
CASES: tuple[str, ...] = tuple(_wn.CASES)
horizon_path = _wn.horizon_path
horizon_lengths = _wn.horizon_lengths
reachability = _wn.reachability
navigation_metrics = _wn.navigation_metrics  # of a flight flown elsewhere (vistrack.fdm)
navigation_guidance = _wn.navigation_guidance  # fly()'s guidance, for a vehicle flown elsewhere (vistrack.fdm)
navigation_time_limit = _wn.navigation_time_limit

_OPTIONS = Options()  # every default below: the bound C++ struct's (the paper's section 3)
# The same as a mapping, for the callers that read one (a copy: changing it changes no default).
DEFAULTS: dict[str, Any] = {name: getattr(_OPTIONS, name)
                            for name in ("turn_radius", "speed", "dt", "gains", "weights", "integration", "method")}
# The waypoint radii of the paper's Figures 11 and 12, in units of R.
PAPER_RADII: tuple[float, ...] = (0.1, 0.5, 1.0)
# Gusts for the paper's units: MIL-F-8785C low altitude, light turbulence (W20 = 15 kt = 7.7 m/s)
# at 50 m, reading the units as 1 = 20 m and 1 s (v = 0.8 -> 16 m/s, R = 0.7 -> 14 m):
# sigma = 0.061 (7.7 % of v), L = 10.1.
PAPER_GUST_MODEL: dict[str, float] = {"altitude": 50.0, "wind_speed_20ft": 7.7, "length_unit": 20.0,
                                      "speed_unit": 20.0}


def paper_gusts(seed: int, model: Optional[dict[str, float]] = None) -> Gusts:
    """Dryden gusts of ``PAPER_GUST_MODEL`` (or ``model``) with this seed."""
    m = {**PAPER_GUST_MODEL, **(model or {})}
    return Gusts.mil_f_8785c(m["altitude"], m["wind_speed_20ft"], seed, m["length_unit"], m["speed_unit"])

Points = Union[np.ndarray, Sequence[Sequence[float]]]


def route_array(waypoints: Points, key: str = "waypoints") -> np.ndarray:
    """The waypoints as a finite (n, 2) float array with n >= 2; VistrackError naming ``key``."""
    try:
        array = np.asarray(waypoints, dtype=float)
    except (TypeError, ValueError):
        raise VistrackError(f"{key} = {preview(waypoints)}: expected an array of (x, y) rows") from None
    if array.ndim != 2 or array.shape[1] != 2:
        raise VistrackError(f"{key}: expected shape (n, 2), got {array.shape}")
    if len(array) < 2:
        raise VistrackError(f"{key} = {len(array)} waypoints: at least two are needed")
    bad = np.argwhere(~np.isfinite(array))
    if len(bad):
        row, col = bad[0]
        raise VistrackError(f"{key}[{row}].{'xy'[col]} = {array[row, col]}: must be a finite number")
    return array


def default_start(route: np.ndarray, key: str = "waypoints") -> tuple[float, float, float]:
    """At the first waypoint, heading to the second (VistrackError when they coincide: no heading)."""
    d = route[1] - route[0]
    if not np.any(d):
        raise VistrackError(f"{key}[1] = ({route[1, 0]:g}, {route[1, 1]:g}): coincides with {key}[0], so the "
                            "flight, which starts there heading to it, has no heading; give start=(x, y, psi)")
    return float(route[0, 0]), float(route[0, 1]), math.atan2(d[1], d[0])


@dataclass
class NavigationFlight:
    """One WN or DWN flight along ``waypoints`` (the flown ones, after ``start``) and its metrics.

    ``trajectory`` is (n, 4): t, x, y, psi; ``flight`` the full record (commands, targets, wind).
    Lengths are in the route's units; ``miss_distances[k]`` is the closest approach to waypoint k
    (for the last one, the distance where the path crosses its finish line, where the flight ends).
    """

    method: str
    waypoint_radius: Optional[float]
    turn_radius: float
    start: tuple[float, float, float]
    waypoints: np.ndarray
    flight: FlightTrajectory
    miss_distances: np.ndarray
    reached: np.ndarray
    closest_times: np.ndarray
    overshoots: np.ndarray
    swirls: int
    overshoot: float
    undershoot: float
    path_length: float
    duration: float
    fuel: float
    finished: bool
    turning_point_records: list[Any] = field(default_factory=list)

    @property
    def trajectory(self) -> np.ndarray:
        """(n, 4): t, x, y, psi."""
        return np.asarray(self.flight.array)

    @property
    def all_reached(self) -> bool:
        return bool(np.all(self.reached))

    @property
    def label(self) -> str:
        """"DWN", "WN R_WP=0.1R" or, beyond the paper, "WN-line R_WP=0.1R" (ArduPlane's switching)."""
        if self.method == "dwn" or self.waypoint_radius is None:
            return "DWN"
        name = "WN-line" if self.method == "wn_passed_line" else "WN"
        return f"{name} R_WP={self.waypoint_radius / self.turn_radius:g}R"

    @property
    def turning_points(self) -> np.ndarray:
        """(k, 2): the DWN turning points in the order they were flown to (empty for WN); the last
        is the last waypoint, flown to directly. These are what a mission would carry."""
        pts = [r.path.point for r in self.turning_point_records]
        return np.array(pts, dtype=float).reshape(-1, 2)

    @property
    def route_points(self) -> np.ndarray:
        """(n + 1, 2): the route flown, the start position then the waypoints."""
        return np.vstack([np.asarray(self.start[:2], dtype=float), np.asarray(self.waypoints, dtype=float)[:, :2]])

    def mission_points(self) -> np.ndarray:
        """(k, 2): the points an autopilot mission of this flight carries: DWN's turning points
        (the paper keeps them "in the background"; the last is the last waypoint, flown to
        directly), or WN's route: the start position, then its waypoints (so that the mission, read
        back with :func:`read_route`, is the route flown)."""
        if self.method == "dwn":
            return self.turning_points
        return self.route_points

    def to_mission(self, georeference: Georeference, altitude: float, *, speed: Optional[float] = None,
                   altitude_mode: str = "relative", firmware: str = "ardupilot",
                   return_to_launch: bool = False) -> Mission:
        """The flight as an autopilot mission (route units taken as metres): one NAV_WAYPOINT per
        :meth:`mission_points` row, with WN's acceptance radius as param2 (DWN's turning points
        carry 0: the autopilot's default), optionally DO_CHANGE_SPEED first and RTL last."""
        builder = MissionBuilder(georeference, altitude, speed=speed, altitude_mode=altitude_mode, firmware=firmware)
        radius = 0.0 if self.method == "dwn" or self.waypoint_radius is None else self.waypoint_radius
        for point in self.mission_points():
            builder.waypoint(point, acceptance_radius=radius)
        if return_to_launch:
            builder.return_to_launch()
        return builder.build()

    def waypoint_table(self) -> list[dict[str, Any]]:
        """One row per waypoint flown: its miss distance (closest approach), the time of it, the
        largest overshoot outside the turn there, and whether the guidance got past it (lengths in
        the route's units and in R)."""
        R = self.turn_radius
        return [{"waypoint": k, "x": float(w[0]), "y": float(w[1]), "miss": float(self.miss_distances[k]),
                 "miss_over_R": float(self.miss_distances[k] / R), "time": float(self.closest_times[k]),
                 "overshoot": float(self.overshoots[k]), "overshoot_over_R": float(self.overshoots[k] / R),
                 "reached": bool(self.reached[k])} for k, w in enumerate(np.asarray(self.waypoints, dtype=float))]

    def leg_table(self) -> list[dict[str, Any]]:
        """One row per leg (start -> W_0 -> W_1 ...): its length, and the flight time and flown
        distance between the closest approaches at its ends."""
        points = self.route_points
        traj = self.trajectory
        t, xy = traj[:, 0], traj[:, 1:3]
        flown = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(xy, axis=0), axis=1))])
        times = np.concatenate([[t[0]], self.closest_times])
        along = np.interp(times, t, flown)
        return [{"leg": k, "length": float(np.linalg.norm(points[k + 1] - points[k])),
                 "time": float(times[k + 1] - times[k]), "flown": float(along[k + 1] - along[k])}
                for k in range(len(points) - 1)]

    def metrics(self) -> dict[str, Any]:
        """The metrics as plain data (JSON), lengths also in units of R."""
        scores = flight_scores(self.turn_radius, self.miss_distances, self.reached, self.finished, self.swirls,
                               self.overshoot, self.undershoot, self.path_length, self.duration, self.fuel)
        return {
            "method": self.method,
            "label": self.label,
            "waypoint_radius": self.waypoint_radius,
            **scores,
            "turning_points": self.turning_points.tolist(),
            "smoothness": self.flight.smoothness().as_dict() if len(self.flight.t) >= 2 else None,
            "waypoints": self.waypoint_table(),
            "legs": self.leg_table(),
        }


def flight_scores(R: float, miss_distances: ArrayLike, reached: ArrayLike, finished: bool, swirls: int,
                  overshoot: float, undershoot: float, path_length: float, duration: float,
                  fuel: float) -> dict[str, Any]:
    """A flight's scores as metrics.json keeps them (lengths also in units of R), for the kinematic
    flights and the 6-DOF ones alike. Every waypoint counts: the last one's miss is where the path
    crosses its finish line."""
    miss = np.asarray(miss_distances, dtype=float)
    return {
        "miss_distances": miss.tolist(),
        "miss_distances_over_R": (miss / R).tolist(),
        "max_miss_over_R": float(miss.max() / R),
        "miss_at_last_over_R": float(miss[-1] / R),
        "reached": [bool(r) for r in np.asarray(reached)],
        "all_reached": bool(np.all(reached)),
        "finished": bool(finished),
        "swirls": int(swirls),
        "overshoot": float(overshoot),
        "overshoot_over_R": float(overshoot) / R,
        "undershoot": float(undershoot),
        "undershoot_over_R": float(undershoot) / R,
        "path_length": float(path_length),
        "duration": float(duration),
        "fuel": float(fuel),
    }


def fly(
    waypoints: Points,
    start: Optional[Sequence[float]] = None,
    method: str = _OPTIONS.method,
    turn_radius: float = _OPTIONS.turn_radius,
    speed: float = _OPTIONS.speed,
    dt: float = _OPTIONS.dt,
    gains: tuple[float, float] = _OPTIONS.gains,
    waypoint_radius: Optional[float] = None,
    wind: Optional[Wind] = None,
    max_time: Optional[float] = None,
    weights: tuple[float, float] = _OPTIONS.weights,
    integration: str = _OPTIONS.integration,
    dynamics: str = str(_OPTIONS.dynamics),
    roll_time_constant: float = _OPTIONS.roll_time_constant,
    max_roll_rate_deg_s: float = _OPTIONS.max_roll_rate_deg_s,
    guidance: str = str(_OPTIONS.guidance),
    l1_period: float = _OPTIONS.l1_period,
    wind_aware: bool = False,
    replan_interval: float = _OPTIONS.replan_interval,
    dwn_tracking: str = str(_OPTIONS.dwn_tracking),
    path_anticipation: Optional[float] = None,
) -> NavigationFlight:
    """Fly a route with DWN (``method="dwn"``), WN (``"wn"``: a waypoint is done inside R_WP) or,
    beyond the paper, ArduPlane's WN (``"wn_passed_line"``: also once past the line through the
    waypoint perpendicular to the leg, and inside a turn distance min(R_WP, L1) x turn / 90 deg).

    ``start`` (x, y, psi): every waypoint is flown. Without it the flight starts at the first
    waypoint heading to the second and flies the others. ``waypoint_radius`` is WN's R_WP (None:
    R); DWN has none. ``wind`` is unknown to the guidance; ``max_time`` None: 3 (route length +
    2 pi R per waypoint) / v. ``weights`` (w_a, w_s) weigh arcs and straights in the turning
    points and in ``fuel``; ``integration`` "discrete" (the paper's) or "continuous".
    ``wind_aware``: the guidance knows the mean wind (``wind`` without its gusts): the leg law
    steers the course over the ground and DWN plans its turning points in the air mass.
    ``replan_interval`` (s, DWN): re-plan the active turning point that often (section 2.1's
    option); 0, the paper's flights: only when it becomes unreachable. ``dwn_tracking`` (beyond the
    paper): "paper" flies the leg law to each turning point, "path" follows each planned horizon
    path in closed loop with the roll anticipated ``path_anticipation`` s ahead (None: the roll
    model's lag), "auto" is "paper" on the dubins vehicle and "path" on the roll model. Every flight ends once past
    the line through the last waypoint perpendicular to the last leg, and the last waypoint's miss
    is the distance where the path crosses that line.
    """
    route = route_array(waypoints)
    if start is None:
        pose = default_start(route)
        flown = route[1:]
    else:
        if len(start) != 3:
            raise VistrackError(f"start = {preview(start)}: expected (x, y, psi)")
        pose = (float(start[0]), float(start[1]), float(start[2]))
        flown = route
    try:
        result = _wn.navigate(flown, pose, method=method, turn_radius=turn_radius, speed=speed, dt=dt, gains=gains,
                              waypoint_radius=waypoint_radius, weights=weights, wind=wind, integration=integration,
                              max_time=max_time, dynamics=dynamics, roll_time_constant=roll_time_constant,
                              max_roll_rate_deg_s=max_roll_rate_deg_s, guidance=guidance, l1_period=l1_period,
                              wind_aware=wind_aware, replan_interval=replan_interval, dwn_tracking=dwn_tracking,
                              path_anticipation=path_anticipation)
    except VistrackError as error:
        if start is not None:
            raise
        # navigate numbers the waypoints it flies, which start at the route's second one.
        text = re.sub(r"waypoints\[(\d+)\]", lambda m: f"waypoints[{int(m.group(1)) + 1}]", str(error))
        raise VistrackError(text) from None
    return NavigationFlight(
        method=result.method,
        waypoint_radius=result.waypoint_radius if result.method != "dwn" else None,
        turn_radius=float(turn_radius),
        start=pose,
        waypoints=flown,
        flight=result.trajectory,
        miss_distances=np.asarray(result.miss_distances),
        reached=np.asarray(result.reached),
        closest_times=np.asarray(result.closest_times),
        overshoots=np.asarray(result.overshoots),
        swirls=int(result.swirls),
        overshoot=float(result.overshoot),
        undershoot=float(result.undershoot),
        path_length=float(result.path_length),
        duration=float(result.duration),
        fuel=float(result.fuel),
        finished=bool(result.trajectory.finished),
        turning_point_records=list(result.turning_points),
    )


def paper_flights(waypoints: Points, wind: Optional[Wind] = None, radii: Sequence[float] = PAPER_RADII,
                  methods: Sequence[str] = ("dwn", "wn"), **options: Any) -> list[NavigationFlight]:
    """DWN and WN at each waypoint radius (in units of R) over one route: Figures 11 (no wind) and
    12 (``wind``); with "wn_passed_line" in ``methods`` also ArduPlane's switching at each radius.
    ``options`` go to :func:`fly` (turn_radius, speed, dt, gains, start, ...; ``replan_interval``
    and ``dwn_tracking`` to DWN's flight only)."""
    for method in methods:
        if method not in METHODS:
            raise VistrackError(f"method = {preview(method)}: must be one of " + ", ".join(map(repr, METHODS)))
    R = float(options.get("turn_radius", _OPTIONS.turn_radius))
    replan = options.pop("replan_interval", _OPTIONS.replan_interval)  # DWN's alone
    tracking = options.pop("dwn_tracking", str(_OPTIONS.dwn_tracking))  # DWN's alone
    flights = []
    if "dwn" in methods:
        flights.append(fly(waypoints, method="dwn", wind=wind, replan_interval=replan, dwn_tracking=tracking,
                           **options))
    for method in ("wn", "wn_passed_line"):
        if method in methods:
            for fraction in radii:
                flights.append(fly(waypoints, method=method, waypoint_radius=fraction * R, wind=wind, **options))
    return flights


def theta_against_weight(arc_weights: Sequence[float] = tuple(np.linspace(1.0, 1.5, 11)), A: float = 4.0,
                         B: float = 4.0, alpha: float = math.radians(-45.0),
                         beta: float = math.radians(30.0)) -> dict[str, Any]:
    """Figure 10: the optimal theta as the arc weight w_a grows (w_s = 1), in the paper's local
    frame (R = 1, C at the origin, W_n = (A, 0), W_{n+1} = W_n + B (cos beta, sin beta), heading
    alpha). Returns the weights, thetas (rad), cases and turning points."""
    pose = (0.0, 0.0, float(alpha))
    w_next = (float(A), 0.0)
    w_after = (A + B * math.cos(beta), B * math.sin(beta))
    points = [turning_point(pose, w_next, w_after, 1.0, (float(w), 1.0)) for w in arc_weights]
    thetas = np.array([p.theta for p in points])
    return {
        "pose": pose, "w_next": w_next, "w_after": w_after, "arc_weights": np.asarray(arc_weights, dtype=float),
        "thetas": thetas, "cases": [p.case for p in points], "points": points,
        "theta_range_deg": float(np.degrees(thetas.max() - thetas.min())),
    }
