"""The city from above: building footprints or mesh roofs coloured by height, roads, POI path.

Functions draw into a given ``Axes`` in east-north metres (equal aspect) and return what a caller
may want to reuse (e.g. the ``ScalarMappable`` for a colourbar).
"""

from __future__ import annotations

from typing import Any, Optional, Sequence, Union

import numpy as np

from .._core import Environment, PoiPath, RoadNetwork


def footprint_path(outer: np.ndarray, holes: Sequence[np.ndarray]) -> Any:
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

    collection: Union[PatchCollection, PolyCollection]
    if env.num_buildings > 0:
        patches = [PathPatch(footprint_path(f.outer, f.holes)) for f in env.footprints]
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
        ax.add_collection(PolyCollection(list(top[ground, :, :2]), facecolor="0.92", edgecolor="0.92",
                                         linewidth=0.3, zorder=0))
        order = np.argsort(height[~ground], kind="stable")
        collection = PolyCollection(list(top[~ground][order, :, :2]), cmap=cmap, edgecolor="face",
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
    lines = LineCollection(list(nodes[edges]), colors=color, linewidths=linewidth, zorder=1, label=label)
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
