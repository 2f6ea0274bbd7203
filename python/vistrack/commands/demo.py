"""``vistrack demo``: the whole job on the embedded synthetic downtown, stage by stage.

Each stage is a function of the shared :class:`DemoRun`; later stages (visibility volumes,
orbits, simulation) are appended to :data:`STAGES` and add their own entries to the summary.
"""

from __future__ import annotations

import argparse
import json
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Optional

import numpy as np

import vistrack as vt

DEFAULT_OUT = Path("vistrack-out") / "demo"

# Where the POI drives: nearest road nodes to these points, joined by shortest road routes
# (three turns, 800 m on the demo grid).
POI_VIA_POINTS = [(-290.0, -210.0), (-95.0, -210.0), (-95.0, 0.0), (95.0, 0.0), (95.0, 205.0)]
POI_SPEED = 5.0  # m/s


@dataclass
class DemoRun:
    out: Path
    quiet: bool
    env: Optional[vt.Environment] = None
    poi: Optional[vt.PoiPath] = None
    summary: dict[str, Any] = field(default_factory=dict)
    files: list[Path] = field(default_factory=list)


def road_route(roads: vt.RoadNetwork, via_points: list[tuple[float, float]]) -> list[int]:
    """Node sequence through the road nodes nearest to the via points, shortest route between each."""
    via = [roads.nearest_node(np.asarray(p)) for p in via_points]
    nodes = [via[0]]
    for a, b in zip(via, via[1:]):
        nodes += roads.shortest_route(a, b)[1:]
    return nodes


def stage_city(run: DemoRun) -> None:
    env = vt.Environment.demo()
    run.env = env
    run.summary["city"] = {
        "buildings": env.num_buildings,
        "triangles": env.num_triangles,
        "tallest_m": env.max_height,
        "bounds_m": env.bounds.tolist(),
        "road_nodes": len(env.roads.nodes),
        "road_edges": len(env.roads.edges),
        "fingerprint": f"{env.fingerprint:016x}",
    }


def stage_poi_path(run: DemoRun) -> None:
    assert run.env is not None
    nodes = road_route(run.env.roads, POI_VIA_POINTS)
    run.poi = vt.PoiPath.from_nodes(run.env.roads, nodes, POI_SPEED)
    headings = np.arctan2(*np.diff(run.poi.waypoints[:, :2], axis=0).T[::-1])
    turns = int(np.count_nonzero(np.abs(np.diff(np.unwrap(headings))) > 1e-9))
    run.summary["poi_path"] = {
        "speed_mps": run.poi.speed,
        "length_m": run.poi.length,
        "duration_s": run.poi.duration,
        "turns": turns,
        "road_nodes": nodes,
        "waypoints_m": run.poi.waypoints[:, :2].tolist(),
        "node_times_s": list(run.poi.node_times),
    }


def stage_city_figure(run: DemoRun) -> None:
    from vistrack.plotting import new_figure, plot_city, save_figure

    assert run.env is not None and run.poi is not None
    fig, ax = new_figure((8.5, 7.5))
    plot_city(ax, run.env, run.poi,
              title=f"vistrack demo city: {run.env.num_buildings} buildings, "
                    f"POI path {run.poi.length:.0f} m at {run.poi.speed:g} m/s")
    run.files.append(save_figure(fig, run.out / "city.png"))


STAGES: list[tuple[str, Callable[[DemoRun], None]]] = [
    ("city", stage_city),
    ("POI path", stage_poi_path),
    ("city figure", stage_city_figure),
]


def run_demo(out: Path, quiet: bool = False) -> DemoRun:
    """Run every stage, then write summary.json; returns the run (environment, path, summary)."""
    from tqdm import tqdm

    out.mkdir(parents=True, exist_ok=True)
    run = DemoRun(out=out, quiet=quiet)
    timings: dict[str, float] = {}
    with tqdm(STAGES, desc="vistrack demo", unit="stage", disable=quiet) as bar:
        for name, stage in bar:
            bar.set_postfix_str(name)
            start = time.perf_counter()
            stage(run)
            timings[name] = round(time.perf_counter() - start, 4)
    run.summary["version"] = vt.__version__
    run.summary["stage_seconds"] = timings
    summary_path = out / "summary.json"
    summary_path.write_text(json.dumps(run.summary, indent=2) + "\n")
    run.files.append(summary_path)
    return run


def main(args: argparse.Namespace) -> int:
    run = run_demo(Path(args.out), quiet=args.quiet)
    city, path = run.summary["city"], run.summary["poi_path"]
    print(f"demo city: {city['buildings']} buildings, {city['triangles']} triangles, "
          f"tallest {city['tallest_m']:.0f} m; POI path {path['length_m']:.0f} m, "
          f"{path['duration_s']:.0f} s, {path['turns']} turns")
    for file in run.files:
        print(f"wrote {file}")
    return 0


def register(subparsers: Any) -> None:
    parser = subparsers.add_parser(
        "demo", help="run the pipeline on the embedded synthetic downtown",
        description="Build the embedded demo city and a POI path on its roads; write city.png "
                    "and summary.json into the output folder.")
    parser.add_argument("--out", default=str(DEFAULT_OUT),
                        help=f"output folder (default: ./{DEFAULT_OUT})")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.set_defaults(func=main)
