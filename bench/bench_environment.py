"""Environment loading: vistrack against trimesh (+ shapely) side by side, as a ratio.

    VISTRACK_BUILD_DIR=build/dev python3 bench/bench_environment.py [--repeat 5]

Peers (pyproject [bench] extra): trimesh.load for the Charlotte OBJ (merging vertices, as
vistrack does), and shapely + trimesh.creation.extrude_polygon for the GeoJSON buildings
(extrusion only: the peer does no overlap or simplicity validation, vistrack does).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "tests" / "python"))
import conftest  # imports vistrack from the build tree when VISTRACK_BUILD_DIR is set
import vistrack as vt
from timing import best_of

DATA = conftest.SHARED_DATA / "charlotte"


def peer_geojson(path: Path):
    import shapely.geometry
    import trimesh

    features = json.loads(path.read_text())["features"]
    meshes = [trimesh.creation.extrude_polygon(shapely.geometry.shape(f["geometry"]), f["properties"]["height"])
              for f in features]
    return trimesh.util.concatenate(meshes)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    import trimesh

    obj, geojson = DATA / "uptown_charlotte.obj", DATA / "buildings.geojson"
    if not obj.exists():
        print(f"real data not found under {DATA}")
        return 1
    rows = [
        ("Charlotte OBJ (from_mesh vs trimesh.load)",
         best_of(args.repeat, lambda: vt.Environment.from_mesh(str(obj), up="y")),
         best_of(args.repeat, lambda: trimesh.load(obj, force="mesh", process=True))),
        ("Charlotte GeoJSON (from_geojson vs shapely+extrude_polygon)",
         best_of(args.repeat, lambda: vt.Environment.from_geojson(str(geojson))),
         best_of(args.repeat, lambda: peer_geojson(geojson))),
        ("demo city (Environment.demo, no peer)", best_of(args.repeat, vt.Environment.demo), float("nan")),
    ]
    print(f"{'case':62s} {'vistrack ms':>12s} {'peer ms':>10s} {'peer/vistrack':>14s}")
    for name, ours, peer in rows:
        print(f"{name:62s} {1e3 * ours:12.1f} {1e3 * peer:10.1f} {peer / ours:14.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
