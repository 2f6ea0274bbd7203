"""DWN turning points: vistrack's exact solver against the same minimisation written with scipy
(``minimize_scalar`` per case), one run; and the whole 6-waypoint discrete flight.

The scipy version evaluates the horizon length F(theta) of each of the four cases from the
geometry (circles, tangents, arcs by atan2, in plain Python), scans 16 thetas per case (as vistrack
does) and polishes the best with ``minimize_scalar(method="bounded")`` on the neighbouring samples
(in an offset variable, so its relative tolerance does not grow with theta). vistrack: 16 samples per case,
breakpoints and the closed-form dF/dh, Brent to 1e-13 rad (waypoint_nav.hpp). Both get the same
random horizons of the paper's domain (legs 4-10 R, any headings); agreement is reported on theta
(where both pick the same case and the minimum is not a tie) and on the length.

Usage:  python bench/waypoint_nav_bench.py [--horizons 20000] [--scipy 1000] [--json out.json]
(with VISTRACK_BUILD_DIR=build/dev to use a CMake build tree).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(HERE.parent / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

from scipy.optimize import minimize_scalar

from timing import best_of, timed
from vistrack import waypoint_nav as wn
from vistrack._core import waypoint_nav as core_wn
from vistrack.io import read_route

TWO_PI = 2.0 * math.pi
CASES = [(1, 1), (1, -1), (-1, 1), (-1, -1)]  # (d1, d2) in wn.CASES order


def horizon_length(pose, wn_, wn1, R, d1, d2, theta):
    """F(theta) from the geometry of the paper's Figure 6 (w_a = w_s = 1)."""
    x, y, psi = pose
    c1x, c1y = x - d1 * R * math.sin(psi), y + d1 * R * math.cos(psi)
    c2x, c2y = wn_[0] + R * math.cos(theta), wn_[1] + R * math.sin(theta)
    vx, vy = c2x - c1x, c2y - c1y
    d = math.hypot(vx, vy)
    chi, p = math.atan2(vy, vx), d
    if d1 != d2:
        if d < 2 * R:
            return math.inf
        chi += d1 * math.asin(2 * R / d)
        p = math.sqrt(d * d - 4 * R * R)
    tx, ty = c2x + d2 * R * math.sin(chi), c2y - d2 * R * math.cos(chi)
    t = (d1 * (chi - psi)) % TWO_PI
    at_w = math.atan2(wn_[1] - c2y, wn_[0] - c2x)
    q = (d2 * (at_w - math.atan2(ty - c2y, tx - c2x))) % TWO_PI
    ux, uy = wn1[0] - c2x, wn1[1] - c2y
    d2len = math.hypot(ux, uy)
    if d2len < R:
        return math.inf
    a = (d2 * (math.atan2(uy, ux) - d2 * math.acos(R / d2len) - at_w)) % TWO_PI
    return R * (t + q + a) + p + math.sqrt(d2len * d2len - R * R)


def scipy_turning_point(pose, wn_, wn1, R, samples=16):
    """(theta, length, case index): per case, a scan and minimize_scalar around its best sample."""
    best = (math.inf, 0.0, -1)
    step = TWO_PI / samples
    for c, (d1, d2) in enumerate(CASES):
        values = [horizon_length(pose, wn_, wn1, R, d1, d2, k * step) for k in range(samples)]
        k = int(np.argmin(values))
        if not math.isfinite(values[k]):
            continue
        centre = k * step
        res = minimize_scalar(lambda u, c0=centre, a=d1, b=d2: horizon_length(pose, wn_, wn1, R, a, b, c0 + u),
                              bounds=(-step, step), method="bounded", options={"xatol": 1e-12})
        value, theta = (res.fun, centre + res.x) if res.fun < values[k] else (values[k], centre)
        if value < best[0]:
            best = (value, theta % TWO_PI, c)
    return best[1], best[0], best[2]


def cpu_timed(fn, repeat: int):
    """Best process CPU seconds of `repeat` calls, and the last call's value."""
    best, value = math.inf, None
    for _ in range(repeat):
        start = time.process_time()
        value = fn()
        best = min(best, time.process_time() - start)
    return best, value


def random_horizons(n: int, seed: int, R: float):
    rng = np.random.default_rng(seed)

    def polar(size):
        return rng.uniform(4 * R, 10 * R, size)[:, None] * np.column_stack(
            [np.cos(a := rng.uniform(-math.pi, math.pi, size)), np.sin(a)])

    w_next = np.zeros((n, 2))
    poses = np.column_stack([polar(n), rng.uniform(-math.pi, math.pi, n)])
    w_after = polar(n)
    return poses, w_next, w_after


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--horizons", type=int, default=20000)
    parser.add_argument("--scipy", type=int, default=1000, help="horizons solved by the scipy version")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--json", type=Path)
    args = parser.parse_args()
    R = 0.7
    poses, w_next, w_after = random_horizons(args.horizons, args.seed, R)

    # Rates from process CPU time as well as wall time: on a shared machine the wall clock also
    # counts the time other processes hold the core; CPU time is what one core does.
    seconds, ours = timed(lambda: wn.turning_points(poses, w_next, w_after, R), 5)
    ours_cpu, _ = cpu_timed(lambda: wn.turning_points(poses, w_next, w_after, R), 5)
    ours_rate, ours_cpu_rate = args.horizons / seconds, args.horizons / ours_cpu
    m = min(args.scipy, args.horizons)
    start_cpu = time.process_time()
    scipy_seconds, theirs = timed(
        lambda: [scipy_turning_point(tuple(poses[i]), w_next[i], w_after[i], R) for i in range(m)], 1)
    scipy_rate, scipy_cpu_rate = m / scipy_seconds, m / (time.process_time() - start_cpu)

    d_theta, d_length, same_case = [], [], 0
    for i, (theta, length, c) in enumerate(theirs):
        d_length.append(ours.length[i] - length)
        if c == ours.case[i]:
            same_case += 1
            d_theta.append(abs((ours.theta[i] - theta + math.pi) % TWO_PI - math.pi))
    d_theta_a, d_length_a = np.array(d_theta), np.array(d_length)

    route = read_route(HERE.parent / "examples" / "waypoints_paper.csv")
    flight = {}
    for method in ("dwn", "wn"):
        flight[method] = best_of(20, lambda m_=method: wn.fly(route, method=m_))
    core = best_of(20, lambda: core_wn.navigate(route[1:], wn.default_start(route)))

    report = {
        "turning_points_per_second": ours_rate,
        "turning_points_per_cpu_second": ours_cpu_rate,
        "scipy_turning_points_per_second": scipy_rate,
        "scipy_turning_points_per_cpu_second": scipy_cpu_rate,
        "ratio": ours_rate / scipy_rate,
        "ratio_cpu": ours_cpu_rate / scipy_cpu_rate,
        "compared": m,
        "same_case": same_case,
        "theta_difference_median": float(np.median(d_theta_a)),
        "theta_difference_p99": float(np.percentile(d_theta_a, 99)),
        "theta_within_1e-8": float(np.mean(d_theta_a < 1e-8)),
        "length_ours_minus_scipy_min": float(d_length_a.min()),
        "length_ours_minus_scipy_max": float(d_length_a.max()),
        "flight_seconds": {"dwn": flight["dwn"], "wn": flight["wn"], "dwn_core_only": core},
    }
    print(f"turning points, one thread: vistrack {ours_rate:,.0f}/s wall, {ours_cpu_rate:,.0f}/s CPU; scipy "
          f"minimize_scalar {scipy_rate:,.0f}/s wall, {scipy_cpu_rate:,.0f}/s CPU; "
          f"ratio x{ours_rate / scipy_rate:,.0f} wall, x{ours_cpu_rate / scipy_cpu_rate:,.0f} CPU")
    print(f"agreement on {m} horizons: same case {same_case}; "
          f"|d theta| median {report['theta_difference_median']:.1e}, p99 {report['theta_difference_p99']:.1e}, "
          f"within 1e-8: {100 * report['theta_within_1e-8']:.1f} %; "
          f"length ours - scipy in [{d_length_a.min():.1e}, {d_length_a.max():.1e}]")
    print(f"6-waypoint discrete flight (dt 0.02): DWN {1e3 * flight['dwn']:.2f} ms, WN {1e3 * flight['wn']:.2f} ms "
          f"(vt.waypoint_nav.fly); DWN {1e3 * core:.2f} ms (the core call alone)")
    if args.json:
        args.json.write_text(json.dumps(report, indent=1) + "\n")


if __name__ == "__main__":
    main()
