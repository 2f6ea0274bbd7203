"""Tracking a moving POI with visibility-volume orbits (the paper the package began with).

- ``scenario``: the scenario file (map, POI path, UAV, sensor, planning, control, report)
- ``pipeline``: the whole job from map to results (:func:`compute`); ``result``: :class:`RunResult`
  (``vt.run`` in ``vistrack.report.run`` adds the report folder)
- ``metrics``: plan and simulation summaries; ``tuning``: the guidance gain beta (Lemma 7)
- ``saved_volumes``: orbit plans from VV files saved by ``vistrack volumes``
- ``to_mission``: an orbit plan as an autopilot mission; ``methods`` attaches it as
  ``OrbitPlan.to_mission``
"""

from __future__ import annotations

from . import methods as _methods  # noqa: F401  (attaches OrbitPlan.to_mission)
from .pipeline import METRIC_SPACINGS, closed_loop, compute, simulate_with_baselines, start_on_orbit
from .result import RunResult
from .scenario import EnvironmentSpec, PoiSpec, ReportOptions, Scenario, default_scenario_text, road_route
from .to_mission import export_orbit_plan, orbit_plan_mission
from .tuning import BetaTuning, default_sweep, tune_beta

__all__ = [
    "METRIC_SPACINGS", "BetaTuning", "EnvironmentSpec", "PoiSpec", "ReportOptions", "RunResult", "Scenario",
    "closed_loop", "compute", "default_scenario_text", "default_sweep", "export_orbit_plan", "orbit_plan_mission",
    "road_route", "simulate_with_baselines", "start_on_orbit", "tune_beta",
]
