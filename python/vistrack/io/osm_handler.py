"""One streamed pass of pyosmium over an OSM file: building footprints in longitude/latitude with
their heights, drivable roads as node chains, and every way or relation left out, by reason.

pyosmium reads ``.osm``, ``.osm.bz2``, ``.osm.gz`` and ``.osm.pbf``; ``apply_file(locations=True)``
keeps node locations in an index (not the objects), so memory grows with the nodes and the
buildings and roads kept, not with the rest of the file. Multipolygon relations are assembled by
pyosmium's area assembler (outer and inner rings); building ways are read directly so that an
unclosed way or a missing node is counted by reason (the assembler drops them silently).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import osmium

from .osm_tags import DRIVABLE, Height, building_height, oneway, road_skip_reason

__all__ = ["Candidate", "OsmHandler", "RoadWay"]


@dataclass
class Candidate:
    """One building object (way ``w<id>`` or multipolygon relation ``r<id>``): its height and its
    polygons, each an outer ring and holes as (n, 2) arrays of (lon, lat)."""

    osm_id: str
    is_part: bool
    height: Height
    polygons: list[tuple[np.ndarray, list[np.ndarray]]]


@dataclass
class RoadWay:
    """One drivable way: its node ids, (lon, lat) rows, and its direction (:func:`oneway`: 1
    driven in the order of its nodes only, -1 against it only, 0 both ways)."""

    osm_id: int
    nodes: list[int]
    lon_lat: np.ndarray
    oneway: int
    maxspeed: str | None


def _is_tagged(tags: Any, key: str) -> bool:
    value = tags.get(key)
    return value is not None and value != "no"


def _ring(nodes: Any) -> np.ndarray:
    return np.array([(node.lon, node.lat) for node in nodes], dtype=float)


@dataclass
class _Counts:
    skipped: Counter[str] = field(default_factory=Counter)
    bad_tags: Counter[str] = field(default_factory=Counter)
    roads_skipped: Counter[str] = field(default_factory=Counter)
    roads_truncated: int = 0


class OsmHandler(osmium.SimpleHandler):
    """Collects :class:`Candidate` buildings and :class:`RoadWay` roads; counts what it leaves out
    (``skipped``: building objects by reason; ``roads_skipped``; ``bad_tags`` by key)."""

    def __init__(self, level_height: float, roof_height: float, default_height: float) -> None:
        super().__init__()
        self._heights = (level_height, roof_height, default_height)
        self.candidates: list[Candidate] = []
        self.roads: list[RoadWay] = []
        self.counts = _Counts()
        self.building_relations: set[int] = set()
        self.assembled_relations: set[int] = set()
        self.building_ways = 0

    def _height(self, tags: Any) -> Height:
        height = building_height({tag.k: tag.v for tag in tags}, *self._heights)
        self.counts.bad_tags.update(height.bad)
        return height

    def way(self, way: Any) -> None:
        tags = way.tags
        if _is_tagged(tags, "building") or _is_tagged(tags, "building:part"):
            self.building_ways += 1
            self._building_way(way)
        elif tags.get("highway") in DRIVABLE and tags.get("area") != "yes":
            self._road(way)

    def _building_way(self, way: Any) -> None:
        if not way.is_closed():
            self.counts.skipped["unclosed"] += 1
            return
        if not all(node.location.valid() for node in way.nodes):
            self.counts.skipped["missing_node"] += 1
            return
        is_part = _is_tagged(way.tags, "building:part")
        self.candidates.append(Candidate(f"w{way.id}", is_part, self._height(way.tags), [(_ring(way.nodes), [])]))

    def _road(self, way: Any) -> None:
        """A drivable way on the ground; one whose nodes are partly missing from the extract (a
        way cut at its edge) keeps its runs of present nodes (counted in ``roads_truncated``)."""
        reason = road_skip_reason({tag.k: tag.v for tag in way.tags})
        runs: list[list[Any]] = [[]]
        for node in way.nodes:
            if node.location.valid():
                runs[-1].append(node)
            elif runs[-1]:
                runs.append([])
        runs = [run for run in runs if len(run) >= 2]
        if reason is None and not runs:
            reason = "fewer_than_two_nodes"
        if reason is not None:
            self.counts.roads_skipped[reason] += 1
            return
        if sum(len(run) for run in runs) < len(way.nodes):
            self.counts.roads_truncated += 1
        tags = way.tags
        direction = oneway({tag.k: tag.v for tag in tags})
        for run in runs:
            self.roads.append(RoadWay(way.id, [node.ref for node in run], _ring(run), direction, tags.get("maxspeed")))

    def relation(self, relation: Any) -> None:
        tags = relation.tags
        if tags.get("type") == "multipolygon" and (_is_tagged(tags, "building") or _is_tagged(tags, "building:part")):
            self.building_relations.add(relation.id)

    def area(self, area: Any) -> None:
        if area.from_way():
            return  # building ways are read in way(), with their reasons
        tags = area.tags
        if not (_is_tagged(tags, "building") or _is_tagged(tags, "building:part")):
            return
        self.assembled_relations.add(area.orig_id())
        polygons = [(_ring(outer), [_ring(inner) for inner in area.inner_rings(outer)])
                    for outer in area.outer_rings()]
        self.candidates.append(Candidate(f"r{area.orig_id()}", _is_tagged(tags, "building:part"),
                                         self._height(tags), polygons))

    def finish(self) -> None:
        """Counts the building relations pyosmium could not assemble (broken rings, members
        missing from the extract)."""
        failed = self.building_relations - self.assembled_relations
        if failed:
            self.counts.skipped["multipolygon_not_assembled"] += len(failed)
