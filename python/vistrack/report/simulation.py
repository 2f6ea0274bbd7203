"""The output folder of ``vistrack simulate``: trajectory CSVs, metrics.json, Figure 10 and 11."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional, Sequence, Union

from .._core import Environment, OrbitPlan, SimulationResult, VisibilityOrbitPlan
from ..io import write_json, write_trajectory
from ..plotting.simulation import figure_errors, figure_trajectory
from ..tracking.metrics import simulation_metrics

Run = tuple[str, Union[OrbitPlan, VisibilityOrbitPlan], SimulationResult, float]  # label, plan, result, s


def write_simulation(out: Path, runs: Sequence[Run], env: Optional[Environment], header: dict[str, Any],
                     converge_after: float, max_turn_rate: float, title: str = "",
                     window: Optional[float] = None) -> dict[str, Any]:
    """trajectory.csv (the first run), trajectory_R<r>.csv (baselines), metrics.json (``header``
    and each run's metrics under its label), trajectory.png and errors.png. Returns the metrics."""
    out.mkdir(parents=True, exist_ok=True)
    summary = dict(header)
    for label, _, result, seconds in runs:
        summary[label] = simulation_metrics(result, converge_after) | {"seconds": seconds}
    write_trajectory(runs[0][2], out / "trajectory.csv")
    for label, _, result, _ in runs[1:]:
        write_trajectory(result, out / f"trajectory_R{label.split('= ')[1].split(' ')[0]}.csv")
    write_json(summary, out / "metrics.json")
    figure_trajectory([(label, plan, result) for label, plan, result, _ in runs], env, out / "trajectory.png", title)
    figure_errors(runs[0][2], out / "errors.png", window, title, max_turn_rate)
    return summary
