"""The output folder of ``vistrack intercept``: intercept.json and the Figure 7 pair."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from .._core.dubins import InterceptResult
from ..intercept import InterceptProblem
from ..io import write_json
from ..plotting.intercept import figure_intercept


def write_intercept(problem: InterceptProblem, result: InterceptResult, out: Path) -> dict[str, Any]:
    """fig7a_travel_times.png, fig7b_path.png and intercept.json (the record, with the figures'
    names); returns the record."""
    out.mkdir(parents=True, exist_ok=True)
    record = problem.record(result)
    record["figures"] = [f.name for f in figure_intercept(problem, result, out)]
    write_json(record, out / "intercept.json")
    return record
