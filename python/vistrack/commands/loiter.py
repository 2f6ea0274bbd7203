"""``vistrack loiter``: Fly-Through, TLPP and LDLPP loiter plans over areas of interest, scored by
camera coverage (Wilhelm, Clem, Eberhart 2017). One scenario file: plans.png, metrics.json,
path_<method>.csv, report.md, trajectory.gif (every method's aircraft with the camera footprint
the coverage scores, in the first --wind when given) and report.html (the same in 3D, and the
report). Several files: the same per scenario in sub-folders, plus table.md / table.json (ours
beside Table 1), fig13_scenarios.png and fig14_comparison.png. --random N: N seeded random
scenarios, the distributions per method. A city block (beyond the paper): loiter circles inside
each AOI's visibility polygon at uav.altitude, coverage with line of sight."""

from __future__ import annotations

import argparse
from functools import partial
from pathlib import Path

from .. import loiter
from .._core import VistrackError
from ..loiter import study as loiter_study
from ..progress import Progress
from ..report import loiter as report
from ..report import loiter_city as report_city
from .export import DEFAULT_EXPORT_ORIGIN, add_export_arguments, export_missions
from .lists import finite_numbers, positive_numbers
from .output import add_report_arguments, output_folder, report_options
from .types import UsageError, add_dynamics_argument, count, fdm_choice, length


def register(subparsers: argparse._SubParsersAction) -> None:
    p = subparsers.add_parser("loiter", help="loiter planners over areas of interest and their camera coverage",
                              description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scenarios", nargs="*", type=Path, help="scenario YAML files (examples/loiter_*.yaml)")
    p.add_argument("--random", type=count("--random", 1, 100000), metavar="N",
                   help="N random scenarios instead of files")
    p.add_argument("--seed", type=count("--seed", 0, 2**63 - 1), default=0,
                   help="seed of the random scenarios (default 0)")
    p.add_argument("--aois", type=count("--aois", 1, 10000), nargs="+", default=list(range(4, 10)),
                   help="AOI counts the random scenarios cycle through (default 4 5 6 7 8 9)")
    p.add_argument("--method", nargs="+", choices=loiter.PLAN_METHODS, default=list(loiter.ALL_METHODS),
                   help="methods (default the paper's three and, beyond the paper, tlpp_best and ldlpp_best; "
                        "best: the fastest of them all)")
    p.add_argument("--order", choices=loiter.ORDERS, default="given",
                   help="'best' also plans the best visiting order and reports the time saved")
    p.add_argument("--wind", action="append", default=[], metavar="E,N", type=finite_numbers("--wind", 2, "5,0", 1e4),
                   help="fly every plan in this unknown constant wind (m/s east, north); repeatable")
    p.add_argument("--wind-sweep", type=positive_numbers("--wind-sweep", "5,10"), default=[], metavar="SPEEDS",
                   help="also fly every plan in winds of these speeds (m/s) from 8 directions")
    p.add_argument("--altitude", type=length("--altitude"),
                   help="mission altitude for --export, m (default: the camera's, 61 m)")
    add_dynamics_argument(p, fdm=True)
    add_export_arguments(p)
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    add_report_arguments(p)
    p.add_argument("--out", type=Path, required=True, help="output folder (created)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    options = report_options(args)
    if args.export and (len(args.scenarios) > 1 or (args.random or 1) > 1):
        raise UsageError(f"--export = {args.export[0]}: exports one scenario's plans; give one scenario file "
                         "or --random 1")
    given = [(east, north) for east, north in args.wind]
    winds = given + loiter_study.wind_directions(args.wind_sweep)
    output_folder(args.out)  # a file there is an error now, not after the plans
    if args.random is not None:
        if args.scenarios:
            raise UsageError(f"--random = {args.random}: give scenario files or --random, not both")
        with Progress("random scenarios", not args.quiet, unit="scenario") as bar:
            records = loiter_study.random_study(args.random, args.seed, args.method, args.order, args.aois, bar)
        written = report.write_random(args.out, records)
        print((args.out / "random.md").read_text(encoding="utf-8"), end="")
    else:
        if not args.scenarios:
            raise UsageError("scenarios: give at least one scenario file, or --random N")
        scenarios = [loiter.load_scenario(path) for path in args.scenarios]
        dynamics, aircraft = fdm_choice(args)
        for scenario in scenarios:
            scenario.dynamics, scenario.aircraft = dynamics or scenario.dynamics, aircraft or scenario.aircraft
        rows, written, planned = [], [], 0
        for scenario in scenarios:  # (--export takes one: its plans are these runs')
            folder = args.out if len(scenarios) == 1 else args.out / scenario.name
            if scenario.city is not None:  # beyond every anchor: loiter circles in visibility polygons
                files, lines, plans = report_city.run_city(folder, scenario, args.method, args.order)
                print(*lines, sep="\n")
                written, planned = written + files, planned + bool(plans)
                continue
            refused: dict[str, str] = {}
            runs = loiter_study.evaluate(scenario, args.method, args.order, winds, refused)
            for method, reason in refused.items():
                print(f"{scenario.name} {method}: skipped, cannot fly this layout: {reason}")
            if not runs:
                continue
            planned += 1
            plans = {run.method: run.plan if run.best_plan is None else run.best_plan for run in runs}
            written += report.write_scenario(folder, scenario, runs, options, given[0] if given else None)
            rows += [run.record(scenario) for run in runs]
            for run in runs:
                line = (f"{scenario.name} {run.method}: {run.plan.flight_time / 60:.2f} min, transit "
                        f"{run.plan.transit_time:.0f} s, covered {run.coverage.time:.0f} s, "
                        f"area {run.coverage.area:.0f} m^2 s")
                if run.best_plan is not None:
                    line += f"; best order {run.best_plan.flight_time / 60:.2f} min"
                print(line)
        if not planned:
            raise VistrackError("--method: no method given can fly " + ("this layout" if len(scenarios) == 1 else
                                                                         "any of these layouts"))
        if winds and len(scenarios) == 1:
            print(report.wind_markdown(loiter_study.wind_summary(rows)) + report.fdm_markdown(rows), end="")
        if len(scenarios) > 1:
            written += report.write_table(args.out, scenarios, rows)
            print((args.out / "table.md").read_text(encoding="utf-8"), end="")
    if args.export:  # one scenario's plans as autopilot missions (vistrack.loiter.to_mission)
        if args.random is not None:  # the random study keeps no plans: plan its one scenario again
            scenario = next(loiter_study.random_scenarios(1, args.seed, args.aois))
            plans = {method: scenario.plan(method, args.order) for method in args.method}
        altitude = scenario.camera.altitude if args.altitude is None else args.altitude
        export_missions(args.export, {m: partial(p.to_mission, altitude=altitude) for m, p in plans.items()},
                        args.origin or scenario.origin, DEFAULT_EXPORT_ORIGIN)
    print(f"{len(written)} files in {args.out}")
    return 0
