"""Autopilot missions and the georeference that puts vistrack's local metres on the Earth.

- :class:`Georeference` (``vistrack.georeference``, re-exported here and as ``vt.Georeference``):
  local east-north-up metres <-> WGS84 through pyproj's topocentric conversion (an ellipsoidal
  local tangent plane, exact in 3D, not an equirectangular shortcut).
  Maps come in through it (``Environment.from_geojson`` projects longitude/latitude files with
  :func:`project_lon_lat`) and routes go out through it, so a route drawn over a building corner
  in local metres lands on that corner's latitude and longitude.
- ``items``: the MAVLink commands and frames vistrack writes and :class:`MissionItem`.
- ``model``: :class:`Mission`, MAVLink mission items with a home position, saved by suffix as a
  QGroundControl ``.plan`` (JSON), ``QGC WPL 110`` text (``.waypoints`` / ``.txt``: tab-separated,
  home as row 0, every number at full double precision) or ``.geojson``; ``reader``: :func:`load`
  reads the first two back (and files pymavlink's ``MAVWPLoader`` writes).
- ``builder``: :class:`MissionBuilder`, what a planner's ``to_mission`` needs, in local metres:
  waypoints, loiter circles joined at an entry point and left at an exit point (so the autopilot
  does not fly to the centre first), speed changes, return to launch; :func:`simplify_route`.

Each planner converts its own plans (``vistrack.tracking.to_mission``: ``OrbitPlan.to_mission``,
``vistrack.loiter.to_mission``: ``vt.loiter.Plan.to_mission``, ``vistrack.follow.to_mission``:
``vt.follow.FollowResult.to_mission``); their functions' old names here still answer.

Altitudes given to the builder are local heights z (the world z of vistrack's flight plane, e.g.
``Uav.altitude``) above the ground at the origin; a mission stores them relative to home
(``altitude_mode="relative"``, MAV_FRAME_GLOBAL_RELATIVE_ALT) or above mean sea level
(``"amsl"``, MAV_FRAME_GLOBAL, adding the georeference's altitude).
"""

from __future__ import annotations

from .._moved import forward
from ..georeference import Georeference, project_lon_lat
from .builder import MissionBuilder, arc_points, simplify_route, tangent_entry, tangent_exit
from .items import (
    ALTITUDE_MODES,
    FIRMWARE_TYPES,
    MISSION_SUFFIXES,
    VEHICLE_FIXED_WING,
    WPL_HEADER,
    Command,
    Frame,
    MissionItem,
)
from .model import Mission, mission_geojson, plan_json, waypoints_text
from .reader import load

__getattr__ = forward(__name__, {
    "orbit_plan_mission": "vistrack.tracking.to_mission",
    "export_orbit_plan": "vistrack.tracking.to_mission",
    "loiter_plan_mission": "vistrack.loiter.to_mission",
    "follow_mission": "vistrack.follow.to_mission",
})

__all__ = [
    "ALTITUDE_MODES", "FIRMWARE_TYPES", "MISSION_SUFFIXES", "VEHICLE_FIXED_WING", "WPL_HEADER", "Command", "Frame",
    "Georeference", "Mission", "MissionBuilder", "MissionItem", "arc_points", "load", "mission_geojson",
    "plan_json", "project_lon_lat", "simplify_route", "tangent_entry", "tangent_exit", "waypoints_text",
]
