"""Issue 32's swirl threshold: WN as printed (the law (5) to each waypoint, switching at R_WP) on the
paper's route in the paper's units, in a constant wind of w/v from 16 directions; for each wind
speed the largest R_WP at which some flight swirls (loops around its active waypoint, counted in
either direction), in how many directions, and DWN's (planned in still air and, wind-aware, in the
air mass) and ArduPlane-style WN's (wn_passed_line) swirls in the same winds. Prints markdown.

    VISTRACK_BUILD_DIR=build/dev python3 bench/waypoint_swirl.py
"""

from __future__ import annotations

import math
import os
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import vistrack as vt
from vistrack import waypoint_nav as wn

RADII = (0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5)
SPEEDS = (0.0, 0.1, 0.2, 0.3, 0.5, 0.6)
DIRECTIONS = 16


def main() -> None:
    route = wn.read_route(REPO / "examples" / "waypoints_paper.csv")
    R, v = wn.DEFAULTS["turn_radius"], wn.DEFAULTS["speed"]
    print("| w / v | largest swirling R_WP (R) | directions swirling there (of 16) | most loops in one flight | "
          "DWN flights that swirl | wind-aware DWN flights that swirl | "
          "ArduPlane's WN flights that swirl (all radii) |")
    print("|---|---|---|---|---|---|---|")
    for ratio in SPEEDS:
        winds = [vt.flight.Wind(east=ratio * v * math.cos(a), north=ratio * v * math.sin(a))
                 for a in (2 * math.pi * k / DIRECTIONS for k in range(DIRECTIONS))]
        largest, count, most = None, 0, 0
        for fraction in RADII:
            swirls = [wn.fly(route, method="wn", waypoint_radius=fraction * R, wind=w).swirls for w in winds]
            most = max(most, max(swirls))
            if any(swirls):
                largest, count = fraction, sum(s > 0 for s in swirls)
        dwn = sum(wn.fly(route, method="dwn", wind=w).swirls > 0 for w in winds)
        aware = sum(wn.fly(route, method="dwn", wind=w, wind_aware=True).swirls > 0 for w in winds)
        line = sum(wn.fly(route, method="wn_passed_line", waypoint_radius=f * R, wind=w).swirls > 0
                   for f in RADII for w in winds)
        print(f"| {ratio:g} | {'none' if largest is None else f'{largest:g}'} | {count if largest else '-'} | "
              f"{most} | {dwn} of {len(winds)} | {aware} of {len(winds)} | {line} of {len(winds) * len(RADII)} |")


if __name__ == "__main__":
    main()
