"""The output folder of ``vistrack volumes``: volumes.json (per POI: the VV's volume, its VP at the
flight altitude and MaxRadius), one mesh per VV, binary VV files, plan.png and vv3d.png."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any, Callable, Optional

import numpy as np

from .._core import Environment, Polygon, VisibilityScene, VisibilityVolume, max_inscribed_radius
from ..io import write_json
from ..plotting.volumes import figure_visibility_polygons, figure_volume_3d
from ..visibility import Band, visibility_volumes

BATCH = 8  # VVs computed in parallel between progress updates (and held in memory at once)


def polygon_record(polygon: Polygon) -> dict[str, Any]:
    return {"outer": polygon.outer.tolist(), "holes": [h.tolist() for h in polygon.holes], "area": polygon.area}


def write_volumes(out: Path, env: Environment, scene: VisibilityScene, pois: np.ndarray, d_max: float, altitude: float,
                  band: Band = None, resolution_deg: float = 1.0, *, meshes: bool = True,
                  save_volumes: Optional[Path] = None, check: bool = False, caption: str = "",
                  header: Optional[dict[str, Any]] = None,
                  progress: Optional[Callable[[int, int], None]] = None) -> dict[str, Any]:
    """The VV of every POI (n, 3), batch by batch (GIL released), its VP at world z = ``altitude``
    (CGAL slicer) and MaxRadius; writes the folder and returns the volumes.json summary."""
    started = time.perf_counter()
    out.mkdir(parents=True, exist_ok=True)
    if save_volumes is not None:
        save_volumes.mkdir(parents=True, exist_ok=True)
    records: list[dict[str, Any]] = []
    shown: list[tuple[np.ndarray, list[Polygon], float]] = []
    first: Optional[VisibilityVolume] = None
    for start in range(0, len(pois), BATCH):
        batch = visibility_volumes(scene, pois[start:start + BATCH], d_max, band, resolution_deg)
        for k, vv in enumerate(batch, start):
            polygons = vv.slice(altitude)
            radius = max_inscribed_radius(polygons, vv.poi[:2])
            record: dict[str, Any] = {"poi": vv.poi.tolist(), "volume": vv.volume, "grid_volume": vv.grid_volume(),
                                      "max_radius": radius,
                                      "visibility_polygon": [polygon_record(p) for p in polygons]}
            if meshes:
                record["mesh"] = f"vv_{k:03d}.ply"
                vv.save(str(out / record["mesh"]))
            if save_volumes is not None:
                vv.save_binary(save_volumes / f"vv-{k:04d}.bin")
            if check:
                result = vv.check()
                record["mesh_valid"], record["mesh_problem"] = result.valid, result.problem
            records.append(record)
            shown.append((vv.poi, polygons, radius))
            first = first or vv
        if progress is not None:
            progress(len(records), len(pois))
    summary = {"format": "vistrack.volumes/1", **(header or {}), "d_max": d_max, "altitude": altitude,
               "altitude_band": list(band) if band else None, "resolution_deg": resolution_deg,
               "seconds": time.perf_counter() - started, "points": records}
    write_json(summary, out / "volumes.json")
    figure_visibility_polygons(env, shown, altitude, d_max, resolution_deg, out / "plan.png", caption)
    if first is not None:
        figure_volume_3d(scene, first, out / "vv3d.png", caption=caption)
    return summary
