"""Sustained VV throughput with glibc's default malloc settings and after vt.keep_freed_memory()
(what the vistrack command sets), side by side: fresh processes, interleaved, as a ratio.

    VISTRACK_BUILD_DIR=build/dev python3 bench/keep_freed_memory.py [--seconds 5] [--rounds 3]

Each process computes 1-degree Charlotte VVs (10 POIs along paper_slow, d_max 400 m) back to back
for --seconds, in batches (visibility_volumes, both cores) and one at a time on one thread
(visibility_volume_cost with parallel=False), and reports VVs per second. Unlike the best-of
timings of visibility_bench.py, a sustained run pays the page faults of memory glibc hands back
to the kernel between batches.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def worker(mode: str, keep: bool, seconds: float) -> None:
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import numpy as np

    import conftest  # vistrack from the build tree when VISTRACK_BUILD_DIR is set
    import vistrack as vt
    from vistrack import _core

    if keep and not vt.keep_freed_memory():
        raise SystemExit("keep_freed_memory: no glibc mallopt here")
    charlotte = conftest.SHARED_DATA / "charlotte"
    scene = vt.VisibilityScene(vt.Environment.from_mesh(str(charlotte / "uptown_charlotte.obj"), up="y"))
    poi = vt.PoiPath.from_csv(str(charlotte / "paths" / "paper_slow.csv"), speed=5.0)
    pois = np.array([poi.position(t) for t in np.linspace(0.0, poi.duration, 10)])
    start, count = time.perf_counter(), 0
    while time.perf_counter() - start < seconds:
        if mode == "batch":
            vt.visibility_volumes(scene, pois, 400.0, None, 1.0)
        else:
            for p in pois:
                _core.visibility_volume_cost(scene, p, 400.0, None, 1.0, False)
        count += len(pois)
    print(count / (time.perf_counter() - start))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=5.0)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--worker", nargs=2, metavar=("MODE", "KEEP"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        worker(args.worker[0], args.worker[1] == "keep", args.seconds)
        return 0
    data = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data")) / "charlotte"
    if not data.is_dir():
        print(f"skipped: no Charlotte data at {data} (set VISTRACK_DATA)")
        return 0
    for mode in ("batch", "single"):
        rates: dict[str, list[float]] = {"default": [], "kept": []}
        for _ in range(args.rounds):
            for name in rates:
                command = [sys.executable, __file__, "--seconds", str(args.seconds), "--worker", mode,
                           "keep" if name == "kept" else "plain"]
                run = subprocess.run(command, check=True, capture_output=True, text=True)
                rates[name].append(float(run.stdout.split()[-1]))
        median = {name: statistics.median(values) for name, values in rates.items()}
        label = "in batches of 10 (both cores)" if mode == "batch" else "one at a time on one thread"
        print(f"VVs/s {label}: default {median['default']:.0f}, after keep_freed_memory {median['kept']:.0f} "
              f"(x{median['kept'] / median['default']:.2f}; per round: "
              + ", ".join(f"{name} {' '.join(f'{v:.0f}' for v in values)}" for name, values in rates.items())
              + f"; load {os.getloadavg()[0]:.1f})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
