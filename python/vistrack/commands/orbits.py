"""``vistrack orbits``: adaptive VVs along a POI path, Algorithm 1, plan JSON and figures."""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from .. import _core, schema
from ..io import footprint_environment, load_environment, read_plan
from ..plotting.orbits import figure_orbits, figure_radius
from ..progress import Progress
from ..report.orbits import write_orbits
from ..tracking.metrics import metric_along_path
from ..tracking.saved_volumes import plan_from_volumes
from .export import add_export_arguments, check_exports, export_plan
from .lists import positive_numbers
from .output import output_folder
from .types import UsageError, checked, count, length, number, speed
from .types import coordinate as coordinate_type


def register(subparsers: argparse._SubParsersAction) -> None:
    p = subparsers.add_parser(
        "orbits", help="plan the orbit locus (adaptive VVs + Algorithm 1) for a POI path",
        description="Adaptive visibility volumes along a POI path (sec. IV.B), visibility polygons at h_UAV, "
        "MaxRadius and Algorithm 1 (sec. IV.C). Writes plan.json, summary.json, orbits.png, radius.png and, with "
        "--figure-metric, metric.png (Figure 4). With --from-volumes DIR --path CSV, plans from saved VVs "
        "(vv-*.bin from `vistrack run --cache DIR`, OrbitPlanner(cache_dir=DIR) or `vistrack volumes "
        "--save-volumes DIR`) without the map: the samples are the saved VVs placed on the path, with no adaptive "
        "insertion (new VVs need the map).")
    uav, sensor, planning, poi = _core.Uav(), _core.Sensor(), _core.Planning(), _core.PoiMotion()
    p.add_argument("--map", help="city: .geojson footprints or a triangle mesh (.obj ...)")
    p.add_argument("--up", default="z", choices=["z", "y"], help="up axis of a mesh file (y: north is -Z)")
    p.add_argument("--path", help="POI path CSV, one x,y[,z] waypoint per line")
    p.add_argument("--from-plan", help="redraw the figures of a saved plan.json (no VVs recomputed)")
    p.add_argument("--from-volumes", metavar="DIR", help="plan from the saved VV files in DIR along --path, "
                   "without the map (--d-max, --resolution and --cutoff come from the files / do not apply)")
    p.add_argument("--out", default="orbits_out", help="output folder (created)")
    p.add_argument("--poi-speed", type=speed("--poi-speed"), default=poi.speed, help="v_g, m/s")
    p.add_argument("--speed", type=speed("--speed"), default=uav.speed, help="UAV speed v, m/s")
    p.add_argument("--min-turn-radius", type=length("--min-turn-radius"), default=uav.min_turn_radius, help="r_min, m")
    p.add_argument("--altitude", type=coordinate_type("--altitude"), default=uav.altitude,
                   help="h_UAV: world z of the flight plane, m")
    p.add_argument("--d-max", type=length("--d-max"), default=sensor.d_max, help="sensor range, m")
    p.add_argument("--spacing", type=length("--spacing"), default=planning.spacing, help="initial VV spacing, m")
    p.add_argument("--cutoff", type=number("--cutoff", 0.0, 1e21, low_open=True), default=planning.cutoff,
                   help="d_cutoff, m^3")
    p.add_argument("--resolution", type=number("--resolution", 0.1, 30.0), default=planning.resolution_deg,
                   help="VV ray grid step, degrees")
    p.add_argument("--min-spacing", type=length("--min-spacing"), default=planning.min_spacing,
                   help="smallest VV spacing, m")
    p.add_argument("--max-depth", type=count("--max-depth", 0, 30), default=planning.max_depth,
                   help="most halvings of one interval")
    p.add_argument("--max-volumes", type=count("--max-volumes", 1, 10**12), default=planning.max_volumes,
                   help="refuse plans that may need more VVs than this (worst case: about path length / "
                        "min_spacing; ~4.7 MB each at 1 degree); default %(default)s")
    p.add_argument("--rate-margin", type=checked("--rate-margin", schema.rate_margin), default=planning.rate_margin,
                   help="keep |dR/dt| <= (1 - margin)(v - v_g) in Algorithm 1 (default 0: Lemma 5's limit)")
    p.add_argument("--locus", default=planning.locus, choices=["smooth", "paper"], help="smooth (default): checked "
                   "against MaxRadius along the whole path, C1; paper: Algorithm 1's piecewise-linear R(t)")
    p.add_argument("--tracking-margin", type=number("--tracking-margin", 0.0, 1e7), default=planning.tracking_margin,
                   help="smooth locus: keep R(t) this far inside MaxRadius, m")
    p.add_argument("--footprints", help="GeoJSON footprints drawn under the orbits (default: the GeoJSON map, or "
                   "buildings.geojson beside a mesh --map)")
    p.add_argument("--figure-metric", action="store_true", help="also draw Figure 4 (metric along the path)")
    p.add_argument("--spacings", type=positive_numbers("--spacings", "50,25,10,1"), default=[50.0, 25.0, 10.0, 1.0],
                   help="fixed spacings for --figure-metric (default 50,25,10,1)")
    add_export_arguments(p, direction=True)
    p.add_argument("--quiet", action="store_true", help="no progress bars")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if not args.from_plan and (not args.path or not (args.map or args.from_volumes)):
        raise UsageError("--path and one of --map, --from-volumes are required (or --from-plan)")
    check_exports(args.export, args.origin, args.map)
    out = output_folder(args.out)
    background = footprint_environment(args.map, args.footprints, args.origin)
    if args.from_plan:
        plan = read_plan(args.from_plan, "--from-plan")
        if not isinstance(plan, _core.VisibilityOrbitPlan):
            raise _core.VistrackError(f"--from-plan = {args.from_plan}: not a plan of `vistrack orbits` (no VPs)")
        figure_orbits(plan, background, out / "orbits.png")
        figure_radius(plan, out / "radius.png")
        print(f"redrew {out}/orbits.png, radius.png from {args.from_plan}")
        return 0
    poi = _core.PoiPath.from_csv(args.path, args.poi_speed)
    uav = _core.Uav(speed=args.speed, min_turn_radius=args.min_turn_radius, altitude=args.altitude)
    planning = _core.Planning(spacing=args.spacing, cutoff=args.cutoff, resolution_deg=args.resolution,
                              min_spacing=args.min_spacing, max_depth=args.max_depth, rate_margin=args.rate_margin,
                              locus=args.locus, tracking_margin=args.tracking_margin,
                              max_volumes=args.max_volumes)
    _core.check_work(poi, planning)  # before the map is read
    start = time.perf_counter()
    metric = None
    if args.from_volumes:
        plan = plan_from_volumes(args.from_volumes, poi, uav, planning)
        source = f"{len(plan.times)} saved VVs from {args.from_volumes}"
    else:
        env = load_environment(args.map, args.up, origin=args.origin)
        background = background or env  # a mesh without footprints beside it: its roofs
        planner = _core.OrbitPlanner(env, _core.Sensor(d_max=args.d_max))
        with Progress("adaptive VVs", not args.quiet) as bar:
            plan = planner.plan(poi, uav, planning, bar)
        source = f"{len(plan.times)} VVs ({plan.volumes_computed} computed)"
    extra = {"seconds": time.perf_counter() - start, **({"from_volumes": str(args.from_volumes)}
                                                         if args.from_volumes else {})}
    if args.figure_metric and not args.from_volumes:
        metric = metric_along_path(planner, poi, planning, args.spacings, not args.quiet)
    write_orbits(out, plan, background, extra, metric,
                 f"{Path(args.path).name}: d_max {args.d_max:g} m, {args.resolution:g}° grid")
    print(f"{source} in {extra['seconds']:.2f} s; {plan.planning.locus} locus, R {plan.radii[0]:.1f} m -> "
          f"{plan.radii[-1]:.1f} m; " + ("feasible" if plan.feasible else f"INFEASIBLE: {plan.infeasibility}"))
    print(f"wrote {out}/plan.json, summary.json, orbits.png, radius.png" + (", metric.png" if metric else ""))
    export_plan(args.export, plan, args.origin, None if args.from_volumes else env, direction=args.direction)
    return 0
