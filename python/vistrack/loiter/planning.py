"""Loiter plans over AOIs, camera coverage and their metrics: the API of ``vistrack.loiter``."""

from __future__ import annotations

import math
import numbers
from collections.abc import Sequence
from typing import Union

import numpy as np

from .._core import VistrackError
from .._core import flight as _flight
from .._core import loiter as _loiter
from ..preview import preview

Plan = _loiter.Plan
Segment = _loiter.Segment
Samples = _loiter.Samples
Camera = _loiter.Camera
Footprint = _loiter.Footprint
Coverage = _loiter.Coverage
Parameters = _loiter.Parameters
CoverageOptions = _loiter.CoverageOptions
Wind = _flight.Wind
FlightTrajectory = _flight.FlightTrajectory
METHODS: tuple[str, ...] = tuple(_loiter.METHODS)  # the paper's printed planners
# Beyond the paper: TLPP with both first directions tried, LDLPP with each AOI's loiter direction
# chosen; "best" plans every method and keeps the best plan (plan.method says which).
BEYOND_PAPER_METHODS: tuple[str, ...] = tuple(_loiter.BEYOND_PAPER_METHODS)
ALL_METHODS: tuple[str, ...] = METHODS + BEYOND_PAPER_METHODS
PLAN_METHODS: tuple[str, ...] = (*ALL_METHODS, "best")
OBJECTIVES: tuple[str, ...] = ("time", "coverage")
METHOD_NAMES = {"fly_through": "Fly-Through", "tlpp": "TLPP", "ldlpp": "LDLPP", "tlpp_best": "TLPP best-first*",
                "ldlpp_best": "LDLPP per-AOI*", "best": "best*"}
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
# The defaults below are the bound C++ structs' (loiter_parameters.hpp), in one place.
_PLAN = Parameters()
_COVERAGE = CoverageOptions()


def _points(aois: Points) -> np.ndarray:
    try:
        array = np.asarray(aois, dtype=float)
    except (TypeError, ValueError):
        raise VistrackError(f"aois = {preview(aois)}: expected a list of (x, y) centres of numbers") from None
    if array.ndim != 2 or array.shape[1] != 2:
        raise VistrackError(f"aois = {preview(aois)}: expected a list of (x, y) centres, shape (n, 2)")
    return array


def _point(value: Point, key: str) -> tuple[float, float]:
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise VistrackError(f"{key} = {preview(value)}: expected (x, y) numbers") from None
    if array.shape != (2,):
        raise VistrackError(f"{key} = {preview(value)}: expected (x, y)")
    return float(array[0]), float(array[1])


def plan(aois: Points, method: str = "ldlpp", start: Point = (0.0, 0.0), end: Point = (0.0, 0.0),
         turn_radius: float = _PLAN.turn_radius, speed: float = _PLAN.speed,
         aoi_radius: float = _PLAN.aoi_radius, turns: int = _PLAN.turns, order: str = "given", *,
         objective: str = "time", camera: Camera | None = None, threshold: float = _COVERAGE.threshold,
         dt: float = _COVERAGE.dt) -> Plan:
    """Plan a loiter mission over the AOI centres ``aois`` (n, 2).

    ``method``: the paper's "fly_through", "tlpp" or "ldlpp"; beyond the paper "tlpp_best" (both
    first directions tried), "ldlpp_best" (each AOI's loiter direction chosen) and "best" (every
    method that can fly the layout; the fastest plan with ``objective="time"``, the most covered
    seconds with ``"coverage"`` (``camera``, ``threshold``, ``dt`` as :func:`coverage`); ties go
    to the printed methods; ``plan.method`` says which). ``order``: "given" or "best" (the
    visiting order with the shortest plan: exact branch and bound up to 9 AOIs, 2-opt / or-opt
    above). Returns a :class:`Plan` with ``flight_time``, ``transit_time``, ``length``,
    ``segments`` and ``sample(dt)``.
    """
    if objective not in OBJECTIVES:
        raise VistrackError(f"objective = {objective!r}: must be one of " + ", ".join(OBJECTIVES))
    args = (_points(aois), _point(start, "start"), _point(end, "end"), turn_radius, speed, aoi_radius, turns, order)
    if method != "best":
        return _loiter.plan(args[0], method, *args[1:])
    plans, refusals = [], []
    for candidate in ALL_METHODS:
        try:
            plans.append(_loiter.plan(args[0], candidate, *args[1:]))
        except VistrackError as error:
            refusals.append(f"{candidate}: {error}")
    if not plans:
        raise VistrackError("method = 'best': no method can fly this layout (" + "; ".join(refusals) + ")")
    if objective == "time":
        return min(plans, key=lambda p: p.flight_time)  # min keeps the first of equals: the printed ones
    scores = [coverage(p, camera=camera, threshold=threshold, dt=dt).time for p in plans]
    return plans[int(np.argmax(scores))]


def plan_in_order(aois: Points, order: Sequence[int], method: str = "ldlpp", start: Point = (0.0, 0.0),
                  end: Point = (0.0, 0.0), turn_radius: float = _PLAN.turn_radius,
                  speed: float = _PLAN.speed, aoi_radius: float = _PLAN.aoi_radius,
                  turns: int = _PLAN.turns) -> Plan:
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
             threshold: float = _COVERAGE.threshold, dt: float = _COVERAGE.dt, *,
             speed: float | None = None,
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
                                   _PLAN.aoi_radius if aoi_radius is None else aoi_radius,
                                   _PLAN.speed if speed is None else speed,
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


def metrics(plan: Plan, cov: Coverage | None = None, dt: float = _COVERAGE.dt,
            threshold: float = _COVERAGE.threshold) -> dict[str, object]:
    """Plan (and coverage) numbers as a JSON-ready dictionary; times in s and min."""
    threshold = threshold_value(threshold)
    out: dict[str, object] = {
        "method": plan.method, "order": list(plan.order), "directions": list(plan.directions),
        "length_m": plan.length, "flight_time_s": plan.flight_time, "flight_time_min": plan.flight_time / 60.0,
        "transit_time_s": plan.transit_time, "loiter_time_s": plan.loiter_time,
        "loiter_turns": [float(s) / (2.0 * math.pi) for s in plan.loiter_sweep],
    }
    if cov is not None:
        out.update({
            "coverage_time_s": cov.time, "coverage_time_per_aoi_s": [float(t) for t in cov.time_per_aoi],
            "coverage_area_m2s": cov.area, "steps_by_role": coverage_by_role(plan, cov, dt, threshold),
        })
    return out


def threshold_value(threshold: float) -> float:
    """A coverage threshold: a fraction in (0, 1] (NaN would count nothing as covered, silently)."""
    if isinstance(threshold, bool) or not isinstance(threshold, numbers.Real) or not 0.0 < threshold <= 1.0:
        raise VistrackError(f"threshold = {preview(threshold)}: must be a fraction in (0, 1]")
    return float(threshold)


def segment_roles(plan: Plan) -> np.ndarray:
    """Each segment's role, an array to index by the samples' segment numbers (``plan.segments``
    builds every segment anew: one call, not one per sample)."""
    return np.array([s.role for s in plan.segments], dtype=object)


def coverage_by_role(plan: Plan, cov: Coverage, dt: float = _COVERAGE.dt,
                     threshold: float = _COVERAGE.threshold) -> dict[str, dict[str, int]]:
    """For each segment role, the time steps (dt apart, as ``cov`` was computed) the plan spends on
    it and how many of them have some AOI covered."""
    threshold = threshold_value(threshold)
    segments = np.asarray(plan.sample_states(dt, False).segment)
    if segments.size != cov.steps:
        raise VistrackError(f"dt = {dt}: the coverage has {cov.steps} steps, the plan sampled at dt "
                            f"has {segments.size}")
    covered = np.any(cov.fraction >= threshold, axis=1)
    roles = segment_roles(plan)[segments]
    out: dict[str, dict[str, int]] = {}
    for role in ("transit", "entry", "loiter", "exit"):
        on = roles == role
        out[role] = {"steps": int(on.sum()), "covered_steps": int((on & covered).sum())}
    return out
