"""From collected OSM buildings (longitude/latitude) to the 2.5D footprints vistrack's
``Environment.from_buildings`` accepts, in local metres: projection, geometry checks, building
parts over their outlines, and overlaps resolved into the 2.5D height field.

Every footprint that is left out is counted by reason, on its OSM object (a way or a relation
counts once, under the first reason that removed all of it):

- ``crosses_antimeridian`` (a longitude span over 180 degrees), ``touches_pole`` (latitude
  +-90), ``outside_local_frame`` (more than 1e7 m from the origin);
- ``zero_area`` (under :data:`MIN_AREA`), ``self_intersecting``, ``invalid_rings`` (shapely's
  validity: a hole outside its ring, rings crossing each other);
- ``top_not_above_base`` (a height at or below ``min_height``);
- ``replaced_by_parts`` (an outline with ``building:part`` footprints inside it: the parts stand
  for it, the OSM wiki's Simple 3D Buildings rule);
- ``covered`` (lying under overlapping buildings at least as tall: it adds nothing to the 2.5D
  city). Where a footprint only partly overlaps a taller one, it keeps the part outside (the
  2.5D height field: the taller wins), counted in ``clipped``.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import shapely

if TYPE_CHECKING:
    from .osm_handler import Candidate

__all__ = ["OVERLAP_TOLERANCE", "Footprint", "footprints", "object_outcomes"]

OVERLAP_TOLERANCE = 1.0  # m^2: the overlap Environment.from_buildings takes as touching walls
POLE_MARGIN = 1e-7  # degrees: a latitude this close to +-90 touches the pole
MAX_COORDINATE = 1e7  # m: vistrack's coordinate limit (vt.limits.MAX_COORDINATE)
MIN_AREA = 0.01  # m^2: below it a footprint has zero area (points on one line: a parallel of latitude
# projects to a slight curve, so exact zero is never seen)


@dataclass
class Footprint:
    """One footprint in local metres (a shapely Polygon), its top and base, and its OSM object."""

    polygon: shapely.Polygon
    top: float
    base: float
    source: str
    osm_id: str
    is_part: bool


def _geographic_reason(outer: np.ndarray) -> str | None:
    if np.ptp(outer[:, 0]) > 180.0:
        return "crosses_antimeridian"
    if np.any(np.abs(outer[:, 1]) >= 90.0 - POLE_MARGIN):
        return "touches_pole"
    return None


def _shape_reason(polygon: shapely.Polygon) -> str | None:
    coordinates = shapely.get_coordinates(polygon)
    if np.abs(coordinates).max() > MAX_COORDINATE:
        return "outside_local_frame"
    if not shapely.is_valid(polygon):
        if shapely.make_valid(polygon).area < MIN_AREA:  # points on one line (a spike at most)
            return "zero_area"
        return "self_intersecting" if "Self-intersection" in shapely.is_valid_reason(polygon) else "invalid_rings"
    if polygon.area < MIN_AREA:
        return "zero_area"
    return None


def _project(candidates: Sequence[Candidate], to_local: object) -> list[list[shapely.Polygon | str]]:
    """Each candidate's polygons in local metres (a reason string in place of a polygon that
    cannot be projected); ``to_local`` maps (lat, lon) arrays to (east, north) arrays."""
    rings: list[np.ndarray] = []
    for candidate in candidates:
        for outer, holes in candidate.polygons:
            if _geographic_reason(outer) is None:
                rings.append(outer)
                rings.extend(holes)
    if rings:
        points = np.concatenate(rings)
        east, north = to_local(points[:, 1], points[:, 0])  # type: ignore[operator]
        local = np.column_stack([np.atleast_1d(east), np.atleast_1d(north)])
    offset = 0
    result: list[list[shapely.Polygon | str]] = []

    def take(ring: np.ndarray) -> np.ndarray:
        nonlocal offset
        piece = local[offset:offset + len(ring)]
        offset += len(ring)
        return piece

    for candidate in candidates:
        items: list[shapely.Polygon | str] = []
        for outer, holes in candidate.polygons:
            reason = _geographic_reason(outer)
            if reason is not None:
                items.append(reason)
                continue
            shell, inner = take(outer), [take(hole) for hole in holes]
            if min(len(ring) for ring in [shell, *inner]) < 4:  # a closed ring of at most 2 points
                items.append("zero_area")
                continue
            items.append(shapely.Polygon(shell, inner))
        result.append(items)
    return result


def _replace_outlines(prints: list[Footprint], skipped: list[tuple[str, str]]) -> list[Footprint]:
    """Outlines with a building part inside them (over half the part's area) give way to the parts."""
    parts = [p.polygon for p in prints if p.is_part]
    if not parts:
        return prints
    tree = shapely.STRtree(parts)
    kept = []
    for footprint in prints:
        if not footprint.is_part:
            near = tree.query(footprint.polygon, predicate="intersects")
            if any(shapely.intersection(footprint.polygon, parts[j]).area >= 0.5 * parts[j].area for j in near):
                skipped.append((footprint.osm_id, "replaced_by_parts"))
                continue
        kept.append(footprint)
    return kept


def _polygons(geometry: shapely.Geometry) -> list[shapely.Polygon]:
    if isinstance(geometry, shapely.Polygon):
        return [geometry]
    return [g for g in getattr(geometry, "geoms", []) if isinstance(g, shapely.Polygon)]


def _resolve_overlaps(prints: list[Footprint], skipped: list[tuple[str, str]]) -> tuple[list[Footprint], int]:
    """Interiors made disjoint: tallest first, each footprint loses what taller (or equally tall,
    earlier) footprints cover when that is more than :data:`OVERLAP_TOLERANCE`. Returns the
    footprints and how many were clipped."""
    order = sorted(range(len(prints)), key=lambda i: -prints[i].top)
    rank = np.empty(len(prints), dtype=int)
    rank[order] = np.arange(len(prints))
    polygons = [p.polygon for p in prints]
    tree = shapely.STRtree(polygons)
    result: list[Footprint] = []
    clipped = 0
    for i in order:
        footprint = prints[i]
        above = [j for j in tree.query(footprint.polygon, predicate="intersects") if rank[j] < rank[i]]
        if above:
            cover = shapely.union_all([polygons[j] for j in above])
            if shapely.intersection(footprint.polygon, cover).area > OVERLAP_TOLERANCE:
                pieces = [p for p in _polygons(shapely.difference(footprint.polygon, cover))
                          if p.area > OVERLAP_TOLERANCE and shapely.is_valid(p)]
                if not pieces:
                    skipped.append((footprint.osm_id, "covered"))
                    continue
                clipped += 1
                result.extend(Footprint(shapely.normalize(p), footprint.top, footprint.base, footprint.source,
                                        footprint.osm_id, footprint.is_part) for p in pieces)
                continue
        result.append(footprint)
    return result, clipped


def footprints(candidates: Sequence[Candidate], to_local: object) -> tuple[list[Footprint], list[tuple[str, str]], int]:
    """The footprints to build, the (osm_id, reason) of every footprint left out, and how many
    footprints were clipped by taller overlapping ones."""
    skipped: list[tuple[str, str]] = []
    prints: list[Footprint] = []
    for candidate, items in zip(candidates, _project(candidates, to_local)):
        height = candidate.height
        for item in items:
            reason = item if isinstance(item, str) else _shape_reason(item)
            if reason is None and height.top <= height.base:
                reason = "top_not_above_base"
            if reason is not None:
                skipped.append((candidate.osm_id, reason))
                continue
            assert isinstance(item, shapely.Polygon)
            prints.append(Footprint(item, height.top, height.base, height.source, candidate.osm_id, candidate.is_part))
    prints = _replace_outlines(prints, skipped)
    prints, clipped = _resolve_overlaps(prints, skipped)
    return prints, skipped, clipped


def object_outcomes(kept: Sequence[Footprint], skipped: Sequence[tuple[str, str]]) -> Counter[str]:
    """Per OSM object: "imported" when any footprint of it was kept, else its first reason."""
    imported = {f.osm_id for f in kept}
    outcome: dict[str, str] = dict.fromkeys(imported, "imported")
    for osm_id, reason in skipped:
        outcome.setdefault(osm_id, reason)
    return Counter(outcome.values())
