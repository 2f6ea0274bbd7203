"""A receding-horizon follower over a city, without foresight: a prototype measured beside the city
orbit (docs/following.md). Each second the follower observes the vehicle (position, velocity), predicts
it at that velocity (``--predict road``: along the road it drives, at its current speed: the road known,
not the vehicle's later speeds; ``--predict true``: its true future, foresight) for the next
``--horizon`` seconds, and solves bench/follow_city_bound.py's dynamic
programme over that horizon (the roll model commanding one of five banks each second; scored when a ray
from the flight altitude reaches the predicted vehicle and the camera sees it at that bank), planning in
the air mass with the wind the follower knows. It commands the bank whose next state has the most
value, flies that second (the roll model in 0.02 s steps, the true wind) and is scored every 0.1 s
against the true vehicle with a ray and the library's camera. No VVs: about 3,700 rays per predicted
second; about 1 s of Python per update, so a run of 400 s takes minutes.

    VISTRACK_BUILD_DIR=build/dev python3 bench/follow_city_horizon.py [FILE ...] [--horizon 12]

Default files: examples/follow_{straight,wind,stop,truck}_city.yaml.
Charlotte geometry (c) OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import follow_city_bound as bound
from vistrack import VisibilityScene
from vistrack.follow import FollowScenario

SPACING, HALF = 20.0, 400.0  # m: the planner's relative-position grid (coarser than the bound's)


def follow(file: Path, horizon: int, prediction: str = "velocity") -> dict[str, float]:
    bound.SPACING, bound.HALF = SPACING, HALF  # interpolate() reads the grid from the module
    scenario = FollowScenario.load(file)
    env = scenario.city.load(scenario.origin)  # type: ignore[union-attr]
    scene = VisibilityScene(env)
    vehicle = scenario.city_vehicle(env)
    uav, camera = scenario.uav, scenario.camera
    wind = np.array([scenario.wind.east, scenario.wind.north])
    p = scenario.parameters
    known = scenario.wind_estimate or ((scenario.wind.east, scenario.wind.north) if p.wind_compensation else (0, 0))
    air = np.asarray(known, dtype=float)
    pro = bound.Programme.of(scenario, scene)

    track = np.asarray(vehicle.positions)  # the road the vehicle drives, for --predict road
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(track, axis=0).T))])
    track_times = np.asarray(vehicle.times)

    def predicted(t: float, at: np.ndarray, velocity: np.ndarray) -> np.ndarray:
        """The vehicle at 0..horizon s ahead: at its velocity, or along its road at its speed."""
        ahead = np.arange(horizon + 1, dtype=float)
        if prediction == "true":
            return np.asarray(vehicle.sample(t + ahead))
        if prediction == "velocity":
            return at + np.outer(ahead, velocity)
        s = float(np.interp(t, track_times, arc)) + float(np.hypot(*velocity)) * ahead
        return np.column_stack([np.interp(s, arc, track[:, 0]), np.interp(s, arc, track[:, 1])])

    def plan(future: np.ndarray) -> np.ndarray:
        """The value one second ahead (bank, heading, position relative to the predicted vehicle)."""
        later = None
        cached: dict[tuple[float, float], list] = {}  # transitions by drift: one set per update at a velocity
        for j in range(horizon, 0, -1):
            q = future[j]
            now = pro.scored(scene, q)
            if later is not None:
                drift = air - (future[j + 1] - q)
                key = (round(float(drift[0]), 9), round(float(drift[1]), 9))
                if key not in cached:
                    cached[key] = bound.transitions(pro.moves, pro.rel, pro.headings, drift, pro.n_side)
                bound.add_best_next(now, later, cached[key])
            later = now
        assert later is not None
        return later

    t0, t_end = vehicle.start_time, vehicle.end_time
    heading = float(vehicle.heading(t0))
    position = np.asarray(vehicle.position(t0)) + 200.0 * np.array([math.cos(heading), math.sin(heading)])
    bank = 0.0
    seen = samples = lost = 0
    started = time.perf_counter()
    k = 0
    while t0 + k <= t_end - 1e-9:
        t = t0 + k
        future = predicted(t, np.asarray(vehicle.position(t)), np.asarray(vehicle.velocity(t)))
        value = plan(future)
        best: tuple[float, np.ndarray, float, float, list] | None = None
        for command in pro.banks:
            q, h, b, trace = bound.fly_second(pro.model, uav.speed, wind, position, heading, bank, command)
            score = bound.state_value(value, pro.banks, b, h, q - future[1], pro.n_side)
            if score <= 0.0:  # nothing seen over the horizon from any next state (off the grid): head for it
                away = future[1] - q
                score = -abs(math.remainder(math.atan2(away[1], away[0]) - h, 2.0 * math.pi))
            if best is None or score > best[0]:
                best = (score, q, h, b, trace)
        assert best is not None
        lost += best[0] <= 0.0
        _, position, heading, bank, trace = best
        seen += bound.score_trace(scene, camera, uav, vehicle, t, trace, pro.altitude)
        samples += len(trace)
        k += 1
    return {"both": seen / max(samples, 1), "seconds": time.perf_counter() - started, "updates": k, "lost": lost}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("files", nargs="*", type=Path, default=bound.FILES)
    parser.add_argument("--horizon", type=int, default=12, help="seconds of prediction (default 12)")
    parser.add_argument("--predict", choices=("velocity", "road", "true"), default="velocity",
                        help="the vehicle ahead: at its velocity, along its road at its speed, or its true "
                             "future (foresight)")
    args = parser.parse_args()
    how = {"velocity": "at its velocity", "road": "along its road", "true": "its true future"}[args.predict]
    print(f"| file | receding horizon ({args.horizon} s, the vehicle {how}), camera and line of sight | updates | "
          "updates with nothing in sight over the horizon (heading for the vehicle) |\n|---|---|---|---|")
    for file in args.files:
        if not FollowScenario.load(file).city_available():
            print(f"| {file.name} | skipped: its city data is missing | | |")
            continue
        out = follow(file, args.horizon, args.predict)
        print(f"| {file.name} | {100 * out['both']:.1f} % | {out['updates']} | {out['lost']} |"
              f"  ({out['seconds']:.0f} s)", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
