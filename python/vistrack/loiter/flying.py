"""Flying a loiter plan through the flight layer in a wind the guidance does not know, and scoring
the flown path with the scenario's camera."""

from __future__ import annotations

from typing import Any

import numpy as np

from .. import flight
from .._core import Uav, VistrackError
from .planning import Coverage, CoverageOptions, FlightTrajectory, Plan, Wind, coverage, threshold_value
from .scenario import Scenario

__all__ = ["flown_samples", "fly", "fly_and_score", "loiter_coverage_fraction", "path_pieces"]

_COVERAGE = CoverageOptions()  # the defaults: the bound C++ struct's


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
        integration: str = "discrete", lookahead_radii: float | None = None,
        heading_gain: float | None = None, uav: Uav | None = None) -> FlightTrajectory:
    """Fly the plan through the flight layer: a ``PathFollower`` on its lines and arcs, the vehicle
    of the plan's speed and turn radius (its model and roll parameters from ``uav``; None: the
    Dubins model), in a wind the guidance does not know (``Wind`` or (east, north) m/s). Starts at
    the plan's start on its first heading; ends at its end point (or after three times the planned
    flight time plus 10 minutes). ``lookahead_radii`` and ``heading_gain``: the follower's gains
    (None: ``PathFollower``'s defaults). The trajectory's turn rates are the flown ones, so its
    coverage sees the bank flown."""
    if wind is not None and not isinstance(wind, flight.Wind):
        east, north = wind
        wind = flight.Wind(east=float(east), north=float(north))
    gains = {name: value for name, value in (("lookahead_radii", lookahead_radii), ("heading_gain", heading_gain))
             if value is not None}
    if uav is not None and str(uav.dynamics) == "roll":
        gains["anticipation"] = uav.roll_time_constant  # start the roll before an arc, not tau late
    follower = flight.PathFollower(path_pieces(plan), plan.speed, plan.turn_radius, **gains)
    start = plan.at_time(0.0)
    return flight.fly(follower, start, plan.speed, plan.turn_radius, wind=wind, dt=dt,
                      max_time=3.0 * plan.flight_time + 600.0, integration=integration, uav=uav)


def flown_samples(trajectory: Any, dt: float = _COVERAGE.dt) -> tuple[np.ndarray, np.ndarray]:
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


def loiter_coverage_fraction(plan: Plan, segments: np.ndarray, cov: Coverage,
                             threshold: float = _COVERAGE.threshold) -> float:
    """Of the time steps spent on a loiter segment (by the index of the segment flown at each), the
    fraction at which that loiter's AOI counts as covered."""
    threshold = threshold_value(threshold)
    pieces = plan.segments  # built once: the property makes every segment anew
    loiters = np.array([s.aoi if s.role == "loiter" and s.aoi is not None else -1 for s in pieces], dtype=np.int64)
    aoi = loiters[np.asarray(segments, dtype=np.int64)]
    steps = np.flatnonzero(aoi >= 0)
    if steps.size == 0:
        return 0.0
    fraction = np.asarray(cov.fraction)
    return float(np.count_nonzero(fraction[steps, aoi[steps]] >= threshold)) / steps.size


def fly_and_score(scenario: Scenario, plan: Plan, wind: tuple[float, float], planned: Coverage | None = None,
                  keep_trajectory: bool = True, trajectory: Any = None) -> dict[str, object]:
    """Fly ``plan`` in the constant ``wind`` (east, north) and score the flown path with the
    scenario's camera against the plan: flight time, covered time (total and per AOI), the share of
    the loiter time with the AOI covered, and how far the path was blown off the plan. ``trajectory``:
    a flight flown elsewhere in that wind to score instead (``vistrack.loiter.fdm``: a 6-DOF one)."""
    planned = planned if planned is not None else scenario.coverage(plan)
    trajectory = trajectory if trajectory is not None else fly(plan, wind, uav=scenario.uav())
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
        "coverage_area_m2s": flown.area, "planned_coverage_area_m2s": planned.area,
        "loiter_covered_fraction": flown_loiter, "planned_loiter_covered_fraction": planned_loiter,
        "loiter_coverage_lost": planned_loiter - flown_loiter,
        "max_cross_track_m": float(np.max(cross_track)),
        "rms_cross_track_m": float(np.sqrt(np.mean(cross_track ** 2))),
        "smoothness": trajectory.smoothness().as_dict() if len(trajectory) >= 2 else None,
    }
    if keep_trajectory:
        record["_trajectory"] = np.column_stack([trajectory.x, trajectory.y])
    return record


def _cross_track(plan: Plan, trajectory: Any) -> np.ndarray:
    """Distance of each flown sample from the planned path (nearest point of a 1 m sampling)."""
    from scipy.spatial import cKDTree

    dense = plan.sample(1.0 / plan.speed)[:, :2]
    distance, _ = cKDTree(dense).query(np.column_stack([trajectory.x, trajectory.y]))
    return np.asarray(distance)
