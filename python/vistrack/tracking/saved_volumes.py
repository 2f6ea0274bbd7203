"""Orbit plans from saved visibility volumes (the VV cache folder), without the map.

Every ``vv-<hex>.bin`` file in a folder (written by ``OrbitPlanner(..., cache_dir=DIR)`` or
``VisibilityVolume.save_binary``) is placed on the POI path by projecting its POI (x, y) onto the
polyline; the samples then go through the planner's own steps: VP at h_UAV by
``plane_visibility_polygon``, MaxRadius by ``max_inscribed_radius`` (line 1 of Algorithm 1), the
POI-frame XOR metric of eq. (56) between neighbours, and Algorithm 1 (``circular_orbits``). No
adaptive insertion: new VVs would need the map.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .. import _core
from ..io.volumes import volume_files

__all__ = ["MAX_OFF_PATH", "arc_length_on_path", "load_samples", "plan_from_volumes"]

MAX_OFF_PATH = 1.0  # m: a VV's POI farther than this from the POI path is not a sample of it


def arc_length_on_path(waypoints: np.ndarray, xy: np.ndarray) -> tuple[float, float]:
    """(s, distance): arc length of the point of the polyline (x, y of the waypoints) nearest to xy."""
    a = np.asarray(waypoints, dtype=float)[:, :2]
    starts, ends = a[:-1], a[1:]
    seg = ends - starts
    lengths = np.hypot(seg[:, 0], seg[:, 1])
    cumulative = np.r_[0.0, np.cumsum(lengths)]
    if len(seg) == 0:
        return 0.0, float(np.hypot(*(xy - a[0])))
    squared = np.maximum(lengths**2, 1e-300)
    u = np.clip(((xy - starts) * seg).sum(axis=1) / squared, 0.0, 1.0)
    nearest = starts + u[:, None] * seg
    distances = np.hypot(*(nearest - xy).T)
    k = int(np.argmin(distances))
    return float(cumulative[k] + u[k] * lengths[k]), float(distances[k])


def load_samples(folder: str | Path, poi: "_core.PoiPath") -> tuple[list[float], list["_core.VisibilityVolume"]]:
    """Arc lengths (increasing) and the VVs at them; VistrackError naming the file for a corrupt
    file, a VV off the path, VVs of different sensor settings or grids, or two VVs at one place."""
    placed: list[tuple[float, Path, _core.VisibilityVolume]] = []
    for file in volume_files(folder):
        vv = _core.VisibilityVolume.load(file)
        xy = np.asarray(vv.poi, dtype=float)[:2]
        s, distance = arc_length_on_path(poi.waypoints, xy)
        if distance > MAX_OFF_PATH:
            raise _core.VistrackError(
                f"VV file '{file}': POI ({xy[0]:.3f}, {xy[1]:.3f}) lies {distance:.3f} m from the POI path "
                f"(more than {MAX_OFF_PATH:g} m): not a VV of this path")
        placed.append((s, file, vv))
    placed.sort(key=lambda item: item[0])
    first_file, first = placed[0][1], placed[0][2]
    for k, (s, file, vv) in enumerate(placed):
        if (vv.d_max, vv.altitude_band, vv.grid.num_elevation, vv.grid.num_azimuth) != \
                (first.d_max, first.altitude_band, first.grid.num_elevation, first.grid.num_azimuth):
            raise _core.VistrackError(
                f"VV file '{file}': d_max {vv.d_max:g}, band {vv.altitude_band}, grid "
                f"{vv.grid.num_elevation}x{vv.grid.num_azimuth} differ from '{first_file}' (d_max {first.d_max:g}, "
                f"band {first.altitude_band}, grid {first.grid.num_elevation}x{first.grid.num_azimuth}): "
                "keep the VVs of one planner run per folder")
        if k > 0 and not (s > placed[k - 1][0]):
            raise _core.VistrackError(
                f"VV file '{file}': same place on the path (s = {s:.6f} m) as '{placed[k - 1][1]}'")
    return [s for s, _, _ in placed], [vv for _, _, vv in placed]


def plan_from_volumes(folder: str | Path, poi: _core.PoiPath, uav: _core.Uav,
                      planning: _core.Planning | None = None) -> _core.VisibilityOrbitPlan:
    """The orbit plan over the saved VVs in ``folder`` along ``poi``, as OrbitPlanner.plan would
    make it from the same samples with nothing inserted: Algorithm 1 (rate_margin from
    ``planning``) and the locus it asks for (for the smooth locus, the check has only the saved
    VVs: no map to compute MaxRadius between them). The plan records the samples' median gap as
    its spacing and the VVs' grid step as its resolution (cutoff and depth stay at the defaults:
    nothing was inserted)."""
    arc_lengths, volumes = load_samples(folder, poi)
    gaps = np.diff(arc_lengths)
    base = planning if planning is not None else _core.Planning()
    recorded = _core.Planning(spacing=float(np.median(gaps)) if len(gaps) else base.spacing,
                              resolution_deg=360.0 / volumes[0].grid.num_azimuth, rate_margin=base.rate_margin,
                              locus=base.locus, tracking_margin=base.tracking_margin,
                              check_spacing=base.check_spacing, check_min_spacing=base.check_min_spacing,
                              turn_share=base.turn_share, radius_smoothing=base.radius_smoothing)
    return _core.plan_on_volumes(poi, uav, recorded, arc_lengths, volumes)
