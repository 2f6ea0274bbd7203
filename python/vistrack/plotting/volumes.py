"""Visibility volumes: in 3D, and their visibility polygons from above."""

from __future__ import annotations

from pathlib import Path
from typing import Sequence

import numpy as np

from .._core import Environment, Polygon, VisibilityScene, VisibilityVolume
from .common import pyplot, save_figure


def figure_volume_3d(scene: VisibilityScene, vv: VisibilityVolume, path: Path | str, caption: str = "",
                     display_resolution_deg: float = 3.0) -> Path:
    """3D view of a VV, shaded, with its POI. Finer VVs are recomputed at display_resolution_deg
    for the picture (matplotlib draws every face); the title gives the true volume."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    from .. import _core

    resolution = 180.0 / vv.grid.num_elevation
    shown = vv if resolution >= display_resolution_deg else _core.visibility_volume(
        scene, vv.poi, vv.d_max, vv.altitude_band, display_resolution_deg)
    triangles = shown.vertices[shown.faces]
    normals = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)
    light = np.array([0.4, -0.5, 0.77])
    shade = 0.35 + 0.65 * np.clip(normals @ light, 0.0, 1.0)
    colors = np.column_stack([0.2 * shade, 0.75 * shade, 0.35 * shade, np.full_like(shade, 0.55)])
    fig = pyplot().figure(figsize=(9.0, 7.5))
    ax = fig.add_subplot(projection="3d")
    ax.add_collection3d(Poly3DCollection(triangles, facecolors=colors, edgecolors="none"))
    ax.scatter(*vv.poi, color="crimson", s=30, label="POI g", depthshade=False)
    lo, hi = shown.vertices.min(axis=0), shown.vertices.max(axis=0)
    span = max(hi - lo)
    center = (lo + hi) / 2
    ax.set_xlim(center[0] - span / 2, center[0] + span / 2)
    ax.set_ylim(center[1] - span / 2, center[1] + span / 2)
    ax.set_zlim(lo[2], lo[2] + span / 2)
    ax.set_box_aspect((2, 2, 1))
    ax.view_init(elev=28, azim=-60)
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    ax.set_zlabel("up (m)")
    ax.set_title(f"Visibility volume at POI ({vv.poi[0]:.0f}, {vv.poi[1]:.0f}): {vv.volume / 1e6:.2f}e6 m³ "
                 f"(mesh shown at {max(resolution, display_resolution_deg):g}°)")
    ax.legend(loc="upper left")
    if caption:
        fig.text(0.01, 0.01, caption, fontsize=7, color="0.3")
    return save_figure(fig, path, dpi=130)


def figure_visibility_polygons(env: Environment, shown: Sequence[tuple[np.ndarray, Sequence[Polygon], float]],
                               altitude: float, d_max: float, resolution_deg: float, path: str | Path,
                               caption: str = "") -> Path:
    """Figure 5 style: VPs at the flight altitude (the first and last filled), the largest
    inscribed circle about each POI and the POIs, over the building footprints. ``shown`` holds
    (POI, VP, MaxRadius) per point."""
    from matplotlib.patches import Circle, PathPatch

    from .city import footprint_path, plot_buildings
    from .common import new_figure

    fig, ax = new_figure((9.0, 8.0))
    plot_buildings(ax, env, cmap="Blues", edgecolor="tab:blue")
    # At most two VPs drawn filled (first and last, as the paper's i-th and j-th), all circles.
    colors = ["magenta", "c"]
    picks = [0, len(shown) - 1] if len(shown) > 1 else [0]
    for color, k in zip(colors, picks):
        poi, polygons, radius = shown[k]
        for polygon in polygons:
            ax.add_patch(PathPatch(footprint_path(polygon.outer, polygon.holes), facecolor=color, alpha=0.18,
                                   edgecolor=color, linewidth=1.2, zorder=3))
    for k, (poi, _, radius) in enumerate(shown):
        color = colors[0] if k == 0 else colors[1] if k == len(shown) - 1 else "0.35"
        if radius > 0:
            ax.add_patch(Circle((float(poi[0]), float(poi[1])), radius, fill=False, linestyle="--", edgecolor=color,
                                linewidth=1.0, zorder=4))
        ax.plot(poi[0], poi[1], "x", color=color, markersize=7, zorder=5)
    pois = np.array([s[0] for s in shown])
    pad = d_max
    ax.set_xlim(pois[:, 0].min() - pad, pois[:, 0].max() + pad)
    ax.set_ylim(pois[:, 1].min() - pad, pois[:, 1].max() + pad)
    ax.set_aspect("equal")
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    ax.set_title(f"Visibility polygons at z = {altitude:g} m, inscribed orbits (d_max = {d_max:g} m, "
                 f"{resolution_deg:g}°)")
    if caption:
        ax.text(0.01, 0.01, caption, transform=ax.transAxes, fontsize=7, color="0.3")
    return save_figure(fig, path)
