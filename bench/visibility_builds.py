"""Two (or more) builds of vistrack timed on the same 1-degree Charlotte VVs, interleaved: each
round runs every build once in a fresh process, so load from other work on a shared machine falls
on all of them alike. Prints medians over the rounds and the load average.

    python3 bench/visibility_builds.py --build before=/work/main/build/dev --build after=build/dev [--rounds 5]

A build is NAME=BUILD_DIR (a CMake build tree with bindings/_core*.so); --repo NAME=REPO gives
the source tree whose python/ goes with it (default: this repository); --env NAME:VAR=VALUE sets an
environment variable for that build's processes only (one build tree under two names compares,
e.g., glibc's allocator settings: --env tuned:GLIBC_TUNABLES=glibc.malloc.trim_threshold=...). Per VV (the 10 POIs of
bench/visibility_bench.py, d_max 400 m): wall ms one VV at a time (visibility_volume, which
spreads one VV over the cores when the build can), wall ms per VV of a batch of the same 10
(visibility_volumes) and VVs per second of a batch of 60, and the CPU ms per VV of that batch
(all threads: what the VV costs, less disturbed by a loaded machine than wall time). --volume-only
times VVs with their volume only (with_mesh=False; builds from issue 35's fourth session on).

Charlotte geometry (c) OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def child(repo: Path, build: str, data: Path, inner: int, volume_only: bool) -> None:
    """One sample in this process: JSON on stdout."""
    os.environ["VISTRACK_BUILD_DIR"] = build
    sys.path.insert(0, str(repo / "tests" / "python"))
    import numpy as np

    import conftest  # noqa: F401  (imports vistrack from repo/python with the build's _core)
    import vistrack as vt

    env = vt.Environment.from_mesh(str(data / "charlotte" / "uptown_charlotte.obj"), up="y")
    scene = vt.VisibilityScene(env)
    path = vt.PoiPath.from_csv(str(data / "charlotte" / "paths" / "paper_slow.csv"), speed=5.0)
    pois = np.array([path.position(t) for t in np.linspace(0.0, path.duration, 10)])
    pois60 = np.array([path.position(t) for t in np.linspace(0.0, path.duration, 60)])

    def run(fn) -> tuple[list[float], list[float]]:
        wall, cpu = [], []
        for _ in range(inner):
            c, w = time.process_time(), time.perf_counter()
            fn()
            wall.append(time.perf_counter() - w)
            cpu.append(time.process_time() - c)
        return wall, cpu

    extra = {"with_mesh": False} if volume_only else {}
    [vt.visibility_volume(scene, p, 400.0, None, 1.0, **extra) for p in pois]  # warm up
    load = os.getloadavg()[0]
    single, _ = run(lambda: [vt.visibility_volume(scene, p, 400.0, None, 1.0, **extra) for p in pois])
    batch, _ = run(lambda: vt.visibility_volumes(scene, pois, 400.0, None, 1.0, **extra))
    batch60, cpu60 = run(lambda: vt.visibility_volumes(scene, pois60, 400.0, None, 1.0, **extra))
    print(json.dumps({"load": load, "single_ms": min(single) / 10 * 1e3, "batch_ms": min(batch) / 10 * 1e3,
                      "batch_vvs_per_s": 60 / min(batch60), "batch_cpu_ms": min(cpu60) / 60 * 1e3}))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", action="append", default=[], help="NAME=BUILD_DIR (repeat)")
    parser.add_argument("--repo", action="append", default=[], help="NAME=REPO whose python/ goes with that build")
    parser.add_argument("--env", action="append", default=[], help="NAME:VAR=VALUE for that build's processes")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--inner", type=int, default=3, help="runs per sample (the best is kept)")
    data = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data"))
    parser.add_argument("--data", type=Path, default=data)
    parser.add_argument("--json", type=Path)
    parser.add_argument("--volume-only", action="store_true", help="VVs with their volume only (with_mesh=False)")
    parser.add_argument("--child", nargs=2, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        child(Path(args.child[0]), args.child[1], args.data, args.inner, args.volume_only)
        return 0
    if not args.build:
        parser.error("give at least one --build NAME=BUILD_DIR")
    if not (args.data / "charlotte" / "uptown_charlotte.obj").exists():
        print(f"real data not found under {args.data}: skipping")
        return 0
    builds = dict(b.split("=", 1) for b in args.build)
    repos = dict.fromkeys(builds, REPO) | {k: Path(v) for k, v in (r.split("=", 1) for r in args.repo)}
    envs: dict[str, dict[str, str]] = {name: dict(os.environ) for name in builds}
    for item in args.env:
        name, assignment = item.split(":", 1)
        if name not in builds or "=" not in assignment:
            parser.error(f"--env {item}: expected NAME:VAR=VALUE with NAME one of {', '.join(builds)}")
        var, value = assignment.split("=", 1)
        envs[name][var] = value
    samples: dict[str, list[dict]] = {name: [] for name in builds}
    for _ in range(args.rounds):
        for name, build in builds.items():
            out = subprocess.run([sys.executable, __file__, "--child", str(repos[name]), str(Path(build).resolve()),
                                  "--inner", str(args.inner), "--data", str(args.data)]
                                 + (["--volume-only"] if args.volume_only else []),
                                 capture_output=True, text=True, check=True, env=envs[name])
            samples[name].append(json.loads(out.stdout.strip().splitlines()[-1]))
    keys = ("single_ms", "batch_ms", "batch_vvs_per_s", "batch_cpu_ms", "load")
    kind = " with their volume only" if args.volume_only else ""
    print(f"1-degree Charlotte VVs{kind}, d_max 400 m; medians of {args.rounds} interleaved rounds (each the best of "
          f"{args.inner}); {os.cpu_count()} cores")
    header = f"{'build':>10} {'ms/VV alone':>11} {'batch ms/VV':>11} {'batch VVs/s':>11} {'CPU ms/VV':>9} {'load':>5}"
    print(header)
    print("-" * len(header))
    medians = {name: {k: statistics.median(s[k] for s in rows) for k in keys} for name, rows in samples.items()}
    for name, m in medians.items():
        print(f"{name:>10} {m['single_ms']:>11.2f} {m['batch_ms']:>11.2f} {m['batch_vvs_per_s']:>11.0f} "
              f"{m['batch_cpu_ms']:>9.2f} {m['load']:>5.1f}")
    names = list(builds)
    for other in names[1:]:
        a, b = medians[names[0]], medians[other]
        print(f"{other} vs {names[0]}: x{a['single_ms'] / b['single_ms']:.2f} alone, "
              f"x{a['batch_ms'] / b['batch_ms']:.2f} batch, x{a['batch_cpu_ms'] / b['batch_cpu_ms']:.2f} CPU per VV")
    print("goal (issue 35, quiet 2-core machine): <= 3.5 ms alone, >= 500 VVs/s in a batch")
    if args.json:
        args.json.write_text(json.dumps({"samples": samples, "medians": medians}, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
