"""Visibility-volume benchmark on uptown Charlotte: vistrack (Embree 3, C++) against trimesh with
its Embree backend (embreex), the same rays from the same POIs, side by side in one run.

    python bench/visibility_bench.py [--data ../shared/data] [--points 10] [--repeat 3] [--keep-freed-memory]

Reports per resolution (1 and 0.5 degrees): milliseconds per VV (rays, intervals, closed mesh and
volume) for one VV at a time and for the parallel batch, the same for a VV with its volume only
(with_mesh=False: the intervals and the volume, no mesh), the rays per second that implies, the
trace-only rays per second
of VisibilityScene.first_hits, and the peer's rays per second for the same directions (trimesh's
intersects_location, first hits with their distances), and where a VV's time goes (one VV on one
thread: per-column bounds, corner rays, refinement at the jumps, mesh, volume; then the same phases
of one VV spread over the cores, and how much each gains from them; the refinement and the mesh
also by stage). Beside the peer
ratio, the fraction of Embree's floor reached: the VV rate divided by the rate Embree alone allows
for the same rays (its own time on one thread, VolumeCost.embree_s, spread over the cores). Goals:
issue 7, a 1-degree Charlotte VV in <= 10 ms and >= 3x the peer's rays per second; issue 35,
<= 3.5 ms one at a time and >= 500 VVs/s in a batch for a VV with its volume (quiet 2-core machine;
with its mesh as well printed beside). Before/after two
builds on a shared machine: bench/visibility_builds.py; accuracy per cost against the peer:
bench/visibility_accuracy_bench.py.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import vistrack as vt
from timing import best_of
from vistrack import _core

REPO = Path(__file__).resolve().parents[1]


def directions(resolution_deg: float) -> np.ndarray:
    """As many rays as one VV answers for its intervals and mesh (bisection aside): one per corner
    of the grid, the poles once (file format 4: the corners also give the grid's intervals). The
    VV finds them by per-triangle tests, the peer by tracing them."""
    grid = vt.DirectionGrid.from_resolution(resolution_deg)
    ne, na = grid.num_elevation, grid.num_azimuth
    el_v = -np.pi / 2 + np.arange(1, ne) * np.pi / ne
    az_v = np.arange(na) * 2 * np.pi / na
    e, a = np.meshgrid(el_v, az_v, indexing="ij")
    sphere = np.column_stack([(np.cos(e) * np.cos(a)).ravel(), (np.cos(e) * np.sin(a)).ravel(), np.sin(e).ravel()])
    return np.vstack([sphere, [[0.0, 0.0, -1.0], [0.0, 0.0, 1.0]]])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data", type=Path,
                        default=Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data")))
    parser.add_argument("--points", type=int, default=10, help="POIs along paper_slow.csv")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--d-max", type=float, default=400.0)
    parser.add_argument("--json", type=Path, help="also write the numbers here")
    parser.add_argument("--keep-freed-memory", action="store_true",
                        help="first call vt.keep_freed_memory() (as the vistrack command does)")
    args = parser.parse_args()
    if args.keep_freed_memory and not vt.keep_freed_memory():
        print("keep_freed_memory: no glibc mallopt here; measuring with the defaults")

    import trimesh
    from trimesh.ray.ray_pyembree import RayMeshIntersector

    env = vt.Environment.from_mesh(str(args.data / "charlotte" / "uptown_charlotte.obj"), up="y")
    start = time.perf_counter()
    scene = vt.VisibilityScene(env)
    ours_build = time.perf_counter() - start
    poi = vt.PoiPath.from_csv(str(args.data / "charlotte" / "paths" / "paper_slow.csv"), speed=5.0)
    pois = np.array([poi.position(t) for t in np.linspace(0.0, poi.duration, args.points)])

    # The peer gets the same triangles plus the same ground square.
    ground = env.ground_level
    h = 1.0e6
    vertices = np.vstack([env.vertices, [[-h, -h, ground], [h, -h, ground], [h, h, ground], [-h, h, ground]]])
    n = len(env.vertices)
    faces = np.vstack([env.faces, [[n, n + 1, n + 2], [n, n + 2, n + 3]]])
    start = time.perf_counter()
    peer = RayMeshIntersector(trimesh.Trimesh(vertices=vertices, faces=faces, process=False))
    peer.intersects_first(np.zeros((1, 3)), np.array([[0.0, 0.0, 1.0]]))  # builds its BVH lazily
    peer_build = time.perf_counter() - start

    print(f"Charlotte: {env.num_triangles} triangles; BVH build vistrack {ours_build * 1e3:.1f} ms, "
          f"trimesh/embreex {peer_build * 1e3:.1f} ms; {args.points} POIs, d_max {args.d_max:g} m, "
          f"best of {args.repeat}")
    header = (f"{'res':>5} {'rays/VV':>8} | {'ms/VV':>7} {'batch ms/VV':>11} {'VV Mrays/s':>10} "
              f"{'trace Mrays/s':>13} | {'peer ms/VV':>10} {'peer Mrays/s':>12} | {'ratio':>6}")
    print(header)
    print("-" * len(header))
    results = []
    for res in (1.0, 0.5):
        dirs = directions(res)
        rays = len(dirs)
        single = best_of(args.repeat, lambda: [vt.visibility_volume(scene, p, args.d_max, None, res) for p in pois])
        batch = best_of(args.repeat, lambda: vt.visibility_volumes(scene, pois, args.d_max, None, res))
        volume_single = best_of(args.repeat, lambda: [vt.visibility_volume(scene, p, args.d_max, None, res,
                                                                           with_mesh=False) for p in pois])
        volume_batch = best_of(args.repeat, lambda: vt.visibility_volumes(scene, pois, args.d_max, None, res,
                                                                          with_mesh=False))
        trace = best_of(args.repeat, lambda: [scene.first_hits(p, dirs, args.d_max) for p in pois])

        def peer_run() -> None:
            for p in pois:
                origins = np.broadcast_to(p, dirs.shape)
                locations, index_ray, _ = peer.intersects_location(origins, dirs, multiple_hits=False)
                distance = np.full(len(dirs), np.inf)
                distance[index_ray] = np.linalg.norm(locations - p, axis=1)
                np.minimum(distance, args.d_max, out=distance)

        peer_time = best_of(args.repeat, peer_run)
        # Same answers: first-hit distances agree (float scenes, so up to a few centimetres).
        p0 = pois[0]
        ours_hits = np.minimum(scene.first_hits(p0, dirs, args.d_max), args.d_max)
        locations, index_ray, _ = peer.intersects_location(np.broadcast_to(p0, dirs.shape), dirs, multiple_hits=False)
        peer_hits = np.full(len(dirs), np.inf)
        peer_hits[index_ray] = np.linalg.norm(locations - p0, axis=1)
        peer_hits = np.minimum(peer_hits, args.d_max)
        agree = float(np.mean(np.abs(ours_hits - peer_hits) < 0.05))

        ms_vv = single / len(pois) * 1e3
        row = {
            "resolution_deg": res,
            "rays_per_vv": rays,
            "ms_per_vv": ms_vv,
            "batch_ms_per_vv": batch / len(pois) * 1e3,
            "volume_ms_per_vv": volume_single / len(pois) * 1e3,
            "volume_batch_ms_per_vv": volume_batch / len(pois) * 1e3,
            "vv_mrays_per_s": rays * len(pois) / single / 1e6,
            "batch_mrays_per_s": rays * len(pois) / batch / 1e6,
            "trace_mrays_per_s": rays * len(pois) / trace / 1e6,
            "peer_ms_per_vv": peer_time / len(pois) * 1e3,
            "peer_mrays_per_s": rays * len(pois) / peer_time / 1e6,
            "hit_agreement": agree,
        }
        row["ratio_vv_vs_peer"] = row["vv_mrays_per_s"] / row["peer_mrays_per_s"]
        row["ratio_batch_vs_peer"] = row["batch_mrays_per_s"] / row["peer_mrays_per_s"]
        results.append(row)
        print(f"{res:>5g} {rays:>8d} | {ms_vv:>7.2f} {row['batch_ms_per_vv']:>11.2f} {row['vv_mrays_per_s']:>10.1f} "
              f"{row['trace_mrays_per_s']:>13.1f} | {row['peer_ms_per_vv']:>10.2f} {row['peer_mrays_per_s']:>12.2f} | "
              f"{row['ratio_vv_vs_peer']:>5.1f}x")
    for res in (1.0, 0.5):
        costs = [_core.visibility_volume_cost(scene, p, args.d_max, None, res, False)[1] for p in pois]
        fields = ("bounds_s", "trace_s", "refine_s", "mesh_s", "volume_s", "rays_traced", "rays_skipped", "refine_rays",
                  "embree_s", "corner_tests", "refine_predicted")
        total = {k: float(np.mean([getattr(c, k) for c in costs])) for k in fields}
        phases = ("bounds_s", "trace_s", "refine_s", "mesh_s", "volume_s")
        spent = sum(total[k] for k in phases)
        print(f"{res:g} deg, one VV on one thread: {spent * 1e3:.2f} ms = "
              + ", ".join(f"{k[:-2]} {total[k] * 1e3:.2f}" for k in phases)
              + f"; corner rays: {total['rays_skipped']:.0f} decided without Embree ({total['corner_tests']:.0f} "
              f"triangle tests), {total['rays_traced']:.0f} traced; {total['refine_rays']:.0f} refining rays traced, "
              f"{total['refine_predicted']:.0f} predicted")
        # The same VVs spread over the cores (visibility_volume alone): which phases gain from them
        # (the pass over the POIs with the least time of --repeat: the threads' wake-ups vary).
        passes = [[_core.visibility_volume_cost(scene, p, args.d_max, None, res, True)[1] for p in pois]
                  for _ in range(args.repeat)]
        spread = min(passes, key=lambda costs: sum(getattr(c, k) for c in costs for k in phases))
        spread_total = {k: float(np.mean([getattr(c, k) for c in spread])) for k in phases}
        print(f"  one VV on {len(os.sched_getaffinity(0))} threads: "
              + ", ".join(f"{k[:-2]} {spread_total[k] * 1e3:.2f} (x{total[k] / spread_total[k]:.2f})"
                          for k in phases if spread_total[k] > 0))
        # The refinement and the mesh by stage, one thread -> spread over the cores: the stages that
        # do not gain from the cores are what one VV alone waits for.
        stages = {"refine": ("candidates_s", "first_pass_s", "second_pass_s", "untwist_s"),
                  "mesh": ("count_s", "vertices_s", "fill_s")}
        one = {k: float(np.mean([getattr(c, k) for c in costs])) for ks in stages.values() for k in ks}
        both = {k: float(np.mean([getattr(c, k) for c in spread])) for ks in stages.values() for k in ks}
        for name, keys in stages.items():
            print(f"  {name} by stage, one thread -> {len(os.sched_getaffinity(0))} threads: "
                  + ", ".join(f"{k[:-2].replace('_', ' ')} {one[k] * 1e3:.2f} -> {both[k] * 1e3:.2f}" for k in keys))
        # The predicted rays (just before an occluder's edge) traced as well, once, as a check.
        checks = [_core.visibility_volume_cost(scene, p, args.d_max, None, res, False, True)[1] for p in pois]
        predicted = sum(c.refine_predicted for c in checks)
        misses = sum(c.predicted_misses for c in checks)
        print(f"  predicted rays traced as a check: {misses} of {predicted} differ from Embree by more than 0.1 % "
              f"(largest |predicted / traced - 1| {max(c.predicted_error for c in checks):.1e})")
        # The floor these rays set: Embree's own time, whatever the rest of the VV costs.
        cores = len(os.sched_getaffinity(0))
        cap = f"{cores / total['embree_s']:.0f}" if total["embree_s"] > 0 else "no"
        print(f"  inside Embree: {total['embree_s'] * 1e3:.2f} ms ({100 * total['embree_s'] / spent:.0f} %) for "
              f"{total['rays_traced'] + total['refine_rays']:.0f} rays; Embree alone caps a {cores}-core batch at "
              f"{cap} VVs/s")
        row = next(r for r in results if r["resolution_deg"] == res)
        row["embree_ms_per_vv"] = total["embree_s"] * 1e3
        row["phases_ms"] = {k[:-2]: total[k] * 1e3 for k in phases}
        if total["embree_s"] > 0:
            # Fraction of the floor: the VV rate over the rate Embree alone allows on these cores.
            row["floor_fraction_single"] = total["embree_s"] * 1e3 / cores / row["ms_per_vv"]
            row["floor_fraction_batch"] = total["embree_s"] * 1e3 / cores / row["batch_ms_per_vv"]
            print(f"  fraction of Embree's floor reached: one VV {100 * row['floor_fraction_single']:.0f} %, "
                  f"batch {100 * row['floor_fraction_batch']:.0f} % (peer ratio x{row['ratio_vv_vs_peer']:.1f})")
    for row in results:
        print(f"{row['resolution_deg']:g} deg: first hits agree with the peer on "
              f"{100 * row['hit_agreement']:.2f}% of rays "
              f"(within 5 cm); batch {row['ratio_batch_vs_peer']:.1f}x the peer's rays/s")
    first = results[0]
    for what, alone, batch_ms in (("its volume (with_mesh=False)", "volume_ms_per_vv", "volume_batch_ms_per_vv"),
                                  ("its volume and its mesh", "ms_per_vv", "batch_ms_per_vv")):
        print(f"1 deg: a VV with {what} {first[alone]:.2f} ms alone, {first[batch_ms]:.2f} ms per VV in a batch "
              f"({1e3 / first[batch_ms]:.0f} VVs/s)")
    one, per_s = first["volume_ms_per_vv"], 1e3 / first["volume_batch_ms_per_vv"]
    mesh_one, mesh_per_s = first["ms_per_vv"], 1e3 / first["batch_ms_per_vv"]
    print(f"goal (issue 35, quiet 2-core machine; load here {os.getloadavg()[0]:.1f}): 1-degree VV with its volume "
          f"<= 3.5 ms: {one:.2f} ms ({'met' if one <= 3.5 else 'NOT met'}); batch >= 500 VVs/s: {per_s:.0f} "
          f"({'met' if per_s >= 500 else 'NOT met'}) [with its mesh as well: {mesh_one:.2f} ms, "
          f"{mesh_per_s:.0f} VVs/s]; "
          f">= 3x peer rays/s: {first['ratio_vv_vs_peer']:.1f}x")
    if args.json:
        args.json.write_text(json.dumps({"load_average": os.getloadavg(), "results": results}, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
