"""Visibility volumes: in 3D, and their visibility polygons from above."""

from __future__ import annotations

from pathlib import Path
from typing import Optional, Sequence, Union

import numpy as np

from .._core import Environment, Polygon, VisibilityScene, VisibilityVolume
from ..report_options import DEFAULT_VIEW
from .common import pyplot, save_figure


def _shade(triangles: np.ndarray, rgb: Sequence[float], alpha: float) -> np.ndarray:
    """Per-face RGBA lit by a fixed light (Lambert, with an ambient floor)."""
    normals = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)
    light = np.array([0.4, -0.5, 0.77])
    shade = 0.45 + 0.55 * np.abs(normals @ light)  # abs: the meshes' winding is not ours to trust
    return np.column_stack([np.outer(shade, rgb), np.full(len(shade), alpha)])


def clip_to_box(triangles: np.ndarray, lo: Union[Sequence[float], np.ndarray],
                hi: Union[Sequence[float], np.ndarray]) -> tuple[list[np.ndarray], np.ndarray]:
    """The parts of triangles (n, 3, 3) inside the box [lo, hi], as convex polygons (mplot3d does
    not clip to its axes: a tower would poke out of the figure), and the index of the triangle
    each polygon comes from (Sutherland-Hodgman against the six planes, for the few that cross)."""
    low, high = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    inside = ((triangles >= low) & (triangles <= high)).all(axis=(1, 2))
    outside = np.any((triangles < low).all(axis=1) | (triangles > high).all(axis=1), axis=1)
    polygons = list(triangles[inside])
    origin = list(np.flatnonzero(inside))
    for index in np.flatnonzero(~inside & ~outside):
        polygon = list(triangles[index])
        for axis in range(3):
            for bound, sign in ((low[axis], 1.0), (high[axis], -1.0)):
                kept = []
                for a, b in zip(polygon, polygon[1:] + polygon[:1]):
                    da, db = sign * (a[axis] - bound), sign * (b[axis] - bound)
                    if da >= 0:
                        kept.append(a)
                    if (da >= 0) != (db >= 0):
                        kept.append(a + (b - a) * da / (da - db))
                polygon = kept
                if len(polygon) < 3:
                    break
            if len(polygon) < 3:
                break
        if len(polygon) >= 3:
            polygons.append(np.array(polygon))
            origin.append(index)
    return polygons, np.asarray(origin, dtype=int)


def figure_volume_3d(scene: VisibilityScene, vv: VisibilityVolume, path: Path | str, caption: str = "",
                     display_resolution_deg: float = 3.0, env: Optional[Environment] = None,
                     view: tuple[float, float] = DEFAULT_VIEW,
                     orbit: Optional[tuple[Sequence[float], float, float]] = None,
                     polygons: Sequence[Polygon] = ()) -> Path:
    """3D view of a VV, translucent, with the buildings of ``env`` within d_max of its POI (the
    occluders that carve it), from ``view`` = (elevation, azimuth) in degrees. ``orbit`` = (center,
    radius, altitude) and ``polygons`` (its VP) are drawn at the flight altitude. Finer VVs are
    recomputed at ``display_resolution_deg`` for the picture (matplotlib draws every face); the
    title gives the true volume. Buildings and VV share one collection so that faces are
    depth-sorted together."""
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

    from .. import _core

    resolution = 180.0 / vv.grid.num_elevation
    shown = vv if resolution >= display_resolution_deg else _core.visibility_volume(
        scene, vv.poi, vv.d_max, vv.altitude_band, display_resolution_deg)
    volume = shown.vertices[shown.faces]
    lo, hi = shown.vertices.min(axis=0), shown.vertices.max(axis=0)
    span = max(hi[:2] - lo[:2])
    center = (lo + hi) / 2
    box_lo, box_hi = center[:2] - span / 2, center[:2] + span / 2
    z_top = lo[2] + span / 2
    polygons3d: list[np.ndarray] = list(volume)
    colors = [_shade(volume, (0.15, 0.7, 0.3), 0.28)]
    buildings = 0
    if env is not None and env.num_triangles:
        corners = np.asarray(env.vertices)[np.asarray(env.faces)]
        # Cut to the drawn box, above the flat ground pieces; a little translucent (mplot3d's
        # painter's sort misorders long walls).
        high = corners[:, :, 2].max(axis=1) > env.ground_level + 0.5
        pieces, origin = clip_to_box(corners[high], [*box_lo, lo[2] - 1.0], [*box_hi, z_top])
        buildings = len(pieces)
        polygons3d += pieces
        colors.append(_shade(corners[high], (0.62, 0.62, 0.66), 0.85)[origin])
    fig = pyplot().figure(figsize=(9.0, 7.5))
    ax = fig.add_subplot(projection="3d")
    ax.computed_zorder = False  # the POI, orbit and VP stay on top of the meshes
    # Polygons of equal length (the last vertex repeated): mplot3d keeps ragged polygons in a padded
    # array whose padding its autoscale reads (garbage limits, even "Axis limits cannot be NaN").
    most = max(len(p) for p in polygons3d)
    faces = np.array([np.vstack([p, np.repeat(p[-1:], most - len(p), axis=0)]) for p in polygons3d])
    ax.add_collection3d(Poly3DCollection(faces, facecolors=np.concatenate(colors), edgecolors="none", zorder=1))
    ax.scatter(*vv.poi, color="crimson", s=40, label="POI g", depthshade=False, zorder=10)
    if orbit is not None:
        center, radius, altitude = orbit
        a = np.linspace(0, 2 * np.pi, 120)
        ax.plot(center[0] + radius * np.cos(a), center[1] + radius * np.sin(a), np.full_like(a, altitude),
                color="black", ls="--", lw=1.5, label=f"orbit R = {radius:.1f} m at {altitude:g} m", zorder=11)
    if polygons and orbit is not None:
        rings = [np.column_stack([r, np.full(len(r), orbit[2])]) for p in polygons for r in [p.outer, *p.holes]]
        segments = [np.stack([r, np.roll(r, -1, axis=0)], axis=1) for r in rings]
        ax.add_collection3d(Line3DCollection(np.concatenate(segments), colors="darkgreen", linewidths=1.0,
                                             label="VP at the flight altitude", zorder=9))
    ax.set_xlim(center[0] - span / 2, center[0] + span / 2)
    ax.set_ylim(center[1] - span / 2, center[1] + span / 2)
    ax.set_zlim(lo[2], z_top)
    ax.set_box_aspect((2, 2, 1), zoom=1.1)
    ax.view_init(elev=view[0], azim=view[1])
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    ax.set_zlabel("up (m)")
    ax.set_title(f"Visibility volume at POI ({vv.poi[0]:.0f}, {vv.poi[1]:.0f}): {vv.volume / 1e6:.2f}e6 m³\n"
                 f"mesh shown at {max(resolution, display_resolution_deg):g}°, {buildings} building faces "
                 f"within d_max = {vv.d_max:g} m; view elevation {view[0]:g}°, azimuth {view[1]:g}°", fontsize=10)
    ax.legend(loc="upper left", fontsize=8)
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
