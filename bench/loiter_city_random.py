"""Loiter over Charlotte at 300 m on seeded random layouts of six street-level AOIs (issue 33 part 4):
how many AOIs get a flyable circle inside their visibility polygon, and the share of each flyable
AOI's loiter time its centre is in line of sight (brute-force Embree rays from the planned path).

    VISTRACK_BUILD_DIR=build/dev python3 bench/loiter_city_random.py [layouts] [first_seed]
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import vistrack as vt
from vistrack.loiter import Scenario
from vistrack.loiter.city import plan_city, random_street_aois

DATA = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data"))


def main() -> None:
    layouts = int(sys.argv[1]) if len(sys.argv) > 1 else 50
    first = int(sys.argv[2]) if len(sys.argv) > 2 else 1000
    env = vt.Environment.from_mesh(DATA / "charlotte" / "uptown_charlotte.obj", up="y")
    scene = vt.VisibilityScene(env)
    for off_centre in (False, True):
        study(scene, layouts, first, off_centre)


def study(scene: vt.VisibilityScene, layouts: int, first: int, off_centre: bool) -> None:
    camera = vt.loiter.Camera(74.0, 25.0, 300.0, True)
    flyable, worst, covered, opened, start = [], [], [], [], time.perf_counter()
    for seed in range(first, first + layouts):
        aois = random_street_aois(scene, 6, np.random.default_rng(seed))
        scenario = Scenario(aois=aois, name=f"street-{seed}", camera=camera)
        result = plan_city(scenario, ["tlpp", "ldlpp_best"], scene, off_centre=off_centre)
        flyable.append(len(result.flyable))
        for run in result.runs:
            worst.append(min(run.centre_line_of_sight))
            covered.append(run.coverage.time)
            opened.append(run.coverage.open_time)
    elapsed = time.perf_counter() - start
    counts = np.bincount(flyable, minlength=7)
    print(f"off_centre={off_centre}: {layouts} layouts (seeds {first}..{first + layouts - 1}), {elapsed:.1f} s")
    print("flyable AOIs of 6: " + ", ".join(f"{k}: {counts[k]}" for k in range(7) if counts[k]))
    print(f"layouts with >= 4 flyable: {np.mean(np.array(flyable) >= 4):.1%}; mean {np.mean(flyable):.2f}")
    print(f"centre in line of sight during loiter, worst AOI per plan: min {min(worst):.2%}, "
          f"median {np.median(worst):.2%}")
    print(f"covered s with line of sight / ignoring buildings: {np.sum(covered) / np.sum(opened):.1%}")


if __name__ == "__main__":
    main()
