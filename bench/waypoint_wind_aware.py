"""Issue 32's wind-aware leg laws: the largest miss before the last waypoint over 16 wind directions
on the paper's route (paper units), each method with and without ``wind_aware`` (the law (5) legs;
ArduPlane's switching with L1 legs, period 8 s). Prints markdown; docs/waypoint-navigation.md quotes it.

    VISTRACK_BUILD_DIR=build/dev python3 bench/waypoint_wind_aware.py
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

import vistrack as vt  # noqa: E402
from vistrack import waypoint_nav as wn  # noqa: E402

CASES = (("dwn", "law5", False), ("dwn", "law5", True), ("dwn", "l1", True), ("wn", "law5", False),
         ("wn", "law5", True), ("wn_passed_line", "l1", True))


def main() -> None:
    route = wn.read_route(REPO / "examples" / "waypoints_paper.csv")
    R, v = wn.DEFAULTS["turn_radius"], wn.DEFAULTS["speed"]
    print("| method | legs | wind-aware | largest miss, 0.1 v (R) | largest miss, 0.3 v (R) |")
    print("|---|---|---|---|---|")
    for method, guidance, aware in CASES:
        cells = []
        for ratio in (0.1, 0.3):
            worst = 0.0
            for k in range(16):
                a = 2 * math.pi * k / 16
                wind = vt.flight.Wind(east=ratio * v * math.cos(a), north=ratio * v * math.sin(a))
                f = wn.fly(route, method=method, waypoint_radius=None if method == "dwn" else 0.1 * R, wind=wind,
                           guidance=guidance, wind_aware=aware, l1_period=8.0)
                worst = max(worst, float(f.miss_distances[:-1].max()) / R)
            cells.append(f"{worst:.3f}")
        print(f"| {method} | {guidance} | {'yes' if aware else 'no'} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
