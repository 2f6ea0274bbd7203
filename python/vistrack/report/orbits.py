"""The output folder of ``vistrack orbits``: plan.json, summary.json, Figure 5 (orbits.png),
R(t) (radius.png) and optionally Figure 4 (metric.png)."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Mapping, Optional, Union

from .._core import Discretization, Environment, VisibilityOrbitPlan
from ..io import write_json, write_plan
from ..plotting.orbits import figure_metric, figure_orbits, figure_radius
from ..tracking.metrics import plan_summary


def write_orbits(out: Path, plan: VisibilityOrbitPlan, background: Optional[Environment],
                 extra: Optional[Mapping[str, Any]] = None,
                 metric: Optional[Mapping[str, Union[Discretization, VisibilityOrbitPlan]]] = None,
                 metric_title: str = "") -> dict[str, Any]:
    """plan.json, orbits.png (over ``background``'s footprints when given), radius.png,
    summary.json (the plan's summary and ``extra``) and, with ``metric`` (Figure 4's data),
    metric.png. Returns the summary."""
    out.mkdir(parents=True, exist_ok=True)
    write_plan(plan, out / "plan.json")
    figure_orbits(plan, background, out / "orbits.png")
    figure_radius(plan, out / "radius.png")
    summary = plan_summary(plan) | dict(extra or {})
    if metric is not None:
        figure_metric(metric, plan.planning.cutoff, out / "metric.png", metric_title)
        summary["metric_max"] = {k: (max(v.metric) if len(v.metric) else 0.0) for k, v in metric.items()}
        summary["metric_volumes"] = {k: len(v.arc_lengths) for k, v in metric.items()}
    write_json(summary, out / "summary.json")
    return summary
