"""Orbit plans from saved visibility volumes (the VV cache folder), without the map.

Every ``vv-<hex>.bin`` file in a folder (written by ``OrbitPlanner(..., cache_dir=DIR)`` or
``VisibilityVolume.save_binary``) is placed on the POI path by projecting its POI (x, y) onto the
polyline; the samples then go through the planner's own steps: VP at h_UAV by
``plane_visibility_polygon``, MaxRadius by ``max_inscribed_radius`` (line 1 of Algorithm 1), the
POI-frame XOR metric of eq. (56) between neighbours, and Algorithm 1 (``circular_orbits``). No
adaptive insertion: new VVs would need the map.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from . import _core

MAX_OFF_PATH = 1.0  # m: a VV's POI farther than this from the POI path is not a sample of it


def volume_files(folder: str | Path) -> list[Path]:
    """The VV files (``*.bin``) in a folder, sorted by name; VistrackError when none."""
    root = Path(folder)
    if not root.is_dir():
        raise _core.VistrackError(f"--from-volumes = {folder}: is not a folder")
    files = sorted(p for p in root.iterdir() if p.is_file() and p.suffix == ".bin")
    if not files:
        raise _core.VistrackError(f"--from-volumes = {folder}: no VV files (*.bin) in the folder")
    return files


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


def _ring(points: np.ndarray) -> list[list[float]]:
    return [[float(x), float(y)] for x, y in np.asarray(points)]


def plan_from_volumes(folder: str | Path, poi: "_core.PoiPath", uav: "_core.Uav",
                      rate_margin: float = 0.0) -> "_core.VisibilityOrbitPlan":
    """The orbit plan (Algorithm 1, |dR/dt| <= (1 - rate_margin)(v - v_g)) over the saved VVs in
    `folder` along `poi`, as OrbitPlanner.plan would make it from the same samples with nothing
    inserted."""
    uav.validate()
    planning = _core.Planning(rate_margin=rate_margin)
    arc_lengths, volumes = load_samples(folder, poi)
    times = [s / poi.speed for s in arc_lengths]
    polygons = [_core.plane_visibility_polygon(vv, uav.altitude) for vv in volumes]
    centres = [np.asarray(vv.poi, dtype=float)[:2] for vv in volumes]
    max_radii = [_core.max_inscribed_radius(vp, c) for vp, c in zip(polygons, centres)]
    metric = [_core.xor_volume(a, b, frame="poi") for a, b in zip(volumes[:-1], volumes[1:])]
    orbits = _core.circular_orbits(times, max_radii, uav, poi.speed, planning.rate_margin)
    first = volumes[0]
    sensor: dict = {"d_max": first.d_max}
    if first.altitude_band is not None:
        sensor["altitude_band"] = list(first.altitude_band)
    gaps = np.diff(arc_lengths)
    text = json.dumps({
        "format": "vistrack.visibility_orbit_plan/1",
        "poi": {"waypoints": np.asarray(poi.waypoints).tolist(), "speed": poi.speed},
        "times": times,
        "radii": list(orbits.radii),
        "max_radii": max_radii,
        "metric": metric,
        "feasible": orbits.feasible,
        "infeasibility": orbits.infeasibility,
        "uav": {"speed": uav.speed, "min_turn_radius": uav.min_turn_radius, "altitude": uav.altitude},
        "sensor": sensor,
        # The samples were chosen by whoever saved the VVs: spacing is their median gap, grid step
        # the saved azimuth step; cutoff and depth stay at the defaults (nothing was inserted here).
        "planning": {"spacing": float(np.median(gaps)) if len(gaps) else planning.spacing,
                     "cutoff": planning.cutoff, "resolution_deg": 360.0 / first.grid.num_azimuth,
                     "min_spacing": planning.min_spacing, "max_depth": planning.max_depth,
                     "rate_margin": planning.rate_margin},
        "centers": [c.tolist() for c in centres],
        "arc_lengths": arc_lengths,
        "depths": [0] * len(times),
        "radius_rates": list(orbits.radius_rates),
        "min_feasible_radius": orbits.min_feasible_radius,
        "failing_samples": list(orbits.failing_samples),
        "volumes_computed": 0,
        "polygons": [[{"outer": _ring(p.outer), "holes": [_ring(h) for h in p.holes]} for p in vp] for vp in polygons],
        "vv_volumes": [vv.volume for vv in volumes],
    })
    return _core.VisibilityOrbitPlan.from_json(text)
