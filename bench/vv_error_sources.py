"""Where a 1-degree VV mesh's volume differs from the 0.2-degree brute-force reference
(vistrack.visibility.reference_rays, the rays behind bench/accuracy.py's reference_volume), cell by
cell: the mesh's volume in each cell of the reference grid (each face's tetrahedron with g, by the
direction of its centroid: they sum to the mesh's volume exactly) against the reference ray's cone
there, summed over two parts of the sphere:

- horizon: within one degree of the horizon (whole mesh rows, so no face straddles the border),
  where a street-level POI sees the ground meet the buildings' feet, and the ground/d_max crease;
- elsewhere: the rest (walls at the jumps, the d_max sphere's flat chords and the creases where a
  building crosses d_max, the buildings' faces). Finer parts are not reliable this way: a face's
  volume goes to its centroid's cell, and the large faces beside a wall straddle any border
  drawn near it.

Also the d_max sphere alone: an open field, g 150 m up, against the exact volume.

    VISTRACK_BUILD_DIR=build/dev python3 bench/vv_error_sources.py [--path paper_small --d-max 100]

Charlotte geometry (c) OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import numpy as np

import vistrack as vt
from vistrack.visibility import reference_rays

DATA = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data"))
REFERENCE_DEG = 0.2
MESH_DEG = 1.0


def mesh_volume_per_cell(vv: vt.VisibilityVolume, rays) -> np.ndarray:
    """The VV mesh's volume binned by the reference grid's cells: each face's signed tetrahedron
    with g (the divergence theorem: they sum to the mesh's volume exactly) goes to the cell of
    its centroid's direction. Radial walls hold no volume (their planes pass through g)."""
    g = np.asarray(vv.poi)
    corners = np.asarray(vv.vertices)[np.asarray(vv.faces)] - g  # (faces, 3, 3)
    six = np.einsum("ij,ij->i", corners[:, 0], np.cross(corners[:, 1], corners[:, 2]))
    centroid = corners.mean(axis=1)
    norm = np.linalg.norm(centroid, axis=1)
    keep = norm > 0.0
    direction = centroid[keep] / norm[keep, None]
    elevation = np.arcsin(np.clip(direction[:, 2], -1.0, 1.0))
    azimuth = np.mod(np.arctan2(direction[:, 1], direction[:, 0]), 2.0 * np.pi)
    row = np.clip(((elevation + np.pi / 2) / (np.pi / rays.num_elevation)).astype(int), 0, rays.num_elevation - 1)
    column = np.clip((azimuth / (2.0 * np.pi / rays.num_azimuth)).astype(int), 0, rays.num_azimuth - 1)
    return np.bincount(row * rays.num_azimuth + column, weights=six[keep] / 6.0,
                       minlength=rays.num_elevation * rays.num_azimuth)


def parts(rays) -> dict[str, np.ndarray]:
    """The two parts of the docstring, as masks over the rays (cells)."""
    elevation = np.degrees(np.arcsin(np.clip(rays.directions[:, 2], -1.0, 1.0)))
    horizon = np.abs(elevation) < MESH_DEG
    return {"horizon": horizon, "elsewhere": ~horizon}


def open_field_sphere() -> float:
    """Relative error of a 1-degree VV in an open field, g 150 m up, d_max 100 m (the whole ball)."""
    box = np.array([[5000, 5000, 0], [5001, 5000, 0], [5001, 5001, 0], [5000, 5001, 0],
                    [5000, 5000, 1], [5001, 5000, 1], [5001, 5001, 1], [5000, 5001, 1]], float)
    faces = np.array([[4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6],
                      [3, 0, 4], [3, 4, 7]])
    scene = vt.VisibilityScene(vt.Environment.from_triangles(box, faces))
    vv = vt.visibility_volume(scene, np.array([0.0, 0.0, 150.0]), 100.0, None, MESH_DEG)
    return vv.volume / (4.0 / 3.0 * np.pi * 100.0**3) - 1.0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data", type=Path, default=DATA)
    parser.add_argument("--path", default="paper_small", help="a path of charlotte/paths (paper_small, paper_slow)")
    parser.add_argument("--d-max", type=float, default=100.0)
    parser.add_argument("--points", type=int, default=10, help="POIs along the path (as bench/accuracy.py)")
    args = parser.parse_args()
    city = args.data / "charlotte" / "uptown_charlotte.obj"
    if not city.exists():
        print(f"skipped: {city} is absent (the shared data folder)")
        return 0
    scene = vt.VisibilityScene(vt.Environment.from_mesh(str(city), up="y"))
    path = vt.PoiPath.from_csv(str(args.data / "charlotte" / "paths" / f"{args.path}.csv"), 5.0)
    times = np.linspace(0.0, path.duration, args.points)
    print(f"{args.path}, d_max {args.d_max:.0f} m, 1-degree VVs against {REFERENCE_DEG}-degree reference rays; "
          "mesh - reference as % of the reference volume, whole and in two parts")
    print(f"{'POI':>3} {'mesh':>8} {'horizon':>10} {'elsewhere':>10}")
    errors = []
    for k, t in enumerate(times):
        g = np.ravel(scene.poi_on_surface(np.ravel(path.position(t))))
        rays = reference_rays(scene, g, args.d_max, REFERENCE_DEG)
        vv = vt.visibility_volume(scene, g, args.d_max, None, MESH_DEG)
        reference = rays.volume
        difference = mesh_volume_per_cell(vv, rays) - rays.solid_angles * rays.distances**3 / 3.0
        shares = [100.0 * difference[mask].sum() / reference for mask in parts(rays).values()]
        errors.append(vv.volume / reference - 1.0)
        print(f"{k:3d} {100.0 * (vv.volume / reference - 1.0):+8.4f} "
              + " ".join(f"{share:+10.4f}" for share in shares))
    size = 100.0 * np.abs(errors)
    print(f"|mesh / reference - 1| max {size.max():.4f} %, 90th percentile {np.percentile(size, 90):.4f} %, mean "
          f"{size.mean():.4f} %, median {np.median(size):.4f} %; the mesh below the reference at "
          f"{int(np.sum(np.asarray(errors) < 0.0))} of {len(errors)} POIs")
    print(f"the d_max sphere alone (open field, g 150 m up): {100.0 * open_field_sphere():+.4f} %")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
