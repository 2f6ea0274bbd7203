"""Issue 28's check on scenarios the smoothing was not tuned on: the tracking closed loop on three
held-out runs (the demo city with another route, the demo city with a faster POI and a wider
turn, Charlotte's long path 3d.csv with Example 1's vehicle), each flown on both vehicle models:
POI visible, roll reversals per second (1-degree deadband) and the largest roll rate.

    VISTRACK_BUILD_DIR=build/dev python3 bench/tracking_held_out.py   (Charlotte needs ../shared/data)
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import numpy as np

import vistrack as vt
from vistrack.scenario import Scenario
from vistrack.tracking.pipeline import compute

DATA = REPO.parent / "shared" / "data"


def cases() -> list[tuple[str, Scenario]]:
    reversed_route = Scenario.demo()
    reversed_route.poi.route = [[290, 205], [-95, 205], [-95, -100], [-290, -100], [-290, -300]]
    faster = Scenario.demo()
    faster.poi.route = [[-290, 0], [290, 0], [290, 205]]
    faster.poi.speed, faster.uav.min_turn_radius = 8.0, 30.0
    out = [("demo city, reversed route", reversed_route), ("demo city, east-west, r_min 30 m, POI 8 m/s", faster)]
    if (DATA / "charlotte").is_dir():
        long_path = Scenario.load(REPO / "examples" / "charlotte_paper_slow.yaml")
        long_path.poi.path = DATA / "charlotte" / "paths" / "3d.csv"
        out.append(("Charlotte 3d.csv, Example 1's vehicle", long_path))
    else:
        print(f"skipping Charlotte: {DATA / 'charlotte'} is absent")
    for _, scenario in out:
        scenario.start = None  # on the orbit
        scenario.uav.dynamics = "dubins"  # flown on both models: the roll model as other_model
    return out


def main() -> None:
    print("| scenario | vehicle | POI visible | roll reversals /s | max roll rate (deg/s) |")
    print("|---|---|---|---|---|")
    for name, scenario in cases():
        result = compute(scenario)
        for model, sim in (("dubins", result.simulation), ("roll", result.other_model)):
            s = vt.flight.flight_smoothness(np.asarray(sim.t), np.asarray(sim.bank))
            print(f"| {name} | {model} | {100 * sim.visibility_fraction:.1f} % | {s.roll_reversals_per_s:.2f} | "
                  f"{s.max_roll_rate_deg_s:.0f} |")


if __name__ == "__main__":
    main()
