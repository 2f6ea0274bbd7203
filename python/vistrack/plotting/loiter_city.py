"""The loiter city figure: the buildings, each AOI's visibility polygon at the flight altitude, its
MaxRadius circle and the loiter circle flown inside it, and a plan's path."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional

import numpy as np

from .city import footprint_path, plot_buildings
from .common import new_figure, save_figure
from .loiter import ROLE_COLORS, _segment_points
from .motion import circle_ring


def _ring(center: Any, radius: float) -> np.ndarray:
    """A circle closed for plotting."""
    ring = circle_ring(center, radius, 180)
    return np.vstack([ring, ring[:1]])


def city_loiter_figure(env: Any, result: Any, path: Path, plan: Optional[Any] = None, title: str = "") -> Path:
    """Top view: buildings by height, each AOI's VP (filled; red edge when no flyable circle fits),
    its MaxRadius circle about the AOI (dashed), the loiter circle (solid, about its own centre: off the
    AOI when only an off-centre circle fits) and ``plan``'s path by segment role."""
    from matplotlib.patches import PathPatch

    fig, ax = new_figure((9.0, 8.0))
    plot_buildings(ax, env)
    for room in result.rooms:
        colour = "tab:blue" if room.flyable else "tab:red"
        for polygon in room.polygons:  # filled with its holes left open
            outer, holes = np.asarray(polygon.outer), [np.asarray(h) for h in polygon.holes]
            ax.add_patch(PathPatch(footprint_path(outer, holes), facecolor=colour, alpha=0.12, lw=0))
            for ring in (outer, *holes):
                ax.plot(*np.vstack([ring, ring[:1]]).T, color=colour, lw=0.6)
        x, y = room.point[0], room.point[1]
        ax.plot(*_ring((x, y), room.max_radius).T, "--", color=colour, lw=0.9)
        if room.flyable and result.radius is not None:
            ax.plot(*_ring(room.center, result.radius).T, color="k", lw=1.6)
        text = f"AOI {room.index}\nMaxRadius {room.max_radius:.0f} m" + ("" if room.flyable else "\nno flyable circle")
        ax.text(x, y, text, fontsize=7, ha="center", va="center", zorder=6,
                bbox={"facecolor": "white", "alpha": 0.7, "lw": 0})
    if plan is not None:
        seen: set[str] = set()
        for segment in plan.segments:
            points = _segment_points(segment)
            ax.plot(points[:, 0], points[:, 1], color=ROLE_COLORS[segment.role], lw=1.0,
                    label=segment.role if segment.role not in seen else None, zorder=4)
            seen.add(segment.role)
        ax.plot(*plan.start, "ks", ms=6, label="start", zorder=6)
        ax.legend(loc="upper right", fontsize=7)
    points = np.array([r.point[:2] for r in result.rooms])
    reach = max([r.max_radius for r in result.rooms] + [100.0])
    ax.set_xlim(points[:, 0].min() - reach, points[:, 0].max() + reach)
    ax.set_ylim(points[:, 1].min() - reach, points[:, 1].max() + reach)
    ax.set_aspect("equal")
    ax.set_xlabel("east [m]")
    ax.set_ylabel("north [m]")
    ax.set_title(title or "loiter circles in their visibility polygons", fontsize=9)
    return save_figure(fig, path)
