"""``vistrack run SCENARIO.yaml``: the whole pipeline from a scenario file to a report folder."""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from ..tracking.scenario import Scenario, default_scenario_text
from .export import add_export_arguments, check_exports, export_plan
from .output import add_report_arguments, output_folder, report_options
from .types import UsageError, add_dynamics_argument, count, fdm_choice


def register(subparsers: Any) -> None:
    parser = subparsers.add_parser(
        "run", help="run a scenario file end to end and write a report folder",
        description="Environment, POI path, adaptive visibility volumes, orbit plan (Algorithm 1), "
                    "closed-loop simulation with line-of-sight evaluation and constant-radius "
                    "baselines; writes report.md with figures, the interactive report.html (3D), "
                    "trajectory.gif, metrics.json, plan.json, trajectory.csv and VV meshes into --out.")
    parser.add_argument("scenario", nargs="?", help="scenario YAML file (see --print-defaults)")
    parser.add_argument("--out", default=None, help="report folder (default: ./vistrack-out/<scenario name>)")
    parser.add_argument("--cache", default=None,
                        help="folder caching visibility volumes between runs (about 4 MB per 1-degree VV); "
                             "a second run with the same inputs reads them instead of ray casting")
    parser.add_argument("--max-volumes", type=count("--max-volumes", 1, 10**12), default=None,
                        help="allow plans that may need up to this many VVs (default: the scenario's "
                             "planning.max_volumes, else 20000; ~4.7 MB each at 1 degree)")
    add_export_arguments(parser)
    add_dynamics_argument(parser, fdm=True)
    parser.add_argument("--quiet", action="store_true", help="no progress output")
    parser.add_argument("--print-defaults", action="store_true",
                        help="print a complete scenario with every default and exit")
    add_report_arguments(parser)
    parser.set_defaults(func=main)


def run_scenario(scenario: Scenario, out: Path, cache: str | None, quiet: bool, export: Sequence[str] = ()) -> int:
    """Shared by ``run`` and ``demo``: run, then print the headline numbers and the report path
    (and write the --export files)."""
    from ..report import percent
    from ..report.run import run

    result = run(scenario, out, quiet=quiet, cache_dir=cache)
    m = result.metrics
    plan, sim = m["plan"], m["simulation"]
    status = "feasible" if plan["feasible"] else "INFEASIBLE"
    print(f"{scenario.name}: {plan['samples']} orbit samples ({status}), R {plan['initial_radius_m']:.1f} -> "
          f"{plan['final_radius_m']:.1f} m; POI visible {percent(sim['visibility_fraction'])} of the time "
          f"({m['uav']['dynamics']} model)")
    other = m.get("other_model")
    if other:
        print(f"  the same plan on the {other['dynamics']} model: visible {percent(other['visibility_fraction'])}")
    six = m.get("fdm")
    if six:
        print(f"  6-DOF on {six['aircraft']} (JSBSim): visible {percent(six['simulation']['visibility_fraction'])}, "
              f"altitude within {six['altitude_error_max_m']:.2f} m, airspeed within "
              f"{six['airspeed_error_max_m_s']:.2f} m/s")
    for radius, baseline in m["baselines"].items():
        print(f"  constant R = {radius} m: visible {percent(baseline['visibility_fraction'])}")
    cache = m.get("volume_cache")
    if cache:
        print(f"visibility-volume cache {cache['folder']}: {cache['hits']} read, {cache['misses']} computed")
    if result.env.origin is not None and scenario.origin is None:
        lat, lon, _ = result.env.origin
        print(f"map in longitude/latitude, projected about its centre: origin = [{lat:.7f}, {lon:.7f}]")
    print(f"report: {out / 'report.md'}")
    for name, made in m.get("report_files", {}).items():
        print(f"  {name}: {made['bytes'] / 1e6:.1f} MB")
    export_plan(export, result.plan, scenario.origin, result.env, direction=scenario.control.direction,
                simulation=result.simulation)
    return 0


def main(args: argparse.Namespace) -> int:
    if args.print_defaults:
        print(default_scenario_text(), end="")
        return 0
    if not args.scenario:
        raise UsageError("a scenario file is required (or --print-defaults)")
    scenario = Scenario.load(args.scenario)
    if args.origin is not None:
        scenario.origin = args.origin
    if args.max_volumes is not None:
        scenario.planning.max_volumes = args.max_volumes
    dynamics, aircraft = fdm_choice(args)
    if dynamics is not None:
        scenario.uav.dynamics = dynamics
    if aircraft is not None:
        scenario.aircraft = aircraft
    scenario.report = report_options(args, scenario.report)
    check_exports(args.export, scenario.origin, scenario.environment.path)
    out = output_folder(args.out if args.out else Path("vistrack-out") / scenario.name)
    return run_scenario(scenario, out, args.cache, args.quiet, args.export)
