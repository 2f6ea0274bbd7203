"""DWN on the 6-DOF Aerosonde (JSBSim) beside the kinematic roll model, docs/fdm.md's waypoint navigation
numbers: the paper's route (examples/waypoints_paper.csv) scaled by the aircraft's tightest turn radius at
cruise over 0.7 (R = 63.7 m, v = 25 m/s), L1 legs (period 8 s), misses in units of R (waypoints 1-5; the
last where the flight crosses its finish line). Prints four markdown tables:

1. the misses: calm, 0.1 v wind from the south known to the guidance (wind_aware) and unknown, DWN
   following its planned paths (dwn_tracking "auto") and the paper's law to the turning points
   ("paper"), on the roll model (vt.waypoint_nav.fly) and the Aerosonde (fly_fdm); below it every
   flight's reached / swirls and the 6-DOF flights' largest altitude and airspeed errors;
2. the wind-aware path-following 6-DOF flight with the air moving towards 8 directions (every 45 degrees
   from east) in 0.1 v and 4 directions in 0.3 v: the largest miss per direction and the range;
3. that flight in 0.1 v from the south with the path anticipation 0.3-0.9 s (default: roll_lead);
4. the same planned with 1.1 R (bank to spare) at 0.3, 0.5 and 0.7 s, misses still in R;
5. the Aerosonde's answer to a step of the commanded turn rate from 0 to v / R (level, calm, 300 m): the
   bank's rise, the turn rate it settles to, and how long its course trails an instantaneous turn
   (beside the roll model's lag, roll_lead).

    VISTRACK_BUILD_DIR=build/dev python3 bench/fdm_waypoints.py [--skip-directions] [--skip-anticipation]
        [--only-step]
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
from pathlib import Path
from typing import Any, Optional

import numpy as np

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import vistrack as vt
from vistrack import fdm
from vistrack.waypoint_nav.fdm import fly_fdm, roll_lead

PLANE = fdm.aircraft("aerosonde")
V = PLANE.envelope.cruise_speed
R = PLANE.envelope.min_turn_radius(V)
ROUTE = np.loadtxt(REPO / "examples" / "waypoints_paper.csv", delimiter=",", skiprows=4) * R / 0.7
L1_PERIOD = 8.0
# (label, wind as a fraction of v towards the north, wind_aware)
WINDS = (("calm", 0.0, False), ("0.1 v from the south, wind-aware", 0.1, True),
         ("0.1 v from the south, unknown", 0.1, False))


def six_dof(wind: Optional[vt.flight.Wind], wind_aware: bool, tracking: str = "auto",
            anticipation: Optional[float] = None, turn_radius: float = R) -> Any:
    """DWN on the Aerosonde, the route planned with ``turn_radius``."""
    return fly_fdm(ROUTE, method="dwn", turn_radius=turn_radius, speed=V, guidance="l1", l1_period=L1_PERIOD,
                   wind=wind, wind_aware=wind_aware, dwn_tracking=tracking, path_anticipation=anticipation)


def kinematic(wind: Optional[vt.flight.Wind], wind_aware: bool, tracking: str = "auto") -> Any:
    """DWN on the kinematic roll model, the same route, leg law and wind."""
    return vt.waypoint_nav.fly(ROUTE, method="dwn", turn_radius=R, speed=V, dynamics="roll", guidance="l1",
                               l1_period=L1_PERIOD, wind=wind, wind_aware=wind_aware, dwn_tracking=tracking)


def largest(flight: Any) -> float:
    return float(np.max(flight.miss_distances)) / R


def misses_table() -> None:
    print("| wind | DWN | vehicle | misses (R) | max |")
    print("|---|---|---|---|---|")
    checks: list[str] = []
    alt, air = 0.0, 0.0
    flag = True  # the first wind-aware row names the CLI flag, as docs/fdm.md does
    for label, fraction, aware in WINDS:
        wind = vt.flight.Wind(north=fraction * V) if fraction else None
        for tracking, name in (("auto", "path followed"), ("paper", "paper's law")):
            for vehicle, flight in (("roll (kinematic)", kinematic(wind, aware, tracking)),
                                    ("6-DOF aerosonde", six_dof(wind, aware, tracking))):
                misses = " ".join(f"{m / R:.3f}" for m in flight.miss_distances)
                shown = label + (" (`--wind-aware`)" if aware and flag else "")
                flag = flag and not aware
                print(f"| {shown} | {name} | {vehicle} | {misses} | {largest(flight):.3f} |")
                if vehicle.startswith("6-DOF"):
                    reached, swirls = flight.metrics["all_reached"], flight.metrics["swirls"]
                    alt = max(alt, flight.trajectory.altitude_error_max)
                    air = max(air, flight.trajectory.airspeed_error_max)
                else:
                    reached, swirls = bool(np.all(flight.reached)), flight.swirls
                checks.append(f"{label} / {name} / {vehicle}: all reached {reached}, swirls {swirls}")
    print()
    print("\n".join(checks))
    print(f"6-DOF flights above: altitude error max {alt:.2f} m, airspeed error max {air:.3f} m/s")


def directions_table() -> None:
    print("| wind (v) | towards (deg from east) | largest miss (R) | all reached | swirls |")
    print("|---|---|---|---|---|")
    for fraction, count in ((0.1, 8), (0.3, 4)):
        worst = []
        for k in range(count):
            a = 2.0 * math.pi * k / count
            wind = vt.flight.Wind(east=fraction * V * math.cos(a), north=fraction * V * math.sin(a))
            flight = six_dof(wind, True)
            worst.append(largest(flight))
            print(f"| {fraction} | {math.degrees(a):.0f} | {worst[-1]:.3f} | {flight.metrics['all_reached']} | "
                  f"{flight.metrics['swirls']} |")
        print(f"| {fraction} ({count} directions) | range | {min(worst):.3f}-{max(worst):.3f} | | |")


def anticipation_tables() -> None:
    wind = vt.flight.Wind(north=0.1 * V)
    default = roll_lead(V, R)
    leads = (0.3, 0.5, None, 0.7, 0.9)
    heads = [f"{a} s" if a is not None else f"{default:.2f} s (default)" for a in leads]
    print("| anticipation | " + " | ".join(heads) + " |")
    print("|---" * (len(leads) + 1) + "|")
    print("| largest miss | " + " | ".join(f"{largest(six_dof(wind, True, anticipation=a)):.3f}" for a in leads)
          + " |")
    print()
    leads = (0.3, 0.5, 0.7)
    print("| planned with 1.1 R, anticipation | " + " | ".join(f"{a} s" for a in leads) + " |")
    print("|---" * (len(leads) + 1) + "|")
    print("| largest miss (R) | " + " | ".join(
        f"{largest(six_dof(wind, True, anticipation=a, turn_radius=1.1 * R)):.3f}" for a in leads) + " |")


class _RateStep:
    """Turn rate 0 until STEP_AT s, then v / R (the plan's turn)."""

    done = False

    def turn_rate(self, t: float, x: float, y: float, psi: float) -> float:
        return 0.0 if t < STEP_AT else V / R

    def advance(self, t: float, x: float, y: float, psi: float) -> None:
        pass


STEP_AT = 2.0


def bank_step_table() -> None:
    flight = fdm.fly(_RateStep(), (0.0, 0.0, 0.0), speed=V, altitude=300.0, duration=12.0, turn_radius=R)
    t = flight.t
    bank = np.degrees(flight.bank)
    course = np.unwrap(np.arctan2(np.gradient(flight.y, t), np.gradient(flight.x, t)))
    steady = (t > STEP_AT + 4.0) & (t < STEP_AT + 8.0)
    settled = float(np.mean(bank[steady]))
    rate, intercept = np.polyfit(t[steady], course[steady], 1)
    before = course[t <= STEP_AT][-1]
    # The course trails a turn begun at once at the step: (rate (t - t_step) - (course - course_0)) / rate.
    lag_own = (before - intercept) / rate - STEP_AT
    lag_plan = float(np.mean(t[steady] - STEP_AT - (course[steady] - before) / (V / R)))
    rise = t[np.argmax(bank >= 0.9 * settled)] - STEP_AT
    print("| commanded turn rate v / R | settled bank | bank at 90 % after | settled course rate | course lag at that "
          "rate | course lag against v / R | roll model's lag (roll_lead) |")
    print("|---|---|---|---|---|---|---|")
    print(f"| {V / R:.3f} rad/s | {settled:.1f} deg | {rise:.2f} s | {rate:.3f} rad/s | {lag_own:.2f} s | "
          f"{lag_plan:.2f} s | {roll_lead(V, R):.2f} s |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--skip-directions", action="store_true", help="no wind-direction table")
    parser.add_argument("--skip-anticipation", action="store_true", help="no anticipation tables")
    parser.add_argument("--only-step", action="store_true", help="only the turn-rate step table")
    args = parser.parse_args()
    start = time.perf_counter()
    if args.only_step:
        bank_step_table()
        return
    print(f"R = {R:.1f} m, v = {V:.0f} m/s, roll lead {roll_lead(V, R):.2f} s\n")
    misses_table()
    if not args.skip_directions:
        print()
        directions_table()
    if not args.skip_anticipation:
        print()
        anticipation_tables()
    print()
    bank_step_table()
    print(f"\n{time.perf_counter() - start:.1f} s")


if __name__ == "__main__":
    main()
