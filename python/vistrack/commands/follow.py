"""``vistrack follow SCENARIO.yaml``: a UAV following a ground vehicle.

Flies the paper's planner (sinusoid below the speed-ratio threshold, loiter above it with a
hysteresis band, an offset point, waypoints at 1 Hz) with the flight layer, beside the tracking
pipeline's vector-field baseline, and, when the scenario has a city section, both again on a city
road with line of sight through the buildings. Writes figures, trajectory.csv, updates.csv (the
planner's effective sigma, T, D, A per update), metrics.json,
report.md, trajectory.gif (plan view: vehicle, UAV, camera footprint, wind, line of sight on the
city road; trajectory_open.gif then adds the open-ground run) and report.html (the same in 3D
with a time slider, and the report) to --out. Scenario keys: see vistrack/follow/scenario.py and
examples/follow_*.yaml.
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any, Optional

from ..follow.keys import STRATEGIES, threshold_value
from ..follow.scenario import FollowScenario
from ..progress import Progress
from ..report.follow import write_follow
from ..report.follow_city import city_orbit_line
from .export import DEFAULT_EXPORT_ORIGIN, add_export_arguments, export_mission
from .output import add_report_arguments, output_folder, report_options
from .types import add_dynamics_argument, fdm_choice, number


def register(subparsers: argparse._SubParsersAction) -> None:
    parser = subparsers.add_parser(
        "follow", help="follow a ground vehicle: sinusoid and loiter modes (the ground-vehicle paper)",
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scenario", type=Path, help="follow scenario (YAML)")
    parser.add_argument("--out", type=Path, default=Path("follow_out"), help="output folder (default follow_out)")
    parser.add_argument("--no-compensation", dest="compensation", action="store_false", default=None,
                        help="plan without the wind estimate (the paper's Fig. 6)")
    parser.add_argument("--no-city", dest="city", action="store_false", help="skip the city runs")
    parser.add_argument("--threshold", metavar="H", help="follow.threshold over the file's: auto (picked from the "
                        "camera) or the speed ratio h (3: the paper's method)")
    parser.add_argument("--strategy", choices=STRATEGIES, help="follow.strategy over the file's: paper (sinusoid "
                        "and loiter), standoff (vector field (74) about the offset point) or auto (per update)")
    add_dynamics_argument(parser, fdm=True)
    parser.add_argument("--export-tolerance", type=number("--export-tolerance", 0.0, 1e7), default=1.0, metavar="M",
                        help="--export keeps the 1 Hz waypoints Douglas-Peucker needs at this tolerance "
                             "(default 1 m; 0: every waypoint)")
    add_export_arguments(parser)
    parser.add_argument("--quiet", action="store_true", help="no progress lines")
    add_report_arguments(parser)
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    options = report_options(args)
    output_folder(args.out)  # a file there is an error now, not after the runs
    scenario = FollowScenario.load(args.scenario)
    dynamics, aircraft = fdm_choice(args)
    if dynamics is not None:
        scenario.uav.dynamics = dynamics
    scenario.aircraft = aircraft or scenario.aircraft
    if args.threshold is not None:
        scenario.parameters.threshold = threshold_value("--threshold", args.threshold)
    if args.strategy is not None:
        scenario.parameters.strategy = args.strategy
    city = args.city and scenario.city_available()
    if args.city and scenario.city is not None and not city:
        print(f"city data not found ({scenario.city.describe()}): skipping the city runs")
    bars: list[Progress] = []

    def stage(name: str) -> Progress:
        """A line per run, and a bar that the runs reporting their updates (the city follower's) draw."""
        print(f"{name} ...", flush=True)
        bars.append(Progress(name, unit="update"))
        return bars[-1]

    study = scenario.run(args.compensation, city, None if args.quiet else stage)
    for bar in bars:
        bar.close()
    record = write_follow(study, args.out, scenario.description, options)
    modes = ", ".join(f"{k} {v:.0f} s" for k, v in record["time_in_mode_s"].items() if v > 0)
    print(f"tracking error {record['mean_tracking_error_m']:.2f} m mean, {record['max_tracking_error_m']:.1f} m max; "
          f"lag {record['along_track_lag_m']:.1f} m; {modes}; {_count(record['mode_switches'], 'switch')}; "
          f"camera {100 * record['camera_fraction']:.1f} %"
          + _baseline_summary(record.get("baseline")) + f" -> {args.out}")
    for warning in record.get("warnings", []):
        print(f"warning: {warning}")
    if "fdm" in record:
        six = record["fdm"]
        print(f"6-DOF on {six['aircraft']} (JSBSim): camera {100 * six['camera_fraction']:.1f} %, altitude within "
              f"{six['altitude_error_max_m']:.2f} m, airspeed within {six['airspeed_error_max_m_s']:.2f} m/s")
    if "note" in record:
        print(f"note: {record['note']}")
    if (line := city_orbit_line(record.get("city"))) is not None:
        print(line)
    uav = scenario.uav
    export_mission(args.export, lambda ref: study.follow.to_mission(
        ref, uav.altitude, speed=uav.speed, tolerance=args.export_tolerance), args.origin or scenario.origin, None,
        DEFAULT_EXPORT_ORIGIN)
    return 0


def _baseline_summary(block: Optional[dict[str, Any]]) -> str:
    if block is None:
        return ""
    if not block["feasible"]:
        return f" (baseline not flown: {block['reason']})"
    return f" (baseline {100 * block['camera_fraction']:.1f} %)"


def _count(n: int, noun: str) -> str:
    """"1 switch", "2 switches"."""
    return f"{n} {noun}" if n == 1 else f"{n} {noun}{'es' if noun.endswith(('s', 'sh', 'ch', 'x')) else 's'}"
