"""What a tracking run computed (``vt.RunResult``)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Optional, Union

from .._core import Discretization, Environment, OrbitPlanner, PoiPath, SimulationResult, VisibilityOrbitPlan
from .fdm import TrackingFdm
from .scenario import Scenario

__all__ = ["RunResult"]


@dataclass
class RunResult:
    """Everything a run computed; ``metrics`` is what metrics.json holds."""

    scenario: Scenario
    env: Environment
    poi: PoiPath
    plan: VisibilityOrbitPlan
    simulation: SimulationResult
    planner: OrbitPlanner
    baselines: dict[float, SimulationResult] = field(default_factory=dict)
    metric_runs: dict[str, Union[Discretization, VisibilityOrbitPlan]] = field(default_factory=dict)
    other_model: Optional[SimulationResult] = None  # the same plan flown on the other vehicle model
    fdm: Optional[TrackingFdm] = None  # the same plan flown on a 6-DOF JSBSim aircraft (uav.dynamics: jsbsim)
    metrics: dict[str, Any] = field(default_factory=dict)
    out: Optional[Path] = None
    files: list[Path] = field(default_factory=list)
    timings: dict[str, float] = field(default_factory=dict)
