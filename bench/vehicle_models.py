"""Issue 28's tables: every planner's example flights with both vehicle models, the papers'
(Dubins: the turn rate at once; the follow legs by the law (5)) and the practitioner's (the roll
model; the follow legs by L1 line tracking), with their camera or visibility figures and how
smoothly they bank (roll reversals per second with a 1-degree deadband, largest roll rate).

    VISTRACK_BUILD_DIR=build/dev python3 bench/vehicle_models.py [--no-tracking] [--no-follow] [--no-waypoints]
        [--tracking demo campus paper_slow paper_small]

Prints markdown tables (docs/vehicle.md quotes them).
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import numpy as np

import vistrack as vt
from vistrack import follow
from vistrack.follow_scenario import FollowScenario

MODELS = (("dubins", "law5"), ("roll", "l1"), ("roll", "law5"), ("dubins", "l1"))
FOLLOW_CASES = (("parked vehicle (Fig. 8's loiter)", None, True), ("Fig. 5 straight", "follow_straight.yaml", True),
                ("Fig. 7 wind, compensated", "follow_wind.yaml", True), ("Fig. 8 stop", "follow_stop.yaml", True),
                ("Fig. 9 truck", "follow_truck.yaml", True))


def smooth(t: np.ndarray, bank: np.ndarray) -> str:
    s = vt.flight.flight_smoothness(t, bank)
    return f"{s.roll_reversals_per_s:.2f} | {s.max_roll_rate_deg_s:.0f}"


def follow_table() -> None:
    print("| run | vehicle, legs | camera sees the vehicle | roll reversals /s | max roll rate (deg/s) |")
    print("|---|---|---|---|---|")
    for name, file, compensation in FOLLOW_CASES:
        for dynamics, guidance in MODELS:
            if file is None:
                uav = vt.Uav(speed=21.0, min_turn_radius=50.0, altitude=200.0, dynamics=dynamics)
                parked = follow.GroundVehicle.from_legs([follow.VehicleLeg(0.0, 0.0, 300.0)], (0.0, 0.0))
                result = follow.simulate(parked, uav, flight=follow.FollowFlight(guidance=guidance))
            else:
                scenario = FollowScenario.load(REPO / "examples" / file)
                scenario.uav.dynamics = dynamics
                scenario.flight.guidance = guidance
                result = scenario.run(compensation, False, None).follow
            m = result.metrics
            print(f"| {name} | {dynamics}, {guidance} | {100 * m['camera_fraction']:.1f} % | "
                  f"{smooth(result.t, np.asarray(result.run.bank))} |")


def tracking_table(names: list[str]) -> None:
    from vistrack.tracking.pipeline import compute

    print("| scenario | vehicle | POI visible | roll reversals /s | max roll rate (deg/s) |")
    print("|---|---|---|---|---|")
    files = {"demo": None, "campus": "campus_flight_test.yaml", "paper_slow": "charlotte_paper_slow.yaml",
             "paper_small": "charlotte_paper_small.yaml"}
    for name in names:
        scenario = vt.Scenario.demo() if files[name] is None else vt.Scenario.load(REPO / "examples" / files[name])
        scenario.uav.dynamics = "dubins"
        result = compute(scenario)  # flies the plan on both models (the roll model as other_model)
        for dynamics, sim in (("dubins", result.simulation), ("roll", result.other_model)):
            print(f"| {name} | {dynamics} | {100 * sim.visibility_fraction:.1f} % | "
                  f"{smooth(np.asarray(sim.t), np.asarray(sim.bank))} |")


def l1_period_table() -> None:
    """Fig. 7's compensated wind run on the roll model with the planned curve flown by L1 at
    ArduPlane's period and at the follow default."""
    print("| Fig. 7, roll, l1 | L1 period (s) | camera sees the vehicle | mean tracking error (m) |")
    print("|---|---|---|---|")
    for period in (17.0, 8.0):
        scenario = FollowScenario.load(REPO / "examples" / "follow_wind.yaml")
        scenario.uav.dynamics = "roll"
        scenario.flight = follow.FollowFlight(guidance="l1", l1_period=period)
        m = scenario.run(True, False, None).follow.metrics
        print(f"| | {period:g} | {100 * m['camera_fraction']:.1f} % | {m['mean_tracking_error_m']:.1f} |")


def loiter_table() -> None:
    from vistrack import loiter

    print("| LDLPP over four AOIs, calm | vehicle | max cross-track (m) | covered (s) | planned (s) | "
          "roll reversals /s | max roll rate (deg/s) |")
    print("|---|---|---|---|---|---|---|")
    scenario = loiter.Scenario(aois=np.array([[200.0, 200.0], [500.0, 200.0], [500.0, 500.0], [200.0, 500.0]]))
    plan = scenario.plan("ldlpp")
    for dynamics, anticipation in (("dubins", None), ("roll", 0.0), ("roll", None)):
        scenario.dynamics = dynamics
        uav = scenario.uav()
        if anticipation is None:
            r = loiter.fly_and_score(scenario, plan, (0.0, 0.0), keep_trajectory=False)
            cross, covered, smooth = r["max_cross_track_m"], r["coverage_time_s"], r["smoothness"]
        else:  # the roll model without the follower's anticipation
            pieces = loiter.path_pieces(plan)
            follower = vt.flight.PathFollower(pieces, plan.speed, plan.turn_radius, anticipation=anticipation)
            flown = vt.flight.fly(follower, plan.at_time(0.0), plan.speed, plan.turn_radius, dt=0.05,
                                  max_time=3 * plan.flight_time + 600, uav=uav)
            samples, _ = loiter.flown_samples(flown, scenario.dt)
            covered = scenario.coverage(samples).time
            dense = plan.sample(1.0 / plan.speed)[:, :2]
            cross = float(np.max(np.min(np.hypot(np.asarray(flown.x)[:, None] - dense[None, :, 0],
                                                 np.asarray(flown.y)[:, None] - dense[None, :, 1]), axis=1)))
            smooth = flown.smoothness().as_dict()
        label = dynamics + ("" if anticipation is None else ", no anticipation")
        print(f"| | {label} | {cross:.1f} | {covered:.0f} | {scenario.coverage(plan).time:.0f} | "
              f"{smooth['roll_reversals_per_s']:.2f} | {smooth['max_roll_rate_deg_s']:.0f} |")


def waypoint_table() -> None:
    """The waypoint paper's route at 75 m per unit (examples/waypoints_metres.csv) flown by the
    default vehicle (20 m/s, R 50 m): each method with the law (5) and with L1 (8 s), on both models,
    in calm air and in a wind of 0.1 v from the south (the air moving north)."""
    from vistrack import waypoint_nav as wn
    from vistrack.io import read_route

    route = read_route(REPO / "examples" / "waypoints_metres.csv")
    uav = vt.Uav()
    R, v = uav.min_turn_radius, uav.speed
    print("| flight | wind (m/s) | vehicle, legs | max miss (R) | all reached | swirls | time (s) | "
          "roll reversals /s | max roll rate (deg/s) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for method, radius in (("dwn", None), ("wn", 0.1 * R), ("wn", R)):
        for north in (0.0, 0.1 * v):
            rows = [(d, g, "paper") for d, g in MODELS]
            if method == "dwn":  # beyond the paper: the planned path followed, the default on the roll model
                rows.insert(1, ("roll", "l1", "path"))
            for dynamics, guidance, tracking in rows:
                f = wn.fly(route, method=method, waypoint_radius=radius, turn_radius=R, speed=v, dynamics=dynamics,
                           guidance=guidance, gains=vt.flight.paper_gains(R), l1_period=8.0,
                           wind=vt.flight.Wind(north=north), dwn_tracking=tracking)
                # Every waypoint counts: the last one's miss is where the flight crosses its finish line.
                miss = float(np.max(f.miss_distances)) / R
                legs = "path" if tracking == "path" else guidance
                print(f"| {f.label} | {north:g} | {dynamics}, {legs} | {miss:.3f} | "
                      f"{'yes' if f.all_reached else 'no'} | {f.swirls} | {f.duration:.1f} | "
                      f"{smooth(np.asarray(f.flight.t), np.asarray(f.flight.bank))} |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-tracking", action="store_true")
    parser.add_argument("--no-follow", action="store_true")
    parser.add_argument("--no-waypoints", action="store_true")
    parser.add_argument("--tracking", nargs="+", default=["demo", "campus", "paper_slow", "paper_small"],
                        choices=["demo", "campus", "paper_slow", "paper_small"])
    args = parser.parse_args()
    if not args.no_follow:
        follow_table()
        print()
        l1_period_table()
        print()
    if not args.no_follow:
        loiter_table()
        print()
    if not args.no_waypoints:
        waypoint_table()
        print()
    if not args.no_tracking:
        tracking_table(args.tracking)


if __name__ == "__main__":
    main()
