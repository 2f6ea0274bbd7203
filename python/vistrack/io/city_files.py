"""A city written for other tools: footprints as RFC 7946 GeoJSON (longitude/latitude, outer rings
counter-clockwise, holes clockwise, ``properties.height`` in metres, ``properties.min_height`` for a
raised base) and the extruded buildings as
a Wavefront OBJ mesh in local east-north-up metres."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional, Sequence

import numpy as np

from .._core import Environment, VistrackError
from ..georeference import Georeference
from .geojson import feature_collection, lon_lat, write_geojson

__all__ = ["city_geojson", "write_city_geojson", "write_obj"]


def _ring(points: np.ndarray, georeference: Georeference) -> list[list[float]]:
    ring = lon_lat(points, georeference)
    return [*ring, ring[0]]  # GeoJSON rings repeat their first position


def city_geojson(env: Environment, georeference: Georeference,
                 names: Optional[Sequence[str]] = None) -> dict[str, Any]:
    """The buildings of ``env`` as a FeatureCollection of Polygons in longitude/latitude about
    ``georeference``; ``names[i]`` (e.g. the OSM object) goes into properties.source."""
    features = []
    bases = env.min_heights
    for i, (footprint, height, ident) in enumerate(zip(env.footprints, env.heights, env.building_ids)):
        properties: dict[str, Any] = {"height": float(height), "id": int(ident)}
        if bases[i] > 0.0:
            properties["min_height"] = float(bases[i])  # the base of a raised part
        if names is not None:
            properties["source"] = names[i]
        rings = [_ring(footprint.outer, georeference)] + [_ring(hole, georeference) for hole in footprint.holes]
        features.append({"type": "Feature", "properties": properties,
                         "geometry": {"type": "Polygon", "coordinates": rings}})
    origin = {"lat": georeference.lat, "lon": georeference.lon, "alt": georeference.alt}
    return feature_collection(features, origin=origin)


def write_city_geojson(env: Environment, georeference: Georeference, path: str | Path,
                       names: Optional[Sequence[str]] = None) -> Path:
    """:func:`city_geojson` written to ``path``."""
    return write_geojson(city_geojson(env, georeference, names), path)


def write_obj(env: Environment, path: str | Path) -> Path:
    """The obstacle triangles as a Wavefront OBJ (``v x y z`` east-north-up metres, 1-based faces)."""
    path = Path(path)
    lines = [f"# vistrack city: {env.num_buildings} buildings, east-north-up metres (z up)"]
    lines += [f"v {x:.4f} {y:.4f} {z:.4f}" for x, y, z in np.asarray(env.vertices)]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in np.asarray(env.faces)]
    try:
        path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    except OSError as error:
        raise VistrackError(f"path = {path}: cannot write the file ({error.strerror})") from None
    return path
