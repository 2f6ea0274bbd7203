"""A city follower on the Charlotte road runs with other options: each file's city follower (``--planner``:
the city orbit, vistrack.follow.city_orbit, by default; or the horizon follower, follow.city_horizon) flown
with its scenario's ``city_orbit`` block overridden by ``--set KEY=VALUE`` (any CityOrbitOptions field, YAML
values: ``--set camera_reach=true --set lookahead=[3,6,12]``), and its camera, line of sight and both,
beside the same run with the file's options. The numbers the follow docs quote for options not on by
default come from here:

    VISTRACK_BUILD_DIR=build/dev python3 bench/follow_city_options.py --set camera_reach=true
    VISTRACK_BUILD_DIR=build/dev python3 bench/follow_city_options.py --set camera_reach=true \\
        examples/follow_helsinki_osm.yaml

Default files: examples/follow_{straight,wind,stop,truck}_city.yaml (the shared Charlotte data).
Charlotte geometry (c) OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path
from typing import Any, Iterator

import yaml

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

from vistrack import VisibilityScene
from vistrack.follow import FollowScenario
from vistrack.follow.city_horizon import city_horizon_follow
from vistrack.follow.city_orbit import CityOrbitResult, city_orbit_follow
from vistrack.follow.keys import city_orbit_block

FILES = [REPO / "examples" / f"follow_{name}_city.yaml" for name in ("straight", "wind", "stop", "truck")]
KEYS = ("camera_fraction", "line_of_sight_fraction", "camera_and_line_of_sight_fraction")


def city_follower(scenario: FollowScenario, scene: VisibilityScene, env: Any, **extra: Any) -> CityOrbitResult:
    """The city follower of the scenario's ``city_orbit.planner`` as ``FollowScenario.run`` flies it (the
    same wind knowledge, flight and camera); ``extra``: more of the follower's arguments (``start``)."""
    p = scenario.parameters
    known = scenario.known_wind(p)
    follow = city_horizon_follow if scenario.city_orbit.planner == "horizon" else city_orbit_follow
    return follow(scenario.city_vehicle(env), scenario.uav, scene, parameters=p, wind_estimate=known,
                  wind=scenario.wind, flight=scenario.flight, camera=scenario.camera, options=scenario.city_orbit,
                  **extra)


def fly(scenario: FollowScenario, scene: VisibilityScene, env: Any) -> dict[str, Any]:
    return city_follower(scenario, scene, env).metrics


def cities(files: list[Path], columns: int) -> Iterator[tuple[Path, FollowScenario, Any, VisibilityScene]]:
    """Each file whose city data is present: (file, scenario, its city, the city's scene); for the others
    a table row of ``columns`` cells saying it was skipped."""
    for file in files:
        scenario = FollowScenario.load(file)
        if not scenario.city_available():
            print(f"| {file.name} | skipped: its city data is missing |" + " |" * (columns - 2))
            continue
        env = scenario.city.load(scenario.origin)  # type: ignore[union-attr]
        yield file, scenario, env, VisibilityScene(env)


def changed(scenario: FollowScenario, changes: dict[str, Any]) -> None:
    """The scenario's city_orbit options with ``changes`` (by name, YAML values) applied and validated."""
    scenario.city_orbit = city_orbit_block({"city_orbit": {**_fields(scenario), **changes}})


def parse_sets(items: list[str]) -> dict[str, Any]:
    """``--set KEY=VALUE`` items as {key: YAML value}."""
    changes: dict[str, Any] = {}
    for item in items:
        key, _, value = item.partition("=")
        changes[key.strip()] = yaml.safe_load(value)
    return changes


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("files", nargs="*", type=Path, default=FILES)
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="a city_orbit option (YAML value); repeatable")
    parser.add_argument("--planner", choices=("orbit", "horizon"), default="orbit",
                        help="the city follower flown (default: the city orbit)")
    args = parser.parse_args()
    changes = parse_sets(args.set)
    print(f"city {args.planner} with {changes or 'the files options'} against the files' options; camera / line "
          "of sight / both, %")
    print("| file | the file's options | with the change | both, change (points) |\n|---|---|---|---|")
    for file, scenario, env, scene in cities(args.files, 4):
        start = time.perf_counter()
        changed(scenario, {"planner": args.planner})
        before = fly(scenario, scene, env)
        changed(scenario, changes)
        after = fly(scenario, scene, env)
        shown = [" / ".join(f"{100 * m[k]:.1f}" for k in KEYS) for m in (before, after)]
        delta = 100 * (after[KEYS[2]] - before[KEYS[2]])
        print(f"| {file.name} | {shown[0]} | {shown[1]} | {delta:+.1f} |  ({time.perf_counter() - start:.0f} s)")
    return 0


def _fields(scenario: FollowScenario) -> dict[str, Any]:
    """The scenario's city_orbit options as a block (lookahead as a list)."""
    options = vars(scenario.city_orbit).copy()
    options["lookahead"] = list(options["lookahead"])
    return options


if __name__ == "__main__":
    sys.exit(main())
