"""Loiter planning and coverage: vistrack against a direct shapely implementation of the coverage
test, side by side in one run.

The peer scores the same sampled plans with the same rules (bank of the coordinated turn, a roll
gimbal of +-25 deg serving the AOI it can hold best, 75 % threshold), written directly in Python:
the footprint ellipse as a 256-vertex shapely polygon, the AOI as a shapely disk polygon, each AOI's
best gimbal angle found as vistrack finds it (the aiming angle and a 5-angle scan, then scipy's
bounded Brent around the best, to 1e-4 rad), and where two AOIs can both count, the angle covering
most of them on a 0.05-degree grid. vistrack computes the ellipse-disk area exactly (C++).

  1. one 9-AOI scenario (examples/loiter_9aoi.yaml), each method: plan, coverage at 1 s;
  2. N random scenarios (4-9 AOIs) end to end, all three methods (plan + coverage); the peer
     scores the first M of them (it is slow) and the ratio is per scenario.

Usage:  python bench/loiter_bench.py [--scenarios 1000] [--peer-scenarios 20] [--json out.json]
(with VISTRACK_BUILD_DIR=build/dev to use a CMake build tree). Needs shapely >= 2.
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

import shapely

from timing import timed
from vistrack import loiter

VERTICES = 256
UNIT = np.linspace(0.0, 2.0 * math.pi, VERTICES, endpoint=False)


def ellipse_polygons(x: float, y: float, psi: float, tilts: np.ndarray, camera: loiter.Camera) -> np.ndarray:
    """Footprint polygons of the conic camera at these tilts (the same plane section as vistrack)."""
    h, beta = camera.altitude, math.radians(camera.fov_deg / 2.0)
    k = math.cos(beta) ** 2 - np.sin(tilts) ** 2
    offset = h * np.sin(tilts) * np.cos(tilts) / k
    semi_along = h * math.sin(beta) / np.sqrt(k)
    semi_across = h * math.sin(beta) * math.cos(beta) / k
    forward = np.array([math.cos(psi), math.sin(psi)])
    left = np.array([-forward[1], forward[0]])
    along = semi_along[:, None] * np.cos(UNIT)[None, :]
    across = offset[:, None] + semi_across[:, None] * np.sin(UNIT)[None, :]
    coords = (np.array([x, y])[None, None, :] + along[..., None] * forward[None, None, :]
              + across[..., None] * left[None, None, :])
    return shapely.polygons(coords)


def best_fraction(x: float, y: float, psi: float, bank: float, centre: np.ndarray, disk: object, disk_area: float,
                  camera: loiter.Camera, limit: float) -> tuple[float, float]:
    """The gimbal angle holding most of the disk in view, and that fraction (scan with the angle that
    aims at the centre, then Brent)."""
    from scipy.optimize import minimize_scalar

    def fraction(gimbal: float) -> float:
        polygon = ellipse_polygons(x, y, psi, np.array([bank + gimbal]), camera)[0]
        return float(shapely.area(shapely.intersection(polygon, disk))) / disk_area

    across = -(centre[0] - x) * math.sin(psi) + (centre[1] - y) * math.cos(psi)
    aim = min(limit, max(-limit, math.atan2(across, camera.altitude) - bank))
    scan = np.concatenate([[aim], np.linspace(-limit, limit, 5)])
    values = [fraction(g) for g in scan]
    k = int(np.argmax(values))
    if values[k] <= 0.0 or values[k] >= 1.0:
        return float(scan[k]), values[k]
    step = 2.0 * limit / 4
    found = minimize_scalar(lambda g: -fraction(g), bounds=(max(-limit, scan[k] - step), min(limit, scan[k] + step)),
                            method="bounded", options={"xatol": 1e-4})
    return (float(found.x), -float(found.fun)) if -found.fun > values[k] else (float(scan[k]), values[k])


def centre_in_view(x: float, y: float, psi: float, bank: float, centre: np.ndarray, camera: loiter.Camera,
                   limit: float) -> bool:
    """Whether some gimbal angle puts the AOI's centre inside the cone."""
    along = (centre[0] - x) * math.cos(psi) + (centre[1] - y) * math.sin(psi)
    across = -(centre[0] - x) * math.sin(psi) + (centre[1] - y) * math.cos(psi)
    h = camera.altitude
    tilt = min(bank + limit, max(bank - limit, math.atan2(across, h)))
    cosine = (across * math.sin(tilt) + h * math.cos(tilt)) / math.sqrt(along ** 2 + across ** 2 + h ** 2)
    return cosine >= math.cos(math.radians(camera.fov_deg / 2.0))


def shapely_coverage(poses: np.ndarray, rates: np.ndarray, aois: np.ndarray, radius: float, speed: float,
                     camera: loiter.Camera, threshold: float = 0.75, dt: float = 1.0) -> dict[str, float]:
    """The coverage test written directly with shapely, with vistrack's rules: each AOI's best gimbal
    angle; when two or more can reach the threshold, the angle (0.05-degree grid) covering most of
    them, then with most of their area in view."""
    beta = math.radians(camera.fov_deg / 2.0)
    limit = math.radians(camera.max_gimbal_deg)
    disks = [shapely.Point(*c).buffer(radius, quad_segs=VERTICES // 4) for c in aois]
    disk_area = math.pi * radius ** 2
    covered_time, area = 0.0, 0.0
    for (x, y, psi), rate in zip(poses, rates):
        bank = math.atan(speed * rate / 9.80665)
        reach = camera.altitude * math.tan(abs(bank) + limit + beta)
        near = [i for i, c in enumerate(aois) if math.hypot(c[0] - x, c[1] - y) - radius < reach]
        best: dict[int, tuple[float, float]] = {}
        for i in near:
            if threshold > 0.5 and not centre_in_view(x, y, psi, bank, aois[i], camera, limit):
                continue  # at most half the disk can be in view: it cannot count
            g, f = best_fraction(x, y, psi, bank, aois[i], disks[i], disk_area, camera, limit)
            if f > 0.0:
                best[i] = (g, f)
        if not best:
            continue
        able = [i for i, (_, f) in best.items() if f >= threshold]
        gimbal = max(best.values(), key=lambda gf: gf[1])[0]
        if len(able) >= 2:
            grid = np.arange(-limit, limit + 1e-12, math.radians(0.05))
            polygons = ellipse_polygons(x, y, psi, bank + grid, camera)
            fractions = np.array([shapely.area(shapely.intersection(polygons, disks[i])) / disk_area for i in able])
            counted = fractions >= threshold
            count = counted.sum(axis=0)
            score = count * 10.0 + (fractions * counted).sum(axis=0)  # most covered, then most area
            gimbal = float(grid[int(np.argmax(score))])
        polygon = ellipse_polygons(x, y, psi, np.array([bank + gimbal]), camera)[0]
        for i in near:
            f = float(shapely.area(shapely.intersection(polygon, disks[i]))) / disk_area
            if f >= threshold:
                covered_time += dt
                area += f * disk_area * dt
    return {"time": covered_time, "area": area}


def vistrack_run(scenario: loiter.Scenario, method: str) -> tuple[loiter.Plan, loiter.Coverage]:
    plan = scenario.plan(method)
    return plan, scenario.coverage(plan)


def peer_run(scenario: loiter.Scenario, plan: loiter.Plan) -> dict[str, float]:
    states = plan.sample_states(scenario.dt, False)
    return shapely_coverage(states.poses, np.asarray(states.turn_rate), scenario.aois, scenario.aoi_radius,
                            scenario.speed, scenario.camera, scenario.threshold, scenario.dt)


def one_scenario(repeat: int) -> dict[str, dict[str, float]]:
    scenario = loiter.load_scenario(HERE.parent / "examples" / "loiter_9aoi.yaml")
    out = {}
    for method in loiter.METHODS:
        plan_time, plan = timed(lambda m=method: scenario.plan(m), repeat)
        coverage_time, cov = timed(lambda p=plan: scenario.coverage(p), repeat)
        peer_time, peer = timed(lambda p=plan: peer_run(scenario, p), 1)
        out[method] = {
            "steps": cov.steps, "plan_ms": 1e3 * plan_time, "coverage_ms": 1e3 * coverage_time,
            "peer_coverage_ms": 1e3 * peer_time, "ratio": peer_time / coverage_time,
            "covered_s": cov.time, "peer_covered_s": peer["time"],
            "area_relative_difference": (peer["area"] - cov.area) / cov.area,
        }
        print(f"9 AOIs, {method:11s}: plan {1e3 * plan_time:6.2f} ms, coverage {1e3 * coverage_time:7.1f} ms "
              f"({cov.steps} steps) | shapely {1e3 * peer_time:8.0f} ms | x{peer_time / coverage_time:5.0f} | "
              f"covered {cov.time:.0f} s vs {peer['time']:.0f} s, "
              f"area {100 * out[method]['area_relative_difference']:+.3f} %",
              flush=True)
    return out


def random_scenarios(count: int, peer_count: int, seed: int) -> dict[str, float]:
    rng = np.random.default_rng(seed)
    scenarios = [loiter.Scenario(aois=loiter.random_aois(4 + k % 6, rng)) for k in range(count)]
    start = time.perf_counter()
    results = [[vistrack_run(s, m) for m in loiter.METHODS] for s in scenarios]
    ours = time.perf_counter() - start
    ours_subset = 0.0
    start = time.perf_counter()
    for s in scenarios[:peer_count]:
        for m in loiter.METHODS:
            vistrack_run(s, m)
    ours_subset = time.perf_counter() - start
    start = time.perf_counter()
    steps_diff, area_diff = [], []
    for s, runs in zip(scenarios[:peer_count], results[:peer_count]):
        for plan, cov in runs:
            peer = peer_run(s, plan)
            steps_diff.append(abs(peer["time"] - cov.time))
            area_diff.append(abs(peer["area"] - cov.area) / max(cov.area, 1e-9))
    peer = time.perf_counter() - start
    per_ours, per_peer = ours / count, peer / max(peer_count, 1)
    out = {"scenarios": count, "vistrack_s": ours, "vistrack_per_scenario_ms": 1e3 * per_ours,
           "peer_scenarios": peer_count, "peer_s": peer, "peer_per_scenario_ms": 1e3 * per_peer,
           "vistrack_same_subset_s": ours_subset, "ratio": peer / ours_subset,
           "max_covered_difference_s": float(max(steps_diff, default=0.0)),
           "max_area_relative_difference": float(max(area_diff, default=0.0))}
    print(f"{count} random scenarios, 3 methods, plan + coverage: vistrack {ours:.1f} s "
          f"({1e3 * per_ours:.0f} ms per scenario)")
    print(f"shapely coverage on the first {peer_count}: {peer:.1f} s ({1e3 * per_peer:.0f} ms per scenario, "
          f"vistrack {ours_subset:.2f} s end to end on the same) | x{out['ratio']:.0f} | covered time within "
          f"{out['max_covered_difference_s']:.0f} s, area within {100 * out['max_area_relative_difference']:.3f} %",
          flush=True)
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scenarios", type=int, default=1000)
    parser.add_argument("--peer-scenarios", type=int, default=20)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--seed", type=int, default=2024)
    parser.add_argument("--json", type=Path)
    args = parser.parse_args()
    record = {"nine_aois": one_scenario(args.repeat),
              "random": random_scenarios(args.scenarios, args.peer_scenarios, args.seed)}
    if args.json:
        args.json.write_text(json.dumps(record, indent=2) + "\n")


if __name__ == "__main__":
    main()
