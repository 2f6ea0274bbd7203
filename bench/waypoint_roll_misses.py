"""DWN on a vehicle that banks (docs/waypoint-navigation.md): the paper's route at 75 m per unit
(examples/waypoints_metres.csv) flown by the default aircraft (roll model, 20 m/s, R 50 m, L1 legs
of 8 s), calm. Prints the roll model's lag (Options.roll_lag) and (v tau)^2 / (2 R); for the paper's
law to T_n (dwn_tracking "paper") and the planned path followed ("path"), each waypoint's miss and
on which side of its turn it lies, and how far the flown path passes each turning point; then a
sluggish roll's largest miss, calm and wind-aware in 0.3 v from 8 directions. Prints markdown.

    VISTRACK_BUILD_DIR=build/dev python3 bench/waypoint_roll_misses.py
"""

from __future__ import annotations

import math
import os
import sys
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import vistrack as vt
from vistrack import waypoint_nav as wn

R, V = 50.0, 20.0
ROUTE = wn.read_route(REPO / "examples" / "waypoints_metres.csv")
BASE = {"turn_radius": R, "speed": V, "dynamics": "roll", "guidance": "l1", "l1_period": 8.0}


def closest(track: np.ndarray, p: np.ndarray) -> np.ndarray:
    """The point of the flown polyline (x, y) closest to p."""
    a, b = track[:-1], track[1:]
    t = np.clip(((p - a) * (b - a)).sum(1) / np.maximum(((b - a) ** 2).sum(1), 1e-30), 0.0, 1.0)
    q = a + t[:, None] * (b - a)
    return q[np.argmin(np.hypot(*(q - p).T))]


def main() -> None:
    tau = wn.Options(**{k: BASE[k] for k in ("turn_radius", "speed", "dynamics")}).roll_lag()
    print(f"roll lag {tau:.3f} s; (v tau)^2 / (2 R) = {(V * 0.5) ** 2 / (2 * R) / R:.3f} R (tau 0.5 s)\n")
    print("| dwn_tracking | miss at waypoints 1-4 (R), side of the turn | farthest turning point from the path (R) |")
    print("|---|---|---|")
    for tracking in ("paper", "path"):
        f = wn.fly(ROUTE, dwn_tracking=tracking, **BASE)
        track = f.trajectory[:, 1:3]
        cells = []
        for i in range(1, len(ROUTE) - 1):
            u_in, u_out = (ROUTE[i] - ROUTE[i - 1]), (ROUTE[i + 1] - ROUTE[i])
            outward = u_in / np.linalg.norm(u_in) - u_out / np.linalg.norm(u_out)
            side = "outside" if (closest(track, ROUTE[i]) - ROUTE[i]) @ outward > 0 else "inside"
            cells.append(f"{f.miss_distances[i - 1] / R:.3f} {side}")
        tp = max(np.hypot(*(closest(track, p) - p)) for p in f.turning_points[:-1]) / R
        print(f"| {tracking} | " + ", ".join(cells) + f" | {tp:.4f} |")
    print("\n| roll (tau, rate) | calm: largest miss (R) | wind-aware 0.3 v, 8 directions (R) |\n|---|---|---|")
    for tau, rate in ((1.0, 70.0), (1.0, 20.0)):
        kw = {**BASE, "roll_time_constant": tau, "max_roll_rate_deg_s": rate}
        calm = wn.fly(ROUTE, **kw).miss_distances.max() / R
        windy = max(wn.fly(ROUTE, wind=vt.flight.Wind(east=0.3 * V * math.cos(a), north=0.3 * V * math.sin(a)),
                           wind_aware=True, **kw).miss_distances.max() for a in np.arange(8) * math.pi / 4) / R
        print(f"| {tau} s, {rate:g} deg/s | {calm:.3f} | {windy:.3f} |")


if __name__ == "__main__":
    main()
