"""Sweep speed: the same 16-case tracking sweep run serially (one case after another in this
process, as `--scheduler serial`) and as Dask tasks on a 2-worker LocalCluster, in one run.

The cases are 16 road routes of the demo city drawn with a fixed seed (each needs its own VVs,
so no case borrows another's cache). Prints the speed-up, the cluster's start-up time, the
per-task overhead (trivial tasks through the same scheduler, and the time workers sat idle per
case in the sweep), that both runs give the same rows, and cases per second against the number
of workers (1 and 2 here) for the scaling note. The machine's other load shows in "cores
obtained" (CPU seconds over wall seconds); the serial run's CPU per thread gives what an idle
machine would do.

    VISTRACK_BUILD_DIR=build/dev python3 bench/sweep_bench.py [--resolution 2] [--no-one-worker]
"""

from __future__ import annotations

import argparse
import logging
import os
import sys
import threading
import time
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(HERE.parent / "tests" / "python"))
    from support import build_tree  # imports vistrack from the build tree, in this process and in the workers

    build_tree.preload_in_dask_workers()

import vistrack as vt
from vistrack.sweep import SERIAL, SweepSpec, run_cases


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


def pin_to_one_core(dask_worker: Any) -> list[int]:
    """Restrict a worker process to one core (worker i to core i): TBB inside it then runs one
    thread, so a case is single-threaded and workers do not oversubscribe the cores."""
    core = int(dask_worker.name) % (os.cpu_count() or 1)
    os.sched_setaffinity(0, {core})
    return sorted(os.sched_getaffinity(0))


def cluster_run(cases: list[vt.sweep.Case], workers: int, pinned: bool = False) -> dict[str, Any]:
    from distributed import Client, LocalCluster

    began = time.perf_counter()
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                           dashboard_address=None, silence_logs=logging.ERROR)
    with Client(cluster) as client:
        client.wait_for_workers(workers)
        if pinned:  # before any case: TBB reads the affinity when it starts in the worker
            client.run(pin_to_one_core)
        client.run(lambda: __import__("vistrack.sweep"))  # the package imported in every worker
        startup = time.perf_counter() - began
        # Per-task overhead: trivial tasks through the same scheduler.
        client.gather(client.map(noop, range(50), pure=False))  # warm up
        t0 = time.perf_counter()
        client.gather(client.map(noop, range(1000), pure=False))
        per_task = (time.perf_counter() - t0) / 1000
        t0 = time.perf_counter()
        rows = run_cases(cases, cluster.scheduler_address)
        wall = time.perf_counter() - t0
    cluster.close()
    busy = sum(row["run_wall_s"] for row in rows)
    return {"rows": rows, "wall": wall, "startup": startup, "per_task": per_task, "cpu": cpu_seconds(rows),
            "idle_per_case": (workers * wall - busy) / len(rows), "busy": busy}


def cpu_seconds(rows: list[dict[str, Any]]) -> float:
    """CPU seconds the cases used (every thread of the process running each case)."""
    return sum(row["run_cpu_s"] for row in rows)


def thread_cpu() -> dict[int, float]:
    """CPU seconds of every thread of this process (Linux /proc), by native thread id."""
    tick = os.sysconf("SC_CLK_TCK")
    times = {}
    for tid in os.listdir("/proc/self/task"):
        fields = Path(f"/proc/self/task/{tid}/stat").read_text().rsplit(")", 1)[1].split()
        times[int(tid)] = (int(fields[11]) + int(fields[12])) / tick  # utime + stime
    return times


def same_rows(a: list[dict[str, Any]], b: list[dict[str, Any]]) -> bool:
    def strip(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
        return [{k: v for k, v in row.items() if not k.startswith("run_")} for row in rows]

    return strip(a) == strip(b)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--resolution", type=float, default=2.0, help="VV grid resolution of the cases (degrees)")
    parser.add_argument("--no-scaling", action="store_true", help="skip the one-core-per-worker runs")
    args = parser.parse_args()
    spec = bench_spec(args.resolution)
    cases = spec.cases()
    n = len(cases)
    print(f"{n} tracking cases: demo-city routes {', '.join(spec.routes)}; "
          f"{args.resolution:g}-degree VVs; {os.cpu_count()} cores; load average {os.getloadavg()[0]:.1f}")

    before, t0 = thread_cpu(), time.perf_counter()
    serial = run_cases(cases, SERIAL)
    serial_wall, after = time.perf_counter() - t0, thread_cpu()
    main_cpu = after[threading.get_native_id()] - before.get(threading.get_native_id(), 0.0)
    pool_cpu = sum(v - before.get(k, 0.0) for k, v in after.items() if k != threading.get_native_id())
    failed = [row["case"] for row in serial if row["run_status"] != "ok"]
    print(f"serial (this process, TBB on every core): {serial_wall:6.1f} s  {n / serial_wall:.3f} cases/s  "
          f"{cpu_seconds(serial) / n:.2f} CPU s/case, {cpu_seconds(serial) / serial_wall:.2f} cores obtained"
          f"  (failed cases: {failed or 'none'})")
    # On an idle machine the serial run takes about the main thread's CPU time (it is busy
    # throughout, alone or beside TBB's threads) and 2 workers about the total CPU over 2 cores.
    print(f"  serial CPU by thread: main {main_cpu:.2f} s, TBB pool {pool_cpu:.2f} s: on an idle {os.cpu_count()}-core "
          f"machine serial ~{main_cpu:.1f} s, 2 workers >= {(main_cpu + pool_cpu) / 2:.1f} s "
          f"(speed-up <= x{2 * main_cpu / (main_cpu + pool_cpu):.2f})")
    two = cluster_run(cases, 2)
    print(f"LocalCluster, 2 workers:                  {two['wall']:6.1f} s  {n / two['wall']:.3f} cases/s  "
          f"{two['cpu'] / n:.2f} CPU s/case, {two['cpu'] / two['wall']:.2f} cores obtained"
          f"  (+ {two['startup']:.1f} s to start the cluster)")
    print(f"speed-up, 2 workers / serial: x{serial_wall / two['wall']:.2f} "
          f"(x{serial_wall / (two['wall'] + two['startup']):.2f} counting the start-up)")
    print(f"per-task overhead: {two['per_task'] * 1e3:.2f} ms per trivial task; workers idle "
          f"{two['idle_per_case'] * 1e3:.0f} ms per case in the sweep (2 x wall - sum of case times)")
    print(f"same rows as serial: {same_rows(serial, two['rows'])}")
    if args.no_scaling:
        return
    # The scaling model: one core per worker (TBB single-threaded inside), 1 and 2 workers.
    one_core = cluster_run(cases, 1, pinned=True)
    two_cores = cluster_run(cases, 2, pinned=True)
    r1, r2 = n / one_core["wall"], n / two_cores["wall"]
    print(f"one core per worker: 1 worker {one_core['wall']:.1f} s ({r1:.3f} cases/s, "
          f"{one_core['cpu'] / one_core['wall']:.2f} cores obtained), 2 workers {two_cores['wall']:.1f} s "
          f"({r2:.3f} cases/s, {two_cores['cpu'] / two_cores['wall']:.2f} cores obtained): x{r2 / r1:.2f} from 1 "
          f"to 2 workers; {two_cores['cpu'] / n:.2f} CPU s/case; same rows: "
          f"{same_rows(serial, one_core['rows']) and same_rows(serial, two_cores['rows'])}")
    print(f"TBB inside one case: serial on every core is x{one_core['wall'] / serial_wall:.2f} faster than "
          f"on one core (mean case {one_core['busy'] / n:.2f} s on one core, {serial_wall / n:.2f} s on all)")


if __name__ == "__main__":
    main()
