"""``vistrack demo``: the whole pipeline on the embedded synthetic downtown, no files needed."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from ..tracking.scenario import Scenario
from .output import add_report_arguments, output_folder, report_options
from .run import run_scenario
from .types import add_dynamics_argument

DEFAULT_OUT = Path("vistrack-out") / "demo"


def main(args: argparse.Namespace) -> int:
    scenario = Scenario.demo()
    if args.dynamics is not None:
        scenario.uav.dynamics = args.dynamics
    scenario.report = report_options(args, scenario.report)
    return run_scenario(scenario, output_folder(args.out), args.cache, args.quiet)


def register(subparsers: Any) -> None:
    parser = subparsers.add_parser(
        "demo", help="run the whole pipeline on the embedded synthetic downtown",
        description="The scenario of python/vistrack/scenarios/demo.yaml (embedded city, a POI "
                    "route on its streets): visibility volumes, orbit plan, closed-loop simulation, "
                    "baselines; writes the report folder (report.md, the interactive report.html, "
                    "trajectory.gif, figures, JSON, CSV) and prints where it is.")
    parser.add_argument("--out", default=str(DEFAULT_OUT), help=f"report folder (default: ./{DEFAULT_OUT})")
    parser.add_argument("--cache", default=None, help="visibility-volume cache folder (off by default)")
    add_dynamics_argument(parser)
    parser.add_argument("--quiet", action="store_true", help="no progress output")
    add_report_arguments(parser)
    parser.set_defaults(func=main)
