"""The loiter numbers the README quotes: Table 1 (flight time and AOI coverage per method on the six
example scenarios) beside the paper's, for the paper's levelled camera (the gimbal angle measured
from the vertical) and for a gimbal under the banked body; then the covered share of the time spent
on each kind of segment, summed over the six scenarios. Prints markdown.

    VISTRACK_BUILD_DIR=build/dev python3 bench/loiter_table.py
"""

from __future__ import annotations

import dataclasses
import os
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

from vistrack import loiter
from vistrack.loiter.study import PAPER_AREA_PER_SECOND

ROLES = ("transit", "entry", "loiter", "exit")


def with_mount(scenario: loiter.Scenario, levelled: bool) -> loiter.Scenario:
    camera = loiter.Camera(scenario.camera.fov_deg, scenario.camera.max_gimbal_deg, scenario.camera.altitude, levelled)
    return dataclasses.replace(scenario, camera=camera)


def main() -> None:
    scenarios = [loiter.load_scenario(REPO / "examples" / f"loiter_{n}aoi.yaml") for n in range(4, 10)]
    for levelled in (True, False):
        title = "levelled camera (the paper's)" if levelled else "camera on the banked body"
        print(f"\n### Table 1, {title}: paper / ours\n")
        print("| method | | " + " | ".join(f"{len(s.aois)} AOIs" for s in scenarios) + " |")
        print("|---|---|" + "---|" * len(scenarios))
        roles = {m: {r: [0, 0] for r in ROLES} for m in loiter.METHODS}
        for method in loiter.METHODS:
            times, areas, covered = [], [], []
            for base in scenarios:
                scenario = with_mount(base, levelled)
                plan = scenario.plan(method)
                cov = scenario.coverage(plan)
                paper = scenario.paper.get(method, {})
                times.append(f"{paper.get('flight_time_min', float('nan')):.2f} / {plan.flight_time / 60:.2f}")
                areas.append(f"{paper.get('coverage_m2', float('nan')) / 1e3:.0f} / {cov.area / 1e3:.0f}")
                covered.append(f"{paper.get('coverage_m2', float('nan')) / PAPER_AREA_PER_SECOND:.0f} / {cov.time:.0f}")
                for role, steps in loiter.coverage_by_role(plan, cov, scenario.dt, scenario.threshold).items():
                    roles[method][role][0] += steps["steps"]
                    roles[method][role][1] += steps["covered_steps"]
            name = loiter.METHOD_NAMES[method]
            print(f"| {name} | flight time (min) | " + " | ".join(times) + " |")
            print("| | covered time (s) | " + " | ".join(covered) + " |")
            print("| | coverage (10^3 m^2 s; the paper's m^2) | " + " | ".join(areas) + " |")
        print(f"\nCovered share of the time on each kind of segment ({title}), six scenarios:\n")
        print("| | " + " | ".join(ROLES) + " |")
        print("|---|" + "---|" * len(ROLES))
        for method in loiter.METHODS:
            cells = []
            for role in ROLES:
                steps, hit = roles[method][role]
                cells.append(f"{steps} s, {100 * hit / steps:.0f} %" if steps else "-")
            print(f"| {loiter.METHOD_NAMES[method]} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
