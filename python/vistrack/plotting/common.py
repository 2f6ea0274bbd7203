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


def plot_bank(ax: Any, t: Any, bank: Any, label: str = "bank flown") -> None:
    """The bank angle (rad, positive left) against time on ``ax``, in degrees, with its smoothness
    (vistrack.flight.flight_smoothness) in the legend."""
    from ..flight import flight_smoothness

    t, bank = np.asarray(t, float), np.asarray(bank, float)
    text = label
    if t.size >= 2:
        s = flight_smoothness(t, bank)
        text += (f" (RMS {s.bank_rms_deg:.1f} deg about its 5 s mean, {s.roll_reversals_per_s:.2f} reversals/s, "
                 f"max {s.max_roll_rate_deg_s:.0f} deg/s)")
    ax.plot(t, np.degrees(bank), color="tab:purple", lw=1, label=text)
    ax.set_ylabel("bank (deg)")
    ax.legend(fontsize=7, loc="upper right")
