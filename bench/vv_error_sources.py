"""Where a 1-degree VV mesh's volume differs from the 0.2-degree brute-force reference
(vistrack.visibility.reference_rays, the rays behind bench/accuracy.py's reference_volume), cell by
cell: the mesh's volume in each cell of the reference grid (ReferenceRays.mesh_volumes: each face's
tetrahedron with g, by the direction of its centroid) against the reference ray's cone there, summed
over two parts of the sphere:

- horizon: within one degree of the horizon (whole mesh rows, so no face straddles the border),
  where a street-level POI sees the ground meet the buildings' feet, and the ground/d_max crease;
- elsewhere: the rest (walls at the jumps, the d_max sphere's flat chords and the creases where a
  building crosses d_max, the buildings' faces). Finer parts are not reliable this way: a face's
  volume goes to its centroid's cell, and the large faces beside a wall straddle any border
  drawn near it.

The d_max sphere's own flat faces: `./build/dev/tests/cpp/visibility_test --gtest_filter='*OpenField*'`
prints an open field's error against the analytic ball.

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
from vistrack.visibility import ReferenceRays, reference_rays

DATA = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data"))
REFERENCE_DEG = 0.2
MESH_DEG = 1.0


def parts(rays: ReferenceRays) -> dict[str, np.ndarray]:
    """The two parts of the docstring, as masks over the rays (cells)."""
    elevation = np.degrees(np.arcsin(np.clip(rays.directions[:, 2], -1.0, 1.0)))
    horizon = np.abs(elevation) < MESH_DEG
    return {"horizon": horizon, "elsewhere": ~horizon}


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
        difference = rays.mesh_volumes(vv) - rays.solid_angles * rays.distances**3 / 3.0
        shares = [100.0 * difference[mask].sum() / reference for mask in parts(rays).values()]
        errors.append(vv.volume / reference - 1.0)
        print(f"{k:3d} {100.0 * (vv.volume / reference - 1.0):+8.4f} "
              + " ".join(f"{share:+10.4f}" for share in shares))
    size = 100.0 * np.abs(errors)
    print(f"|mesh / reference - 1| max {size.max():.4f} %, 90th percentile {np.percentile(size, 90):.4f} %, mean "
          f"{size.mean():.4f} %, median {np.median(size):.4f} %; the mesh below the reference at "
          f"{int(np.sum(np.asarray(errors) < 0.0))} of {len(errors)} POIs")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
