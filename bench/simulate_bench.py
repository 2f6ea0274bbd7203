"""Closed-loop simulation speed: vistrack (C++ Dormand-Prince 5(4)) against scipy.integrate.solve_ivp
(RK45, the same method and tolerances) with the numpy right-hand side of closed_loop_reference.py.

Both integrate the paper's section VI loop segment by segment, so they take the same steps; the
benchmark checks that the trajectories agree (to 1e-5 m) and reports the speed ratio and the
right-hand-side evaluations per second.

    VISTRACK_BUILD_DIR=build/dev python3 bench/simulate_bench.py [--repeat 200]
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(HERE.parent / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from the build tree)

import vistrack as vt
from closed_loop_reference import simulate_reference
from timing import timed as best_time

DATA = Path(os.environ.get("VISTRACK_DATA", HERE.parent.parent / "shared" / "data"))


def morphing_plan(poi, uav, r_first, r_last, wiggle, period=6.0):
    """R(t) from r_first to r_last with a wiggle, sampled every `period` s (plan JSON round trip)."""
    times = [*np.arange(0.0, poi.duration, period).tolist(), poi.duration]
    radii = [r_first + (r_last - r_first) * t / poi.duration + wiggle * math.sin(t / 4) for t in times]
    text = json.loads(vt.constant_radius_plan(poi, r_first, uav).to_json())
    text["times"], text["radii"], text["max_radii"] = times, radii, radii
    return vt.OrbitPlan.from_json(json.dumps(text))


def cases():
    slow = DATA / "charlotte" / "paths" / "paper_slow.csv"
    small = DATA / "charlotte" / "paths" / "paper_small.csv"
    if slow.exists():
        poi1 = vt.PoiPath.from_csv(str(slow), 5.0)
        poi2 = vt.PoiPath.from_csv(str(small), 5.0)
    else:  # the same waypoints, so the benchmark runs without the data folder
        poi1 = vt.PoiPath(np.array([[-150.0, -45.0], [-50.0, 45.0], [20.0, -35.0]]), 5.0)
        poi2 = vt.PoiPath(np.array([[-45.0, 430.0], [-147.0, 343.0], [-45.0, 235.0]]), 5.0)
    uav1 = vt.Uav(speed=20.0, min_turn_radius=50.0, altitude=300.0)
    uav2 = vt.Uav(speed=20.0, min_turn_radius=5.0, altitude=50.0)
    yield ("example 1 (v 20, r_min 50, beta 0.025, k 20), R 158 -> 127 m",
           morphing_plan(poi1, uav1, 158.0, 127.0, 8.0), uav1, vt.Control(beta=0.025, k_psi=20.0),
           np.array([0.0, 100.0, -math.pi]))
    yield ("example 2 (v 20, r_min 5, beta 0.5, k 40), R 21.5 -> 19.7 m",
           morphing_plan(poi2, uav2, 21.5, 19.7, 1.5), uav2, vt.Control(beta=0.5, k_psi=40.0),
           np.array([-45.0, 450.0, 0.0]))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeat", type=int, default=200, help="timing repetitions for vistrack (best of)")
    parser.add_argument("--repeat-reference", type=int, default=3, help="repetitions for scipy (best of)")
    parser.add_argument("--rtol", type=float, default=vt.SimulationOptions().rtol)
    parser.add_argument("--atol", type=float, default=vt.SimulationOptions().atol)
    parser.add_argument("--json", help="also write the numbers to this JSON file")
    args = parser.parse_args()
    options = vt.SimulationOptions(rtol=args.rtol, atol=args.atol)
    rows = []
    print(f"closed loop, RK45 rtol={args.rtol:g} atol={args.atol:g} max_step={options.max_step:g} s, "
          f"output every {options.output_step:g} s")
    for name, plan, uav, control, x0 in cases():
        ours_s, ours = best_time(lambda: vt.simulate(plan, uav, x0, control, None, options), args.repeat)
        ref_s, (t, states, nfev) = best_time(
            lambda: simulate_reference(plan.times, plan.radii, plan.poi.waypoints, plan.poi.speed, x0,
                                       speed=uav.speed, min_turn_radius=uav.min_turn_radius, beta=control.beta,
                                       k_psi=control.k_psi, direction=control.direction, rtol=args.rtol,
                                       atol=args.atol, max_step=options.max_step,
                                       output_step=options.output_step),
            args.repeat_reference)
        gap = float(np.max(np.linalg.norm(ours.state[:, :2] - states[:, :2], axis=1)))
        ours_nfev = ours.statistics.rhs_evaluations
        row = {"case": name, "duration_s": float(t[-1]), "samples": len(t),
               "vistrack_s": ours_s, "scipy_s": ref_s, "speedup": ref_s / ours_s,
               "vistrack_rhs": ours_nfev, "scipy_rhs": nfev,
               "vistrack_rhs_per_s": ours_nfev / ours_s, "scipy_rhs_per_s": nfev / ref_s,
               "max_position_gap_m": gap, "agree_1e-5_m": gap < 1e-5}
        rows.append(row)
        print(f"\n{name}: {row['duration_s']:.2f} s simulated, {row['samples']} samples")
        print(f"  vistrack  {ours_s * 1e3:9.3f} ms  {ours_nfev:6d} RHS  {row['vistrack_rhs_per_s']:12.3e} RHS/s")
        print(f"  scipy     {ref_s * 1e3:9.3f} ms  {nfev:6d} RHS  {row['scipy_rhs_per_s']:12.3e} RHS/s")
        print(f"  speed-up {row['speedup']:.0f}x   max |position difference| {gap:.2e} m "
              f"({'agree' if gap < 1e-5 else 'DISAGREE'} to 1e-5 m)")
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1))
    return 0 if all(r["agree_1e-5_m"] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
