"""Loiter over Charlotte (docs/loiter.md, City mode): examples/loiter_charlotte_city.yaml with circles
about each AOI only (off_centre false) and with off-centre circles (the file's default). Prints each
AOI's MaxRadius, then per method the flight time, covered seconds with line of sight and ignoring
buildings, the worst share of loiter time an AOI's centre is in line of sight, and how closely the
sampled footprint (48 disk points) agrees with the paper's exact disk-in-ellipse fraction: the mean
over time steps and AOIs of |sampled - exact|. Prints markdown.

    VISTRACK_BUILD_DIR=build/dev python3 bench/loiter_city_example.py
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import vistrack as vt
from vistrack.loiter.city import plan_city
from vistrack.loiter.files import read_loiter_scenario

METHODS = ("fly_through", "tlpp", "ldlpp", "ldlpp_best")


def main() -> None:
    scenario = read_loiter_scenario(REPO / "examples" / "loiter_charlotte_city.yaml")
    scene = vt.VisibilityScene(scenario.city.load(scenario.origin))
    for off_centre in (False, True):
        result = plan_city(scenario, METHODS, scene, off_centre=off_centre)
        print(f"off_centre {str(off_centre).lower()}: flyable AOIs {result.flyable}; MaxRadius (m) "
              + ", ".join(f"{room.max_radius:.1f}" for room in result.rooms) + "\n")
        print("| method | flight (min) | covered s, line of sight | covered s, ignoring buildings | "
              "centres seen in loiter | sampled footprint vs exact (mean abs) |")
        print("|---|---|---|---|---|---|")
        for run in result.runs:
            cov = run.coverage
            error = np.mean(np.abs(cov.in_footprint - np.asarray(cov.paper.fraction)))
            print(f"| {run.method} | {run.plan.flight_time / 60:.2f} | {cov.time:.0f} | {cov.open_time:.0f} | "
                  f"{min(run.centre_line_of_sight):.0%} | {error:.2%} |")
        print()


if __name__ == "__main__":
    main()
