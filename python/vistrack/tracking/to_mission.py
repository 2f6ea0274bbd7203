"""An orbit plan as an autopilot mission (``OrbitPlan.to_mission``: see ``methods``) and its export
by suffix: a mission file or GeoJSON over a map."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike

from .._core import OrbitPlan, SimulationResult
from ..georeference import Georeference
from ..io.geojson import feature_collection, orbit_plan_geojson, trajectory_geojson, write_geojson
from ..mission.builder import MissionBuilder, tangent_entry
from ..mission.items import MISSION_SUFFIXES, Command
from ..mission.model import Mission, mission_geojson
from ..schema import fail

__all__ = ["export_orbit_plan", "orbit_plan_mission"]


_ORBIT_ENDS = ("loiter", "rtl", "none")


def orbit_plan_mission(plan: OrbitPlan, georeference: Georeference | Sequence[float], altitude: float | None = None,
                       *, direction: str = "ccw", speed: float | None = None, start: ArrayLike | None = None,
                       end: str = "loiter", firmware: str = "ardupilot",
                       altitude_mode: str = "relative") -> Mission:
    """An orbit plan as an autopilot mission: one NAV_LOITER_TIME per segment [t_k, t_k+1] about
    the POI's position at the segment's middle, with R(t) there, for the segment's duration.

    The autopilot circles fixed centres one after the other, so its orbit lags the moving POI by up
    to v_g (t_k+1 - t_k) / 2 and it flies no guidance law: a companion computer flying vistrack's
    vector field (eq. 74) along the plan (``vistrack simulate``) tracks far better; the mission is
    for a ground station's map, a plain autopilot, or a fallback.

    ``altitude`` / ``speed`` default to the plan's UAV (a VisibilityOrbitPlan); the mission first
    flies from ``start`` (local x, y; default home = the origin) to the tangent entry point of the
    first orbit, and ends with a loiter over the POI's last position (``end="loiter"``), a return
    to launch ("rtl") or nothing ("none"). For ArduPilot, which counts whole seconds, the segment
    boundaries are rounded to whole seconds from the start (the total stays within 0.5 s).
    """
    georeference = Georeference.from_value(georeference, "georeference")
    uav = getattr(plan, "uav", None)
    if altitude is None:
        if uav is None:
            raise fail("altitude", None, "give the flight altitude (m above the ground at the origin); "
                       "this plan does not carry its UAV")
        altitude = uav.altitude
    if speed is None and uav is not None:
        speed = uav.speed
    if end not in _ORBIT_ENDS:
        raise fail("end", end, "must be " + ", ".join(map(repr, _ORBIT_ENDS)))
    times = np.asarray(plan.times, dtype=float)
    if len(times) < 2:
        raise fail("plan.times", list(times), "an orbit plan needs at least two samples")
    builder = MissionBuilder(georeference, altitude, speed=speed, firmware=firmware, altitude_mode=altitude_mode,
                             home=start)
    boundaries = times - times[0]
    if firmware == "ardupilot":
        boundaries = np.round(boundaries)
    middles = 0.5 * (times[:-1] + times[1:])
    centers = np.array([plan.poi.position(t)[:2] for t in middles])
    radii = np.array([plan.radius(t) for t in middles])
    if np.any(radii <= 0):
        k = int(np.argmax(radii <= 0))
        raise fail(f"plan.radii[{k}]", float(radii[k]), "the POI is not visible there (MaxRadius 0): no orbit to fly")
    first = int(np.argmax(np.diff(boundaries) > 0))
    builder.waypoint(tangent_entry(builder.home_xy, centers[first], radii[first], direction))
    for k, duration in enumerate(np.diff(boundaries)):
        if duration > 0:
            builder.loiter(centers[k], radii[k], direction=direction, seconds=float(duration))
    if end == "loiter":
        last = np.asarray(plan.poi.position(times[-1]))[:2]
        builder.loiter(last, float(plan.radii[-1]), direction=direction)
    elif end == "rtl":
        builder.return_to_launch()
    return builder.build()


def export_orbit_plan(path: str | Path, plan: OrbitPlan, georeference: Georeference, *, direction: str = "ccw",
                      altitude: float | None = None, speed: float | None = None,
                      simulation: SimulationResult | None = None, firmware: str = "ardupilot") -> str:
    """Write an orbit plan by the file's suffix: a mission (``.plan``, ``.waypoints``, ``.txt``;
    :func:`orbit_plan_mission`) or GeoJSON (``.geojson``: the POI path, the orbit centres, the
    mission's route and, given a simulation, the flown trajectory). Returns a one-line summary."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in MISSION_SUFFIXES:
        raise fail("--export", str(path), "unknown format; the suffix must be one of " + ", ".join(MISSION_SUFFIXES))
    mission = orbit_plan_mission(plan, georeference, altitude, direction=direction, speed=speed, firmware=firmware)
    if suffix != ".geojson":
        mission.save(path)
        loiters = sum(item.command == Command.NAV_LOITER_TIME for item in mission.items)
        return (f"wrote {path}: {len(mission)} mission items ({loiters} timed loiters); an autopilot circles fixed "
                "centres, a companion computer flying the vector field tracks better")
    features = orbit_plan_geojson(plan, georeference)
    features += [f for f in mission_geojson(mission)["features"] if f["properties"]["kind"] in ("home", "route")]
    if simulation is not None:
        features.append(trajectory_geojson(simulation, georeference))
    write_geojson(feature_collection(features, origin=[georeference.lat, georeference.lon, georeference.alt]),
                     path)
    return f"wrote {path}: {len(features)} GeoJSON features in WGS84"
