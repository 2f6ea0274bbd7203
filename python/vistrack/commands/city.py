"""``vistrack city FILE --out DIR``: import an OpenStreetMap file (.osm, .osm.bz2, .osm.pbf), print
what was imported and skipped, and write the city as GeoJSON (lon/lat), an OBJ mesh and
summary.json."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from ..io.city_files import write_city_geojson, write_obj
from ..io.osm import DEFAULT_HEIGHT, LEVEL_HEIGHT, ROOF_HEIGHT, read_osm
from ..io.text import write_json
from .output import output_folder
from .types import length, number

DEFAULT_OUT = Path("vistrack-out") / "city"


def main(args: argparse.Namespace) -> int:
    folder = output_folder(args.out)  # checked before the import
    origin = None if args.origin is None else tuple(args.origin)
    city = read_osm(args.file, level_height=args.level_height, roof_height=args.roof_height,
                    default_height=args.default_height, origin=origin, key="FILE")
    print("\n".join(city.summary.lines()))
    folder.mkdir(parents=True, exist_ok=True)
    write_city_geojson(city.environment, city.georeference, folder / "city.geojson", city.osm_ids)
    write_obj(city.environment, folder / "city.obj")
    write_json(city.summary.to_dict(), folder / "summary.json")
    print(f"wrote {folder}/city.geojson, city.obj, summary.json")
    return 0


def register(subparsers: Any) -> None:
    parser = subparsers.add_parser(
        "city", help="import an OpenStreetMap file: buildings and roads, with a summary",
        description="Buildings (ways, multipolygons, building:part) and drivable roads from .osm, .osm.bz2 "
                    "or .osm.pbf, projected to local metres; prints the summary (imported, skipped by "
                    "reason, height sources, bounding box, tallest, roads) and writes city.geojson "
                    "(lon/lat, RFC 7946), city.obj (east-north-up metres) and summary.json.")
    parser.add_argument("file", metavar="FILE", help="OpenStreetMap file")
    parser.add_argument("--out", default=str(DEFAULT_OUT), help=f"output folder (default: ./{DEFAULT_OUT})")
    parser.add_argument("--level-height", type=length("--level-height"), default=LEVEL_HEIGHT,
                        help=f"metres per building:levels (default {LEVEL_HEIGHT:g})")
    parser.add_argument("--roof-height", type=number("--roof-height", 0.0, 1e3), default=ROOF_HEIGHT,
                        help=f"metres added to a levels height without roof tags (default {ROOF_HEIGHT:g})")
    parser.add_argument("--default-height", type=length("--default-height"), default=DEFAULT_HEIGHT,
                        help=f"metres for a building without height or levels "
                             f"(default {DEFAULT_HEIGHT:g})")
    parser.add_argument("--origin", nargs=2, type=number("--origin", -180.0, 180.0), metavar=("LAT", "LON"),
                        default=None,
                        help="local origin (default: the centre of the data's bounding box)")
    parser.set_defaults(func=main)
