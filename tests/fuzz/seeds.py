"""Seed inputs of each fuzz target: small valid files of each format (made here, so the
fuzzer mutates short inputs), the real data in ../shared/data where it is small enough, the
examples, and every stored finding and reproducer (tests/fuzz/regressions/<target>/)."""

from __future__ import annotations

import hashlib
import os
from pathlib import Path

import numpy as np
import targets

import vistrack as vt

DATA = Path(os.environ.get("VISTRACK_DATA", targets.REPO.parent / "shared" / "data"))
REGRESSIONS = Path(__file__).resolve().parent / "regressions"

CUBE_OBJ = b"""v 0 0 0\nv 10 0 0\nv 10 10 0\nv 0 10 0\nv 0 0 10\nv 10 0 10\nv 10 10 10\nv 0 10 10
f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8
"""
CUBE_OFF = b"""OFF\n8 6 0\n0 0 0\n10 0 0\n10 10 0\n0 10 0\n0 0 10\n10 0 10\n10 10 10\n0 10 10
4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7
"""
CUBE_PLY = b"""ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z
element face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n10 0 0\n0 10 0\n0 0 10
3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3
"""
TRIANGLE_STL = b"""solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 10 0 0\nvertex 0 10 0\nendloop
endfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 5\nvertex 10 0 5\nvertex 0 10 5\nendloop\nendfacet\nendsolid t
"""
BUILDINGS = b"""{"type": "FeatureCollection", "features": [
 {"type": "Feature", "properties": {"height": 20, "id": 7},
  "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [30, 0], [30, 20], [0, 20], [0, 0]],
                                                  [[5, 5], [10, 5], [10, 10], [5, 10], [5, 5]]]}},
 {"type": "Feature", "properties": {"building:levels": "4"},
  "geometry": {"type": "MultiPolygon", "coordinates": [[[[40, 0], [60, 0], [60, 15], [40, 0]]]]}}]}
"""
LONLAT = b"""{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"height": "12.5 m"},
 "geometry": {"type": "Polygon", "coordinates": [[[-80.8403, 35.2249], [-80.8401, 35.2249], [-80.8401, 35.2251],
 [-80.8403, 35.2251]]]}}]}
"""
INTERCEPT = b"""pursuer: [0.0, 0.0, 0.0]\nrho: 1.0\npursuer_speed: 1.0\ncenter: [-4.0, 3.0]\nradius: 1.0
target_angle0: 3.14159\ntarget_speed: 1.2\ndirection: cw\n"""
SCENARIO = b"""name: fuzz\nenvironment: {demo: true}
poi: {speed: 5.0, waypoints: [[-290, -210], [-100, -210], [-100, 50]]}
uav: {speed: 20.0, min_turn_radius: 40.0, altitude: 200.0, start: null}\nsensor: {d_max: 300.0, altitude_band: null}
planning: {spacing: 20.0, cutoff: 2.0e7, resolution_deg: 2.0, min_spacing: 1.0, max_depth: 8, rate_margin: 0.0}
control: {beta: 0.025, k_psi: 20.0, direction: ccw}\nbaselines: [40.0, 120.0]
"""
SWEEP = b"""name: fuzz\nkind: loiter\nbase:\n  random: {count: 4, seed: 0}\nparameters:
  random.seed: {start: 0, stop: 3, step: 1}\n  method: [fly_through, ldlpp]\nmetrics: [method, flight_time_s]
"""


def _generated(target: str) -> list[bytes]:
    """Valid inputs made with vistrack itself (plans, VV files, missions)."""
    poi = vt.PoiPath(np.array([[0.0, 0.0], [120.0, 0.0], [120.0, 80.0]]), 5.0)
    constant = vt.constant_radius_plan(poi, 60.0, vt.Uav())
    if target == "plan":
        env = vt.Environment.demo()
        planned = vt.plan_orbits(env, vt.PoiPath(np.array([[-290.0, -210.0], [-230.0, -210.0]]), 5.0),
                                 vt.Uav(altitude=200.0), vt.Sensor(d_max=300.0),
                                 vt.Planning(spacing=30.0, resolution_deg=10.0))
        return [constant.to_json().encode(), planned.to_json().encode()]
    if target == "vv":
        out = []
        for resolution in (30.0, 15.0):
            volume = vt.visibility_volume(targets.demo(), (-290.0, -210.0, 0.5), 200.0, resolution_deg=resolution)
            volume.save_binary(targets.SCRATCH / "seed.bin")
            out.append(b"\x00" + (targets.SCRATCH / "seed.bin").read_bytes())
        return out
    if target == "mission":
        built = constant.to_mission(vt.Georeference(35.2249, -80.8403), altitude=60.0)
        out = []
        for flag, suffix in ((b"\x00", ".plan"), (b"\x01", ".waypoints")):
            built.save(targets.SCRATCH / f"seed{suffix}")
            out.append(flag + (targets.SCRATCH / f"seed{suffix}").read_bytes())
        return out
    return []


def seed_inputs(target: str) -> list[bytes]:
    """Every seed of one target, generated and stored."""
    inputs: list[bytes] = []
    if target == "documents":
        inputs += [b"\x00" + BUILDINGS, b"\x00" + b"[" * 100 + b"]" * 100, b"\x01" + SCENARIO, b"\x01" + SWEEP,
                   b"\x01" + b"a: &a [x, y]\nb: &b [*a, *a]\nc: {<<: {k: *b}, j: [*b, *b]}\n"]
    elif target == "geojson":
        inputs += [BUILDINGS, LONLAT]
        if (DATA / "charlotte" / "buildings.geojson").is_file():
            inputs.append((DATA / "charlotte" / "buildings.geojson").read_bytes())
    elif target == "mesh":
        inputs += [b"\x00" + CUBE_OBJ, b"\x04" + CUBE_OBJ, b"\x01" + CUBE_OFF, b"\x02" + CUBE_PLY,
                   b"\x03" + TRIANGLE_STL]
    elif target == "csv":
        inputs += [b"x,y,z\n0,0,0.5\n10,0,0.5\n10,10,0.5\n", b"# comment\n0 0\n\n5 5\n"]
        for path in sorted((DATA / "charlotte" / "paths").glob("*.csv")) + sorted((DATA / "campus").glob("*.csv")):
            inputs.append(path.read_bytes())
    elif target == "scenario":
        inputs.append(SCENARIO)
        inputs += [p.read_bytes() for p in sorted((targets.REPO / "examples").glob("*.yaml"))]
        inputs.append((targets.REPO / "python" / "vistrack" / "scenarios" / "demo.yaml").read_bytes())
    elif target == "intercept":
        inputs.append(INTERCEPT)
    elif target == "loiter":
        inputs += [p.read_bytes() for p in sorted((targets.REPO / "examples").glob("loiter_*aoi.yaml"))]
    elif target == "follow":
        inputs += [p.read_bytes() for p in sorted((targets.REPO / "examples").glob("follow_*.yaml"))]
    elif target == "sweep":
        inputs.append(SWEEP)
        inputs += [p.read_bytes() for p in sorted((targets.REPO / "examples").glob("sweep_*.yaml"))]
    elif target == "route":
        inputs += [b"\x00" + (targets.REPO / "examples" / "waypoints_paper.csv").read_bytes(),
                   b"\x00" + b"0,0\n100,0\n100,100\n",
                   b"\x01" + b"t,x,y\n0,0,0\n10,100,0\n20,100,50\n",
                   b"\x02" + (targets.REPO / "examples" / "charlotte_roads.geojson").read_bytes()]
    elif target == "arrays":
        inputs += [bytes(range(256)), bytes(64), hashlib.sha256(b"vistrack").digest() * 8]
    inputs += _generated(target)
    inputs += stored(target)
    return inputs


def stored(target: str) -> list[bytes]:
    """The stored findings and reproducers of one target (tests/fuzz/regressions/<target>/*)."""
    folder = REGRESSIONS / target
    return [p.read_bytes() for p in sorted(folder.iterdir())] if folder.is_dir() else []


def write_seeds(target: str, folder: Path) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    for old in folder.iterdir():
        old.unlink()
    for data in seed_inputs(target):
        (folder / hashlib.sha1(data).hexdigest()).write_bytes(data)
