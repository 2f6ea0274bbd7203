"""Dubins shortest paths: vistrack vs OMPL's DubinsStateSpace (the `ompl` wheel), one run.

Measures, side by side on the same random pairs:
  * agreement of the lengths with OMPL (relative difference) on random pairs, and on
    degenerate pairs where both libraries snap (the differences are listed and explained);
  * paths per second through OMPL's Python API (one distance() per pair, states set from
    Python) against vistrack per path (dubins.shortest_path) and batch
    (dubins.shortest_lengths on all cores and on one core).

Usage:  python bench/dubins_bench.py [--pairs 100000] [--batch 4000000] [--json out.json]
(with VISTRACK_BUILD_DIR=build/dev to use a CMake build tree). Needs `pip install ompl`.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(HERE.parent / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

from timing import best_of
from vistrack import dubins

try:
    from ompl import base as ob
except ImportError:  # pragma: no cover
    sys.exit("this benchmark needs OMPL's Python wheel: pip install ompl")

TWO_PI = 2.0 * math.pi


def random_pairs(rng: np.random.Generator, n: int, extent: float) -> tuple[np.ndarray, np.ndarray]:
    def configurations() -> np.ndarray:
        return np.column_stack([rng.uniform(-extent, extent, (n, 2)), rng.uniform(-math.pi, math.pi, n)])

    return configurations(), configurations()


class Ompl:
    """OMPL's Dubins distance through its Python API (asymmetric: the forward path, like ours)."""

    def __init__(self, rho: float) -> None:
        self.space = ob.DubinsStateSpace(rho, False)
        self.a = self.space.allocState()
        self.b = self.space.allocState()

    def length(self, q0, q1) -> float:
        a, b = self.a, self.b
        a.setX(q0[0]); a.setY(q0[1]); a.setYaw(q0[2])  # noqa: E702
        b.setX(q1[0]); b.setY(q1[1]); b.setYaw(q1[2])  # noqa: E702
        return self.space.distance(a, b)

    def lengths(self, q0s: np.ndarray, q1s: np.ndarray) -> np.ndarray:
        a0, a1 = q0s.tolist(), q1s.tolist()
        return np.array([self.length(p, q) for p, q in zip(a0, a1)])


def agreement(rho: float, pairs: int, seed: int) -> dict:
    rng = np.random.default_rng(seed)
    ompl = Ompl(rho)
    out = {}
    for name, extent in (("far (|x|,|y| <= 10 rho)", 10.0 * rho), ("near (|x|,|y| <= 2 rho, CCC regime)", 2.0 * rho)):
        q0, q1 = random_pairs(rng, pairs, extent)
        ours, _ = dubins.shortest_lengths(q0, q1, rho)
        theirs = ompl.lengths(q0, q1)
        rel = np.abs(ours - theirs) / np.maximum(theirs, 1e-300)
        worst = int(np.argmax(rel))
        out[name] = {
            "pairs": pairs,
            "max_relative_difference": float(rel.max()),
            "pairs_above_1e-9": int((rel > 1e-9).sum()),
            "worst_pair": [q0[worst].tolist(), q1[worst].tolist(), float(ours[worst]), float(theirs[worst])],
        }
    return out


def degenerate_cases(rho: float) -> list[dict]:
    """Pairs inside the snapping tolerances. OMPL (DubinsStateSpace.cpp): mod2pi maps
    (-1e-7, 0) and [2 pi - 5e-7, 2 pi) to 0, and d < 1e-6 with |alpha - beta| < 1e-6 (d in units of
    rho) is the zero path LSL(0, d, 0). vistrack snaps at eps = 1e-11 (1 + max|coord|/rho)."""
    ompl = Ompl(rho)
    r = rho
    cases = [
        ("identical", (1.0, 2.0, 0.3), (1.0, 2.0, 0.3)),
        ("heading + 2 pi * 7", (1.0, 2.0, 0.3), (1.0, 2.0, 0.3 + 14 * math.pi)),
        ("1e-3 rho ahead", (0, 0, 0), (1e-3 * r, 0, 0)),
        ("1e-9 rho ahead", (0, 0, 0), (1e-9 * r, 0, 0)),
        ("1e-3 rho behind", (0, 0, 0), (-1e-3 * r, 0, 0)),
        ("1e-7 rho behind", (0, 0, 0), (-1e-7 * r, 0, 0)),
        ("1e-9 rho behind", (0, 0, 0), (-1e-9 * r, 0, 0)),
        ("1e-13 rho behind", (0, 0, 0), (-1e-13 * r, 0, 0)),
        ("on left circle, 1 rad", (0, 0, 0), (r * math.sin(1), r * (1 - math.cos(1)), 1.0)),
        ("on left circle, 1e-8 rad", (0, 0, 0), (r * math.sin(1e-8), r * (1 - math.cos(1e-8)), 1e-8)),
        ("tangent LSR circles", (0, 0, 0), (2 * r, 2 * r, 0.0)),
        ("heading 1e-8 rad off, same point", (0, 0, 0), (0, 0, 1e-8)),
        ("heading -1e-8 rad off, same point", (0, 0, 0), (0, 0, -1e-8)),
    ]
    # Re-planning from a point sampled on a path (remaining length expected).
    p = dubins.shortest_path((0, 0, 0.4), (3 * r, -2 * r, 2.5), rho)
    s = p.segment_lengths[0] + p.segment_lengths[1] + 0.999999 * p.segment_lengths[2]
    cases.append(("re-plan on final arc (remaining %.3g)" % (p.length - s), tuple(p.at(s)), (3 * r, -2 * r, 2.5)))
    rows = []
    for name, q0, q1 in cases:
        ours = dubins.shortest_path(q0, q1, rho).length
        theirs = ompl.length(q0, q1)
        rows.append({"case": name, "vistrack": ours, "ompl": theirs, "difference": ours - theirs})
    return rows


def throughput(rho: float, per_path: int, batch: int, repeat: int, seed: int) -> dict:
    rng = np.random.default_rng(seed)
    q0, q1 = random_pairs(rng, per_path, 10.0 * rho)
    ompl = Ompl(rho)
    l0, l1 = q0.tolist(), q1.tolist()
    t_ompl = best_of(repeat, lambda: [ompl.length(a, b) for a, b in zip(l0, l1)])
    # OMPL's distance() alone, on states built beforehand (the kernel plus one Python call).
    states = []
    for p, q in zip(l0, l1):
        a, b = ompl.space.allocState(), ompl.space.allocState()
        a.setX(p[0]); a.setY(p[1]); a.setYaw(p[2])  # noqa: E702
        b.setX(q[0]); b.setY(q[1]); b.setYaw(q[2])  # noqa: E702
        states.append((a, b))
    distance = ompl.space.distance
    t_ompl_distance = best_of(repeat, lambda: [distance(a, b) for a, b in states])
    t_ours_length = best_of(repeat, lambda: [dubins.shortest_length(a, b, rho) for a, b in zip(l0, l1)])
    t_ours_path = best_of(repeat, lambda: [dubins.shortest_path(a, b, rho) for a, b in zip(l0, l1)])
    b0, b1 = random_pairs(rng, batch, 10.0 * rho)
    dubins.shortest_lengths(b0[:1000], b1[:1000], rho)  # warm the thread pool
    t_batch_all = best_of(repeat, lambda: dubins.shortest_lengths(b0, b1, rho))
    t_batch_one = best_of(repeat, lambda: dubins.shortest_lengths(b0, b1, rho, threads=1))
    cpu0 = time.process_time()
    dubins.shortest_lengths(b0, b1, rho)
    cpu_all = time.process_time() - cpu0
    n0, n1 = random_pairs(rng, batch, 2.0 * rho)
    t_near = best_of(repeat, lambda: dubins.shortest_lengths(n0, n1, rho))
    return {
        "ompl_python_per_path": {"paths_per_s": per_path / t_ompl, "ns_per_path": 1e9 * t_ompl / per_path},
        "ompl_python_distance_only": {"paths_per_s": per_path / t_ompl_distance,
                                      "ns_per_path": 1e9 * t_ompl_distance / per_path},
        "vistrack_python_shortest_length": {"paths_per_s": per_path / t_ours_length,
                                            "ns_per_path": 1e9 * t_ours_length / per_path},
        "vistrack_python_shortest_path": {"paths_per_s": per_path / t_ours_path,
                                          "ns_per_path": 1e9 * t_ours_path / per_path},
        "vistrack_batch_all_cores": {"paths_per_s": batch / t_batch_all, "ns_per_path": 1e9 * t_batch_all / batch,
                                     "cpu_ns_per_path": 1e9 * cpu_all / batch},
        "vistrack_batch_one_core": {"paths_per_s": batch / t_batch_one, "ns_per_path": 1e9 * t_batch_one / batch},
        "vistrack_batch_all_cores_near": {"paths_per_s": batch / t_near, "ns_per_path": 1e9 * t_near / batch},
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--pairs", type=int, default=100_000, help="random pairs for agreement and per-path timing")
    parser.add_argument("--batch", type=int, default=4_000_000, help="pairs for the batch timing")
    parser.add_argument("--repeat", type=int, default=3, help="timing repeats (best is kept)")
    parser.add_argument("--rho", type=float, default=1.0)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--json", type=Path, help="also write the results here")
    args = parser.parse_args()

    load = os.getloadavg()
    print(f"machine: {os.cpu_count()} logical cores, load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    agree = agreement(args.rho, args.pairs, args.seed)
    print("\n== lengths vs OMPL DubinsStateSpace (relative difference) ==")
    for name, row in agree.items():
        print(f"{name:40s} pairs {row['pairs']:>8d}  max {row['max_relative_difference']:.2e}  "
              f"> 1e-9: {row['pairs_above_1e-9']}")
    cases = degenerate_cases(args.rho)
    print("\n== degenerate pairs (inside the snapping tolerances) ==")
    for row in cases:
        flag = "" if abs(row["difference"]) <= 1e-9 * max(1.0, row["ompl"]) else "   <- differs"
        print(f"{row['case']:42s} vistrack {row['vistrack']:.12g}  ompl {row['ompl']:.12g}{flag}")
    speed = throughput(args.rho, min(args.pairs, 100_000), args.batch, args.repeat, args.seed + 1)
    print(f"\n== throughput (random pairs within 10 rho, '_near': within 2 rho; wall clock, best of {args.repeat}) ==")
    for name, row in speed.items():
        extra = f"  (cpu {row['cpu_ns_per_path']:.0f} ns/path over all threads)" if "cpu_ns_per_path" in row else ""
        print(f"{name:32s} {row['paths_per_s'] / 1e6:8.3f} M paths/s  {row['ns_per_path']:9.1f} ns/path{extra}")
    base = speed["ompl_python_per_path"]["paths_per_s"]
    print("\nratios vs OMPL Python API (states set per pair): per path (length) x%.2f, per path (path object) x%.2f, "
          "batch one core x%.1f, batch all cores x%.1f" % (
        speed["vistrack_python_shortest_length"]["paths_per_s"] / base,
        speed["vistrack_python_shortest_path"]["paths_per_s"] / base,
        speed["vistrack_batch_one_core"]["paths_per_s"] / base,
        speed["vistrack_batch_all_cores"]["paths_per_s"] / base))
    base = speed["ompl_python_distance_only"]["paths_per_s"]
    print("ratios vs OMPL distance() on prebuilt states: per path (length) x%.2f, batch one core x%.1f, "
          "batch all cores x%.1f" % (
        speed["vistrack_python_shortest_length"]["paths_per_s"] / base,
        speed["vistrack_batch_one_core"]["paths_per_s"] / base,
        speed["vistrack_batch_all_cores"]["paths_per_s"] / base))
    if args.json:
        record = {"load": load, "agreement": agree, "degenerate": cases, "throughput": speed}
        args.json.write_text(json.dumps(record, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
