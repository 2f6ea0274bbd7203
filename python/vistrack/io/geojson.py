"""GeoJSON: trajectories and orbit plans in WGS84 (RFC 7946: [longitude, latitude]) for any GIS
tool to show over a map, and road networks of LineStrings in local metres.

Local points go through the georeference's map plane (Georeference.to_latlon), the same one maps
come in through."""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from .._core import OrbitPlan, RoadNetwork, SimulationResult, VistrackError
from ..preview import preview
from .documents import read_json

if TYPE_CHECKING:
    from ..georeference import Georeference

__all__ = ["ROAD_MERGE_DISTANCE", "feature_collection", "line_feature", "lon_lat", "orbit_plan_geojson",
           "point_feature", "read_roads", "trajectory_geojson", "write_geojson"]


def lon_lat(points: Any, georeference: Georeference) -> list[list[float]]:
    """[[lon, lat], ...] of local points, rows (x, y[, ...])."""
    array = np.asarray(points, dtype=float)
    if array.ndim != 2 or array.shape[1] < 2 or len(array) == 0:
        raise VistrackError(f"points = array of shape {array.shape}: must be rows (x, y) in local metres")
    lat, lon = georeference.to_latlon(array[:, 0], array[:, 1])
    return [[float(a), float(b)] for a, b in zip(np.atleast_1d(lon), np.atleast_1d(lat))]


def line_feature(points: Any, georeference: Georeference, properties: dict[str, Any] | None = None) -> dict[str, Any]:
    """A LineString Feature through local points."""
    return {"type": "Feature", "properties": dict(properties or {}),
            "geometry": {"type": "LineString", "coordinates": lon_lat(points, georeference)}}


def point_feature(point: Sequence[float], georeference: Georeference,
                  properties: dict[str, Any] | None = None) -> dict[str, Any]:
    """A Point Feature at a local point (x, y)."""
    return {"type": "Feature", "properties": dict(properties or {}),
            "geometry": {"type": "Point", "coordinates": lon_lat([point[:2]], georeference)[0]}}


def feature_collection(features: list[dict[str, Any]], **members: Any) -> dict[str, Any]:
    """A FeatureCollection (extra top-level members, e.g. the origin, kept as given)."""
    return {"type": "FeatureCollection", **members, "features": features}


def trajectory_geojson(result: SimulationResult, georeference: Georeference,
                       properties: dict[str, Any] | None = None) -> dict[str, Any]:
    """The flown path of a simulation (``result.state`` rows x, y, psi) as a LineString, with
    its duration and visibility fraction."""
    state = np.asarray(result.state, dtype=float)
    fraction = result.visibility_fraction  # None when simulated without a scene
    props = {"kind": "trajectory", "duration_s": float(result.t[-1] - result.t[0]),
             "visibility_fraction": None if fraction is None else float(fraction), **(properties or {})}
    return line_feature(state[:, :2], georeference, props)


def orbit_plan_geojson(plan: OrbitPlan, georeference: Georeference) -> list[dict[str, Any]]:
    """An orbit plan's features: the POI path (LineString) and one Point per sample at the orbit
    centre g(t_k) with its time and radius."""
    features = [line_feature(np.asarray(plan.poi.waypoints)[:, :2], georeference,
                             {"kind": "poi_path", "speed_mps": float(plan.poi.speed)})]
    for k, (t, center, radius) in enumerate(zip(plan.times, np.asarray(plan.centers), plan.radii)):
        features.append(point_feature(center, georeference, {"kind": "orbit_center", "sample": k,
                                                             "time_s": float(t), "radius_m": float(radius)}))
    return features


def write_geojson(collection: dict[str, Any], path: str | Path) -> Path:
    """Write a FeatureCollection (full double precision)."""
    path = Path(path)
    try:
        path.write_text(json.dumps(collection, indent=1, allow_nan=False) + "\n", encoding="utf-8")
    except OSError as error:
        raise VistrackError(f"path = {path}: cannot write the file ({error.strerror})") from None
    return path


ROAD_MERGE_DISTANCE = 0.5  # m: vertices of different LineStrings this close are one road node


def read_roads(path: str | Path, key: str = "routes.roads") -> RoadNetwork:
    """A road network from a GeoJSON file of LineString / MultiLineString features in local
    (east, north) metres: every vertex is a node, consecutive vertices are joined by an edge, and
    vertices closer than ``ROAD_MERGE_DISTANCE`` (lines meeting at a junction) are one node. Roads
    meet only where they share a vertex, as in OpenStreetMap ways."""
    from scipy.spatial import cKDTree

    data = read_json(path, key)
    features = data.get("features") if isinstance(data, dict) else None
    if not isinstance(features, list):
        raise VistrackError(f"{key} = {path}: not a GeoJSON FeatureCollection (no 'features' list)")
    lines: list[list[tuple[float, float]]] = []
    for i, feature in enumerate(features):
        geometry = feature.get("geometry") if isinstance(feature, dict) else None
        kind = geometry.get("type") if isinstance(geometry, dict) else None
        coordinates = geometry.get("coordinates") if isinstance(geometry, dict) else None
        if kind not in ("LineString", "MultiLineString") or not isinstance(coordinates, list):
            raise VistrackError(f"{key} = {path}: features[{i}] is {preview(kind)}, "
                                "not a LineString or MultiLineString")
        for part in [coordinates] if kind == "LineString" else coordinates:
            try:
                line = [(float(p[0]), float(p[1])) for p in part]
            except (TypeError, ValueError, IndexError):
                raise VistrackError(f"{key} = {path}: features[{i}] has a position that is not [x, y]") from None
            if len(line) < 2 or not np.isfinite(line).all():
                raise VistrackError(f"{key} = {path}: features[{i}] needs at least two finite positions")
            lines.append(line)
    if not lines:
        raise VistrackError(f"{key} = {path}: no roads in the file")
    vertices = np.array([p for line in lines for p in line])
    # Union-find over vertices closer than the merge distance; a node is each group's first vertex.
    parent = list(range(len(vertices)))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for a, b in sorted(cKDTree(vertices).query_pairs(ROAD_MERGE_DISTANCE)):
        ra, rb = root(a), root(b)
        parent[max(ra, rb)] = min(ra, rb)
    node_of: dict[int, int] = {}
    for i in range(len(vertices)):
        node_of.setdefault(root(i), len(node_of))
    nodes = np.array([vertices[r] for r in sorted(node_of, key=node_of.__getitem__)])
    edges: set[tuple[int, int]] = set()
    first = 0
    for line in lines:
        ids = [node_of[root(first + k)] for k in range(len(line))]
        first += len(line)
        edges.update((min(a, b), max(a, b)) for a, b in zip(ids, ids[1:]) if a != b)
    return RoadNetwork(nodes, np.array(sorted(edges), dtype=np.int64).reshape(-1, 2))
