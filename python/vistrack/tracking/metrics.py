"""The numbers a run is judged by: the closed loop's errors and visibility (section VI), the
orbit plan's summary (section IV), and Figure 4's XOR metric along the path (section IV.B)."""

from __future__ import annotations

from typing import Any, Sequence, Union

import numpy as np

from .._core import Discretization, OrbitPlanner, Planning, PoiPath, SimulationResult, VisibilityOrbitPlan
from ..flight import flight_smoothness
from ..progress import Progress

__all__ = ["CONVERGE_AFTER", "locus_summary", "metric_along_path", "plan_summary", "simulation_metrics"]

# Errors are summarised after the initial capture: from this time on (s; issue 12's t > 15 s).
CONVERGE_AFTER = 15.0

PathMetric = Union[Discretization, VisibilityOrbitPlan]  # both carry arc_lengths and metric


def simulation_metrics(result: SimulationResult, converge_after: float = CONVERGE_AFTER) -> dict[str, Any]:
    """Summary numbers of one closed-loop run (errors after ``converge_after`` seconds)."""
    t = np.asarray(result.t)
    radial = np.asarray(result.radial_error)
    heading = np.asarray(result.heading_error)
    control = np.asarray(result.control)
    late = t >= min(converge_after, t[-1])
    stats = result.statistics
    return {
        "duration_s": float(t[-1] - t[0]),
        "samples": len(t),
        "rhs_evaluations": int(stats.rhs_evaluations),
        "accepted_steps": int(stats.accepted_steps),
        "rejected_steps": int(stats.rejected_steps),
        "restarts": int(len(result.restart_times) - 1),
        "initial_radial_error_m": float(radial[0]),
        "converge_after_s": float(converge_after),
        "radial_error_after_mean_m": float(np.mean(radial[late])),
        "radial_error_after_max_abs_m": float(np.max(np.abs(radial[late]))),
        "heading_error_after_max_abs_rad": float(np.max(np.abs(heading[late]))),
        "control_max_abs": float(np.max(np.abs(control))),
        "saturated_fraction": float(np.mean(np.asarray(result.control_unsaturated) != control)),
        "orbit_radius_first_m": float(result.orbit_radius[0]),
        "orbit_radius_last_m": float(result.orbit_radius[-1]),
        "visibility_fraction": None if result.visibility_fraction is None else float(result.visibility_fraction),
        "smoothness": flight_smoothness(t, np.asarray(result.bank)).as_dict() if len(t) >= 2 else None,
    }


def locus_summary(plan: VisibilityOrbitPlan) -> dict[str, Any]:
    """The locus a plan follows and, for the smooth one, what its check found: how often and how far
    the paper's piecewise-linear R(t) leaves the VPs between the samples, and how much (and where)
    the smooth R(t) lies below it."""
    out: dict[str, Any] = {"locus": plan.planning.locus}
    if plan.planning.locus != "smooth":
        return out
    c = plan.check
    times = np.asarray(c.times)
    lowering = np.asarray(c.lowering)
    reference = plan.reference
    out.update({
        "tracking_margin_m": plan.planning.tracking_margin,
        "check_points": len(times),
        "check_volumes_computed": int(c.volumes_computed),
        "check_rounds": int(c.rounds),
        "paper_violations": int(c.paper_violations),
        "paper_max_violation_m": float(c.paper_max_violation),
        "min_clearance_m": float(c.min_clearance),
        "max_lowering_m": float(c.max_lowering),
        "max_lowering_at_s": float(c.max_lowering_time),
        "max_lowering_at_m": float(c.max_lowering_time * plan.poi.speed),
        "mean_lowering_m": float(np.mean(lowering)) if len(lowering) else 0.0,
        "knots": len(reference.times),
        "max_abs_rate_mps": float(np.max(np.abs(reference.rates))) if reference.smooth else None,
        "max_abs_acceleration_mps2": float(np.max(np.abs(np.diff(reference.rates) / np.diff(reference.times))))
        if reference.smooth and len(reference.times) > 1 else None,
    })
    return out


def plan_summary(plan: VisibilityOrbitPlan) -> dict[str, Any]:
    """The numbers of an orbit plan worth printing and comparing with the paper."""
    return {
        "samples": len(plan.times),
        "volumes_computed": int(plan.volumes_computed),
        "inserted": sum(1 for d in plan.depths if d > 0),
        "initial_radius": plan.radii[0],
        "final_radius": plan.radii[-1],
        "initial_max_radius": plan.max_radii[0],
        "final_max_radius": plan.max_radii[-1],
        "min_radius": min(plan.radii),
        "min_feasible_radius": plan.min_feasible_radius,
        "max_metric": max(plan.metric) if len(plan.metric) else 0.0,
        "feasible": plan.feasible,
        "infeasibility": plan.infeasibility,
        "duration": plan.times[-1],
        **locus_summary(plan),
    }


def metric_along_path(planner: OrbitPlanner, poi: PoiPath, planning: Planning,
                      spacings: Sequence[float] = (50.0, 25.0, 10.0, 1.0),
                      progress: bool = True) -> dict[str, PathMetric]:
    """Figure 4's data: the XOR metric (56) between neighbouring VVs at fixed spacings and for the
    adaptive method, keyed "50 m", ..., "adaptive". The finest spacing is computed first so that
    coarser ones come from the planner's VV cache."""
    results: dict[str, PathMetric] = {}
    for spacing in sorted(spacings):
        with Progress(f"VVs every {spacing:g} m", progress) as bar:
            results[f"{spacing:g} m"] = planner.fixed(poi, spacing, planning.resolution_deg, bar,
                                                      max_volumes=planning.max_volumes)
    with Progress("adaptive VVs", progress) as bar:
        results["adaptive"] = planner.adaptive(poi, planning, bar)
    ordered = {f"{s:g} m": results[f"{s:g} m"] for s in spacings}
    ordered["adaptive"] = results["adaptive"]
    return ordered
