"""``vistrack sweep SWEEP.yaml --out DIR [--scheduler ADDR] [--workers N]``: many cases as Dask tasks."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from ..sweep import SERIAL, SweepSpec, run
from ..sweep.connect import CONNECT_TIMEOUT_S, check_scheduler
from .output import output_folder
from .types import UsageError, add_dynamics_argument, count


def register(subparsers: Any) -> None:
    parser = subparsers.add_parser(
        "sweep", help="run a parameter sweep or many routes as Dask tasks, into a results table",
        description="Every case of a sweep file (a base scenario, parameters to vary, road routes) as "
                    "one Dask task, on a LocalCluster on this machine or on the cluster of --scheduler; "
                    "writes results.csv, results.parquet, sweep.json and figures/ into --out. A failed "
                    "case is a row with its error; results equal a serial run's.")
    parser.add_argument("sweep", help="sweep YAML file")
    parser.add_argument("--out", default=None,
                        help="output folder (default: the file's out:, else ./vistrack-out/<sweep name>)")
    parser.add_argument("--scheduler", default=None, metavar="ADDR",
                        help=f"Dask scheduler address (tcp://host:8786), checked first: a TCP connection, "
                             f"Dask's handshake and a scheduler's reply, {CONNECT_TIMEOUT_S:g} s each at most; "
                             f"default: a LocalCluster here; '{SERIAL}': one case after another in this process")
    parser.add_argument("--workers", type=count("--workers", 1, 1024), default=None, metavar="N",
                        help="LocalCluster worker processes (default: one per core); not with --scheduler")
    parser.add_argument("--no-figures", action="store_true", help="write the table only")
    add_dynamics_argument(parser)
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.set_defaults(func=main)


def main(args: argparse.Namespace) -> int:
    if args.workers is not None and args.scheduler is not None:
        raise UsageError(f"--workers = {args.workers}: only applies without --scheduler (a LocalCluster)")
    if args.scheduler not in (None, SERIAL):  # a one-line error within seconds, before the sweep file is read
        check_scheduler(args.scheduler, "--scheduler")
    spec = SweepSpec.load(args.sweep)
    if args.dynamics is not None:  # every case's vehicle model (a uav.dynamics parameter still wins)
        if spec.kind.name == "waypoints" and args.dynamics != "dubins":
            raise UsageError(f"--dynamics = {args.dynamics}: waypoint sweeps fly the paper's dimensionless units, "
                             "the Dubins vehicle only")
        spec.base = spec.kind.set(spec.base, "uav.dynamics", args.dynamics)
    # The folder (the sweep file's out: key unless --out is given) is checked and locked before the cases run.
    out = output_folder(args.out or spec.out or Path("vistrack-out") / spec.name, "out" if spec.out and not args.out
                        else "--out")
    print(f"{spec.name}: {spec.case_count} {spec.kind.name} cases over {', '.join(spec.parameters)} "
          f"({spec.combine})", flush=True)
    result = run(spec, args.scheduler, args.workers, out=out, quiet=args.quiet, figures=not args.no_figures,
                 scheduler_checked=args.scheduler is not None)  # checked above, before the file was read
    workers = ", ".join(f"{w}: {s['environments_built']} map(s), {s['cases_run']} case(s)"
                        for w, s in sorted(result.workers.items()))
    print(f"{len(result.rows)} cases in {result.wall_s:.1f} s on {result.scheduler} ({workers})")
    for row in result.failed:
        print(f"  case {row['case']} failed: {row['run_error']}")
    print(f"results: {result.out / 'results.csv'} and results.parquet; figures: {result.out / 'figures'}")
    return 0
