"""``vistrack volumes``: visibility volumes (VVs) along a POI path or at given points, their
visibility polygons (VPs) at the UAV altitude and the largest inscribed orbit radius (MaxRadius).

Writes to ``--out``: ``volumes.json`` (per point: POI, VV volume, VP rings, MaxRadius), one
``vv_###.ply`` mesh per point (unless ``--no-meshes``), ``plan.png`` (VPs, inscribed circles and
building footprints from above, like Figure 5 of the visibility-volume paper) and ``vv3d.png``
(a 3D view of the first VV).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import vistrack as vt
from vistrack.io import load_environment
from vistrack.plotting import map_credit
from vistrack.progress import Progress
from vistrack.report.volumes import write_volumes
from vistrack.visibility import check_count, poi_positions

from .lists import point_list
from .output import output_folder
from .types import coordinate, count, length, number

DEFAULT_OUT = Path("vistrack-out") / "volumes"


def register(subparsers: argparse._SubParsersAction) -> None:
    sensor, uav, planning = vt.Sensor(), vt.Uav(), vt.Planning()
    p = subparsers.add_parser("volumes", help="visibility volumes, visibility polygons and MaxRadius along a "
                              "path or at points", description=__doc__,
                              formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--map", required=True, type=Path, help="GeoJSON buildings or a triangle mesh (OBJ/PLY/STL/OFF)")
    p.add_argument("--up", default="z", choices=["z", "y"], help="up axis of a mesh file (y: north is -Z)")
    where = p.add_mutually_exclusive_group(required=True)
    where.add_argument("--path", type=Path, help="POI path CSV (x,y[,z] per line): VVs every --spacing metres")
    where.add_argument("--points", type=point_list("--points"), help='POI positions "x,y[,z];x,y[,z];..." (z '
                       "defaults to 0.5 m above the surface); write --points=-1,2 when the first number is negative")
    p.add_argument("--spacing", type=length("--spacing"), default=planning.spacing,
                   help="metres between VVs along --path")
    p.add_argument("--max-volumes", type=count("--max-volumes", 1, 10**12), default=planning.max_volumes,
                   help="refuse more VVs than this along --path (default %(default)s; ~4.7 MB each at 1 degree)")
    p.add_argument("--d-max", type=length("--d-max"), default=sensor.d_max, help="maximum viewing distance d_max (m)")
    p.add_argument("--altitude", type=coordinate("--altitude"), default=uav.altitude,
                   help="UAV altitude h_UAV for the VPs (world z, m)")
    p.add_argument("--band", type=coordinate("--band"), nargs=2, metavar=("H_LO", "H_HI"),
                   help="feasible altitude band (world z)")
    p.add_argument("--resolution", type=number("--resolution", 0.1, 30.0), default=planning.resolution_deg,
                   help="angular step of the ray grid (deg)")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, help="output folder")
    p.add_argument("--save-volumes", type=Path, metavar="DIR", help="also write each whole VV as DIR/vv-NNNN.bin "
                   "(binary VV files, read back by `vistrack orbits --from-volumes DIR`)")
    p.add_argument("--no-meshes", action="store_true", help="do not write the VV meshes")
    p.add_argument("--check", action="store_true", help="validate every mesh with CGAL (closed, manifold, ...)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    output_folder(args.out)
    if args.save_volumes is not None:
        output_folder(args.save_volumes, "--save-volumes")
    path = vt.PoiPath.from_csv(str(args.path), speed=1.0) if args.path is not None else None
    if path is not None:
        check_count(path, args.spacing, args.max_volumes, "--max-volumes", "--spacing")  # before the map is read
    env = load_environment(args.map, args.up)
    scene = vt.VisibilityScene(env)
    pois = poi_positions(scene, points=args.points, path=path, spacing=args.spacing, max_volumes=args.max_volumes)
    band = tuple(args.band) if args.band else None
    with Progress("visibility volumes", not args.quiet) as bar:
        summary = write_volumes(args.out, env, scene, pois, args.d_max, args.altitude, band, args.resolution,
                                meshes=not args.no_meshes, save_volumes=args.save_volumes, check=args.check,
                                caption=map_credit(args.map), header={"map": str(args.map)}, progress=bar)
    if not args.quiet:
        radii = [r["max_radius"] for r in summary["points"]]
        print(f"{len(radii)} VVs, MaxRadius {min(radii):.1f}-{max(radii):.1f} m at z = {args.altitude:g} m; "
              f"wrote {args.out}")
    return 0
