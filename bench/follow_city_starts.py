"""How much a city run's numbers owe to where the UAV starts: the baseline, the city orbit and the horizon
follower on a Charlotte road run, all three from the same start, ``--distance`` m from the vehicle at
each of ``--bearings`` (degrees, counter-clockwise from the vehicle's heading), level and heading the
vehicle's way. Camera and line of sight together, and the horizon follower's margin over the baseline
(the issue's bar: +10 points). The runs are chaotic (small changes move them by points), so one start
per file says little about a follower; this measures the spread.

    VISTRACK_BUILD_DIR=build/dev python3 bench/follow_city_starts.py [FILE ...] [--bearings 0,90,180,270]

Default files: examples/follow_{straight,wind}_city.yaml (where the margin is thinnest); about 4
minutes per file and four starts. Charlotte geometry (c) OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import argparse
import math
import os
import sys
from pathlib import Path
from typing import Any

import numpy as np

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

from follow_city_options import changed, cities, city_follower
from vistrack import VisibilityScene
from vistrack.follow import FollowScenario

FILES = [REPO / "examples" / f"follow_{name}_city.yaml" for name in ("straight", "wind")]
BOTH = "camera_and_line_of_sight_fraction"


def from_start(scenario: FollowScenario, scene: VisibilityScene, env: Any, pose: tuple[float, float, float]
               ) -> dict[str, float]:
    """Camera and line of sight together for the baseline, the orbit and the horizon follower from ``pose``,
    each as ``FollowScenario.run`` flies it (the same wind knowledge, flight, camera and reports)."""
    base = scenario.baseline_run(scenario.city_vehicle(env), scenario.parameters, scene=scene, start=pose)
    out = {"baseline": base.metrics[BOTH]}
    for planner in ("orbit", "horizon"):
        changed(scenario, {"planner": planner})
        out[planner] = city_follower(scenario, scene, env, start=pose).metrics[BOTH]
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("files", nargs="*", type=Path, default=FILES)
    parser.add_argument("--bearings", default="0,90,180,270", help="degrees from the vehicle's heading")
    parser.add_argument("--distance", type=float, default=200.0, help="m from the vehicle (default 200)")
    args = parser.parse_args()
    bearings = [float(b) for b in args.bearings.split(",")]
    print("| file | start (bearing, distance) | baseline | city orbit | horizon follower | horizon over the baseline |")
    print("|---|---|---|---|---|---|")
    for file, scenario, env, scene in cities(args.files, 6):
        vehicle = scenario.city_vehicle(env)
        t0 = vehicle.start_time
        heading = float(vehicle.heading(t0))
        margins = []
        for bearing in bearings:
            angle = heading + math.radians(bearing)
            at = np.asarray(vehicle.position(t0)) + args.distance * np.array([math.cos(angle), math.sin(angle)])
            out = from_start(scenario, scene, env, (float(at[0]), float(at[1]), heading))
            margins.append(out["horizon"] - out["baseline"])
            print(f"| {file.name} | {bearing:g} deg, {args.distance:g} m | {100 * out['baseline']:.1f} | "
                  f"{100 * out['orbit']:.1f} | {100 * out['horizon']:.1f} | {100 * margins[-1]:+.1f} |", flush=True)
        print(f"| {file.name} | smallest margin | | | | {100 * min(margins):+.1f} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
