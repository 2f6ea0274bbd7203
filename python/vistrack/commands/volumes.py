"""``vistrack volumes``: visibility volumes (VVs) along a POI path or at given points, their
visibility polygons (VPs) at the UAV altitude and the largest inscribed orbit radius (MaxRadius).

Writes to ``--out``: ``volumes.json`` (per point: POI, VV volume, VP rings, MaxRadius), one
``vv_###.ply`` mesh per point (unless ``--no-meshes``), ``plan.png`` (VPs, inscribed circles and
building footprints from above, like Figure 5 of the visibility-volume paper) and ``vv3d.png``
(a 3D view of the first VV).
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path
from typing import Any, Optional

import numpy as np

import vistrack as vt
from vistrack.planning import load_environment
from vistrack.plotting import figure_volume_3d

DEFAULT_OUT = Path("vistrack-out") / "volumes"
BATCH = 8  # VVs per parallel batch between progress updates


def register(subparsers: Any) -> None:
    sensor, uav, planning = vt.Sensor(), vt.Uav(), vt.Planning()
    p = subparsers.add_parser(
        "volumes",
        help="visibility volumes, visibility polygons and MaxRadius along a path or at points",
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--map", required=True, type=Path, help="GeoJSON buildings or a triangle mesh (OBJ/PLY/STL/OFF)")
    p.add_argument("--up", default="z", choices=["z", "y"], help="up axis of a mesh file (y: north is -Z)")
    where = p.add_mutually_exclusive_group(required=True)
    where.add_argument("--path", type=Path, help="POI path CSV (x,y[,z] per line): VVs every --spacing metres")
    where.add_argument("--points", help='POI positions "x,y[,z];x,y[,z];..." (z defaults to 0.5 m above the surface); write --points=-1,2 when the first number is negative')
    p.add_argument("--spacing", type=float, default=planning.spacing, help="metres between VVs along --path")
    p.add_argument("--d-max", type=float, default=sensor.d_max, help="maximum viewing distance d_max (m)")
    p.add_argument("--altitude", type=float, default=uav.altitude, help="UAV altitude h_UAV for the VPs (world z, m)")
    p.add_argument("--band", type=float, nargs=2, metavar=("H_LO", "H_HI"), help="feasible altitude band (world z)")
    p.add_argument("--resolution", type=float, default=planning.resolution_deg, help="angular step of the ray grid (deg)")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, help="output folder")
    p.add_argument("--save-volumes", type=Path, metavar="DIR",
                   help="also write each whole VV as DIR/vv-NNNN.bin (binary VV files, read back by "
                   "`vistrack orbits --from-volumes DIR`)")
    p.add_argument("--no-meshes", action="store_true", help="do not write the VV meshes")
    p.add_argument("--check", action="store_true", help="validate every mesh with CGAL (closed, manifold, ...)")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=run)


def parse_points(text: str) -> list[list[float]]:
    points = []
    for k, item in enumerate(filter(None, (s.strip() for s in text.split(";")))):
        try:
            values = [float(v) for v in item.split(",")]
        except ValueError:
            raise vt.VistrackError(f"--points[{k}] = {item!r}: expected x,y or x,y,z numbers") from None
        if len(values) not in (2, 3) or not np.all(np.isfinite(values)):
            raise vt.VistrackError(f"--points[{k}] = {item!r}: expected 2 or 3 finite numbers")
        points.append(values)
    if not points:
        raise vt.VistrackError(f"--points = {text!r}: no points")
    return points


POI_HEIGHT = 0.5  # m above the surface for points given without z (as in the data's paths)


def poi_positions(args: argparse.Namespace, scene: vt.VisibilityScene) -> np.ndarray:
    """POI positions (n, 3): along the path every --spacing metres (ends included), or the given
    points; z is the height above the surface (0.5 m when not given)."""
    if args.path is not None:
        if not args.path.is_file():
            raise vt.VistrackError(f"--path = {args.path}: no such file")
        if not (args.spacing > 0 and np.isfinite(args.spacing)):
            raise vt.VistrackError(f"--spacing = {args.spacing}: must be a finite number > 0")
        poi = vt.PoiPath.from_csv(str(args.path), speed=1.0)  # speed 1: time = arc length
        count = max(2, int(np.ceil(poi.length / args.spacing)) + 1)
        points = np.array([poi.position(s) for s in np.linspace(0.0, poi.length, count)])
    else:
        given = parse_points(args.points)
        points = np.array([p if len(p) == 3 else [p[0], p[1], np.nan] for p in given])
    points[:, 2] = np.where(np.isfinite(points[:, 2]), points[:, 2], POI_HEIGHT)
    return scene.poi_on_surface(points)


def polygon_json(polygon: vt.Polygon) -> dict[str, Any]:
    return {"outer": polygon.outer.tolist(), "holes": [h.tolist() for h in polygon.holes], "area": polygon.area}


def run(args: argparse.Namespace) -> int:
    started = time.perf_counter()
    env = load_environment(args.map, args.up)
    scene = vt.VisibilityScene(env)
    band: Optional[tuple[float, float]] = tuple(args.band) if args.band else None
    pois = poi_positions(args, scene)
    out: Path = args.out
    out.mkdir(parents=True, exist_ok=True)
    if args.save_volumes:
        args.save_volumes.mkdir(parents=True, exist_ok=True)

    from tqdm import tqdm

    records: list[dict[str, Any]] = []
    first: Optional[vt.VisibilityVolume] = None
    shown: list[tuple[np.ndarray, list[vt.Polygon], float]] = []
    with tqdm(total=len(pois), desc="visibility volumes", unit="VV", disable=args.quiet) as bar:
        for start in range(0, len(pois), BATCH):
            batch = vt.visibility_volumes(scene, pois[start : start + BATCH], args.d_max, band, args.resolution)
            for k, vv in enumerate(batch, start):
                polygons = vv.slice(args.altitude)
                radius = vt.max_inscribed_radius(polygons, vv.poi[:2])
                record: dict[str, Any] = {
                    "index": k,
                    "poi": vv.poi.tolist(),
                    "volume": vv.volume,
                    "grid_volume": vv.grid_volume(),
                    "max_radius": radius,
                    "visibility_polygon": [polygon_json(p) for p in polygons],
                }
                if not args.no_meshes:
                    name = f"vv_{k:03d}.ply"
                    vv.save(str(out / name))
                    record["mesh"] = name
                if args.save_volumes:
                    vv.save_binary(args.save_volumes / f"vv-{k:04d}.bin")
                if args.check:
                    check = vv.check()
                    record["mesh_valid"] = check.valid
                    record["mesh_problem"] = check.problem
                records.append(record)
                shown.append((vv.poi, polygons, radius))
                if first is None:
                    first = vv
            bar.update(len(batch))

    summary = {
        "format": "vistrack.volumes/1",
        "map": str(args.map),
        "d_max": args.d_max,
        "altitude": args.altitude,
        "altitude_band": list(band) if band else None,
        "resolution_deg": args.resolution,
        "seconds": time.perf_counter() - started,
        "points": records,
    }
    (out / "volumes.json").write_text(json.dumps(summary, indent=1))
    plot_plan(env, shown, args, out / "plan.png")
    if first is not None:
        figure_volume_3d(scene, first, out / "vv3d.png", caption=attribution(args))
    if not args.quiet:
        radii = [r["max_radius"] for r in records]
        print(f"{len(records)} VVs, MaxRadius {min(radii):.1f}-{max(radii):.1f} m at z = {args.altitude:g} m; wrote {out}")
    return 0


def attribution(args: argparse.Namespace) -> str:
    text = f"map: {args.map.name}"
    if "charlotte" in str(args.map).lower():
        text += " (buildings © OpenStreetMap contributors, ODbL)"
    return text


def plot_plan(env: vt.Environment, shown: list, args: argparse.Namespace, path: Path) -> None:
    """Figure 5 style: VPs at h_UAV, inscribed circles and POIs over the building footprints."""
    from matplotlib.patches import Circle, PathPatch

    from ..plotting import footprint_path, new_figure, plot_buildings, save_figure

    fig, ax = new_figure((9.0, 8.0))
    plot_buildings(ax, env, cmap="Blues", edgecolor="tab:blue")
    # At most two VPs drawn filled (first and last, as the paper's i-th and j-th), all circles.
    colors = ["magenta", "c"]
    picks = [0, len(shown) - 1] if len(shown) > 1 else [0]
    for color, k in zip(colors, picks):
        poi, polygons, radius = shown[k]
        for polygon in polygons:
            ax.add_patch(PathPatch(footprint_path(polygon.outer, polygon.holes), facecolor=color, alpha=0.18,
                                   edgecolor=color, linewidth=1.2, zorder=3))
    for k, (poi, polygons, radius) in enumerate(shown):
        color = colors[0] if k == 0 else colors[1] if k == len(shown) - 1 else "0.35"
        if radius > 0:
            ax.add_patch(Circle(poi[:2], radius, fill=False, linestyle="--", edgecolor=color, linewidth=1.0, zorder=4))
        ax.plot(poi[0], poi[1], "x", color=color, markersize=7, zorder=5)
    pois = np.array([s[0] for s in shown])
    pad = args.d_max
    ax.set_xlim(pois[:, 0].min() - pad, pois[:, 0].max() + pad)
    ax.set_ylim(pois[:, 1].min() - pad, pois[:, 1].max() + pad)
    ax.set_aspect("equal")
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    ax.set_title(f"Visibility polygons at z = {args.altitude:g} m, inscribed orbits (d_max = {args.d_max:g} m, "
                 f"{args.resolution:g}°)")
    ax.text(0.01, 0.01, attribution(args), transform=ax.transAxes, fontsize=7, color="0.3")
    save_figure(fig, path)
