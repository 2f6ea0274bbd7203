"""The two numerical examples of the visibility-volume paper (section VI, Figures 10 and 11) on
uptown Charlotte: adaptive VVs + Algorithm 1 (vt.plan_orbits), then the closed loop (vt.simulate)
with line of sight evaluated at every sample, beside the paper's numbers.

    python3 examples/paper_examples.py [--out paper_examples_out] [--map obj|geojson] [--resolution 1]

Reads ../shared/data/charlotte (OpenStreetMap geometry, © OpenStreetMap contributors, ODbL).
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
    import conftest  # noqa: F401  (vistrack from the build tree)

import vistrack as vt  # noqa: E402
from vistrack.commands.simulate import figure_errors, figure_trajectory, metrics  # noqa: E402

DATA = Path(os.environ.get("VISTRACK_DATA", HERE.parent.parent / "shared" / "data")) / "charlotte"

# Section VI: parameters and the numbers the paper reports.
EXAMPLES = [
    dict(name="example1", path="paper_slow.csv", speed=20.0, min_turn_radius=50.0, altitude=300.0, d_max=400.0,
         spacing=20.0, cutoff=20e6, beta=0.025, k_psi=20.0, x0=(0.0, 100.0, -math.pi),
         paper=dict(R_initial=158.0, R_final=127.0, duration=48.16)),
    dict(name="example2", path="paper_small.csv", speed=20.0, min_turn_radius=5.0, altitude=50.0, d_max=100.0,
         spacing=20.0, cutoff=500e3, beta=0.5, k_psi=40.0, x0=(-45.0, 450.0, 0.0),
         paper=dict(R_initial=21.5, R_final=19.7, duration=56.52)),
]


def load_city(kind: str):
    if kind == "geojson":
        return vt.Environment.from_geojson(str(DATA / "buildings.geojson"))
    return vt.Environment.from_mesh(str(DATA / "uptown_charlotte.obj"), "y")


def run(example: dict, env, out: Path, resolution: float, drawing) -> dict:
    from tqdm import tqdm

    poi = vt.PoiPath.from_csv(str(DATA / "paths" / example["path"]), 5.0)
    uav = vt.Uav(speed=example["speed"], min_turn_radius=example["min_turn_radius"], altitude=example["altitude"])
    sensor = vt.Sensor(d_max=example["d_max"])
    planning = vt.Planning(spacing=example["spacing"], cutoff=example["cutoff"], resolution_deg=resolution)
    control = vt.Control(beta=example["beta"], k_psi=example["k_psi"])
    bar = tqdm(desc=f"{example['name']}: VVs", unit="VV", leave=False)

    def progress(done: int, total: int) -> None:
        bar.total = total
        bar.n = done
        bar.refresh()

    start = time.perf_counter()
    plan = vt.plan_orbits(env, poi, uav, sensor, planning, progress)
    bar.close()
    plan_seconds = time.perf_counter() - start
    start = time.perf_counter()
    result = vt.simulate(plan, uav, np.array(example["x0"]), control, env)
    sim_seconds = time.perf_counter() - start
    (out / f"{example['name']}_plan.json").write_text(plan.to_json())
    (out / f"{example['name']}_trajectory.csv").write_text(result.to_csv())
    title = (f"{example['name']}: v {uav.speed:g} m/s, r_min {uav.min_turn_radius:g} m, h {uav.altitude:g} m, "
             f"beta {control.beta:g}, k_psi {control.k_psi:g}")
    figure_trajectory([("UAV", plan, result)], drawing, out / f"{example['name']}_trajectory.png", title,
                      orbit_count=6)
    figure_errors(result, out / f"{example['name']}_errors.png", 20.0, title + " (first 20 s)",
                  uav.speed / uav.min_turn_radius)
    m = metrics(result)
    row = dict(example=example["name"], volumes=len(plan.times), feasible=plan.feasible,
               R_initial=plan.radii[0], R_final=plan.radii[-1], duration=float(result.t[-1]),
               visibility=m["visibility_fraction"], radial_error_after_20s_max=m["radial_error_after_max_abs_m"],
               saturated_fraction=m["saturated_fraction"], plan_seconds=plan_seconds, simulate_seconds=sim_seconds,
               paper=example["paper"])
    return row


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="paper_examples_out")
    parser.add_argument("--map", default="obj", choices=["obj", "geojson"], help="city model (default: the mesh)")
    parser.add_argument("--resolution", type=float, default=1.0, help="VV ray grid, degrees")
    args = parser.parse_args()
    if not DATA.is_dir():
        print(f"Charlotte data not found at {DATA} (set VISTRACK_DATA)", file=sys.stderr)
        return 2
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    env = load_city(args.map)
    drawing = load_city("geojson")  # footprints for the figures, whichever model is simulated
    rows = [run(example, env, out, args.resolution, drawing) for example in EXAMPLES]
    (out / "summary.json").write_text(json.dumps(rows, indent=1))
    print(f"{'':10s} {'R_i ours':>9s} {'paper':>6s} {'R_f ours':>9s} {'paper':>6s} {'T ours':>7s} {'paper':>6s}"
          f" {'visible':>8s} {'|r-R| >20s':>10s} {'VVs':>4s} {'plan s':>7s} {'sim ms':>7s}")
    for r in rows:
        p = r["paper"]
        vis = "n/a" if r["visibility"] is None else f"{100 * r['visibility']:.1f}%"
        print(f"{r['example']:10s} {r['R_initial']:9.1f} {p['R_initial']:6.1f} {r['R_final']:9.1f} {p['R_final']:6.1f}"
              f" {r['duration']:7.2f} {p['duration']:6.2f} {vis:>8s} {r['radial_error_after_20s_max']:10.2f}"
              f" {r['volumes']:4d} {r['plan_seconds']:7.1f} {1e3 * r['simulate_seconds']:7.1f}")
    print(f"wrote {out}/")
    return 0


if __name__ == "__main__":
    sys.exit(main())
