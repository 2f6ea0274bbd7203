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
- ``covered`` (lying under overlapping buildings at least as tall and not raised above its base:
  it adds nothing to the city). Where a footprint only partly overlaps a taller one, it keeps the
  part outside, counted in ``clipped``; under a taller footprint with a raised base it keeps the
  piece between its own base and that base (the volumes' union is unchanged).
"""

from __future__ import annotations

import heapq
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import shapely

from .._core import limits as _limits

if TYPE_CHECKING:
    from .osm_handler import Candidate

__all__ = ["OVERLAP_TOLERANCE", "Footprint", "footprints", "object_outcomes"]

OVERLAP_TOLERANCE = 1.0  # m^2: the overlap Environment.from_buildings takes as touching walls
POLE_MARGIN = 1e-7  # degrees: a latitude this close to +-90 touches the pole
MAX_COORDINATE = _limits.MAX_COORDINATE  # m: vistrack's coordinate limit
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
    """Volumes made disjoint, each footprint a solid from its base to its top. Tallest first, a
    footprint loses what the footprints already placed (taller, or equally tall and earlier) cover
    when that is more than :data:`OVERLAP_TOLERANCE`, except those standing wholly above it (base
    at or above its top: stacked parts, which may share a footprint). Under a placed footprint
    whose base is above its own, it keeps a piece from its base up to that base (the open space
    under a raised part that it fills), placed in turn like any footprint. The union of the
    solids is unchanged. Returns the footprints and how many were clipped."""
    tree = shapely.STRtree([p.polygon for p in prints]) if prints else None
    queue = [(-p.top, i, i, p) for i, p in enumerate(prints)]  # originals first on equal tops
    heapq.heapify(queue)
    placed: list[list[Footprint]] = [[] for _ in prints]  # what each original put in the city so far
    result: list[Footprint] = []
    clipped = 0
    counter = len(prints)

    def place(origin: int, footprints: list[Footprint]) -> None:
        placed[origin].extend(footprints)
        result.extend(footprints)

    while queue:
        _, order, origin, footprint = heapq.heappop(queue)
        near = [q for j in (tree.query(footprint.polygon, predicate="intersects") if tree else [])
                for q in placed[j] if shapely.intersects(q.polygon, footprint.polygon)]
        above = [p for p in near if p.base < footprint.top]  # the others stand wholly above it
        cover = shapely.union_all([p.polygon for p in above]) if above else None
        if cover is None or shapely.intersection(footprint.polygon, cover).area <= OVERLAP_TOLERANCE:
            place(origin, [footprint])
            continue
        for raised in (p for p in above if p.base > footprint.base):
            for piece in _polygons(shapely.intersection(footprint.polygon, raised.polygon)):
                if piece.area > OVERLAP_TOLERANCE and shapely.is_valid(piece):
                    heapq.heappush(queue, (-raised.base, counter, origin, Footprint(
                        shapely.normalize(piece), raised.base, footprint.base, footprint.source,
                        footprint.osm_id, footprint.is_part)))
                    counter += 1
        rest = [p for p in _polygons(shapely.difference(footprint.polygon, cover))
                if p.area > OVERLAP_TOLERANCE and shapely.is_valid(p)]
        if not rest:
            if order < len(prints):  # a piece under a raised part counts with its object
                skipped.append((footprint.osm_id, "covered"))
            continue
        clipped += order < len(prints)
        place(origin, [Footprint(shapely.normalize(p), footprint.top, footprint.base, footprint.source,
                                 footprint.osm_id, footprint.is_part) for p in rest])
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
