"""Instructions per 1-degree Charlotte VV on one thread, counted by callgrind (deterministic, unlike
wall time on a shared machine): the 10 POIs of bench/visibility_bench.py, d_max 400 m.

    VISTRACK_BUILD_DIR=build/dev valgrind --tool=callgrind --callgrind-out-file=/tmp/vv.callgrind \\
        --toggle-collect='vistrack::visibility_volume_with_cost*' python3 bench/vv_instructions.py
    callgrind_annotate /tmp/vv.callgrind | head -30   # the total over the 10 VVs, and where it goes

The script computes each VV once with vt._core.visibility_volume_cost(parallel=False) (the whole VV
on the calling thread, so callgrind sees every instruction) and prints the rays it traced; divide
callgrind's total ("PROGRAM TOTALS", counted only inside visibility_volume_with_cost) by 10.

Charlotte geometry (c) OpenStreetMap contributors (ODbL).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
if os.environ.get("VISTRACK_BUILD_DIR"):
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import conftest  # noqa: F401  (imports vistrack from python/ with the build tree's _core)

import vistrack as vt
from vistrack import _core


def main() -> int:
    data = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data"))
    env = vt.Environment.from_mesh(str(data / "charlotte" / "uptown_charlotte.obj"), up="y")
    scene = vt.VisibilityScene(env)
    poi = vt.PoiPath.from_csv(str(data / "charlotte" / "paths" / "paper_slow.csv"), speed=5.0)
    rays = 0
    for t in np.linspace(0.0, poi.duration, 10):
        _vv, cost = _core.visibility_volume_cost(scene, poi.position(t), 400.0, None, 1.0, False)
        rays += cost.rays_traced + cost.refine_rays
    print(f"10 VVs on one thread, {rays / 10:.0f} rays handed to Embree per VV")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
