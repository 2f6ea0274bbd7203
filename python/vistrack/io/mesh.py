"""Maps: GeoJSON 2.5D footprints or any triangle mesh, as a vistrack Environment."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Optional

from .._core import Environment
from .text import input_file

if TYPE_CHECKING:
    from ..georeference import Georeference

__all__ = ["GEOJSON_SUFFIXES", "footprint_environment", "load_environment"]

GEOJSON_SUFFIXES = (".geojson", ".json")


def load_environment(path: str | Path, up: str = "z", kind: Optional[str] = None,
                     origin: Georeference | None = None, key: str = "--map") -> Environment:
    """A city from a file: GeoJSON 2.5D footprints or any triangle mesh (OBJ, PLY, STL, OFF), whose
    up axis is ``up`` ("z", or "y" for Y-up files such as the Charlotte and campus OBJ exports,
    where north is -Z). ``kind`` "geojson" or "mesh"; by default from the suffix
    (``.geojson``/``.json`` are GeoJSON). ``origin`` becomes ``env.origin``; a longitude/latitude
    GeoJSON is projected about it (without it: about the data's centre). Errors name ``key``."""
    text = str(input_file(path, key))  # the C++ loaders check again; this names the key
    if kind is None:
        kind = "geojson" if Path(text).suffix.lower() in GEOJSON_SUFFIXES else "mesh"
    if kind == "geojson":
        return Environment.from_geojson(text, origin=origin)
    env = Environment.from_mesh(text, up)
    env.origin = origin
    return env


def footprint_environment(map_path: str | Path | None, footprints: str | Path | None = None,
                          origin: Georeference | None = None) -> Environment | None:
    """Building footprints to draw under a figure without loading the map for planning: the
    given GeoJSON, else a GeoJSON map itself, else ``buildings.geojson`` beside a mesh map
    (Charlotte ships both), else None. Longitude/latitude files are projected about ``origin``
    (else their centre), as the map is."""
    if footprints:
        return Environment.from_geojson(str(footprints), origin=origin)
    if not map_path:
        return None
    map_file = Path(map_path)
    if map_file.suffix.lower() in GEOJSON_SUFFIXES:
        return Environment.from_geojson(str(map_file), origin=origin)
    beside = map_file.with_name("buildings.geojson")
    return Environment.from_geojson(str(beside), origin=origin) if beside.exists() else None
