"""Benchmark: the whole paper_slow plan (adaptive VVs + Algorithm 1), the smooth locus against the
paper's on the three paths with real data (the locus check and the smooth R(t) on top of the same
VVs), and the XOR metric (56) per pair of neighbouring 1-degree VVs: our fast paths (radial: exact
per direction on the meshes; grid: the cell intervals) vs our CGAL corefinement path vs the same
Boolean volume through manifold3d (PyPI), side by side in one run.

    VISTRACK_BUILD_DIR=build/dev python3 bench/orbit_bench.py [--pairs 6] [--repeat 3] [--skip-xor]

Goals (issue 5): <= 50 ms per pair on the fast path (radial, the planner's metric); the whole paper_slow plan
<= 3 s on 2 cores.
Goal (issue 12): the smooth locus within 2x of the paper's planning time.
Charlotte geometry © OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import numpy as np

import vistrack as vt
from timing import timed
from vistrack.io import load_environment

DATA = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data"))


def manifold_xor(a, b):
    """vol(A) + vol(B) - 2 vol(A n B) with manifold3d, both VVs in their POI frame."""
    import manifold3d as m3d

    def solid(vv):
        verts = (np.asarray(vv.vertices) - np.asarray(vv.poi)[None, :]).astype(np.float32)
        mesh = m3d.Mesh(vert_properties=verts, tri_verts=np.asarray(vv.faces, dtype=np.uint32))
        return m3d.Manifold(mesh)

    def volume(m):
        return m.volume() if hasattr(m, "volume") else m.get_volume()

    ma, mb = solid(a), solid(b)
    return volume(ma) + volume(mb) - 2.0 * volume(ma ^ mb)


def locus_timings(charlotte: vt.Environment, repeat: int) -> None:
    """Planning time of the smooth locus (check + smooth R(t)) against the paper's, cold (a new
    scene and VV cache each time), on paper_slow, paper_small and the campus."""
    campus = load_environment(str(DATA / "campus" / "campus.obj"), "y")
    runs = [("paper_slow", charlotte, "charlotte/paths/paper_slow.csv", 5.0,
             vt.Uav(speed=20.0, min_turn_radius=50.0, altitude=300.0), 400.0, {"spacing": 20.0, "cutoff": 20e6}),
            ("paper_small", charlotte, "charlotte/paths/paper_small.csv", 5.0,
             vt.Uav(speed=20.0, min_turn_radius=5.0, altitude=50.0), 100.0, {"spacing": 20.0, "cutoff": 500e3}),
            ("campus", campus, "campus/flight_test_path.csv", 0.35,
             vt.Uav(speed=3.0, min_turn_radius=5.0, altitude=35.0), 50.0, {"spacing": 20.0, "cutoff": 1e5})]
    print("\nplanning time, smooth locus (check + smooth R(t)) against the paper's (Algorithm 1 only), cold:")
    for name, env, path, speed, uav, d_max, planning in runs:
        poi = vt.PoiPath.from_csv(str(DATA / path), speed)
        sensor = vt.Sensor(d_max=d_max)
        paper = vt.Planning(**planning, locus="paper")
        t_paper, _ = timed(lambda: vt.plan_orbits(env, poi, uav, sensor, paper), repeat)
        t_smooth, plan = timed(lambda: vt.plan_orbits(env, poi, uav, sensor, vt.Planning(**planning)), repeat)
        c = plan.check
        print(f"  {name:11s} paper {t_paper:.3f} s, smooth {t_smooth:.3f} s: x{t_smooth / t_paper:.2f} "
              f"({len(c.times)} check points, {c.rounds} rounds; "
              f"goal <= x2: {'met' if t_smooth <= 2 * t_paper else 'NOT met'})")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--map", default=str(DATA / "charlotte" / "uptown_charlotte.obj"))
    parser.add_argument("--pairs", type=int, default=6, help="neighbouring VV pairs for the XOR comparison")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--cgal-time-limit", type=float, default=60.0)
    parser.add_argument("--skip-xor", action="store_true", help="only the plans")
    args = parser.parse_args()
    path = DATA / "charlotte" / "paths" / "paper_slow.csv"
    if not path.exists():
        print(f"real data not found under {DATA}: skipping")
        return 0

    env = load_environment(args.map, "y")
    poi = vt.PoiPath.from_csv(str(path), 5.0)
    uav = vt.Uav(speed=20.0, min_turn_radius=50.0, altitude=300.0)
    sensor = vt.Sensor(d_max=400.0)

    print(f"machine: {os.cpu_count()} cores; vistrack {vt.__version__}")
    # The whole plan, cold: a new scene and an empty VV cache each time.
    paper = vt.Planning(spacing=20.0, cutoff=20e6, resolution_deg=1.0, locus="paper")
    t_plan, plan = timed(lambda: vt.plan_orbits(env, poi, uav, sensor, paper), args.repeat)
    print(f"paper_slow plan (scene + {len(plan.times)} VVs + metric + VPs + Algorithm 1): "
          f"{t_plan:.3f} s  (goal <= 3 s: {'met' if t_plan <= 3.0 else 'NOT met'})")
    print(f"  R {plan.radii[0]:.1f} -> {plan.radii[-1]:.1f} m, feasible={plan.feasible}")
    locus_timings(env, args.repeat)
    if args.skip_xor:
        return 0

    # XOR per pair: neighbouring VVs of the plan (1-degree grid), POI frame.
    k_all = list(range(len(plan.times) - 1))
    picks = [k_all[i] for i in np.linspace(0, len(k_all) - 1, min(args.pairs, len(k_all))).astype(int)]
    rows = []
    for k in picks:
        a, b = plan.volume(k), plan.volume(k + 1)
        t_radial, d_radial = timed(lambda: vt.xor_volume(a, b, frame="poi", method="radial"), args.repeat)
        t_grid, d_grid = timed(lambda: vt.xor_volume(a, b, frame="poi", method="grid"), args.repeat)
        try:
            t_cgal, d_cgal = timed(lambda: vt.xor_volume(a, b, frame="poi", method="mesh",
                                                         time_limit=args.cgal_time_limit), 1)
        except vt.VistrackError as error:
            t_cgal, d_cgal = float("nan"), float("nan")
            print(f"  pair {k}: CGAL path failed: {error}")
        try:
            t_m3d, d_m3d = timed(lambda: manifold_xor(a, b), args.repeat)
        except ImportError:
            t_m3d, d_m3d = float("nan"), float("nan")
        rows.append((k, len(a.faces) + len(b.faces), d_radial, d_grid, d_cgal, d_m3d, t_radial, t_grid, t_cgal, t_m3d))

    print("\nXOR metric per pair (frame poi, 1-degree VVs); relative differences from CGAL:")
    print(f"{'pair':>4} {'faces':>7} {'radial m^3':>12} {'radial':>9} {'grid':>9} {'manifold':>9}"
          f" {'radial ms':>9} {'grid ms':>8} {'CGAL ms':>9} {'m3d ms':>8}")
    for k, faces, dr, dg, dc, dm, tr, tg, tc, tm in rows:
        print(f"{k:>4} {faces:>7} {dr:12.5g} {dr / dc - 1:+9.1e} {dg / dc - 1:+9.1e} {dm / dc - 1:+9.1e}"
              f" {1e3 * tr:9.2f} {1e3 * tg:8.2f} {1e3 * tc:9.1f} {1e3 * tm:8.1f}")
    tr, tg, tc, tm = (statistics.median(r[i] for r in rows) for i in (6, 7, 8, 9))
    print(f"median per pair: radial {1e3 * tr:.2f} ms (goal <= 50 ms: {'met' if tr <= 0.05 else 'NOT met'}), "
          f"grid {1e3 * tg:.2f} ms, CGAL {1e3 * tc:.0f} ms, manifold3d {1e3 * tm:.1f} ms")
    print(f"ratios: CGAL / radial = {tc / tr:.0f}x, manifold3d / radial = {tm / tr:.0f}x, "
          f"radial / grid = {tr / tg:.0f}x, CGAL / manifold3d = {tc / tm:.1f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
