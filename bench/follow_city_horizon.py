"""The horizon city follower (vistrack.follow.city_horizon, the default city follower) on the Charlotte
road runs, beside the baseline and the city orbit (the issue's part 6) on the same road: camera, line of
sight, both, the margin over the baseline against the issue's bar (+10 points), the share of updates at
which a flyable visible circle existed, the VVs cast, the updates with nothing in sight over the horizon,
and the follower's time per update (its dynamic programme, the VV, the flight and the scoring).

    VISTRACK_BUILD_DIR=build/dev python3 bench/follow_city_horizon.py [FILE ...] [--set horizon=12]

``--set KEY=VALUE``: a city_orbit option for the horizon follower (YAML value; repeatable). Each file is
flown as ``vistrack follow`` flies it (FollowScenario.run: the planner, the baseline and the city
follower), then once more with ``planner: orbit``. Default files: examples/follow_{straight,wind,stop,
truck}_city.yaml; about a minute per file (the truck, 1055 s, two to three).
Charlotte geometry (c) OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

from follow_city_options import FILES, changed, city_follower, parse_sets
from vistrack import VisibilityScene
from vistrack.follow import FollowScenario

BOTH = "camera_and_line_of_sight_fraction"


def measure(file: Path, changes: dict[str, Any]) -> dict[str, Any]:
    scenario = FollowScenario.load(file)
    changed(scenario, {"planner": "horizon", **changes})
    stages: list[tuple[str, float]] = []
    study = scenario.run(stage=lambda name: stages.append((name, time.perf_counter())))
    seconds = time.perf_counter() - stages[-1][1]  # the last stage is the city follower's
    city = study.metrics()["city"]
    assert study.environment is not None
    changed(scenario, {"planner": "orbit"})
    orbit = city_follower(scenario, VisibilityScene(study.environment), study.environment).metrics
    return {"horizon": city["orbit"], "baseline": city.get("baseline", {}), "orbit": orbit,
            "ms_per_update": 1000.0 * seconds / max(city["orbit"]["updates"], 1)}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("files", nargs="*", type=Path, default=FILES)
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="a city_orbit option for the horizon follower (YAML value); repeatable")
    args = parser.parse_args()
    changes = parse_sets(args.set)
    print(f"horizon follower ({changes or 'the files options'}); camera and line of sight together unless named")
    print("| file | baseline | city orbit | horizon: camera / line of sight / both | over the baseline (bar +10) | "
          "flyable visible circle | VVs / updates | nothing in sight | ms per update |")
    print("|---|---|---|---|---|---|---|---|---|")
    for file in args.files:
        if not FollowScenario.load(file).city_available():
            print(f"| {file.name} | skipped: its city data is missing | | | | | | | |")
            continue
        out = measure(file, changes)
        h, base = out["horizon"], out["baseline"]
        shown = " / ".join(f"{100 * h[k]:.1f}" for k in ("camera_fraction", "line_of_sight_fraction", BOTH))
        margin = f"{100 * (h[BOTH] - base[BOTH]):+.1f}" if BOTH in base else "-"
        baseline = f"{100 * base[BOTH]:.1f}" if BOTH in base else "-"
        print(f"| {file.name} | {baseline} | {100 * out['orbit'][BOTH]:.1f} | {shown} | {margin} | "
              f"{100 * h['flyable_circle_in_polygon_fraction']:.1f} % | {h['volumes']} / {h['updates']} | "
              f"{h['updates_heading_for_vehicle']} | {out['ms_per_update']:.0f} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
