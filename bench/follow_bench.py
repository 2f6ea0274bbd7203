"""Following a ground vehicle: vistrack against scipy, one run.

Measures, side by side:
  * the sinusoid's amplitude from the speed ratio (eqs. 9-10): vistrack's safeguarded Newton on
    std::comp_ellint_2 (one Python call per solve, and one call on a numpy array of solves)
    against scipy's brentq on (2/pi) ellipe(-a^2) - sigma, on the same random ratios in [1.001, 10];
    the largest relative difference of the amplitudes;
  * the Figure 9 truck scenario (examples/follow_truck.yaml, 1055 s of flight at dt 0.02 s) end to
    end: the planner's run (plan at 1 Hz + flight + metrics) and the baseline's, without the city.

Usage:  python bench/follow_bench.py [--solves 20000] [--repeat 3] [--json out.json]
(with VISTRACK_BUILD_DIR=build/dev to use a CMake build tree). Needs scipy.
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
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(HERE.parent / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

from timing import best_of, timed
from vistrack import follow
from vistrack.follow_scenario import FollowScenario

try:
    from scipy.optimize import brentq
    from scipy.special import ellipe
except ImportError:  # pragma: no cover
    sys.exit("this benchmark needs scipy")


def scipy_amplitude(sigma: float, distance: float) -> float:
    """The same problem with scipy: brentq on sigma(a) = (2/pi) E(-a^2) over [0, pi sigma]."""
    slope = brentq(lambda a: 2.0 / math.pi * ellipe(-a * a) - sigma, 0.0, math.pi * sigma, xtol=1e-14, rtol=1e-14)
    return slope * distance / (2.0 * math.pi)


def amplitude(solves: int, repeat: int, seed: int) -> dict:
    rng = np.random.default_rng(seed)
    sigmas = rng.uniform(1.001, 10.0, solves)
    distance = 500.0
    few = sigmas[: max(1, solves // 10)]  # scipy is slow: time it on a tenth
    t_scipy, theirs = timed(lambda: np.array([scipy_amplitude(s, distance) for s in few]), repeat)
    t_call, ours_calls = timed(lambda: np.array([follow.sinusoid_amplitude(s, distance) for s in sigmas]), repeat)
    t_array, ours = timed(lambda: follow.sinusoid_amplitude(sigmas, distance), repeat)
    assert np.array_equal(ours, ours_calls)
    difference = np.abs(ours[: len(few)] - theirs) / theirs
    return {
        "solves": solves,
        "scipy_solves_per_s": len(few) / t_scipy,
        "vistrack_call_solves_per_s": solves / t_call,
        "vistrack_array_solves_per_s": solves / t_array,
        "ns_per_solve_array": 1e9 * t_array / solves,
        "max_relative_difference": float(difference.max()),
        "ratio_call": (solves / t_call) / (len(few) / t_scipy),
        "ratio_array": (solves / t_array) / (len(few) / t_scipy),
    }


def truck(repeat: int) -> dict:
    scenario = FollowScenario.load(HERE.parent / "examples" / "follow_truck.yaml")
    duration = scenario.vehicle.end_time - scenario.vehicle.start_time
    t_follow = best_of(repeat, lambda: follow.simulate(scenario.vehicle, scenario.uav, scenario.parameters,
                                                       wind=scenario.wind, flight=scenario.flight))
    t_study, study = timed(lambda: scenario.run(city=False), repeat)
    m = study.follow.metrics
    return {
        "flight_seconds": duration,
        "steps": len(study.follow.t),
        "updates": len(study.follow.ticks),
        "follow_s": t_follow,
        "follow_and_baseline_s": t_study,
        "real_time_factor": duration / t_follow,
        "camera_fraction": m["camera_fraction"],
        "baseline_camera_fraction": study.baseline.metrics["camera_fraction"] if study.baseline else None,
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--solves", type=int, default=20000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--json", type=Path)
    args = parser.parse_args()
    load = os.getloadavg()
    print(f"machine: {os.cpu_count()} logical cores, load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")

    a = amplitude(args.solves, args.repeat, args.seed)
    print(f"\n== amplitude from the speed ratio, {a['solves']} solves (best of {args.repeat}) ==")
    print(f"scipy brentq on ellipe       {a['scipy_solves_per_s']:12.0f} solves/s")
    print(f"vistrack, one call per solve {a['vistrack_call_solves_per_s']:12.0f} solves/s   x{a['ratio_call']:.1f}")
    print(f"vistrack, one array call     {a['vistrack_array_solves_per_s']:12.0f} solves/s   x{a['ratio_array']:.1f}"
          f"   ({a['ns_per_solve_array']:.0f} ns/solve)")
    print(f"largest relative difference of the amplitudes: {a['max_relative_difference']:.1e}")

    t = truck(args.repeat)
    print(f"\n== Figure 9 truck scenario end to end ({t['flight_seconds']:.0f} s of flight, {t['steps']} steps, "
          f"{t['updates']} updates) ==")
    print(f"planner + flight + metrics   {t['follow_s']:.3f} s   ({t['real_time_factor']:.0f}x real time)")
    print(f"... and the baseline         {t['follow_and_baseline_s']:.3f} s")
    print(f"camera fraction: planner {t['camera_fraction']:.3f}, baseline {t['baseline_camera_fraction']:.3f}")
    if args.json:
        args.json.write_text(json.dumps({"amplitude": a, "truck": t}, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
