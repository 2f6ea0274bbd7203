"""OpenStreetMap import speed (issue 30): vistrack.io.read_osm against plain pyosmium passes, side
by side, on the three extracts in ../shared/data/osm and on a synthetic extract of N buildings
(a grid of tagged boxes with streets between them, written as .osm.pbf by pyosmium).

The peers do less than the import (no projection, checks, parts, overlaps or environment): a
pyosmium pass counting building ways and relations with node locations, and the same pass with
pyosmium's area assembly (what read_osm's reading costs at least). The ratio says how much the
import adds on top of reading the file.

    VISTRACK_BUILD_DIR=build/dev python3 bench/osm_import.py [--synthetic 50000] [--repeat 3]

OSM data © OpenStreetMap contributors (ODbL 1.0).
"""

from __future__ import annotations

import argparse
import os
import resource
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import osmium

import vistrack as vt
from timing import timed

DATA = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data")) / "osm"
FILES = ("Helsinki.osm.pbf", "West-Oakland.osm.bz2", "planet_10.068,48.135_10.071,48.137.osm")


class CountBuildings(osmium.SimpleHandler):
    """The peer: closed building ways and building multipolygon relations (and, with areas on,
    the building areas pyosmium assembles)."""

    def __init__(self) -> None:
        super().__init__()
        self.ways = self.relations = self.areas = 0

    def way(self, way: osmium.osm.Way) -> None:
        if ("building" in way.tags or "building:part" in way.tags) and way.is_closed():
            self.ways += 1

    def relation(self, relation: osmium.osm.Relation) -> None:
        tags = relation.tags
        if tags.get("type") == "multipolygon" and ("building" in tags or "building:part" in tags):
            self.relations += 1


class CountAreas(CountBuildings):
    def area(self, area: osmium.osm.Area) -> None:
        if "building" in area.tags or "building:part" in area.tags:
            self.areas += 1


def peer(path: Path, handler_class: type[CountBuildings]) -> CountBuildings:
    handler = handler_class()
    handler.apply_file(str(path), locations=True)
    return handler


def synthetic(path: Path, buildings: int) -> Path:
    """A square grid of 12 m x 12 m buildings 20 m apart (heights and levels alternating, every
    tenth untagged), with a residential street along each row."""
    side = int(buildings ** 0.5 + 0.999)
    step = 20.0 / 111_320.0  # degrees of latitude; longitudes scaled at 60 degrees north
    size = 12.0 / 111_320.0
    lat0, lon0 = 60.0, 24.0
    writer = osmium.SimpleWriter(str(path))
    node_id = way_id = 1
    ways = []
    try:
        for row in range(side):
            street = []
            for column in range(side + 1):
                lat, lon = lat0 + row * step - 4 / 111_320.0, lon0 + column * step * 2
                writer.add_node(osmium.osm.mutable.Node(id=node_id, location=(lon, lat)))
                street.append(node_id)
                node_id += 1
            ways.append(osmium.osm.mutable.Way(id=way_id, nodes=street, tags={"highway": "residential"}))
            way_id += 1
            for column in range(side):
                if row * side + column >= buildings:
                    break
                lat, lon = lat0 + row * step, lon0 + column * step * 2
                corners = [(lon, lat), (lon + 2 * size, lat), (lon + 2 * size, lat + size), (lon, lat + size)]
                ids = []
                for corner in corners:
                    writer.add_node(osmium.osm.mutable.Node(id=node_id, location=corner))
                    ids.append(node_id)
                    node_id += 1
                k = row * side + column
                tags = {"building": "yes"}
                if k % 10 == 1:
                    tags["height"] = f"{10 + k % 40} m"
                elif k % 10 != 0:
                    tags["building:levels"] = str(1 + k % 8)
                ways.append(osmium.osm.mutable.Way(id=way_id, nodes=[*ids, ids[0]], tags=tags))
                way_id += 1
        for way in ways:
            writer.add_way(way)
    finally:
        writer.close()
    return path


def row(name: str, path: Path, repeat: int) -> None:
    seconds, city = timed(lambda: vt.io.read_osm(path), repeat)
    count_seconds, counted = timed(lambda: peer(path, CountBuildings), repeat)
    area_seconds, _ = timed(lambda: peer(path, CountAreas), repeat)
    s = city.summary
    objects = s.imported + sum(s.skipped.values()) - s.skipped.get("unclosed", 0)
    print(f"| {name} | {counted.ways + counted.relations} | {objects} | {s.imported} | {s.footprints} | "
          f"{sum(s.skipped.values())} | {seconds:.3f} | {s.footprints / seconds:,.0f} | {count_seconds:.3f} | "
          f"{area_seconds:.3f} | {seconds / area_seconds:.1f} |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--synthetic", type=int, default=50_000, help="buildings in the synthetic extract (0: none)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per timing (the best is shown)")
    args = parser.parse_args()
    print("| file | pyosmium: closed building ways + relations | read_osm: objects seen | imported | footprints | "
          "skipped | read_osm s | footprints/s | pyosmium count s | pyosmium + areas s | read_osm / areas |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name in FILES:
        if (DATA / name).exists():
            row(name, DATA / name, args.repeat)
        else:
            print(f"| {name} | absent ({DATA}) |")
    if args.synthetic:
        with tempfile.TemporaryDirectory() as folder:
            path = synthetic(Path(folder) / "synthetic.osm.pbf", args.synthetic)
            row(f"synthetic {args.synthetic:,} buildings ({path.stat().st_size / 1e3:.0f} kB)", path, 1)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"\npeak resident memory of this process: {peak:.0f} MB")


if __name__ == "__main__":
    main()
