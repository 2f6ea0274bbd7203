"""Loiter planning over areas of interest (AOIs) and camera coverage.

Wilhelm, Clem, Eberhart, *Direct Entry Minimal Path UAV Loitering Path Planning* (Aerospace,
2017): the Fly-Through loiter of common autopilots, the Tangential (TLPP) and the Least-Distance
(LDLPP) planners, as exact paths of lines and arcs (C++ ``vistrack._core.loiter``), and the
paper's coverage metric: a conic 74-degree camera on a +-25 degree roll gimbal; an AOI counts as
covered at a time step when at least 75 % of its disk lies in the footprint.

>>> import vistrack as vt
>>> plan = vt.loiter.plan([(300, 200), (600, 500)], method="ldlpp")
>>> cov = vt.loiter.coverage(plan)
>>> plan.flight_time, plan.transit_time, cov.time, cov.area
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Union

import numpy as np

from ._core import VistrackError
from ._core import flight as _flight
from ._core import loiter as _loiter
from .georeference import Georeference

Plan = _loiter.Plan
Segment = _loiter.Segment
Samples = _loiter.Samples
Camera = _loiter.Camera
Footprint = _loiter.Footprint
Coverage = _loiter.Coverage
Wind = _flight.Wind
FlightTrajectory = _flight.FlightTrajectory
METHODS: tuple[str, ...] = tuple(_loiter.METHODS)
METHOD_NAMES = {"fly_through": "Fly-Through", "tlpp": "TLPP", "ldlpp": "LDLPP"}
ORDERS: tuple[str, ...] = tuple(_loiter.ORDERS)
EXACT_ORDER_LIMIT: int = _loiter.EXACT_ORDER_LIMIT
entry_angle = _loiter.entry_angle
entry_distance = _loiter.entry_distance
turn_angle = _loiter.turn_angle
bank_angle = _loiter.bank_angle
ellipse_disk_area = _loiter.ellipse_disk_area
best_order = _loiter.best_order
order_length = _loiter.order_length

Point = Union[Sequence[float], np.ndarray]
Points = Union[Sequence[Sequence[float]], np.ndarray]

# Section 4.1: AOIs inside an 800 x 800 m square, start and end at the origin (a corner of it).
AREA_SIZE = 800.0

__all__ = [
    "AREA_SIZE",
    "EXACT_ORDER_LIMIT",
    "METHODS",
    "METHOD_NAMES",
    "ORDERS",
    "Camera",
    "Coverage",
    "FlightTrajectory",
    "Footprint",
    "Plan",
    "Samples",
    "Scenario",
    "Segment",
    "Wind",
    "bank_angle",
    "best_order",
    "coverage",
    "coverage_by_role",
    "ellipse_disk_area",
    "entry_angle",
    "entry_distance",
    "flown_samples",
    "fly",
    "fly_and_score",
    "load_scenario",
    "loiter_circles",
    "loiter_coverage_fraction",
    "metrics",
    "order_length",
    "path_pieces",
    "plan",
    "plan_in_order",
    "random_aois",
    "random_scenario",
    "segment_records",
    "turn_angle",
    "turn_rates_from_headings",
]


def _points(aois: Points) -> np.ndarray:
    try:
        array = np.asarray(aois, dtype=float)
    except (TypeError, ValueError):
        raise VistrackError(f"aois = {aois!r}: expected a list of (x, y) centres of numbers") from None
    if array.ndim != 2 or array.shape[1] != 2:
        raise VistrackError(f"aois = {aois!r}: expected a list of (x, y) centres, shape (n, 2)")
    return array


def _point(value: Point, key: str) -> tuple[float, float]:
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise VistrackError(f"{key} = {value!r}: expected (x, y) numbers") from None
    if array.shape != (2,):
        raise VistrackError(f"{key} = {value!r}: expected (x, y)")
    return float(array[0]), float(array[1])


def plan(aois: Points, method: str = "ldlpp", start: Point = (0.0, 0.0), end: Point = (0.0, 0.0),
         turn_radius: float = 46.0, speed: float = 12.0, aoi_radius: float = 46.0, turns: int = 1,
         order: str = "given") -> Plan:
    """Plan a loiter mission over the AOI centres ``aois`` (n, 2).

    ``method``: "fly_through", "tlpp" or "ldlpp"; ``order``: "given" or "best" (the visiting order
    with the shortest plan: exact branch and bound up to 9 AOIs, 2-opt / or-opt above). Returns a
    :class:`Plan` with ``flight_time``, ``transit_time``, ``length``, ``segments`` and ``sample(dt)``.
    """
    return _loiter.plan(_points(aois), method, _point(start, "start"), _point(end, "end"), turn_radius, speed,
                        aoi_radius, turns, order)


def plan_in_order(aois: Points, order: Sequence[int], method: str = "ldlpp", start: Point = (0.0, 0.0),
                  end: Point = (0.0, 0.0), turn_radius: float = 46.0, speed: float = 12.0,
                  aoi_radius: float = 46.0, turns: int = 1) -> Plan:
    """Plan visiting the AOIs in ``order`` (a permutation of their indices)."""
    return _loiter.plan_in_order(_points(aois), list(order), method, _point(start, "start"), _point(end, "end"),
                                 turn_radius, speed, aoi_radius, turns)


def turn_rates_from_headings(headings: np.ndarray, dt: float) -> np.ndarray:
    """Turn rates (rad/s) of headings sampled every ``dt`` (central differences of the unwrapped heading)."""
    psi = np.unwrap(np.asarray(headings, dtype=float))
    if psi.size < 2:
        return np.zeros_like(psi)
    return np.gradient(psi, dt)


def coverage(plan_or_samples: Plan | np.ndarray, aois: Points | None = None, camera: Camera | None = None,
             threshold: float = 0.75, dt: float = 1.0, *, speed: float | None = None,
             aoi_radius: float | None = None, turn_rates: np.ndarray | None = None) -> Coverage:
    """Camera coverage of the AOIs (section 4.1) along a plan, or along poses sampled every ``dt``.

    A plan is sampled at t = 0, dt, ... with the exact turn rate of each segment (its AOIs, speed
    and AOI radius are used unless given). Samples are an (n, 3) array of x, y, psi, or (n, 4) with
    the turn rate (rad/s) as fourth column; otherwise ``turn_rates`` or, when absent, the rates of
    the headings (central differences). The turn rate sets the bank angle. Returns a
    :class:`Coverage`: ``time`` (covered seconds summed over AOIs), ``time_per_aoi``, ``area``.
    """
    camera = camera if camera is not None else Camera()
    if isinstance(plan_or_samples, Plan):
        if aois is None and speed is None and aoi_radius is None:
            return _loiter.plan_coverage(plan_or_samples, camera, threshold, dt)
        samples = plan_or_samples.sample_states(dt, False)
        poses, rates = samples.poses, samples.turn_rate
        aois = plan_or_samples.aois if aois is None else aois
        speed = plan_or_samples.speed if speed is None else speed
        aoi_radius = plan_or_samples.aoi_radius if aoi_radius is None else aoi_radius
    else:
        array = np.asarray(plan_or_samples, dtype=float)
        if array.ndim != 2 or array.shape[1] not in (3, 4):
            raise VistrackError(f"samples: expected an array of shape (n, 3) or (n, 4), got {array.shape}")
        if aois is None:
            raise VistrackError("aois = None: sampled poses need the AOI centres")
        poses = np.ascontiguousarray(array[:, :3])
        if array.shape[1] == 4:
            rates = array[:, 3]
        elif turn_rates is not None:
            rates = np.asarray(turn_rates, dtype=float)
        else:
            rates = turn_rates_from_headings(array[:, 2], dt)
    return _loiter.sample_coverage(poses, list(np.asarray(rates, dtype=float)), _points(aois),
                                   46.0 if aoi_radius is None else aoi_radius, 12.0 if speed is None else speed,
                                   camera, threshold, dt)


def segment_records(plan: Plan) -> list[dict[str, object]]:
    """The plan's segments as plain dictionaries (JSON, mission export)."""
    records: list[dict[str, object]] = []
    for s in plan.segments:
        records.append({
            "kind": s.kind, "role": s.role, "start": list(s.start), "end": list(s.end),
            "start_heading": s.start_heading, "end_heading": s.end_heading,
            "center": None if s.center is None else list(s.center), "radius": s.radius,
            "direction": s.direction, "sweep": s.sweep, "length": s.length, "aoi": s.aoi,
        })
    return records


def loiter_circles(plan: Plan) -> list[dict[str, object]]:
    """Each AOI's loiter in visiting order: centre, radius, direction, where the aircraft joins and
    leaves the circle, the angle flown on it and the full turns that makes (for mission export)."""
    circles = []
    for aoi in plan.order:
        arcs = [s for s in plan.segments if s.role == "loiter" and s.aoi == aoi]
        sweep = sum(s.sweep for s in arcs)
        circles.append({
            "aoi": int(aoi), "center": [float(v) for v in plan.aois[aoi]], "radius": plan.aoi_radius,
            "direction": plan.directions[aoi], "entry": list(arcs[0].start), "exit": list(arcs[-1].end),
            "sweep": sweep, "turns": sweep / (2.0 * math.pi),
        })
    return circles


def metrics(plan: Plan, cov: Coverage | None = None, dt: float = 1.0, threshold: float = 0.75) -> dict[str, object]:
    """Plan (and coverage) numbers as a JSON-ready dictionary; times in s and min."""
    threshold = _threshold(threshold)
    out: dict[str, object] = {
        "method": plan.method, "order": list(plan.order), "directions": list(plan.directions),
        "length_m": plan.length, "flight_time_s": plan.flight_time, "flight_time_min": plan.flight_time / 60.0,
        "transit_time_s": plan.transit_time, "loiter_time_s": plan.loiter_time,
        "loiter_turns": [float(s) / (2.0 * math.pi) for s in plan.loiter_sweep],
    }
    if cov is not None:
        out.update({
            "coverage_time_s": cov.time, "coverage_time_per_aoi_s": [float(t) for t in cov.time_per_aoi],
            "coverage_area_m2": cov.area, "steps_by_role": coverage_by_role(plan, cov, dt, threshold),
        })
    return out


def _threshold(threshold: float) -> float:
    """A coverage threshold: a fraction in (0, 1] (NaN would count nothing as covered, silently)."""
    if isinstance(threshold, bool) or not isinstance(threshold, numbers.Real) or not 0.0 < threshold <= 1.0:
        raise VistrackError(f"threshold = {threshold!r}: must be a fraction in (0, 1]")
    return float(threshold)


def coverage_by_role(plan: Plan, cov: Coverage, dt: float = 1.0, threshold: float = 0.75) -> dict[str, dict[str, int]]:
    """For each segment role, the time steps (dt apart, as ``cov`` was computed) the plan spends on
    it and how many of them have some AOI covered."""
    threshold = _threshold(threshold)
    segments = np.asarray(plan.sample_states(dt, False).segment)
    if segments.size != cov.steps:
        raise VistrackError(f"dt = {dt}: the coverage has {cov.steps} steps, the plan sampled at dt "
                            f"has {segments.size}")
    covered = np.any(cov.fraction >= threshold, axis=1)
    out: dict[str, dict[str, int]] = {}
    for role in ("transit", "entry", "loiter", "exit"):
        on = np.array([plan.segments[int(k)].role == role for k in segments], dtype=bool)
        out[role] = {"steps": int(on.sum()), "covered_steps": int((on & covered).sum())}
    return out


@dataclass
class Scenario:
    """A loiter mission: AOI centres, start and end, vehicle, camera and coverage settings.

    ``paper`` holds the paper's Table 1 numbers for the scenario of the same size, when the file
    gives them (``{"fly_through": {"flight_time_min": ..., "coverage_m2": ...}, ...}``).
    """

    aois: np.ndarray
    name: str = "scenario"
    start: tuple[float, float] = (0.0, 0.0)
    end: tuple[float, float] = (0.0, 0.0)
    turn_radius: float = 46.0
    speed: float = 12.0
    aoi_radius: float = 46.0
    turns: int = 1
    camera: Camera = field(default_factory=Camera)
    threshold: float = 0.75
    dt: float = 1.0
    paper: dict[str, dict[str, float]] = field(default_factory=dict)
    origin: Georeference | None = None  # where local (0, 0) lies on the Earth (mission export)

    def plan(self, method: str, order: str = "given") -> Plan:
        return plan(self.aois, method, self.start, self.end, self.turn_radius, self.speed, self.aoi_radius,
                    self.turns, order)

    def coverage(self, plan_or_samples: Plan | np.ndarray) -> Coverage:
        return coverage(plan_or_samples, self.aois, self.camera, self.threshold, self.dt, speed=self.speed,
                        aoi_radius=self.aoi_radius)


def path_pieces(plan: Plan) -> np.ndarray:
    """The plan as (n, 5) rows x0, y0, heading, length, curvature: the path a
    ``vistrack.flight.PathFollower`` flies."""
    rows = []
    for s in plan.segments:
        curvature = 0.0
        if s.radius is not None:  # arcs
            curvature = (1.0 if s.direction == "ccw" else -1.0) / s.radius
        rows.append((s.start[0], s.start[1], s.start_heading, s.length, curvature))
    return np.array(rows, dtype=float)


def fly(plan: Plan, wind: Wind | tuple[float, float] | None = None, dt: float = 0.05,
        integration: str = "discrete", lookahead_radii: float = 1.0, heading_gain: float = 3.0) -> FlightTrajectory:
    """Fly the plan through the flight layer: a ``PathFollower`` on its lines and arcs, the Dubins
    vehicle of the plan's speed and turn radius, in a wind the guidance does not know (``Wind`` or
    (east, north) m/s). Starts at the plan's start on its first heading; ends at its end point (or
    after three times the planned flight time plus 10 minutes)."""
    from . import flight

    if wind is not None and not isinstance(wind, flight.Wind):
        east, north = wind
        wind = flight.Wind(east=float(east), north=float(north))
    follower = flight.PathFollower(path_pieces(plan), plan.speed, plan.turn_radius, lookahead_radii, heading_gain)
    start = plan.at_time(0.0)
    return flight.fly(follower, start, plan.speed, plan.turn_radius, wind=wind, dt=dt,
                      max_time=3.0 * plan.flight_time + 600.0, integration=integration)


def flown_samples(trajectory: FlightTrajectory, dt: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """A flown trajectory every ``dt`` (whole multiples of its output step): (n, 4) rows x, y, psi and
    the turn rate applied there (the input of :func:`coverage`), and the index of the path piece
    (plan segment) being flown at each."""
    t = np.asarray(trajectory.t)
    step = float(t[1] - t[0]) if t.size > 1 else dt
    stride = max(1, round(dt / step))
    if abs(stride * step - dt) > 1e-9 * dt:
        raise VistrackError(f"dt = {dt}: must be a multiple of the flight's output step {step}")
    keep = slice(0, t.size, stride)
    rows = np.column_stack([trajectory.x[keep], trajectory.y[keep], trajectory.psi[keep], trajectory.command[keep]])
    return rows, np.asarray(trajectory.target_index)[keep]


def loiter_coverage_fraction(plan: Plan, segments: np.ndarray, cov: Coverage, threshold: float = 0.75) -> float:
    """Of the time steps spent on a loiter segment (by the index of the segment flown at each), the
    fraction at which that loiter's AOI counts as covered."""
    threshold = _threshold(threshold)
    covered, total = 0, 0
    for k, index in enumerate(segments):
        segment = plan.segments[int(index)]
        if segment.role == "loiter" and segment.aoi is not None:
            total += 1
            covered += bool(cov.fraction[k, segment.aoi] >= threshold)
    return covered / total if total else 0.0


def fly_and_score(scenario: Scenario, plan: Plan, wind: tuple[float, float], planned: Coverage | None = None,
                  keep_trajectory: bool = True) -> dict[str, object]:
    """Fly ``plan`` in the constant ``wind`` (east, north) and score the flown path with the
    scenario's camera against the plan: flight time, covered time (total and per AOI), the share of
    the loiter time with the AOI covered, and how far the path was blown off the plan."""
    planned = planned if planned is not None else scenario.coverage(plan)
    trajectory = fly(plan, wind)
    samples, segments = flown_samples(trajectory, scenario.dt)
    flown = coverage(samples, scenario.aois, scenario.camera, scenario.threshold, scenario.dt, speed=scenario.speed,
                     aoi_radius=scenario.aoi_radius)
    planned_segments = np.asarray(plan.sample_states(scenario.dt, False).segment)
    planned_loiter = loiter_coverage_fraction(plan, planned_segments, planned, scenario.threshold)
    flown_loiter = loiter_coverage_fraction(plan, segments, flown, scenario.threshold)
    cross_track = _cross_track(plan, trajectory)
    record: dict[str, object] = {
        "wind": [float(wind[0]), float(wind[1])], "finished": bool(trajectory.finished),
        "flight_time_s": float(trajectory.end_time), "planned_flight_time_s": plan.flight_time,
        "coverage_time_s": flown.time, "planned_coverage_time_s": planned.time,
        "coverage_time_per_aoi_s": [float(t) for t in flown.time_per_aoi],
        "coverage_area_m2": flown.area, "planned_coverage_area_m2": planned.area,
        "loiter_covered_fraction": flown_loiter, "planned_loiter_covered_fraction": planned_loiter,
        "loiter_coverage_lost": planned_loiter - flown_loiter,
        "max_cross_track_m": float(np.max(cross_track)),
        "rms_cross_track_m": float(np.sqrt(np.mean(cross_track ** 2))),
    }
    if keep_trajectory:
        record["_trajectory"] = np.column_stack([trajectory.x, trajectory.y])
    return record


def _cross_track(plan: Plan, trajectory: FlightTrajectory) -> np.ndarray:
    """Distance of each flown sample from the planned path (nearest point of a 1 m sampling)."""
    from scipy.spatial import cKDTree

    dense = plan.sample(1.0 / plan.speed)[:, :2]
    distance, _ = cKDTree(dense).query(np.column_stack([trajectory.x, trajectory.y]))
    return np.asarray(distance)


def load_scenario(path: str | Path) -> Scenario:
    """Read a loiter scenario YAML file (see examples/loiter_*.yaml)."""
    from .io import read_loiter_scenario

    return read_loiter_scenario(Path(path))


def random_aois(count: int, rng: np.random.Generator, size: float = AREA_SIZE, separation: float = 160.0,
                clearance: float = 80.0, start: Point = (0.0, 0.0), end: Point = (0.0, 0.0),
                attempts: int = 100000) -> np.ndarray:
    """``count`` AOI centres uniform in [0, size]^2, at least ``separation`` apart and ``clearance``
    from the start and end (defaults: LDLPP can fly every order, 2 D_Entry = 159.3 m and
    D_Entry = 79.7 m at R = r = 46 m)."""
    if count < 1:
        raise VistrackError(f"count = {count}: at least one AOI")
    anchors = [np.asarray(start, dtype=float), np.asarray(end, dtype=float)]
    chosen: list[np.ndarray] = []
    for _ in range(attempts):
        c = rng.uniform(0.0, size, 2)
        if all(np.hypot(*(c - a)) >= clearance for a in anchors) and all(
                np.hypot(*(c - o)) >= separation for o in chosen):
            chosen.append(c)
            if len(chosen) == count:
                return np.array(chosen)
    raise VistrackError(f"count = {count}: could not place that many AOIs {separation} m apart in "
                        f"{size} x {size} m")


def random_scenario(count: int, seed: int, **settings: object) -> Scenario:
    """A seeded random scenario of ``count`` AOIs (section 4.1's area and vehicle)."""
    rng = np.random.default_rng(seed)
    return Scenario(aois=random_aois(count, rng), name=f"random-{count}-{seed}", **settings)  # type: ignore[arg-type]

