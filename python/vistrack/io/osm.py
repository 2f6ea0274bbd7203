"""OpenStreetMap cities: buildings and drivable roads from ``.osm``, ``.osm.bz2`` and ``.osm.pbf``
(pyosmium, streamed) as a vistrack Environment in local metres about a Georeference.

``read_osm(path)`` returns an :class:`OsmCity`: the environment (built by
``Environment.from_buildings``, the path GeoJSON footprints take, so the two agree), its
georeference and an :class:`OsmSummary` of what was imported and what was left out, by reason.
``vt.Environment.from_osm(path, ...)`` is the short form returning the environment alone.

The tag rules are in :mod:`vistrack.io.osm_tags`, the geometry rules in
:mod:`vistrack.io.osm_build`, the road rules in :mod:`vistrack.io.osm_roads`. A part's base
(``min_height``, ``building:min_level``) is its solid's bottom: a raised part is a solid from its
base to its top, the space under it open for lines of sight.
"""

from __future__ import annotations

import re
import time
from collections import Counter
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, Optional, Sequence

import numpy as np

from .._core import Environment, Polygon, VistrackError
from ..georeference import Georeference
from ..schema import fail, number
from .osm_build import Footprint, footprints, object_outcomes
from .osm_roads import RoadSummary, add_roads
from .text import input_file

__all__ = ["DEFAULT_HEIGHT", "LEVEL_HEIGHT", "OSM_SUFFIXES", "ROOF_HEIGHT", "OsmCity", "OsmSummary",
           "from_osm", "read_osm"]

LEVEL_HEIGHT = 3.0  # m per building:levels (the GeoJSON loader's levels rule)
ROOF_HEIGHT = 0.0  # m added to a levels height when neither roof:height nor roof:levels is tagged
DEFAULT_HEIGHT = 10.0  # m for a building with no usable height or levels tag
OSM_SUFFIXES = (".osm", ".osm.bz2", ".osm.gz", ".osm.pbf", ".pbf")
_BUILDING = re.compile(r"buildings\[(\d+)\]")


@dataclass
class OsmSummary:
    """What an OSM import kept and left out. ``objects``: building ways and relations by outcome
    ("imported" or the reason all of it was left out); ``footprints``: ``env.num_buildings``;
    ``height_sources``: footprints by where the top came from; ``bad_tags``: tag values that did
    not parse, by key (ignored); ``raised_base``: footprints with a base above the ground
    (solids from their base up, open underneath); ``clipped``: footprints cut where a taller one overlaps them."""

    file: str
    origin: tuple[float, float, float]
    level_height: float
    roof_height: float
    default_height: float
    objects: dict[str, int]
    footprints: int
    height_sources: dict[str, int]
    bad_tags: dict[str, int]
    raised_base: int
    clipped: int
    bbox_lon_lat: Optional[list[float]]
    tallest: Optional[dict[str, Any]]
    roads: RoadSummary = field(default_factory=RoadSummary)
    seconds: float = 0.0

    @property
    def imported(self) -> int:
        """Building objects (ways and relations) with at least one footprint in the city."""
        return self.objects.get("imported", 0)

    @property
    def skipped(self) -> dict[str, int]:
        """Building objects left out entirely, by reason."""
        return {k: v for k, v in sorted(self.objects.items()) if k != "imported"}

    def to_dict(self) -> dict[str, Any]:
        """The summary as JSON-ready data (summary.json)."""
        return {**asdict(self), "imported": self.imported, "skipped": self.skipped}

    def lines(self) -> list[str]:
        """The summary as text lines for the console."""
        out = [f"{self.file}: {self.imported} building objects imported as {self.footprints} footprints "
               f"({self.clipped} clipped by taller overlapping ones)"]
        out.append("  skipped: " + (", ".join(f"{k} {v}" for k, v in self.skipped.items()) or "none"))
        out.append("  heights from: " + ", ".join(f"{k} {v}" for k, v in sorted(self.height_sources.items()))
                   + f" (levels x {self.level_height:g} m + roof {self.roof_height:g} m; "
                   f"default {self.default_height:g} m)")
        if self.bad_tags:
            out.append("  bad tag values ignored: " + ", ".join(f"{k} {v}" for k, v in sorted(self.bad_tags.items())))
        if self.raised_base:
            out.append(f"  {self.raised_base} footprints with a base above the ground (open underneath)")
        if self.tallest:
            out.append(f"  tallest: {self.tallest['height']:.1f} m ({self.tallest['osm_id']})")
        if self.bbox_lon_lat:
            out.append("  bbox lon/lat: " + ", ".join(f"{v:.6f}" for v in self.bbox_lon_lat))
        out.append(f"  origin: lat {self.origin[0]:.7f}, lon {self.origin[1]:.7f}")
        r = self.roads
        out.append(f"  roads: {r.ways} ways ({r.truncated} cut at the extract's edge), {r.nodes} nodes, "
                   f"{r.edges} edges, {r.length_m / 1000:.2f} km; "
                   f"skipped " + (", ".join(f"{k} {v}" for k, v in sorted(r.skipped.items())) or "none")
                   + f"; {r.edges_crossing_buildings} edges crossing a building left out; "
                   f"{r.oneway_ways} one-way ways ({r.oneway_edges} one-way edges)")
        out.append(f"  read in {self.seconds:.2f} s")
        return out


@dataclass
class OsmCity:
    """An imported OSM city: the environment, its georeference, the summary, and the OSM object
    of each building (``osm_ids[i]``: ``w<id>`` or ``r<id>`` of ``environment.building_ids[i]``)."""

    environment: Environment
    georeference: Georeference
    summary: OsmSummary
    osm_ids: list[str]


def _origin(bbox: Optional[list[float]], origin: Any, where: str) -> Georeference:
    if origin is not None:
        return Georeference.from_value(origin)
    if bbox is None:
        raise VistrackError(f"{where}: no buildings or drivable roads in the file")
    lon, lat = 0.5 * (bbox[0] + bbox[2]), 0.5 * (bbox[1] + bbox[3])  # rounded like the GeoJSON loader's
    return Georeference(round(lat * 1e7) / 1e7, round(lon * 1e7) / 1e7)


def _environment(prints: list[Footprint], skipped: list[tuple[str, str]]) -> tuple[Environment, list[Footprint]]:
    """``Environment.from_buildings`` over the footprints; one it still refuses (its tolerances
    differ from shapely's) is left out as ``rejected`` and the rest built again."""
    prints = list(prints)
    for _ in range(1000):
        items = [(Polygon(np.asarray(f.polygon.exterior.coords), [np.asarray(r.coords) for r in f.polygon.interiors]),
                  f.top, i, f.base) for i, f in enumerate(prints)]
        try:
            return Environment.from_buildings(items), prints
        except VistrackError as error:
            found = _BUILDING.findall(str(error))
            if not found:
                raise
            bad = max(int(i) for i in found)
            skipped.append((prints[bad].osm_id, "rejected"))
            del prints[bad]
    raise VistrackError("osm: more than 1000 footprints refused by Environment.from_buildings")


def read_osm(path: str | Path, *, level_height: float = LEVEL_HEIGHT, roof_height: float = ROOF_HEIGHT,
             default_height: float = DEFAULT_HEIGHT, origin: Georeference | Sequence[float] | None = None,
             key: str = "osm") -> OsmCity:
    """An OSM file's buildings and drivable roads as an :class:`OsmCity`, projected about
    ``origin`` (a Georeference or (lat, lon[, alt]); by default the centre of the data's
    bounding box, rounded to 1e-7 degree). Errors name ``key`` and the file."""
    from .osm_handler import OsmHandler

    file = input_file(path, key)
    level_height = number("level_height", level_height, low=1e-3, high=1e3)
    roof_height = number("roof_height", roof_height, low=0.0, high=1e3)
    default_height = number("default_height", default_height, low=1e-3, high=1e4)
    if not file.name.lower().endswith(OSM_SUFFIXES):
        raise fail(key, str(path), "must end in " + ", ".join(OSM_SUFFIXES))
    start = time.perf_counter()
    handler = OsmHandler(level_height, roof_height, default_height)
    try:
        handler.apply_file(str(file), locations=True)
    except RuntimeError as error:  # pyosmium's parse errors
        raise VistrackError(f"{key} = {path}: not a readable OSM file ({' '.join(str(error).split())})") from None
    handler.finish()
    bbox = _bbox(handler)
    georeference = _origin(bbox, origin, f"{key} = {path}")
    prints, skipped, clipped = footprints(handler.candidates, georeference.to_local)
    env, prints = _environment(prints, skipped)
    env.origin = georeference
    objects = object_outcomes(prints, skipped)
    objects.update(handler.counts.skipped)
    roads = add_roads(env, handler.roads, handler.counts.roads_skipped, handler.counts.roads_truncated,
                      georeference.to_local)
    summary = OsmSummary(
        file=str(path), origin=(georeference.lat, georeference.lon, georeference.alt), level_height=level_height,
        roof_height=roof_height, default_height=default_height, objects=dict(sorted(objects.items())),
        footprints=env.num_buildings, height_sources=dict(Counter(f.source for f in prints)),
        bad_tags=dict(handler.counts.bad_tags), raised_base=sum(f.base > 0 for f in prints), clipped=clipped,
        bbox_lon_lat=bbox, tallest=_tallest(prints), roads=roads)
    summary.seconds = time.perf_counter() - start
    return OsmCity(env, georeference, summary, [f.osm_id for f in prints])


def _bbox(handler: Any) -> Optional[list[float]]:
    """[lon_min, lat_min, lon_max, lat_max] of every building ring and road, or None."""
    rings = [outer for c in handler.candidates for outer, _ in c.polygons] + [w.lon_lat for w in handler.roads]
    if not rings:
        return None
    points = np.concatenate(rings)
    return [float(v) for v in (*points.min(axis=0), *points.max(axis=0))]


def _tallest(prints: list[Footprint]) -> Optional[dict[str, Any]]:
    if not prints:
        return None
    best = max(prints, key=lambda f: f.top)
    return {"height": best.top, "osm_id": best.osm_id}


def from_osm(path: Any, *, level_height: float = LEVEL_HEIGHT, roof_height: float = ROOF_HEIGHT,
             default_height: float = DEFAULT_HEIGHT, origin: Any = None) -> Environment:
    """``Environment.from_osm``: the environment of :func:`read_osm` (its summary dropped). ``path``
    an OSM file (str or Path); ``origin`` a Georeference or (lat, lon[, alt]), by default the
    centre of the data's bounding box. (Annotated ``Any``: the compiled module's stubs list it.)"""
    return read_osm(path, level_height=level_height, roof_height=roof_height, default_height=default_height,
                    origin=origin).environment


Environment.from_osm = staticmethod(from_osm)  # type: ignore[method-assign]
