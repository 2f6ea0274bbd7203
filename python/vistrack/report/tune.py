"""The output folder of ``vistrack tune``: tune.json and tune.png (Figure 9)."""

from __future__ import annotations

from pathlib import Path

from ..io import write_json
from ..plotting.tune import figure_tuning
from ..tracking.tuning import BetaTuning


def write_tuning(tuning: BetaTuning, out: Path) -> list[Path]:
    """tune.json (the summary) and tune.png (the map and the sweep)."""
    out.mkdir(parents=True, exist_ok=True)
    return [write_json(tuning.summary(), out / "tune.json"), figure_tuning(tuning, out / "tune.png")]
