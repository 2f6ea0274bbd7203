"""The accuracy numbers the README quotes, reproduced on Charlotte (and the campus):

1. XOR paths: the grid path (the grid corners' intervals, trapezoid rule) against the radial path
   (the exact XOR of the two meshes, equal to CGAL on them: tests/python/test_xor.py) on every
   pair of VVs 20, 10 and 5 m apart along paper_slow and paper_small, 1-degree grids.
2. VVs: the 1-degree mesh volume against the per-direction volume of a 0.2-degree grid (issue 19's
   reference, by brute force: vistrack.visibility.reference_volume;
   bench/visibility_accuracy_bench.py has the accuracy per cost against trimesh + embreex) at 10
   POIs along paper_slow (d_max 400 m) with the time that accuracy costs, and VPs at 20 and 50 m
   (paper_small, d_max 100 m) against line-of-sight queries on a 1 m lattice.
3. Example 1's tracking against Algorithm 1's rate margin (planning.rate_margin, the paper's
   locus), and with the smooth locus.
4. The locus check's probe (MaxRadius by line of sight, vt.visible_disk_radius) against MaxRadius
   of the 1-degree VV's polygon, at 60 times along paper_slow, paper_small and the campus path.

    VISTRACK_BUILD_DIR=build/dev python3 bench/accuracy.py [--skip-tracking]

Charlotte geometry © OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import numpy as np

import vistrack as vt
from vistrack.visibility import polygon_agreement, reference_volume

DATA = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data"))
PATHS = (("paper_slow", 400.0), ("paper_small", 100.0))


def path_pois(scene, name: str, step: float) -> np.ndarray:
    path = vt.PoiPath.from_csv(str(DATA / "charlotte" / "paths" / f"{name}.csv"), 5.0)
    arc = np.arange(0.0, path.length + 1e-9, step)
    return np.array([np.ravel(scene.poi_on_surface(np.ravel(path.position(s / 5.0)))) for s in arc])


def xor_paths(scene) -> None:
    print("1. grid XOR path against the radial (exact mesh) path, 1-degree VVs, POI frame")
    for step in (20.0, 10.0, 5.0):
        for name, d_max in PATHS:
            volumes = vt.visibility_volumes(scene, path_pois(scene, name, step), d_max, None, 1.0)
            errors = np.abs([vt.xor_volume(a, b, method="grid") / vt.xor_volume(a, b, method="radial") - 1
                             for a, b in zip(volumes[:-1], volumes[1:])])
            print(f"   {name:11s} pairs {step:4.0f} m apart: {len(errors):3d} pairs, "
                  f"|grid / radial - 1| median {100 * np.median(errors):.2f} %, max {100 * errors.max():.2f} %")


def volumes_and_polygons(scene) -> None:
    print("2. 1-degree VV mesh volume against the per-direction volume of a 0.2-degree grid, 10 POIs per path")
    for name, d_max in PATHS:
        path = vt.PoiPath.from_csv(str(DATA / "charlotte" / "paths" / f"{name}.csv"), 5.0)
        pois = [np.ravel(scene.poi_on_surface(np.ravel(path.position(t)))) for t in np.linspace(0.0, path.duration, 10)]
        mesh_errors, grid_errors = [], []
        for g in pois:
            reference = reference_volume(scene, g, d_max)
            vv = vt.visibility_volume(scene, g, d_max, None, 1.0)
            mesh_errors.append(abs(vv.volume / reference - 1))
            grid_errors.append(abs(vv.grid_volume() / reference - 1))
        times = []
        for _ in range(3):
            start = time.perf_counter()
            for g in pois:
                vt.visibility_volume(scene, g, d_max, None, 1.0)
            times.append((time.perf_counter() - start) / len(pois))
        print(f"   {name:11s} d_max {d_max:3.0f} m: |mesh / reference - 1| max {100 * max(mesh_errors):.3f} %, "
              f"median {100 * np.median(mesh_errors):.3f} % (grid intervals alone max {100 * max(grid_errors):.3f} %) "
              f"at {1e3 * min(times):.2f} ms per VV (best of 3, one at a time, load {os.getloadavg()[0]:.1f})")
    path = vt.PoiPath.from_csv(str(DATA / "charlotte" / "paths" / "paper_small.csv"), 5.0)
    ious = []
    for t in np.linspace(0.0, path.duration, 8):
        vv = vt.visibility_volume(scene, np.ravel(scene.poi_on_surface(np.ravel(path.position(t)))), 100.0, None, 1.0)
        ious += [polygon_agreement(scene, vv, h) for h in (20.0, 50.0)]
    print(f"   VPs at 20/50 m of 8 paper_small VVs against line of sight: IoU {min(ious):.4f}-{max(ious):.4f}")


def tracking() -> None:
    print("3. Example 1 (examples/charlotte_paper_slow.yaml) against planning.rate_margin (paper's locus), "
          "and the smooth locus")
    for locus, margin in (("paper", 0.0), ("paper", 0.05), ("paper", 0.1), ("paper", 0.2), ("smooth", 0.0)):
        scenario = vt.Scenario.load(REPO / "examples" / "charlotte_paper_slow.yaml")
        scenario.planning.rate_margin = margin
        scenario.planning.locus = locus
        result = vt.run(scenario)
        simulation = result.metrics["simulation"]
        t, error = np.asarray(result.simulation.t), np.abs(np.asarray(result.simulation.radial_error))
        print(f"   {locus:6s} margin {margin:4.2f}: R {result.plan.radii[0]:.1f} -> {result.plan.radii[-1]:.1f} m, "
              f"radial error after 15 s <= {error[t > 15].max():.1f} m (after 20 s {error[t > 20].max():.1f} m), "
              f"POI visible {100 * simulation['visibility_fraction']:.1f} %")


def probe_against_polygons() -> None:
    print("4. MaxRadius by line of sight (the locus check's probe) against MaxRadius of the 1-degree VV's polygon")
    runs = [("paper_slow", "charlotte/uptown_charlotte.obj", "charlotte/paths/paper_slow.csv", 5.0, 300.0, 400.0),
            ("paper_small", "charlotte/uptown_charlotte.obj", "charlotte/paths/paper_small.csv", 5.0, 50.0, 100.0),
            ("campus", "campus/campus.obj", "campus/flight_test_path.csv", 0.35, 35.0, 50.0)]
    scenes: dict[str, vt.VisibilityScene] = {}
    for name, mesh, csv, speed, altitude, d_max in runs:
        scene = scenes.setdefault(mesh, vt.VisibilityScene(vt.Environment.from_mesh(str(DATA / mesh), up="y")))
        poi = vt.PoiPath.from_csv(str(DATA / csv), speed)
        sensor = vt.Sensor(d_max=d_max)
        differences = []
        for t in np.linspace(0.0, poi.duration, 60):
            g = np.ravel(poi.position(t))
            vv = vt.visibility_volume(scene, np.ravel(scene.poi_on_surface(g)), d_max, None, 1.0)
            polygon = vt.max_inscribed_radius(vt.plane_visibility_polygon(vv, altitude), g[:2])
            differences.append(vt.visible_disk_radius(scene, g, altitude, sensor) - polygon)
        d = np.asarray(differences)
        print(f"   {name:11s}: probe - polygon median {np.median(d):+.2f} m, range {d.min():+.2f} .. {d.max():+.2f} m")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--skip-tracking", action="store_true", help="leave out section 3 (four closed-loop runs)")
    args = parser.parse_args()
    mesh = DATA / "charlotte" / "uptown_charlotte.obj"
    if not mesh.exists():
        print(f"real data not found under {DATA}: skipping")
        return 0
    scene = vt.VisibilityScene(vt.Environment.from_mesh(str(mesh), up="y"))
    xor_paths(scene)
    volumes_and_polygons(scene)
    probe_against_polygons()
    if not args.skip_tracking:
        tracking()
    return 0


if __name__ == "__main__":
    sys.exit(main())
