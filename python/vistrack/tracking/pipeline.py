"""The whole job from map to results (``vistrack run`` and ``vistrack demo``).

Stages: environment -> POI path -> adaptive visibility volumes and orbit plan (section IV) ->
closed-loop simulation with line-of-sight evaluation (sections V-VI) -> constant-radius baselines.
The report folder is the view's: ``vistrack.report.run.run`` (``vt.run``) computes and writes it.
"""

from __future__ import annotations

import functools
import math
import time
from pathlib import Path
from typing import Any, Optional, Sequence, Union

import numpy as np

from .._core import (
    Control,
    Environment,
    OrbitPlan,
    OrbitPlanner,
    SimulationOptions,
    SimulationResult,
    Uav,
    VisibilityOrbitPlan,
    VisibilityScene,
    VistrackError,
    check_work,
    constant_radius_plan,
    simulate,
)
from ..fdm.aircraft import aircraft
from ..flight import flight_smoothness
from ..progress import Stages
from ..scenario_blocks import uav_dict, with_dynamics
from .fdm import fly_tracking, tracking_fdm_metrics
from .metrics import CONVERGE_AFTER, locus_summary, simulation_metrics
from .result import RunResult
from .scenario import Scenario

__all__ = ["METRIC_SPACINGS", "closed_loop", "compute", "simulate_with_baselines", "start_on_orbit"]

# Fixed spacings drawn beside the adaptive method in the Figure 4 plot of a run (m).
METRIC_SPACINGS = (50.0, 25.0, 10.0)

AnyPlan = Union[OrbitPlan, VisibilityOrbitPlan]


def start_on_orbit(plan: AnyPlan, direction: str) -> np.ndarray:
    """A start on the first orbit, east of the POI, heading along the circulation ("ccw"/"cw")."""
    g = np.asarray(plan.poi.position(plan.times[0]))[:2]
    heading = math.pi / 2 if direction == "ccw" else -math.pi / 2
    return np.array([g[0] + plan.radii[0], g[1], heading])


def compute(scenario: Scenario, *, quiet: bool = True, cache_dir: str | Path | None = None,
            environment: Optional[Environment] = None, planner: Optional[OrbitPlanner] = None,
            metric_spacings: Sequence[float] = METRIC_SPACINGS) -> RunResult:
    """Run a scenario end to end, writing no file (``vt.run`` adds the report folder).

    A caller running many scenarios on one map (``vistrack.sweep``) passes the map's
    ``environment`` and a ``planner`` built on it with ``scenario.sensor`` (and ``cache_dir``), so
    the Embree scene and the VV cache are built once; the results are the same as without them.
    ``metric_spacings``: the fixed spacings of Figure 4's metric runs (none: only the adaptive one).
    """
    if scenario.aircraft is not None:  # a plan the aircraft cannot fly is refused before any work
        aircraft(scenario.aircraft).check_plan(scenario.uav.speed, scenario.uav.min_turn_radius)
    stages = Stages(quiet)
    env = environment if environment is not None else stages.run("environment", scenario.environment.load,
                                                                   scenario.origin)
    poi = stages.run("POI path", scenario.poi.build, env)
    check_work(poi, scenario.planning)  # refuses a plan past planning.max_volumes before any VV
    if planner is None:
        planner = stages.run("visibility scene", OrbitPlanner, env, scenario.sensor,
                             "" if cache_dir is None else str(cache_dir))
    plan: VisibilityOrbitPlan = stages.run("visibility volumes and orbits", planner.plan, poi, scenario.uav,
                                           scenario.planning, bar_unit="VV")
    metric_runs: dict[str, Any] = {}
    for spacing in metric_spacings:
        fixed = functools.partial(planner.fixed, max_volumes=scenario.planning.max_volumes)
        metric_runs[f"{spacing:g} m"] = stages.run(f"metric at {spacing:g} m spacing", fixed, poi, spacing,
                                                   scenario.planning.resolution_deg, bar_unit="VV")
    metric_runs["adaptive"] = plan.discretization
    if plan.reference.min_radius <= 0.0:
        raise VistrackError(
            f"plan: the POI is not visible from the flight plane at some samples ({plan.infeasibility}); "
            f"raise sensor.d_max = {scenario.sensor.d_max:g} m or change uav.altitude = {scenario.uav.altitude:g} m")
    x0 = np.asarray(scenario.start) if scenario.start is not None else start_on_orbit(plan, scenario.control.direction)
    loop = (scenario.uav, scenario.control, scenario.simulation, planner.scene)
    simulation = stages.run("closed-loop simulation", closed_loop, plan, x0, *loop)
    # The same plan flown on the other vehicle model: the report shows both (the papers' Dubins
    # vehicle, the roll model).
    other = other_model(scenario.uav)
    other_run = stages.run(f"closed loop, {other.dynamics} model", closed_loop, plan, x0, other, *loop[1:])
    six_dof = None
    if scenario.aircraft is not None:
        six_dof = stages.run(f"6-DOF flight on {scenario.aircraft} (JSBSim)", fly_tracking, plan, x0, scenario.uav,
                             scenario.control, planner.scene, scenario.aircraft)
    baselines = {}
    for radius in scenario.baselines:
        baseline = constant_radius_plan(poi, radius, scenario.uav)
        baselines[radius] = stages.run(f"baseline R = {radius:g} m", closed_loop, baseline,
                                       start_on_orbit(baseline, scenario.control.direction), *loop)
    result = RunResult(scenario, env, poi, plan, simulation, planner, baselines, metric_runs, other_run, six_dof)
    result.timings = stages.timings
    result.metrics = _metrics(result)
    if cache_dir is not None:
        result.metrics["volume_cache"] = {"folder": str(cache_dir), "hits": planner.disk_hits,
                                          "misses": planner.disk_misses}
    return result


def other_model(uav: Uav) -> Uav:
    """The same vehicle on the other model (roll <-> dubins)."""
    return with_dynamics(uav, "dubins" if str(uav.dynamics) == "roll" else "roll")


def closed_loop(plan: AnyPlan, x0: np.ndarray, uav: Uav, control: Control, options: SimulationOptions,
                scene: Optional[VisibilityScene], fixed_step: float = 0.0) -> SimulationResult:
    """The closed loop of section VI around ``plan`` from ``x0`` = (x, y, psi), with the line of
    sight at every output sample when a scene is given (GIL released)."""
    return simulate(plan, uav, x0, control, scene, options, fixed_step=fixed_step)


def simulate_with_baselines(plan: AnyPlan, x0: np.ndarray, uav: Uav, control: Control,
                            options: SimulationOptions, scene: Optional[VisibilityScene],
                            baseline_radii: Sequence[float] = (), fixed_step: float = 0.0,
                            ) -> list[tuple[str, AnyPlan, SimulationResult, float]]:
    """The closed loop around ``plan`` and around constant-radius orbits of each baseline radius,
    all from ``x0``. Returns (label, plan, result, seconds) per run."""
    plans: list[tuple[str, AnyPlan]] = [("visibility orbit", plan)]
    plans += [(f"constant R = {r:g} m", constant_radius_plan(plan.poi, r, uav)) for r in baseline_radii]
    runs = []
    for label, p in plans:
        began = time.perf_counter()
        result = closed_loop(p, x0, uav, control, options, scene, fixed_step)
        runs.append((label, p, result, time.perf_counter() - began))
    return runs


def _metrics(result: RunResult) -> dict[str, Any]:
    plan, s = result.plan, result.scenario
    return {
        "scenario": s.name,
        "environment": s.environment.describe(),
        "environment_triangles": int(result.env.num_triangles),
        "environment_max_height_m": float(result.env.max_height),
        "origin": None if result.env.origin is None else list(result.env.origin),
        "poi": {"length_m": result.poi.length, "duration_s": result.poi.duration, "speed_mps": result.poi.speed},
        "uav": uav_dict(s.uav),
        "plan": {
            "samples": len(plan.times),
            "volumes_computed": int(plan.volumes_computed),
            "feasible": bool(plan.feasible),
            "infeasibility": plan.infeasibility,
            "initial_radius_m": plan.radii[0],
            "final_radius_m": plan.radii[-1],
            "min_radius_m": float(plan.reference.min_radius),
            "max_radius_m": float(max(plan.reference.radii)),
            "min_feasible_radius_m": plan.min_feasible_radius,
            "max_metric_m3": max(plan.metric) if len(plan.metric) else 0.0,
            "cutoff_m3": s.planning.cutoff,
            **locus_summary(plan),
        },
        "simulation": simulation_metrics(result.simulation),
        "other_model": None if result.other_model is None else {
            "dynamics": str(other_model(s.uav).dynamics),
            "visibility_fraction": result.other_model.visibility_fraction,
            "smoothness": flight_smoothness(result.other_model.t, result.other_model.bank).as_dict()},
        "baselines": {f"{r:g}": {"radius_m": r, "visibility_fraction": b.visibility_fraction}
                      for r, b in result.baselines.items()},
        "timings_s": {k: round(v, 4) for k, v in result.timings.items()},
        **({"fdm": tracking_fdm_metrics(result.fdm, CONVERGE_AFTER)} if result.fdm is not None else {}),
    }
