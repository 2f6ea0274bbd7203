"""Road routes between two points: the POI drives the shortest road route between the road nodes
nearest to a start and an end, given as WGS84 (longitude, latitude) like GeoJSON when the city is
georeferenced (``env.origin``, as an OSM or longitude/latitude GeoJSON city is), or as local
(east, north) metres with ``crs="local"``.

``vt.PoiPath.from_route(env, start, end, speed, crs="lonlat")`` is the short form of
:func:`route_path`. Routes drive one-way edges (``RoadNetwork.oneway``) their way only. Two points
on parts of the road network that no road joins are a one-line VistrackError naming both, and so
are two points only joined against one-way streets (the message says so).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from ._core import Environment, PoiPath, RoadNetwork, VistrackError
from .georeference import Georeference, degrees
from .schema import fail, number, reject_unknown

__all__ = ["CRS", "road_route", "route_ends", "route_nodes", "route_path"]

CRS = ("lonlat", "local")


def _local(env: Environment, point: Sequence[float], crs: str, key: str) -> np.ndarray:
    if isinstance(point, (str, bytes)) or not isinstance(point, Sequence) or len(point) != 2:
        raise fail(key, point, "must be [lon, lat] (crs lonlat) or [x, y] (crs local)")
    if crs == "local":
        return np.array([number(f"{key}[0]", point[0]), number(f"{key}[1]", point[1])])
    georeference = Georeference.of(env)
    if georeference is None:
        raise fail(key, list(point), "is [lon, lat] but the city has no georeference (env.origin): "
                                     "give a georeference or crs local")
    lon, lat = degrees(f"{key}[0]", point[0], 180.0), degrees(f"{key}[1]", point[1], 90.0)
    east, north = georeference.to_local(lat, lon)
    return np.array([east, north])


def route_ends(value: Mapping[str, Any], key: str) -> dict[str, Any]:
    """A route's ends from a scenario: ``{from: [lon, lat], to: [lon, lat], crs: lonlat | local}``
    (crs lonlat unless given), checked for shape; errors name ``key``."""
    reject_unknown(value, {"from", "to", "crs"}, f"{key}.", where=f" in {key}")
    crs = value.get("crs", "lonlat")
    if crs not in CRS:
        raise fail(f"{key}.crs", crs, "must be lonlat or local")
    ends: dict[str, Any] = {"crs": crs}
    for name in ("from", "to"):
        point = value.get(name)
        if not isinstance(point, list) or len(point) != 2:
            raise fail(f"{key}.{name}", point, "must be [lon, lat] (crs lonlat) or [x, y] (crs local)")
        ends[name] = [number(f"{key}.{name}[{k}]", c) for k, c in enumerate(point)]
    return ends


def road_route(roads: RoadNetwork, via_points: Sequence[Sequence[float]] | Sequence[np.ndarray]) -> list[int]:
    """Road nodes from the node nearest the first point, through the nodes nearest the others,
    joined by shortest routes along the road edges (one-way edges their way only)."""
    via = [roads.nearest_node(np.asarray(p, dtype=float)) for p in via_points]
    nodes = [via[0]]
    for a, b in zip(via, via[1:]):
        nodes += roads.shortest_route(a, b)[1:]
    return nodes


def route_nodes(env: Environment, start: Sequence[float], end: Sequence[float], crs: str = "lonlat",
                key: str = "route") -> list[int]:
    """Road nodes of the shortest route from the node nearest ``start`` to the node nearest
    ``end`` (both included); errors name ``key``."""
    if crs not in CRS:
        raise fail(f"{key}.crs", crs, "must be lonlat or local")
    roads = env.roads
    if len(roads.nodes) == 0:
        raise VistrackError(f"{key}: the city has no road network")
    ends = [_local(env, point, crs, f"{key}.{name}") for point, name in ((start, "from"), (end, "to"))]
    try:
        return road_route(roads, ends)
    except VistrackError as error:
        first, last = (roads.nearest_node(point) for point in ends)
        if "one-way" in str(error):
            raise VistrackError(f"{key}: no road route from = {list(start)} (road node {first}) to = "
                                f"{list(end)} (road node {last}) that respects one-way streets: one "
                                "exists only driving against them") from None
        raise VistrackError(f"{key}: no road connects from = {list(start)} (road node {first}) and to = "
                            f"{list(end)} (road node {last}): they lie on parts of the road network that "
                            "no road joins") from None


def route_path(env: Environment, start: Sequence[float], end: Sequence[float], speed: float,
               crs: str = "lonlat") -> PoiPath:
    """A POI driving at constant ``speed`` (m/s) along :func:`route_nodes`."""
    return PoiPath.from_nodes(env.roads, route_nodes(env, start, end, crs), speed)


PoiPath.from_route = staticmethod(route_path)  # type: ignore[method-assign]
