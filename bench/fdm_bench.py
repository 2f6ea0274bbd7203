"""How fast the 6-DOF flight runs beside the kinematic one (issue 34: at least 100 x real time on one
core for Charlotte's paper_slow). One plan per scenario; each flight timed as the best of --repeat
runs, every flight with its line-of-sight evaluation: the kinematic closed loop (vector field (74),
steering law (86), RK45) on the roll and Dubins models, and the same guidance on the JSBSim aircraft
(trim included; JSBSim 120 Hz, autopilot 60 Hz, guidance 20 Hz). Prints a Markdown table: flown
seconds, wall seconds, times real time, POI visible, and for the 6-DOF flight its largest altitude
and airspeed errors.

    VISTRACK_BUILD_DIR=build/dev python3 bench/fdm_bench.py [--repeat 5] [--aircraft aerosonde] [--long]
    (needs ../shared/data; --long adds Charlotte's long path 3d.csv with Example 1's vehicle)
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).resolve().parent))
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import numpy as np

from timing import timed
from vistrack.scenario import Scenario
from vistrack.scenario_blocks import with_dynamics
from vistrack.tracking.fdm import fly_tracking
from vistrack.tracking.pipeline import closed_loop, compute, start_on_orbit

DATA = REPO.parent / "shared" / "data"


def scenarios(long: bool) -> list[tuple[str, Scenario]]:
    paper_slow = Scenario.load(REPO / "examples" / "charlotte_paper_slow.yaml")
    out = [("paper_slow", paper_slow)]
    if long:
        long_path = Scenario.load(REPO / "examples" / "charlotte_paper_slow.yaml")
        long_path.poi.path = DATA / "charlotte" / "paths" / "3d.csv"
        long_path.start = None
        out.append(("3d.csv, Example 1's vehicle", long_path))
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--aircraft", default="aerosonde")
    parser.add_argument("--long", action="store_true")
    args = parser.parse_args()
    if not (DATA / "charlotte").is_dir():
        sys.exit(f"needs the Charlotte data at {DATA / 'charlotte'}")
    print("| scenario | vehicle | flown (s) | wall (s) | x real time | POI visible | altitude err max (m) "
          "| airspeed err max (m/s) |")
    print("|---|---|---|---|---|---|---|---|")
    for label, scenario in scenarios(args.long):
        bench_scenario(label, scenario, args.repeat, args.aircraft)


def bench_scenario(label: str, scenario: Scenario, repeat: int, aircraft: str) -> None:
    """Plan once, then time the kinematic flights and the 6-DOF one (one table row each)."""
    result = compute(scenario, metric_spacings=())
    plan, scene = result.plan, result.planner.scene
    x0 = (np.asarray(scenario.start) if scenario.start is not None
          else start_on_orbit(plan, scenario.control.direction))
    for dynamics in ("roll", "dubins"):
        uav = with_dynamics(scenario.uav, dynamics)
        seconds, sim = timed(lambda uav=uav: closed_loop(plan, x0, uav, scenario.control, scenario.simulation,
                                                         scene), repeat)
        flown = sim.t[-1] - sim.t[0]
        print(f"| {label} | {dynamics} (kinematic) | {flown:.1f} | {seconds:.4f} | {flown / seconds:,.0f} | "
              f"{100 * sim.visibility_fraction:.1f} % | | |")
    seconds, six = timed(lambda: fly_tracking(plan, x0, scenario.uav, scenario.control, scene, aircraft), repeat)
    traj = six.trajectory
    flown = traj.t[-1] - traj.t[0]
    print(f"| {label} | 6-DOF {aircraft} (JSBSim) | {flown:.1f} | {seconds:.4f} | {flown / seconds:,.0f} | "
          f"{100 * six.visibility_fraction:.1f} % | {traj.altitude_error_max:.2f} | {traj.airspeed_error_max:.2f} |")

if __name__ == "__main__":
    main()
