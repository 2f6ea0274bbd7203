"""What every figure module shares: the Agg pyplot, figure creation and saving, the map credit.

Nothing here needs a display: :func:`pyplot` selects the non-interactive Agg backend.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

# Shown on figures of real cities (the data is OpenStreetMap-derived).
OSM_CREDIT = "Buildings © OpenStreetMap contributors (ODbL)"


def pyplot() -> Any:
    """matplotlib.pyplot on the non-interactive Agg backend (no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def evenly_spaced_indices(n: int, count: int) -> list[int]:
    """At most ``count`` indices of ``range(n)`` spread evenly, first and last included."""
    if n <= count:
        return list(range(n))
    return sorted({round(i) for i in np.linspace(0, n - 1, count)})


def new_figure(size: tuple[float, float] = (8.0, 8.0)) -> tuple[Any, Any]:
    """A figure with one axes, on the non-interactive Agg backend."""
    return pyplot().subplots(figsize=size, constrained_layout=True)


def save_figure(fig: Any, path: Path | str, dpi: int = 150) -> Path:
    """Write the figure (format from the suffix) and close it."""
    plt = pyplot()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path


def add_credit(fig: Any, credit: str | None) -> None:
    """The data credit in small grey type at the bottom right of a figure (nothing when None)."""
    if credit:
        fig.text(0.99, 0.01, credit, ha="right", va="bottom", fontsize=6, color="gray")


def map_credit(map_path: str | Path) -> str:
    """The caption naming a map file, with the OpenStreetMap credit for the Charlotte data."""
    text = f"map: {Path(map_path).name}"
    if "charlotte" in str(map_path).lower():
        text += " (buildings © OpenStreetMap contributors, ODbL)"
    return text
