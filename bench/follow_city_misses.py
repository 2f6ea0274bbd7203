"""Where the city orbit (vistrack.follow.city_orbit) loses the vehicle on a Charlotte road run: the
flight split by whether a flyable circle fitted about the vehicle at the update (camera, line of sight
and both in each part), where the camera's misses fall (the UAV's bank, its distance from the orbit it
was asked to fly) and how often the orbit moved. docs/following.md's "What limits the camera" comes
from here:

    VISTRACK_BUILD_DIR=build/dev python3 bench/follow_city_misses.py [examples/follow_straight_city.yaml]
        [--set KEY=VALUE ...]

Charlotte geometry (c) OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

from follow_city_options import changed, city_follower, parse_sets
from vistrack import VisibilityScene
from vistrack.follow import FollowScenario
from vistrack.follow.city_orbit import CityOrbitResult

FULL_BANK_DEG = 40.0  # the roll model's bank limit at 21 m/s and r_min 50 m is 42 degrees


def report(result: CityOrbitResult) -> None:
    t = result.t
    weights = np.diff(t, append=t[-1])
    times = np.array([u.t for u in result.updates])
    index = np.clip(np.searchsorted(times, t, side="right") - 1, 0, len(times) - 1)  # the update in force
    fits = np.array([u.fits_about for u in result.updates])[index]
    both = result.in_view & result.line_of_sight
    print("| part of the flight | share of the time | camera | line of sight | both |\n|---|---|---|---|---|")
    for label, part in (("a flyable circle fits about the vehicle", fits), ("none fits", ~fits),
                        ("all", np.ones_like(fits))):
        w = weights[part]
        share = w.sum() / weights.sum()
        cells = [100 * float(w @ x[part]) / max(w.sum(), 1e-12) for x in (result.in_view, result.line_of_sight, both)]
        print(f"| {label} | {100 * share:.1f} % | " + " | ".join(f"{c:.1f} %" for c in cells) + " |")
    bank = np.degrees(np.abs(result.bank))
    misses = ~result.in_view
    full = bank > FULL_BANK_DEG
    shift = np.array([u.shift for u in result.updates])[index]
    radius = np.array([u.radius for u in result.updates])[index]
    off_orbit = np.abs(np.hypot(*(result.state[:, :2] - result.vehicle - shift).T) - radius)
    w_miss = weights[misses]
    print(f"\ncamera misses: {100 * float(w_miss @ full[misses]) / max(w_miss.sum(), 1e-12):.1f} % of them at "
          f"|bank| > {FULL_BANK_DEG:.0f} deg ({100 * float(weights @ full) / weights.sum():.1f} % of the flight at "
          f"it); the UAV a median {np.median(off_orbit[misses]):.0f} m off the orbit it was asked to fly "
          f"({np.median(off_orbit):.0f} m over the flight)")
    radii = np.array([u.radius for u in result.updates])
    shifts = np.array([u.shift for u in result.updates])
    print(f"updates: {len(radii)}; radius changed by more than 5 m at {int(np.sum(np.abs(np.diff(radii)) > 5))}, "
          f"the centre's offset jumped by more than 10 m at {int(np.sum(np.hypot(*np.diff(shifts, axis=0).T) > 10))}; "
          f"off-centre at {int(np.sum(np.any(shifts != 0, axis=1)))}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file", nargs="?", type=Path, default=REPO / "examples" / "follow_straight_city.yaml")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="a city_orbit option (YAML value); repeatable")
    args = parser.parse_args()
    scenario = FollowScenario.load(args.file)
    if not scenario.city_available():
        print(f"{args.file.name}: skipped, its city data is missing (../shared/data)")
        return 0
    changed(scenario, {"planner": "orbit", **parse_sets(args.set)})  # the city orbit's updates are analysed
    env = scenario.city.load(scenario.origin)  # type: ignore[union-attr]
    result = city_follower(scenario, VisibilityScene(env), env)
    print(f"{args.file.name}, city orbit ({'options ' + ' '.join(args.set) if args.set else 'the file options'})")
    report(result)
    return 0


if __name__ == "__main__":
    sys.exit(main())
