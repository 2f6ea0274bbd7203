"""Routes in: waypoints as local (east, north) metres from a CSV table, an autopilot mission
(QGroundControl ``.plan`` or ``QGC WPL 110``: what ``--export`` writes) or GeoJSON (a LineString,
or Point features in order, in longitude/latitude). Missions keep only their navigation waypoints
(home, speed changes and loiters are skipped) and are placed about ``origin``, else about their
home; GeoJSON needs ``origin``."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Optional, Sequence, Union

import numpy as np

from .._core import VistrackError
from ..georeference import Georeference, project_lon_lat
from ..io.tables import read_route as read_table_route
from ..io.text import read_text
from ..mission.items import WPL_HEADER, Command
from ..mission.reader import load as load_mission

__all__ = ["read_route", "route_georeference"]

Origin = Union[Georeference, Sequence[float], None]

_MISSION_SUFFIXES = (".plan", ".waypoints")
_GEOJSON_SUFFIXES = (".geojson", ".json")


def _kind(path: Path, key: str) -> str:
    suffix = path.suffix.lower()
    if suffix in _MISSION_SUFFIXES:
        return "mission"
    if suffix in _GEOJSON_SUFFIXES:
        return "geojson"
    first = next((line.strip() for line in read_text(path, key).splitlines() if line.strip()), "")
    return "mission" if first == WPL_HEADER else "table"  # a .txt or .csv in QGC WPL 110 is a mission


def route_georeference(path: Union[str, Path], key: str = "route") -> Optional[Georeference]:
    """Where a route file says its local (0, 0) lies: a mission's home; None for other files."""
    file = Path(path)
    if _kind(file, key) != "mission":
        return None
    home = load_mission(file).home
    return Georeference(home[0], home[1], home[2])


def read_route(path: Union[str, Path], origin: Origin = None, key: str = "route") -> np.ndarray:
    """The route's waypoints as an (n, 2) array of local (east, north) metres, n >= 2.

    CSV: columns ``x``, ``y`` (already local; ``origin`` is not used). A mission (``.plan``,
    ``.waypoints``, or any file starting ``QGC WPL 110``): its NAV_WAYPOINT items in order, about
    ``origin`` (lat, lon[, alt]) or, when None, about the mission's home. GeoJSON: a LineString (or
    the first one in a FeatureCollection) or Point features in order, in (longitude, latitude);
    ``origin`` is required. Errors name ``key`` and the file."""
    file = Path(path)
    kind = _kind(file, key)
    if kind == "table":
        return read_table_route(file, key)
    if kind == "mission":
        mission = load_mission(file)
        lat_lon = [(item.lat, item.lon) for item in mission.items if item.command == Command.NAV_WAYPOINT]
        reference = Georeference.from_value(origin, "origin") if origin is not None else Georeference(*mission.home)
        points = np.array([reference.to_local(lat, lon) for lat, lon in lat_lon], dtype=float).reshape(-1, 2)
    else:
        if origin is None:
            raise VistrackError(f"{key} = {file}: a GeoJSON route is in longitude/latitude; give its origin "
                                "(lat, lon; --origin LAT,LON on the command line)")
        points = project_lon_lat(_geojson_lon_lat(file, key), origin)
    if len(points) < 2:
        raise VistrackError(f"{key} = {file}: {len(points)} waypoint(s), at least two are needed")
    return points


def _geojson_lon_lat(file: Path, key: str) -> np.ndarray:
    try:
        document = json.loads(read_text(file, key))
    except (json.JSONDecodeError, RecursionError) as error:
        raise VistrackError(f"{key} = {file}: not JSON ({str(error)[:80]})") from None
    geometries = _geometries(document)
    lines = [g["coordinates"] for g in geometries if g.get("type") == "LineString"]
    if lines:
        coordinates: Any = lines[0]
    else:
        coordinates = [g["coordinates"] for g in geometries if g.get("type") == "Point"]
    try:
        array = np.array([(float(c[0]), float(c[1])) for c in coordinates], dtype=float).reshape(-1, 2)
    except (TypeError, ValueError, IndexError, KeyError):
        raise VistrackError(f"{key} = {file}: coordinates must be [longitude, latitude] numbers") from None
    if not np.all(np.isfinite(array)) or np.any(np.abs(array[:, 0]) > 180.0) or np.any(np.abs(array[:, 1]) > 90.0):
        raise VistrackError(f"{key} = {file}: coordinates must be finite longitudes in [-180, 180] and latitudes "
                            "in [-90, 90]")
    return array


def _geometries(document: Any) -> list[dict[str, Any]]:
    """The geometries of a GeoJSON document in order: a geometry, a Feature or a FeatureCollection."""
    if not isinstance(document, dict):
        return []
    kind = document.get("type")
    if kind == "FeatureCollection":
        features = document.get("features")
        if not isinstance(features, list):
            return []
        return [g for f in features if isinstance(f, dict) for g in _geometries(f)]
    if kind == "Feature":
        geometry = document.get("geometry")
        return [geometry] if isinstance(geometry, dict) else []
    return [document] if isinstance(kind, str) and "coordinates" in document else []
