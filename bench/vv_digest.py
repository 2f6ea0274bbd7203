"""One SHA-256 digest of 48 Charlotte VVs (grid intervals, mesh vertices and faces, volume), to check
that a refactor of the VV code is bit-identical: run it on the trees before and after and compare.
The VVs: 6 POIs each of paper_slow at d_max 400 m and paper_small at 100 m without a band, and of
paper_slow at 300 m in the bands (0, 60) and (40, 80) m (star and shell meshes), each computed in a
batch (one VV per thread) and alone (one VV over every thread).

    VISTRACK_BUILD_DIR=build/dev python3 bench/vv_digest.py

Charlotte geometry (c) OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import hashlib
import os
import sys
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import vistrack as vt

CASES = (("paper_slow", 400.0, None), ("paper_small", 100.0, None), ("paper_slow", 300.0, (0.0, 60.0)),
         ("paper_slow", 300.0, (40.0, 80.0)))


def main() -> int:
    data = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data"))
    mesh = data / "charlotte" / "uptown_charlotte.obj"
    if not mesh.exists():
        print(f"skipped: {mesh} is missing (the shared data, ../shared/data)")
        return 0
    scene = vt.VisibilityScene(vt.Environment.from_mesh(str(mesh), up="y"))
    digest = hashlib.sha256()
    for name, d_max, band in CASES:
        poi = vt.PoiPath.from_csv(str(data / "charlotte" / "paths" / f"{name}.csv"), speed=5.0)
        pois = np.array([poi.position(t) for t in np.linspace(0.0, poi.duration, 6)])
        vvs = vt.visibility_volumes(scene, pois, d_max, band, 1.0)
        vvs += [vt.visibility_volume(scene, p, d_max, band, 1.0) for p in pois]
        for vv in vvs:
            for array in (vv.near, vv.far, vv.vertices, vv.faces):
                digest.update(np.ascontiguousarray(array).tobytes())
            digest.update(np.float64(vv.volume).tobytes())
    print(digest.hexdigest())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
