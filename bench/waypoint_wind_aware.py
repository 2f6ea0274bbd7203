"""Issue 32's variants side by side, in the paper's units (R 0.7, v 0.8, dt 0.02, law (5) unless
said; L1 legs with the follow runs' L1 / R = 0.76): DWN (planned in still air, the paper's), DWN
re-planning every 0.5 s (section 2.1's option), wind-aware DWN (turning points planned in the air
mass), WN as printed, ArduPlane's WN (wn_passed_line), and wind-aware leg laws. Every waypoint
counts: the last one's miss is measured where the flight ends, on its finish line. Prints five
markdown tables:

1. the paper's route (examples/waypoints_paper.csv) without wind and in 0.1 v wind from the bottom
   (Figures 11 and 12): largest miss, overshoot, swirls;
2. the same route in wind of 0.1 v and 0.3 v from 16 directions: the largest miss;
3. 50 random routes (vt.waypoint_nav.random_route: 6 waypoints, legs 4-10 R, turns <= 90 deg; seed
   1, not the tests' 20261205), each in 0.1 v and 0.3 v wind from a random direction: largest
   and median miss over every waypoint of every flight, flights that swirl;
4. in metres (examples/waypoints_metres.csv, the default aircraft: 20 m/s, R 50 m, L1 period 8 s,
   law (5)'s gains scaled by 0.7 / R) on both vehicle models, DWN planned in still air and in the
   air mass, wind of 0, 0.1 v and 0.3 v from 8 directions: the largest miss;
5. DWN on the roll model in metres (the default aircraft), 50 random routes each in a random wind
   direction: the paper's law to the turning points against the planned path followed
   (dwn_tracking "path"), calm, 0.1 v, 0.1 v wind-aware and 0.3 v wind-aware: largest and median miss.

    VISTRACK_BUILD_DIR=build/dev python3 bench/waypoint_wind_aware.py
"""

from __future__ import annotations

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

import vistrack as vt
from vistrack import waypoint_nav as wn

R, V = wn.DEFAULTS["turn_radius"], wn.DEFAULTS["speed"]
# L1 legs with the follow runs' L1 / R (8 s at 20 m/s and R 50 m: L1 = 0.76 R), in the paper's units:
# the period scaled by the ratio of the turn times R / v (0.875 here, 2.5 s there).
L1_PERIOD = 8.0 * (R / V) / (vt.Uav().min_turn_radius / vt.Uav().speed)
# (label, fly()'s keyword arguments; waypoint_radius in units of R)
VARIANTS: tuple[tuple[str, dict[str, Any]], ...] = (
    ("DWN", {"method": "dwn"}),
    ("DWN re-planning 0.5 s", {"method": "dwn", "replan_interval": 0.5}),
    ("DWN wind-aware", {"method": "dwn", "wind_aware": True}),
    ("DWN wind-aware, L1 legs", {"method": "dwn", "wind_aware": True, "guidance": "l1", "l1_period": L1_PERIOD}),
    ("WN 0.1R", {"method": "wn", "waypoint_radius": 0.1}),
    ("WN 0.5R", {"method": "wn", "waypoint_radius": 0.5}),
    ("WN R", {"method": "wn", "waypoint_radius": 1.0}),
    ("WN 0.1R wind-aware", {"method": "wn", "waypoint_radius": 0.1, "wind_aware": True}),
    ("WN-line 0.1R", {"method": "wn_passed_line", "waypoint_radius": 0.1}),
    ("WN-line 0.1R wind-aware, L1 legs", {"method": "wn_passed_line", "waypoint_radius": 0.1, "wind_aware": True,
                                          "guidance": "l1", "l1_period": L1_PERIOD}),
)


def fly(route: np.ndarray, wind: vt.flight.Wind, options: dict[str, Any]) -> wn.NavigationFlight:
    kwargs = dict(options)
    if "waypoint_radius" in kwargs:
        kwargs["waypoint_radius"] *= R
    return wn.fly(route, wind=wind, **kwargs)


def wind_at(ratio: float, angle: float) -> vt.flight.Wind:
    return vt.flight.Wind(east=ratio * V * math.cos(angle), north=ratio * V * math.sin(angle))


def paper_route_table(route: np.ndarray) -> None:
    print("| flight | no wind: max miss (R) | no wind: overshoot (R) | 0.1 v from the bottom: max miss (R) | "
          "overshoot (R) | swirls |")
    print("|---|---|---|---|---|---|")
    for label, options in VARIANTS:
        calm, windy = fly(route, vt.flight.Wind(), options), fly(route, wind_at(0.1, 0.5 * math.pi), options)
        print(f"| {label} | {calm.miss_distances.max() / R:.3f} | {calm.overshoot / R:.2f} | "
              f"{windy.miss_distances.max() / R:.3f} | {windy.overshoot / R:.2f} | {windy.swirls} |")


def directions_table(route: np.ndarray) -> None:
    print("| flight | largest miss, 0.1 v (R) | largest miss, 0.3 v (R) | flights that swirl (of 32) |")
    print("|---|---|---|---|")
    for label, options in VARIANTS:
        cells, swirling = [], 0
        for ratio in (0.1, 0.3):
            flights = [fly(route, wind_at(ratio, 2 * math.pi * k / 16), options) for k in range(16)]
            cells.append(f"{max(f.miss_distances.max() for f in flights) / R:.3f}")
            swirling += sum(f.swirls > 0 for f in flights)
        print(f"| {label} | " + " | ".join(cells) + f" | {swirling} |")


def random_table(count: int = 50, seed: int = 1) -> None:
    rng = np.random.default_rng(seed)
    cases = {ratio: [] for ratio in (0.1, 0.3)}
    for _ in range(count):
        route = wn.random_route(rng, 6, R)
        for ratio in cases:
            cases[ratio].append((route, wind_at(ratio, rng.uniform(0.0, 2 * math.pi))))
    print(f"| flight | 0.1 v: largest miss (R) | 0.1 v: median (R) | 0.3 v: largest miss (R) | 0.3 v: median (R) | "
          f"flights that swirl (of {2 * count}) | all reached |")
    print("|---|---|---|---|---|---|---|")
    for label, options in VARIANTS:
        cells, swirling, reached = [], 0, 0
        for flights in cases.values():
            flown = [fly(route, wind, options) for route, wind in flights]
            misses = np.concatenate([f.miss_distances for f in flown]) / R
            cells += [f"{misses.max():.3f}", f"{np.median(misses):.3f}"]
            swirling += sum(f.swirls > 0 for f in flown)
            reached += sum(f.all_reached for f in flown)
        print(f"| {label} | " + " | ".join(cells) + f" | {swirling} | {reached} of {2 * count} |")


def metres_table() -> None:
    route = wn.read_route(REPO / "examples" / "waypoints_metres.csv")
    uav = vt.Uav()
    R_m, v_m = uav.min_turn_radius, uav.speed
    base = {"turn_radius": R_m, "speed": v_m, "gains": vt.flight.paper_gains(R_m), "l1_period": 8.0}
    print("| vehicle, legs | DWN, calm (R) | DWN, 0.1 v (R) | DWN wind-aware, 0.1 v (R) | DWN, 0.3 v (R) | "
          "DWN wind-aware, 0.3 v (R) |")
    print("|---|---|---|---|---|---|")
    rows = (("dubins", "law5", "paper"), ("dubins", "l1", "paper"), ("roll", "law5", "paper"), ("roll", "l1", "paper"),
            ("roll", "l1", "path"))
    for dynamics, guidance, tracking in rows:
        cells = []
        for ratio, aware in ((0.0, False), (0.1, False), (0.1, True), (0.3, False), (0.3, True)):
            worst = 0.0
            for k in range(8 if ratio else 1):
                a = 2 * math.pi * k / 8
                wind = vt.flight.Wind(east=ratio * v_m * math.cos(a), north=ratio * v_m * math.sin(a))
                f = wn.fly(route, wind=wind, wind_aware=aware, dynamics=dynamics, guidance=guidance,
                           dwn_tracking=tracking, **base)
                worst = max(worst, float(f.miss_distances.max()) / R_m)
            cells.append(f"{worst:.3f}")
        label = "path followed (the default on roll)" if tracking == "path" else f"{guidance} legs"
        print(f"| {dynamics}, {label} | " + " | ".join(cells) + " |")


def roll_random_table(count: int = 50, seed: int = 1) -> None:
    """DWN on the roll model in metres (the default aircraft) over random routes, each in a random wind
    direction: the paper's law to the turning points against the planned path followed (beyond the paper)."""
    uav = vt.Uav()
    R_m, v_m = uav.min_turn_radius, uav.speed
    rng = np.random.default_rng(seed)
    cases = [(wn.random_route(rng, 6, R_m), rng.uniform(0.0, 2 * math.pi)) for _ in range(count)]
    print(f"| DWN on the roll model ({count} routes) | calm: largest (median) miss (R) | 0.1 v | 0.1 v wind-aware | "
          "0.3 v wind-aware | flights that swirl | all reached |")
    print("|---|---|---|---|---|---|---|")
    for label, tracking in (("paper's law to T_n, L1 legs", "paper"), ("path followed (default)", "path")):
        cells, swirling, reached = [], 0, 0
        for ratio, aware in ((0.0, False), (0.1, False), (0.1, True), (0.3, True)):
            flown = [wn.fly(route, wind=vt.flight.Wind(east=ratio * v_m * math.cos(a), north=ratio * v_m * math.sin(a)),
                            wind_aware=aware, dynamics="roll", guidance="l1", l1_period=8.0, turn_radius=R_m,
                            speed=v_m, dwn_tracking=tracking) for route, a in cases]
            misses = np.concatenate([f.miss_distances for f in flown]) / R_m
            cells.append(f"{misses.max():.3f} ({np.median(misses):.3f})")
            swirling += sum(f.swirls > 0 for f in flown)
            reached += sum(f.all_reached for f in flown)
        print(f"| {label} | " + " | ".join(cells) + f" | {swirling} | {reached} of {4 * count} |")


def main() -> None:
    route = wn.read_route(REPO / "examples" / "waypoints_paper.csv")
    paper_route_table(route)
    print()
    directions_table(route)
    print()
    random_table()
    print()
    metres_table()
    print()
    roll_random_table()


if __name__ == "__main__":
    main()
