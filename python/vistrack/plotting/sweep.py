"""Summary figures of a sweep: each varied parameter against each metric.

One PNG per parameter (``figures/<parameter>.png``), one panel per metric: every successful case
as a dot, joined by a line per value of the other varied parameter when there is one (with at most
MAX_GROUPS values), else by the mean over the other parameters; failed cases as red crosses along
the bottom. Numeric parameters are drawn on a numeric axis, others (routes, directions, maps) as
categories in sweep order. Booleans count as 0/1; text metrics are not drawn.
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from .common import pyplot, save_figure

__all__ = ["MAX_PANELS", "sweep_figures"]

MAX_PANELS = 12  # metrics per figure; further metrics go into <parameter>-2.png, ...
MAX_GROUPS = 8  # one line per value of the other parameter up to this many values


def _numeric(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _as_number(value: Any) -> float | None:
    if isinstance(value, bool):
        return float(value)
    return float(value) if _numeric(value) else None


def _file_name(parameter: str) -> str:
    return re.sub(r"[^\w.-]+", "_", parameter) or "parameter"


def sweep_figures(rows: Sequence[dict[str, Any]], parameters: Sequence[str], metrics: Sequence[str],
                  folder: str | Path, title: str = "sweep") -> list[Path]:
    """Draw each parameter that takes two values or more against each metric with numbers (or
    booleans) in some row; returns the files written."""
    drawable = [m for m in metrics if any(_as_number(row.get(m)) is not None for row in rows)]
    files: list[Path] = []
    if not drawable:
        return files
    for parameter in parameters:
        if len({repr(row.get(parameter)) for row in rows}) < 2:
            continue  # a parameter that did not vary here
        others = [p for p in parameters if p != parameter and len({repr(row.get(p)) for row in rows}) > 1]
        group = others[0] if len(others) == 1 and len({repr(row.get(others[0])) for row in rows}) <= MAX_GROUPS \
            else None
        for part, start in enumerate(range(0, len(drawable), MAX_PANELS)):
            chunk = drawable[start:start + MAX_PANELS]
            name = _file_name(parameter) + (f"-{part + 1}" if part else "") + ".png"
            files.append(_figure(rows, parameter, chunk, Path(folder) / name, title, group))
    return files


def _figure(rows: Sequence[dict[str, Any]], parameter: str, metrics: Sequence[str], path: Path, title: str,
            group: str | None) -> Path:
    plt = pyplot()
    values = [row.get(parameter) for row in rows]
    numeric_axis = all(_numeric(v) for v in values)
    labels: list[str] = []
    if numeric_axis:
        x = np.array(values, dtype=float)
    else:  # categories in the order they first appear (sweep order)
        labels = list(dict.fromkeys(str(v) for v in values))
        x = np.array([labels.index(str(v)) for v in values], dtype=float)
    ok = np.array([row.get("run_status") == "ok" for row in rows])
    columns = min(3, len(metrics))
    lines = math.ceil(len(metrics) / columns)
    fig, axes = plt.subplots(lines, columns, figsize=(4.6 * columns, 3.4 * lines), squeeze=False,
                             constrained_layout=True)
    for ax, metric in zip(axes.flat, metrics):
        y = np.array([_as_number(row.get(metric)) if good else None for row, good in zip(rows, ok)], dtype=float)
        have = ~np.isnan(y)
        if group is not None:
            keys = [repr(row.get(group)) for row in rows]
            for colour, key in enumerate(dict.fromkeys(keys)):
                mine = have & np.array([k == key for k in keys])
                order = np.argsort(x[mine], kind="stable")
                value = rows[keys.index(key)].get(group)
                ax.plot(x[mine][order], y[mine][order], "o-", ms=4, lw=1.2, color=f"C{colour}",
                        label=f"{group} = {value}")
        else:
            ax.plot(x[have], y[have], "o", ms=4, alpha=0.6, color="tab:blue")
            centres = np.unique(x[have])
            if len(centres) > 1 and len(centres) < have.sum():
                ax.plot(centres, [y[have][x[have] == c].mean() for c in centres], "-", color="tab:blue", lw=1.2,
                        label="mean over the other parameters")
            elif len(centres) > 1:
                ax.plot(centres, [y[have][x[have] == c].mean() for c in centres], "-", color="tab:blue", lw=1.2)
        if (~ok).any():
            bottom = np.nanmin(y) if have.any() else 0.0
            ax.plot(x[~ok], np.full((~ok).sum(), bottom), "x", color="red", ms=7, label=f"failed ({(~ok).sum()})")
        ax.set_title(metric, fontsize=9)
        ax.grid(alpha=0.3)
        if labels:
            step = max(1, len(labels) // 20)
            ax.set_xticks(range(0, len(labels), step))
            ax.set_xticklabels(labels[::step], rotation=60 if len(labels) > 6 else 0, fontsize=7)
        ax.set_xlabel(parameter, fontsize=8)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
    for ax in list(axes.flat)[len(metrics):]:
        ax.set_visible(False)
    fig.suptitle(f"{title}: {parameter} against the metrics ({len(rows)} cases)", fontsize=11)
    return save_figure(fig, path, dpi=110)
