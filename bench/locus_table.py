"""The locus numbers the README quotes (issue 12): each tracking example run with the paper's locus
(Algorithm 1, piecewise linear) and with the smooth one (the default), side by side:
- the planned R(t) against MaxRadius of the VP at 400 evenly spaced times (1-degree VVs through the
  edge-walking slicer: independent of the planner's samples and of the locus check's probe),
- what the locus check found (check points, how far the paper's R(t) leaves the VP, how much and
  where the smooth R(t) lies below it),
- the closed loop of `vistrack run` (RK45, line of sight at every output sample): POI visible, the
  largest |radial error| after the initial capture (t > 15 s and t > 20 s), and the planning time.

    VISTRACK_BUILD_DIR=build/dev python3 bench/locus_table.py [--names campus demo] [--no-dense]

Charlotte and campus geometry © OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import argparse
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
from vistrack.scenario import Scenario

EXAMPLES = {"campus": "examples/campus_flight_test.yaml", "paper_small": "examples/charlotte_paper_small.yaml",
            "paper_slow": "examples/charlotte_paper_slow.yaml", "demo": "python/vistrack/scenarios/demo.yaml"}


def dense_check(planner: vt.OrbitPlanner, plan: vt.VisibilityOrbitPlan, scenario: Scenario, count: int = 400) -> str:
    """R(t) against MaxRadius of the VP at `count` evenly spaced times."""
    poi = plan.poi
    times = np.linspace(0.0, poi.duration, count)
    scene = planner.scene
    points = np.array([np.ravel(scene.poi_on_surface(np.ravel(poi.position(t)))) for t in times])
    truth = np.array([  # batches of 100 VVs (400 at once would pass visibility_volumes' memory budget)
        vt.max_inscribed_radius(vt.plane_visibility_polygon(vv, scenario.uav.altitude), np.ravel(poi.position(t))[:2])
        for start in range(0, count, 100)
        for vv, t in zip(vt.visibility_volumes(scene, points[start:start + 100], scenario.sensor.d_max, None,
                                               scenario.planning.resolution_deg), times[start:start + 100])])
    over = plan.radius_at(times) - truth
    outside = int((over > 1e-9).sum())
    if outside:
        return f"{outside}/{count} outside, by up to {over.max():.2f} m"
    return f"0/{count} outside (closest {-over.max():.2f} m inside)"


def one(name: str, locus: str, dense: bool) -> dict[str, str]:
    scenario = Scenario.load(REPO / EXAMPLES[name])
    scenario.uav.dynamics = "dubins"  # the paper's vehicle; the roll model's rows: bench/vehicle_models.py
    scenario.planning.locus = locus
    env = scenario.environment.load(scenario.origin)
    planner = vt.OrbitPlanner(env, scenario.sensor)
    poi = scenario.poi.build(env)
    start = time.perf_counter()
    planner.plan(poi, scenario.uav, scenario.planning)  # timed cold (new planner, empty VV cache)
    plan_s = time.perf_counter() - start
    result = vt.run(scenario, environment=env, planner=planner, metric_spacings=())
    t = np.asarray(result.simulation.t)
    error = np.abs(np.asarray(result.simulation.radial_error))
    plan = result.plan
    row = {"example": name, "locus": locus,
           "R_i -> R_f (min..max)": f"{plan.radius(0.0):.1f} -> {plan.radius(plan.times[-1]):.1f} m "
                                    f"({plan.reference.min_radius:.1f}..{max(plan.radius_at(t)):.1f})",
           "POI visible": f"{100 * result.simulation.visibility_fraction:.1f} %",
           "max |radial err| t>15 s / t>20 s": f"{error[t > 15].max():.2f} / {error[t > 20].max():.2f} m",
           "plan time": f"{plan_s:.2f} s"}
    if dense:
        row["R(t) vs VP at 400 times"] = dense_check(planner, plan, scenario)
    if locus == "smooth":
        c = plan.check
        row["locus check"] = (f"{len(c.times)} points, paper's R(t) outside at {c.paper_violations} by up to "
                              f"{c.paper_max_violation:.2f} m; lowered {np.mean(c.lowering):.2f} m on average, "
                              f"at most {c.max_lowering:.2f} m at t = {c.max_lowering_time:.1f} s "
                              f"({c.max_lowering_time * plan.poi.speed:.0f} m along the path)")
    return row


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--names", nargs="+", default=list(EXAMPLES), choices=list(EXAMPLES))
    parser.add_argument("--no-dense", action="store_true", help="leave out the 400-time VP check")
    args = parser.parse_args()
    rows = []
    for name in args.names:
        for locus in ("paper", "smooth"):
            row = one(name, locus, not args.no_dense)
            print("  ".join(f"{k}: {v}" for k, v in row.items()), flush=True)
            rows.append(row)
    keys = [k for k in rows[0] if k != "locus check"] + (["locus check"] if any("locus check" in r for r in rows)
                                                          else [])
    print("\n| " + " | ".join(keys) + " |\n|" + "---|" * len(keys))
    for row in rows:
        print("| " + " | ".join(row.get(k, "") for k in keys) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
