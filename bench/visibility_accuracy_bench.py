"""Accuracy per cost of a Charlotte visibility volume (issue 19): the rays and milliseconds that
vistrack and trimesh + embreex each need to bring the volume within 0.1 % and 0.05 % of a
0.2-degree reference, side by side in one run, as a ratio.

    VISTRACK_BUILD_DIR=build/dev python3 bench/visibility_accuracy_bench.py [--points 10] [--repeat 3]

The same POIs as bench/visibility_bench.py (paper_slow, d_max 400 m, no band), put on the surface.
The reference is the per-direction volume of a 0.2-degree grid (vistrack.visibility.reference_volume:
brute-force staggered cell rays times their solid angles, as in tests/python/test_visibility.py);
vistrack's 0.2-degree mesh volume and the peer's 0.2-degree value are printed beside it as checks
of the reference. Per grid resolution:
- vistrack: visibility_volume (one ray per grid corner, then bisection rays at the jumps of the
  visible distance; the volume of the closed mesh). Its rays are all corner directions (traced or
  decided by the per-column clearance bounds) plus the bisection rays.
- trimesh + embreex: one first-hit ray through every cell centre of the same grid
  (intersects_location, with the ground square of bench/visibility_bench.py), the distance
  clipped to d_max and to the ground plane, volume = sum of r^3 / 3 times the cell's solid angle.
The error of a method at a resolution is the largest |V / V_ref - 1| over the POIs; a method
reaches a bound at the coarsest resolution from which every finer one stays within it. Cost is
CPU milliseconds per VV on one thread (vistrack's VV without its own threads), which a machine
shared with other work disturbs less than wall time; wall time is printed too.

Charlotte geometry (c) OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path
from typing import Callable

import numpy as np

if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import vistrack as vt
from vistrack import _core
from vistrack.visibility import reference_volume

REPO = Path(__file__).resolve().parents[1]
OURS_RESOLUTIONS = (4.0, 3.0, 2.0, 1.5, 1.25, 1.0, 0.75, 0.5, 0.35)
PEER_RESOLUTIONS = (2.0, 1.0, 0.75, 0.5, 0.35, 0.25, 0.2)
BOUNDS = (1e-3, 5e-4)
REFERENCE_DEG = 0.2


def cpu_and_wall(repeat: int, fn: Callable[[], object]) -> tuple[float, float]:
    """Median CPU seconds and median wall seconds of `repeat` calls."""
    cpu, wall = [], []
    for _ in range(repeat):
        c, w = time.process_time(), time.perf_counter()
        fn()
        wall.append(time.perf_counter() - w)
        cpu.append(time.process_time() - c)
    return float(np.median(cpu)), float(np.median(wall))


class Peer:
    """trimesh + embreex: first hits through the cell centres, volume by cells."""

    def __init__(self, env: vt.Environment, d_max: float) -> None:
        import trimesh
        from trimesh.ray.ray_pyembree import RayMeshIntersector

        self.ground, self.d_max = env.ground_level, d_max
        h = 1.0e6
        vertices = np.vstack([env.vertices, [[-h, -h, self.ground], [h, -h, self.ground], [h, h, self.ground],
                                             [-h, h, self.ground]]])
        n = len(env.vertices)
        faces = np.vstack([env.faces, [[n, n + 1, n + 2], [n, n + 2, n + 3]]])
        self.intersector = RayMeshIntersector(trimesh.Trimesh(vertices=vertices, faces=faces, process=False))
        self.intersector.intersects_first(np.zeros((1, 3)), np.array([[0.0, 0.0, 1.0]]))  # builds its BVH

    @staticmethod
    def grid(resolution_deg: float) -> tuple[np.ndarray, np.ndarray]:
        """Cell-centre directions (n, 3) and their solid angles (n,) of vistrack's grid."""
        grid = vt.DirectionGrid.from_resolution(resolution_deg)
        ne, na = grid.num_elevation, grid.num_azimuth
        edges = -np.pi / 2 + np.arange(ne + 1) * np.pi / ne
        el = 0.5 * (edges[:-1] + edges[1:])
        az = (np.arange(na) + 0.5) * 2 * np.pi / na
        e, a = np.meshgrid(el, az, indexing="ij")
        dirs = np.column_stack([(np.cos(e) * np.cos(a)).ravel(), (np.cos(e) * np.sin(a)).ravel(), np.sin(e).ravel()])
        solid = np.repeat(np.diff(np.sin(edges)) * 2 * np.pi / na, na)
        return dirs, solid

    def volume(self, g: np.ndarray, dirs: np.ndarray, solid: np.ndarray) -> float:
        locations, index_ray, _ = self.intersector.intersects_location(np.broadcast_to(g, dirs.shape), dirs,
                                                                       multiple_hits=False)
        r = np.full(len(dirs), self.d_max)
        r[index_ray] = np.minimum(self.d_max, np.linalg.norm(locations - g, axis=1))
        down = dirs[:, 2] < 0.0
        r[down] = np.minimum(r[down], np.maximum(0.0, (self.ground - g[2]) / dirs[down, 2]))
        return float(np.sum(r**3 * solid) / 3.0)


def reach(rows: list[dict], bound: float) -> dict | None:
    """The coarsest row from which every finer row has an error within bound."""
    found = None
    for row in reversed(rows):  # finest first
        if row["max_error"] > bound:
            break
        found = row
    return found


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    data = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data"))
    parser.add_argument("--data", type=Path, default=data)
    parser.add_argument("--points", type=int, default=10, help="POIs along paper_slow.csv")
    parser.add_argument("--repeat", type=int, default=3, help="timing runs per resolution (medians)")
    parser.add_argument("--d-max", type=float, default=400.0)
    parser.add_argument("--json", type=Path, help="also write the numbers here")
    args = parser.parse_args()
    mesh = args.data / "charlotte" / "uptown_charlotte.obj"
    if not mesh.exists():
        print(f"real data not found under {args.data}: skipping")
        return 0

    env = vt.Environment.from_mesh(str(mesh), up="y")
    scene = vt.VisibilityScene(env)
    path = vt.PoiPath.from_csv(str(args.data / "charlotte" / "paths" / "paper_slow.csv"), speed=5.0)
    times = np.linspace(0.0, path.duration, args.points)
    pois = [np.ravel(scene.poi_on_surface(np.ravel(path.position(t)))) for t in times]
    d_max = args.d_max
    peer = Peer(env, d_max)

    fine = [vt.visibility_volume(scene, g, d_max, None, REFERENCE_DEG) for g in pois]
    reference = np.array([reference_volume(scene, g, d_max, REFERENCE_DEG) for g in pois])
    mesh_at_reference = np.array([vv.volume for vv in fine])
    dirs, solid = Peer.grid(REFERENCE_DEG)
    peer_at_reference = np.array([peer.volume(g, dirs, solid) for g in pois])

    def spread(values: np.ndarray) -> str:
        errors = 100 * np.abs(values / reference - 1)
        return f"max {errors.max():.3f} %, median {np.median(errors):.3f} %"

    print(f"Charlotte, {args.points} POIs on paper_slow, d_max {d_max:g} m, load {os.getloadavg()[0]:.1f}; reference: "
          f"per-direction volume of a {REFERENCE_DEG:g}-degree grid; at {REFERENCE_DEG:g} degrees vistrack's mesh "
          f"differs from it by {spread(mesh_at_reference)}, the peer by {spread(peer_at_reference)}")

    def serial_vv(g: np.ndarray, res: float) -> tuple[float, dict]:
        vv, cost = _core.visibility_volume_cost(scene, g, d_max, None, res, False)
        return vv.volume, cost

    ours: list[dict] = []
    for res in OURS_RESOLUTIONS:
        results = [serial_vv(g, res) for g in pois]
        volumes = np.array([v for v, _ in results])
        rays = np.mean([c.rays_traced + c.rays_skipped + c.refine_rays for _, c in results])
        embree = np.mean([c.rays_traced + c.refine_rays for _, c in results])
        cpu, _ = cpu_and_wall(args.repeat, lambda res=res: [serial_vv(g, res) for g in pois])
        _, wall = cpu_and_wall(args.repeat,
                               lambda res=res: [vt.visibility_volume(scene, g, d_max, None, res) for g in pois])
        ours.append({"resolution_deg": res, "max_error": float(np.max(np.abs(volumes / reference - 1))),
                     "median_error": float(np.median(np.abs(volumes / reference - 1))), "rays": float(rays),
                     "embree_rays": float(embree), "cpu_ms": cpu / len(pois) * 1e3,
                     "wall_ms": wall / len(pois) * 1e3})
    theirs: list[dict] = []
    for res in PEER_RESOLUTIONS:
        dirs, solid = Peer.grid(res)
        volumes = np.array([peer.volume(g, dirs, solid) for g in pois])
        cpu, wall = cpu_and_wall(args.repeat,
                                 lambda dirs=dirs, solid=solid: [peer.volume(g, dirs, solid) for g in pois])
        theirs.append({"resolution_deg": res, "max_error": float(np.max(np.abs(volumes / reference - 1))),
                       "median_error": float(np.median(np.abs(volumes / reference - 1))), "rays": float(len(dirs)),
                       "embree_rays": float(len(dirs)), "cpu_ms": cpu / len(pois) * 1e3,
                       "wall_ms": wall / len(pois) * 1e3})

    header = f"{'method':>9} {'res':>5} {'rays/VV':>9} {'max err':>8} {'median':>7} {'CPU ms/VV':>9} {'wall ms/VV':>10}"
    print(header)
    print("-" * len(header))
    for name, rows in (("vistrack", ours), ("peer", theirs)):
        for row in rows:
            print(f"{name:>9} {row['resolution_deg']:>5g} {row['rays']:>9.0f} {100 * row['max_error']:>7.3f}% "
                  f"{100 * row['median_error']:>6.3f}% {row['cpu_ms']:>9.2f} {row['wall_ms']:>10.2f}")
    summary = []
    for bound in BOUNDS:
        a, b = reach(ours, bound), reach(theirs, bound)
        entry = {"bound": bound, "vistrack": a, "peer": b}
        summary.append(entry)
        if a is None:
            print(f"{100 * bound:.2f} % volume error: vistrack does not reach it on its finest grid")
            continue
        # A peer that never gets there is charged its finest grid: the ratios are then lower bounds.
        at_least = b is None
        b = b if b is not None else theirs[-1]
        entry["peer_reached"] = not at_least
        entry["ray_ratio"] = b["rays"] / a["rays"]
        entry["cpu_ratio"] = b["cpu_ms"] / a["cpu_ms"]
        more = ">=" if at_least else ""
        where = (f"not reached at {b['resolution_deg']:g} deg ({100 * b['max_error']:.3f} %)" if at_least
                 else f"at {b['resolution_deg']:g} deg")
        print(f"{100 * bound:.2f} % volume error: vistrack at {a['resolution_deg']:g} deg, {a['rays']:.0f} rays, "
              f"{a['cpu_ms']:.2f} CPU ms; peer {where}, {b['rays']:.0f} rays, {b['cpu_ms']:.1f} CPU ms: "
              f"x{more}{entry['ray_ratio']:.1f} fewer rays, x{more}{entry['cpu_ratio']:.0f} less CPU")
    if args.json:
        args.json.write_text(json.dumps({"load_average": os.getloadavg(), "reference_deg": REFERENCE_DEG,
                                         "vistrack": ours, "peer": theirs, "summary": summary}, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
