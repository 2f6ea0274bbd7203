"""Matplotlib helpers shared by the CLI and the examples: the city from above, roads, POI path.

All functions draw into a given ``Axes`` in east-north metres (equal aspect) and return what a
caller may want to reuse (e.g. the ``ScalarMappable`` for a colourbar). The Agg backend is
selected by :func:`new_figure`, so nothing here needs a display.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional, Sequence

import numpy as np

from ._core import Environment, PoiPath, RoadNetwork

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
    return sorted({int(round(i)) for i in np.linspace(0, n - 1, count)})


def new_figure(size: tuple[float, float] = (8.0, 8.0)) -> tuple[Any, Any]:
    """A figure with one axes, on the non-interactive Agg backend."""
    return pyplot().subplots(figsize=size, constrained_layout=True)


def save_figure(fig: Any, path: Path | str, dpi: int = 150) -> Path:
    """Write the figure (format from the suffix) and close it."""
    import matplotlib.pyplot as plt

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path


def _footprint_path(outer: np.ndarray, holes: Sequence[np.ndarray]) -> Any:
    from matplotlib.path import Path as MplPath

    rings = [outer, *holes]
    vertices = np.concatenate([np.vstack([r, r[:1]]) for r in rings])
    codes = np.concatenate(
        [[MplPath.MOVETO] + [MplPath.LINETO] * (len(r) - 1) + [MplPath.CLOSEPOLY] for r in rings]
    )
    return MplPath(vertices, codes)


def plot_buildings(ax: Any, env: Environment, *, cmap: str = "viridis", vmax: Optional[float] = None,
                   edgecolor: str = "0.25", linewidth: float = 0.3,
                   ground_tolerance: float = 0.5) -> Any:
    """Footprints coloured by height (2.5D environments), or, for a mesh environment, its
    triangles seen from above coloured by their top height, higher ones drawn on top (those
    within ground_tolerance metres of the ground level in grey). Returns the collection of
    buildings (a ScalarMappable)."""
    from matplotlib.collections import PatchCollection, PolyCollection
    from matplotlib.patches import PathPatch

    if env.num_buildings > 0:
        patches = [PathPatch(_footprint_path(f.outer, f.holes)) for f in env.footprints]
        collection = PatchCollection(patches, cmap=cmap, edgecolor=edgecolor, linewidth=linewidth)
        collection.set_array(np.asarray(env.heights))
    else:
        vertices, faces = env.vertices, env.faces
        corners = vertices[faces]  # (m, 3, 3)
        normal_z = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])[:, 2]
        top = corners[np.abs(normal_z) > 1e-9]  # walls have no area seen from above
        height = top[:, :, 2].max(axis=1) - env.ground_level
        # Flat ground pieces (terrain planes in the file) in light grey, under the buildings.
        ground = height < ground_tolerance
        ax.add_collection(PolyCollection(top[ground, :, :2], facecolor="0.92", edgecolor="0.92",
                                         linewidth=0.3, zorder=0))
        order = np.argsort(height[~ground], kind="stable")
        collection = PolyCollection(top[~ground][order, :, :2], cmap=cmap, edgecolor="face",
                                    linewidth=0.2)
        collection.set_array(height[~ground][order])
    collection.set_clim(0.0, vmax if vmax is not None else max(env.max_height, 1.0))
    ax.add_collection(collection)
    return collection


def plot_roads(ax: Any, roads: RoadNetwork, *, color: str = "0.55", linewidth: float = 1.2,
               label: Optional[str] = "roads") -> Any:
    """Road edges as grey lines under everything else."""
    from matplotlib.collections import LineCollection

    nodes, edges = roads.nodes, roads.edges
    lines = LineCollection(nodes[edges], colors=color, linewidths=linewidth, zorder=1, label=label)
    ax.add_collection(lines)
    return lines


def plot_poi_path(ax: Any, poi: PoiPath, *, color: str = "crimson", label: str = "POI path") -> None:
    """The POI path with a start (circle) and end (square) marker."""
    xy = poi.waypoints[:, :2]
    ax.plot(xy[:, 0], xy[:, 1], color=color, linewidth=2.5, zorder=4, label=label)
    ax.plot(*xy[0], marker="o", markersize=9, color=color, markeredgecolor="white", zorder=5,
            linestyle="none", label="start")
    ax.plot(*xy[-1], marker="s", markersize=9, color=color, markeredgecolor="white", zorder=5,
            linestyle="none", label="end")


def plot_city(ax: Any, env: Environment, poi: Optional[PoiPath] = None, *, roads: bool = True,
              colorbar: bool = True, cmap: str = "viridis", title: Optional[str] = None,
              margin: float = 20.0) -> Any:
    """Top view of an environment: buildings coloured by height with a colourbar, roads and an
    optional POI path, equal axes in metres. Returns the buildings' collection."""
    collection = plot_buildings(ax, env, cmap=cmap)
    if roads and len(env.roads.edges):
        plot_roads(ax, env.roads)
    if poi is not None:
        plot_poi_path(ax, poi)
    (x0, y0, _), (x1, y1, _) = env.bounds
    if roads and len(env.roads.nodes):
        nodes = env.roads.nodes
        x0, y0 = min(x0, nodes[:, 0].min()), min(y0, nodes[:, 1].min())
        x1, y1 = max(x1, nodes[:, 0].max()), max(y1, nodes[:, 1].max())
    ax.set_xlim(x0 - margin, x1 + margin)
    ax.set_ylim(y0 - margin, y1 + margin)
    ax.set_aspect("equal")
    ax.set_xlabel("east [m]")
    ax.set_ylabel("north [m]")
    if title:
        ax.set_title(title)
    if colorbar:
        label = "building height [m]" if env.num_buildings else "height above ground level [m]"
        ax.figure.colorbar(collection, ax=ax, shrink=0.8, label=label)
    if poi is not None or (roads and len(env.roads.edges)):
        # Below the map, so it never hides a building.
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.08), ncol=4, frameon=False,
                  fontsize="small")
    return collection


def figure_volume_3d(scene: Any, vv: Any, path: Path | str, caption: str = "",
                     display_resolution_deg: float = 3.0) -> Path:
    """3D view of a VV, shaded, with its POI. Finer VVs are recomputed at display_resolution_deg
    for the picture (matplotlib draws every face); the title gives the true volume."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    from . import _core

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
