"""Drivable OSM ways to vistrack's road network (``Environment.set_roads``) in local metres.

Every node of a way is a graph node (ways meet where they share an OSM node) and consecutive
nodes are joined by an edge, one-way (``RoadNetwork.oneway``) when its way is (``oneway``,
roundabouts: :func:`vistrack.io.osm_tags.oneway`), oriented the way it is driven; two ways over
the same pair of nodes make a two-way edge unless both go the same way. An edge that crosses a
building's interior (a road drawn through a building without a tunnel, covered or layer tag, or
an arcade) is left out and counted, as ``set_roads`` refuses it; nodes left without an edge are
dropped.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import shapely

from .._core import Environment, VistrackError

if TYPE_CHECKING:
    from .osm_handler import RoadWay

__all__ = ["RoadSummary", "add_roads"]

_EDGE = re.compile(r"roads\.edges\[(\d+)\]")


@dataclass
class RoadSummary:
    """What became of the drivable ways."""

    ways: int = 0
    truncated: int = 0  # ways cut at the extract's edge: their runs of present nodes kept
    skipped: dict[str, int] = field(default_factory=dict)
    oneway_ways: int = 0  # ways driven one way only (their edges are one-way)
    oneway_edges: int = 0
    nodes: int = 0
    edges: int = 0
    edges_crossing_buildings: int = 0
    length_m: float = 0.0
    maxspeed: dict[str, int] = field(default_factory=dict)


def _crossing(nodes: np.ndarray, edges: np.ndarray, env: Environment) -> np.ndarray:
    """A mask of the edges whose interior meets a footprint's interior."""
    if len(edges) == 0 or env.num_buildings == 0:
        return np.zeros(len(edges), dtype=bool)
    polygons = [shapely.Polygon(p.outer, list(p.holes)) for p in env.footprints]
    lines = shapely.linestrings(nodes[edges.reshape(-1)].reshape(-1, 2, 2))
    line_index, polygon_index = shapely.STRtree(polygons).query(lines, predicate="intersects")
    hits = shapely.relate_pattern(lines[line_index], np.asarray(polygons, dtype=object)[polygon_index], "T********")
    mask = np.zeros(len(edges), dtype=bool)
    mask[line_index[hits]] = True
    return mask


def add_roads(env: Environment, ways: Sequence[RoadWay], skipped: Counter[str], truncated: int,
              to_local: object) -> RoadSummary:
    """Sets the network of ``ways`` on ``env``; ``skipped`` are the ways the reader left out."""
    oneway = {w.osm_id for w in ways if w.oneway}
    summary = RoadSummary(ways=len({w.osm_id for w in ways}), truncated=truncated, skipped=dict(skipped),
                          oneway_ways=len(oneway),
                          maxspeed=dict(Counter({w.osm_id: w.maxspeed for w in ways if w.maxspeed}.values())))
    if not ways:
        return summary
    index: dict[int, int] = {}
    lon_lat: list[np.ndarray] = []
    directions: dict[tuple[int, int], set[tuple[int, int]]] = {}  # node pair -> the ways it is driven
    for way in ways:
        ids = []
        for node, point in zip(way.nodes, way.lon_lat):
            if node not in index:
                index[node] = len(index)
                lon_lat.append(point)
            ids.append(index[node])
        for a, b in zip(ids, ids[1:]):
            if a != b:
                driven = {(a, b)} if way.oneway > 0 else {(b, a)} if way.oneway < 0 else {(a, b), (b, a)}
                directions.setdefault((min(a, b), max(a, b)), set()).update(driven)
    points = np.array(lon_lat)
    east, north = to_local(points[:, 1], points[:, 0])  # type: ignore[operator]
    nodes = np.column_stack([np.atleast_1d(east), np.atleast_1d(north)])
    pairs = sorted(directions)
    edges = np.array([next(iter(directions[p])) if len(directions[p]) == 1 else p for p in pairs],
                     dtype=np.int64).reshape(-1, 2)
    one_way = np.array([len(directions[p]) == 1 for p in pairs], dtype=bool)
    keep = np.any(nodes[edges[:, 0]] != nodes[edges[:, 1]], axis=1)  # zero length
    keep &= ~_crossing(nodes, edges, env)
    summary.edges_crossing_buildings = int(np.any(nodes[edges[:, 0]] != nodes[edges[:, 1]], axis=1).sum()
                                           - keep.sum())
    edges, one_way = edges[keep], one_way[keep]
    for _ in range(1000):  # set_roads' own check is the last word (its tolerance differs from shapely's)
        used, inverse = np.unique(edges.reshape(-1), return_inverse=True)
        try:
            env.set_roads(nodes[used], inverse.reshape(-1, 2).astype(np.int64), one_way.tolist())
            break
        except VistrackError as error:
            match = _EDGE.search(str(error))
            if match is None:
                raise
            edges, one_way = np.delete(edges, int(match.group(1)), axis=0), np.delete(one_way, int(match.group(1)))
            summary.edges_crossing_buildings += 1
    summary.nodes, summary.edges, summary.oneway_edges = len(used), len(edges), int(one_way.sum())
    summary.length_m = float(np.linalg.norm(nodes[edges[:, 0]] - nodes[edges[:, 1]], axis=1).sum())
    return summary
