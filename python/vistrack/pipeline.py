"""The whole job from map to report (``vistrack run`` and ``vistrack demo``).

Stages: environment -> POI path -> adaptive visibility volumes and orbit plan (section IV) ->
closed-loop simulation with line-of-sight evaluation (sections V-VI) -> constant-radius baselines
-> report folder (report.md with figures, metrics.json, plan.json, trajectory.csv, VV meshes).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Optional

import numpy as np

from . import _core
from .progress import Stages
from .scenario import Scenario

__all__ = ["RunResult", "run", "start_on_orbit"]

# Fixed spacings drawn beside the adaptive method in the Figure 4 plot of a run (m).
METRIC_SPACINGS = (50.0, 25.0, 10.0)
# Most VV meshes written into a report (evenly picked along the path).
MAX_SAVED_VOLUMES = 12


@dataclass
class RunResult:
    """Everything a run computed; ``metrics`` is what metrics.json holds."""

    scenario: Scenario
    env: Any
    poi: Any
    plan: Any
    simulation: Any
    planner: Any = None
    baselines: dict[float, Any] = field(default_factory=dict)
    metric_runs: dict[str, Any] = field(default_factory=dict)
    metrics: dict[str, Any] = field(default_factory=dict)
    out: Optional[Path] = None
    files: list[Path] = field(default_factory=list)
    timings: dict[str, float] = field(default_factory=dict)


def start_on_orbit(plan: Any, control: Any) -> np.ndarray:
    """A start on the first orbit, east of the POI, heading along the circulation."""
    g = np.asarray(plan.poi.position(0.0))[:2]
    radius = plan.radii[0]
    heading = math.pi / 2 if control.direction == "ccw" else -math.pi / 2
    return np.array([g[0] + radius, g[1], heading])


def run(scenario: Scenario, out: str | Path | None = None, *, quiet: bool = True,
        cache_dir: str | Path | None = None) -> RunResult:
    """Run a scenario end to end; with ``out``, also write the report folder there."""
    stages = Stages(quiet)
    env = stages.run("environment", scenario.environment.load)
    poi = stages.run("POI path", scenario.poi.build, env)
    planner = stages.run("visibility scene", _planner, env, scenario, cache_dir)
    plan = stages.run("visibility volumes and orbits", planner.plan, poi, scenario.uav, scenario.planning,
                      bar_unit="VV")
    metric_runs: dict[str, Any] = {}
    for spacing in METRIC_SPACINGS:
        metric_runs[f"{spacing:g} m"] = stages.run(f"metric at {spacing:g} m spacing", planner.fixed, poi,
                                                   spacing, bar_unit="VV")
    metric_runs["adaptive"] = plan_discretization(plan)
    if min(plan.radii) <= 0.0:
        raise _core.VistrackError(
            f"plan: the POI is not visible from the flight plane at some samples ({plan.infeasibility}); "
            f"raise sensor.d_max = {scenario.sensor.d_max:g} m or change uav.altitude = {scenario.uav.altitude:g} m")
    x0 = np.asarray(scenario.start) if scenario.start is not None else start_on_orbit(plan, scenario.control)
    scene = planner.scene
    simulation = stages.run("closed-loop simulation", _simulate, plan, scenario, x0, scene)
    baselines = {}
    for radius in scenario.baselines:
        baseline_plan = _core.constant_radius_plan(poi, radius, scenario.uav)
        baselines[radius] = stages.run(f"baseline R = {radius:g} m", _simulate, baseline_plan, scenario,
                                       start_on_orbit(baseline_plan, scenario.control), scene)
    result = RunResult(scenario, env, poi, plan, simulation, planner, baselines, metric_runs)
    result.timings = stages.timings
    result.metrics = _metrics(result)
    if cache_dir is not None:
        result.metrics["volume_cache"] = {"folder": str(cache_dir), "hits": planner.disk_hits,
                                          "misses": planner.disk_misses}
    if out is not None:
        from .report import write_report

        stages.run("report", write_report, result, Path(out))
        result.timings = stages.timings
    return result


@dataclass
class PathSamples:
    """Samples along the POI path in the shape Figure 4 draws."""

    arc_lengths: list[float]
    metric: list[float]


def plan_discretization(plan: Any) -> PathSamples:
    """The adaptive samples of a plan (arc lengths and the metric between neighbours)."""
    return PathSamples(list(plan.arc_lengths), list(plan.metric))


def _planner(env: Any, scenario: Scenario, cache_dir: str | Path | None) -> Any:
    return _core.OrbitPlanner(env, scenario.sensor, scenario.planning.resolution_deg, None if cache_dir is None else str(cache_dir))


def _simulate(plan: Any, scenario: Scenario, x0: np.ndarray, scene: Any) -> Any:
    return _core.simulate(plan, scenario.uav, x0, scenario.control, scene, scenario.simulation)


def _finite(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def _metrics(result: RunResult) -> dict[str, Any]:
    from .commands.simulate import metrics as simulation_metrics

    plan, sim, s = result.plan, result.simulation, result.scenario
    metrics: dict[str, Any] = {
        "scenario": s.name,
        "environment": s.environment.describe(),
        "environment_triangles": int(result.env.num_triangles),
        "environment_max_height_m": float(result.env.max_height),
        "poi": {"length_m": result.poi.length, "duration_s": result.poi.duration, "speed_mps": result.poi.speed},
        "plan": {
            "samples": len(plan.times),
            "volumes_computed": int(plan.volumes_computed),
            "feasible": bool(plan.feasible),
            "infeasibility": plan.infeasibility,
            "initial_radius_m": plan.radii[0],
            "final_radius_m": plan.radii[-1],
            "min_radius_m": min(plan.radii),
            "max_radius_m": max(plan.radii),
            "min_feasible_radius_m": plan.min_feasible_radius,
            "max_metric_m3": max(plan.metric) if len(plan.metric) else 0.0,
            "cutoff_m3": s.planning.cutoff,
        },
        "simulation": simulation_metrics(sim),
        "baselines": {f"{r:g}": {"radius_m": r, "visibility_fraction": _finite(b.visibility_fraction)}
                      for r, b in result.baselines.items()},
        "timings_s": {k: round(v, 4) for k, v in result.timings.items()},
    }
    return metrics
