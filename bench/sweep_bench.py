"""Sweep speed: the same 16-case tracking sweep run serially (one case after another in this
process, as `--scheduler serial`) and as Dask tasks on a 2-worker LocalCluster, in one run.

The cases are 16 road routes of the demo city drawn with a fixed seed (each needs its own VVs,
so no case borrows another's cache). Prints the speed-up, the cluster's start-up time, the
per-task overhead (trivial tasks through the same scheduler, and the time workers sat idle per
case in the sweep), that both runs give the same rows, and cases per second against the number
of workers (1 and 2 here) for the scaling note.

    VISTRACK_BUILD_DIR=build/dev python3 bench/sweep_bench.py [--resolution 2] [--no-one-worker]
"""

from __future__ import annotations

import argparse
import logging
import os
import sys
import time
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(HERE.parent / "tests" / "python"))
    import build_tree  # imports vistrack from the build tree, in this process and in the workers

    build_tree.preload_in_dask_workers()

import vistrack as vt  # noqa: E402
from vistrack.sweep import SERIAL, SweepSpec, run_cases  # noqa: E402


def bench_spec(resolution: float) -> SweepSpec:
    return SweepSpec.from_dict({
        "name": "bench16", "seed": 2024,
        "base": {"environment": {"demo": True}, "poi": {"speed": 5.0},
                 "uav": {"speed": 20.0, "min_turn_radius": 15.0, "altitude": 200.0},
                 "sensor": {"d_max": 300.0},
                 "planning": {"spacing": 20.0, "cutoff": 5.0e6, "resolution_deg": resolution},
                 "baselines": [120.0]},
        "routes": {"nodes": "all", "sample": 16},
    })


def noop(i: int) -> int:
    return i


def cluster_run(cases: list[vt.sweep.Case], workers: int) -> dict[str, Any]:
    from distributed import Client, LocalCluster

    began = time.perf_counter()
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                           dashboard_address=None, silence_logs=logging.ERROR)
    with Client(cluster) as client:
        client.wait_for_workers(workers)
        client.run(lambda: __import__("vistrack.sweep"))  # the package imported in every worker
        startup = time.perf_counter() - began
        # Per-task overhead: trivial tasks through the same scheduler, submitted as the sweep does.
        client.gather(client.map(noop, range(50), pure=False))  # warm up
        t0 = time.perf_counter()
        client.gather(client.map(noop, range(1000), pure=False))
        per_task = (time.perf_counter() - t0) / 1000
        t0 = time.perf_counter()
        rows = run_cases(cases, cluster.scheduler_address)
        wall = time.perf_counter() - t0
    cluster.close()
    busy = sum(row["run_wall_s"] for row in rows)
    return {"rows": rows, "wall": wall, "startup": startup, "per_task": per_task,
            "idle_per_case": (workers * wall - busy) / len(rows), "busy": busy}


def same_rows(a: list[dict[str, Any]], b: list[dict[str, Any]]) -> bool:
    def strip(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
        return [{k: v for k, v in row.items() if not k.startswith("run_")} for row in rows]

    return strip(a) == strip(b)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--resolution", type=float, default=2.0, help="VV grid resolution of the cases (degrees)")
    parser.add_argument("--no-one-worker", action="store_true", help="skip the 1-worker LocalCluster run")
    args = parser.parse_args()
    spec = bench_spec(args.resolution)
    cases = spec.cases()
    print(f"{len(cases)} tracking cases: demo-city routes {', '.join(spec.routes)}; "
          f"{args.resolution:g}-degree VVs; {os.cpu_count()} cores; load average {os.getloadavg()[0]:.1f}")

    t0 = time.perf_counter()
    serial = run_cases(cases, SERIAL)
    serial_wall = time.perf_counter() - t0
    failed = [row["case"] for row in serial if row["run_status"] != "ok"]
    print(f"serial (this process):        {serial_wall:7.1f} s  {len(cases) / serial_wall:.3f} cases/s"
          f"  (failed cases: {failed or 'none'})")

    two = cluster_run(cases, 2)
    print(f"LocalCluster, 2 workers:      {two['wall']:7.1f} s  {len(cases) / two['wall']:.3f} cases/s"
          f"  (+ {two['startup']:.1f} s to start the cluster)")
    print(f"speed-up, 2 workers / serial: x{serial_wall / two['wall']:.2f} "
          f"(x{serial_wall / (two['wall'] + two['startup']):.2f} counting the start-up)")
    print(f"per-task overhead: {two['per_task'] * 1e3:.2f} ms per trivial task; workers idle "
          f"{two['idle_per_case'] * 1e3:.0f} ms per case in the sweep (2 x wall - sum of case times)")
    print(f"same rows as serial: {same_rows(serial, two['rows'])}")

    if not args.no_one_worker:
        one = cluster_run(cases, 1)
        print(f"LocalCluster, 1 worker:       {one['wall']:7.1f} s  {len(cases) / one['wall']:.3f} cases/s"
              f"  (same rows: {same_rows(serial, one['rows'])})")
        rate1, rate2 = len(cases) / one["wall"], len(cases) / two["wall"]
        print(f"scaling: {rate1:.3f} -> {rate2:.3f} cases/s from 1 to 2 workers (x{rate2 / rate1:.2f}); "
              f"mean case {one['busy'] / len(cases):.2f} s alone on a worker, "
              f"{two['busy'] / len(cases):.2f} s with two workers on {os.cpu_count()} cores")


if __name__ == "__main__":
    main()
