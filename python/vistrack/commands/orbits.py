"""``vistrack orbits``: adaptive VVs along a POI path, Algorithm 1, plan JSON and figures."""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path
from typing import Optional

from .. import _core
from .. import planning as pl
from .. import saved_volumes
from . import positive_numbers


def register(subparsers: argparse._SubParsersAction) -> None:
    p = subparsers.add_parser(
        "orbits",
        help="plan the orbit locus (adaptive VVs + Algorithm 1) for a POI path",
        description="Adaptive visibility volumes along a POI path (sec. IV.B), visibility polygons at "
        "h_UAV, MaxRadius and Algorithm 1 (sec. IV.C). Writes plan.json, summary.json, orbits.png, "
        "radius.png and, with --figure-metric, metric.png (Figure 4). With --from-volumes DIR --path CSV, plans "
        "from saved VVs (vv-*.bin from `vistrack run --cache DIR`, OrbitPlanner(cache_dir=DIR) or "
        "`vistrack volumes --save-volumes DIR`) without the map: the samples are the saved VVs placed on the "
        "path, with no adaptive insertion (new VVs need the map); writes plan.json, summary.json, orbits.png "
        "(over --footprints when given) and radius.png.",
    )
    p.add_argument("--map", help="city: .geojson footprints or a triangle mesh (.obj ...)")
    p.add_argument("--up", default="y", choices=["y", "z"], help="up axis of a mesh file (default y)")
    p.add_argument("--path", help="POI path CSV, one x,y[,z] waypoint per line")
    p.add_argument("--from-plan", default=None,
                   help="redraw the figures of a saved plan.json (VPs are stored in it; no VVs recomputed)")
    p.add_argument("--from-volumes", default=None, metavar="DIR",
                   help="plan from the saved VV files in DIR along --path, without the map "
                   "(no adaptive insertion; --d-max, --resolution and --cutoff come from the files / do not apply)")
    p.add_argument("--out", default="orbits_out", help="output folder (created)")
    p.add_argument("--poi-speed", type=float, default=5.0, help="v_g, m/s")
    p.add_argument("--speed", type=float, default=_core.Uav().speed, help="UAV speed v, m/s")
    p.add_argument("--min-turn-radius", type=float, default=_core.Uav().min_turn_radius, help="r_min, m")
    p.add_argument("--altitude", type=float, default=_core.Uav().altitude, help="h_UAV above ground, m")
    p.add_argument("--d-max", type=float, default=_core.Sensor().d_max, help="sensor range, m")
    d = _core.Planning()
    p.add_argument("--spacing", type=float, default=d.spacing, help="initial VV spacing, m")
    p.add_argument("--cutoff", type=float, default=d.cutoff, help="d_cutoff, m^3")
    p.add_argument("--resolution", type=float, default=d.resolution_deg, help="VV ray grid step, degrees")
    p.add_argument("--min-spacing", type=float, default=d.min_spacing, help="smallest VV spacing, m")
    p.add_argument("--max-depth", type=int, default=d.max_depth, help="most halvings of one interval")
    p.add_argument("--rate-margin", type=float, default=d.rate_margin,
                   help="keep |dR/dt| <= (1 - margin)(v - v_g) in Algorithm 1 (default 0: Lemma 5's limit)")
    p.add_argument("--footprints", default=None,
                   help="GeoJSON footprints drawn under the orbits (default: buildings.geojson beside --map; "
                   "with --from-volumes, none unless given)")
    p.add_argument("--figure-metric", action="store_true", help="also draw Figure 4 (metric along the path)")
    p.add_argument("--spacings", type=positive_numbers("--spacings", "50,25,10,1"), default=[50.0, 25.0, 10.0, 1.0],
                   help="fixed spacings for --figure-metric (default 50,25,10,1)")
    p.add_argument("--quiet", action="store_true", help="no progress bars")
    p.set_defaults(func=run)


def footprints(args: argparse.Namespace) -> Optional[_core.Environment]:
    """What to draw under the orbits without loading the map for planning: --footprints, else
    buildings.geojson beside --map, else a GeoJSON --map itself, else nothing."""
    background = pl.footprint_environment(args.map or "", args.footprints) if (args.map or args.footprints) else None
    if background is None and args.map and str(args.map).lower().endswith((".geojson", ".json")):
        background = _core.Environment.from_geojson(str(args.map))
    return background


def redraw(args: argparse.Namespace, out: Path) -> int:
    plan = pl.read_plan(args.from_plan)
    pl.figure_orbits(plan, footprints(args), out / "orbits.png")
    pl.figure_radius(plan, out / "radius.png")
    print(f"redrew {out}/orbits.png, radius.png from {args.from_plan}")
    return 0


def from_volumes(args: argparse.Namespace, out: Path) -> int:
    if not args.path:
        raise _core.VistrackError("orbits: --from-volumes needs --path (the POI path CSV the VVs were made along)")
    poi = _core.PoiPath.from_csv(args.path, args.poi_speed)
    uav = _core.Uav(speed=args.speed, min_turn_radius=args.min_turn_radius, altitude=args.altitude)
    start = time.perf_counter()
    plan = saved_volumes.plan_from_volumes(args.from_volumes, poi, uav, args.rate_margin)
    summary = pl.plan_summary(plan)
    summary["seconds"] = time.perf_counter() - start
    summary["from_volumes"] = str(args.from_volumes)
    out.mkdir(parents=True, exist_ok=True)
    pl.write_plan(plan, out / "plan.json")
    pl.figure_orbits(plan, footprints(args), out / "orbits.png")
    pl.figure_radius(plan, out / "radius.png")
    (out / "summary.json").write_text(json.dumps(summary, indent=1))
    print(f"{len(plan.times)} saved VVs from {args.from_volumes}; R {plan.radii[0]:.1f} m -> {plan.radii[-1]:.1f} m; "
          + ("feasible" if plan.feasible else f"INFEASIBLE: {plan.infeasibility}"))
    print(f"wrote {out}/plan.json, summary.json, orbits.png, radius.png")
    return 0


def run(args: argparse.Namespace) -> int:
    out = Path(args.out)
    if args.from_volumes:
        return from_volumes(args, out)
    out.mkdir(parents=True, exist_ok=True)
    if args.from_plan:
        return redraw(args, out)
    if not args.map or not args.path:
        raise _core.VistrackError("orbits: --map and --path are required (or --from-plan PLAN.json)")
    env = pl.load_environment(args.map, args.up)
    poi = _core.PoiPath.from_csv(args.path, args.poi_speed)
    uav = _core.Uav(speed=args.speed, min_turn_radius=args.min_turn_radius, altitude=args.altitude)
    sensor = _core.Sensor(d_max=args.d_max)
    planning = _core.Planning(spacing=args.spacing, cutoff=args.cutoff, resolution_deg=args.resolution,
                              min_spacing=args.min_spacing, max_depth=args.max_depth,
                              rate_margin=args.rate_margin)
    start = time.perf_counter()
    planner = _core.OrbitPlanner(env, sensor, args.resolution)
    bar = pl.Progress("adaptive VVs", not args.quiet)
    try:
        plan = planner.plan(poi, uav, planning, bar)
    finally:
        bar.close()
    seconds = time.perf_counter() - start
    pl.write_plan(plan, out / "plan.json")
    summary = pl.plan_summary(plan)
    summary["seconds"] = seconds
    background = env if str(args.map).lower().endswith((".geojson", ".json")) else \
        pl.footprint_environment(args.map, args.footprints)
    pl.figure_orbits(plan, background if background is not None else env, out / "orbits.png")
    pl.figure_radius(plan, out / "radius.png")
    if args.figure_metric:
        results = pl.metric_along_path(planner, poi, planning, args.spacings, not args.quiet)
        pl.figure_metric(results, args.cutoff, out / "metric.png",
                         f"{Path(args.path).name}: d_max {args.d_max:g} m, {args.resolution:g}° grid")
        summary["metric_max"] = {k: (max(v.metric) if len(v.metric) else 0.0) for k, v in results.items()}
        summary["metric_volumes"] = {k: len(v.times) for k, v in results.items()}
    (out / "summary.json").write_text(json.dumps(summary, indent=1))
    print(f"{len(plan.times)} VVs ({plan.volumes_computed} computed) in {seconds:.2f} s; "
          f"R {plan.radii[0]:.1f} m -> {plan.radii[-1]:.1f} m; "
          + ("feasible" if plan.feasible else f"INFEASIBLE: {plan.infeasibility}"))
    print(f"wrote {out}/plan.json, summary.json, orbits.png, radius.png"
          + (", metric.png" if args.figure_metric else ""))
    return 0
