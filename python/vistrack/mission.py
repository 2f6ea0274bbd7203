"""Autopilot missions and the georeference that puts vistrack's local metres on the Earth.

- :class:`Georeference` (``vistrack.georeference``, re-exported here and as ``vt.Georeference``):
  local east-north-up metres <-> WGS84 through pyproj's topocentric conversion (an ellipsoidal
  local tangent plane, exact in 3D, not an equirectangular shortcut).
  Maps come in through it (``Environment.from_geojson`` projects longitude/latitude files with
  :func:`project_lon_lat`) and routes go out through it, so a route drawn over a building corner
  in local metres lands on that corner's latitude and longitude.
- :class:`Mission`: MAVLink mission items with a home position, saved by suffix as a
  QGroundControl ``.plan`` (JSON), ``QGC WPL 110`` text (``.waypoints`` / ``.txt``: tab-separated,
  home as row 0, every number at full double precision) or ``.geojson``; :func:`load` reads the
  first two back (and files pymavlink's ``MAVWPLoader`` writes).
- :class:`MissionBuilder`: what a planner's ``to_mission`` needs, in local metres: waypoints,
  loiter circles joined at an entry point and left at an exit point (so the autopilot does not fly
  to the centre first), speed changes, return to launch. :func:`orbit_plan_mission` turns an orbit
  plan into timed loiters (``OrbitPlan.to_mission`` calls it), :func:`loiter_plan_mission` a loiter
  plan into its path with NAV_LOITER_TURNS (``vt.loiter.Plan.to_mission``), :func:`follow_mission`
  a follow run's 1 Hz waypoints, decimated (``vt.follow.FollowResult.to_mission``).

Altitudes given to the builder are local heights z (the world z of vistrack's flight plane, e.g.
``Uav.altitude``) above the ground at the origin; a mission stores them relative to home
(``altitude_mode="relative"``, MAV_FRAME_GLOBAL_RELATIVE_ALT) or above mean sea level
(``"amsl"``, MAV_FRAME_GLOBAL, adding the georeference's altitude).
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from enum import IntEnum
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from .georeference import Georeference, degrees, project_lon_lat
from .io import read_text
from .schema import fail, number

if TYPE_CHECKING:
    from ._core import OrbitPlan, SimulationResult
    from ._core.loiter import Plan as LoiterPlan

__all__ = [
    "ALTITUDE_MODES", "FIRMWARE_TYPES", "MISSION_SUFFIXES", "Command", "Frame", "Georeference", "Mission",
    "MissionBuilder", "MissionItem", "arc_points", "export_orbit_plan", "follow_mission", "load", "loiter_plan_mission",
    "orbit_plan_mission", "project_lon_lat", "simplify_route", "tangent_entry", "tangent_exit",
]

# ---------------------------------------------------------------------------------------------
# Mission items and files
# ---------------------------------------------------------------------------------------------


class Command(IntEnum):
    """The MAVLink commands vistrack writes (MAV_CMD_*)."""

    NAV_WAYPOINT = 16
    NAV_LOITER_UNLIM = 17
    NAV_LOITER_TURNS = 18
    NAV_LOITER_TIME = 19
    NAV_RETURN_TO_LAUNCH = 20
    DO_CHANGE_SPEED = 178


class Frame(IntEnum):
    """The MAVLink frames vistrack writes (MAV_FRAME_*)."""

    GLOBAL = 0               # latitude, longitude, altitude above mean sea level
    MISSION = 2              # no coordinate: a command such as DO_CHANGE_SPEED
    GLOBAL_RELATIVE_ALT = 3  # altitude relative to home


# altitude_mode -> the frame of items with a coordinate, and QGroundControl's AltitudeMode.
ALTITUDE_MODES = {"relative": Frame.GLOBAL_RELATIVE_ALT, "amsl": Frame.GLOBAL}
_QGC_ALTITUDE_MODE = {Frame.GLOBAL_RELATIVE_ALT: 1, Frame.GLOBAL: 2}  # QGC AltMode enum
FIRMWARE_TYPES = {"ardupilot": 3, "px4": 12}  # MAV_AUTOPILOT
VEHICLE_FIXED_WING = 1  # MAV_TYPE
MISSION_SUFFIXES = (".plan", ".waypoints", ".txt", ".geojson")
WPL_HEADER = "QGC WPL 110"
_COORDINATE_FRAMES = (Frame.GLOBAL, Frame.GLOBAL_RELATIVE_ALT)


@dataclass(frozen=True)
class MissionItem:
    """One MAVLink mission item: command, frame, param1-4, latitude, longitude, altitude (in the
    frame's sense; zeros for commands without a coordinate) and autocontinue."""

    command: int
    frame: int
    params: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
    lat: float = 0.0
    lon: float = 0.0
    alt: float = 0.0
    autocontinue: bool = True

    @property
    def has_coordinate(self) -> bool:
        return self.frame in _COORDINATE_FRAMES

    @property
    def name(self) -> str:
        try:
            return Command(self.command).name
        except ValueError:
            return f"MAV_CMD {self.command}"


@dataclass
class Mission:
    """A mission: items flown in order after take-off from ``home`` (lat, lon, alt AMSL).

    ``cruise_speed`` and ``hover_speed`` (m/s) are QGroundControl's planning speeds (a
    DO_CHANGE_SPEED item sets the flown speed); ``firmware`` is "ardupilot" or "px4".
    """

    items: list[MissionItem]
    home: tuple[float, float, float]
    cruise_speed: float = 15.0
    hover_speed: float = 5.0
    firmware: str = "ardupilot"

    def __post_init__(self) -> None:
        if not self.items:
            raise fail("items", [], "a mission needs at least one item")
        home = Georeference.from_value(self.home, "home")
        self.home = (home.lat, home.lon, home.alt)
        self.cruise_speed = number("cruise_speed", self.cruise_speed, low=0.0, low_open=True)
        self.hover_speed = number("hover_speed", self.hover_speed, low=0.0, low_open=True)
        if self.firmware not in FIRMWARE_TYPES:
            raise fail("firmware", self.firmware, "must be " + " or ".join(map(repr, FIRMWARE_TYPES)))
        for i, item in enumerate(self.items):
            _check_item(item, f"items[{i}]")

    def __len__(self) -> int:
        return len(self.items)

    @property
    def altitude_mode(self) -> str:
        """"relative", "amsl", or "mixed" when items use both frames."""
        frames = {item.frame for item in self.items if item.has_coordinate}
        modes = [mode for mode, frame in ALTITUDE_MODES.items() if frame in frames]
        return modes[0] if len(modes) == 1 else ("mixed" if modes else "relative")

    def coordinates(self) -> np.ndarray:
        """(lat, lon, alt) of the items with a coordinate, array (n, 3)."""
        return np.array([(i.lat, i.lon, i.alt) for i in self.items if i.has_coordinate]).reshape(-1, 3)

    def save(self, path: str | Path) -> Path:
        """Write the mission; the format follows the suffix: ``.plan`` (QGroundControl JSON),
        ``.waypoints`` or ``.txt`` (QGC WPL 110), ``.geojson`` (route and items over a map)."""
        path = Path(path)
        suffix = path.suffix.lower()
        if suffix == ".plan":
            text = json.dumps(plan_json(self), indent=4, allow_nan=False) + "\n"
        elif suffix in (".waypoints", ".txt"):
            text = waypoints_text(self)
        elif suffix == ".geojson":
            from .io import mission_geojson

            text = json.dumps(mission_geojson(self), indent=1, allow_nan=False) + "\n"
        else:
            raise fail("path", str(path),
                       "unknown mission format; the suffix must be one of " + ", ".join(MISSION_SUFFIXES))
        try:
            path.write_text(text, encoding="utf-8")
        except OSError as error:
            raise fail("path", str(path), f"cannot write the file ({error.strerror})") from None
        return path


def _check_item(item: MissionItem, key: str) -> None:
    if not isinstance(item, MissionItem):
        raise fail(key, item, "must be a MissionItem")
    if not 0 <= int(item.command) <= 65535:
        raise fail(f"{key}.command", item.command, "must be a MAV_CMD number in [0, 65535]")
    if len(item.params) != 4:
        raise fail(f"{key}.params", item.params, "must be param1..param4")
    for name, value in [*(("params", p) for p in item.params), ("lat", item.lat), ("lon", item.lon), ("alt", item.alt)]:
        if not math.isfinite(float(value)):
            raise fail(f"{key}.{name}", value, "must be finite")
    if item.has_coordinate:
        degrees(f"{key}.lat", item.lat, 90.0)
        degrees(f"{key}.lon", item.lon, 180.0)


def _qgc_altitude_mode(item: MissionItem, key: str) -> int:
    try:
        return _QGC_ALTITUDE_MODE[Frame(item.frame)]
    except (ValueError, KeyError):
        raise fail(f"{key}.frame", item.frame, "unknown altitude mode for a .plan; vistrack writes frames "
                   "0 (AMSL) and 3 (relative to home) for items with a coordinate, 2 for commands") from None


def plan_json(mission: Mission) -> dict[str, Any]:
    """The QGroundControl .plan document (fileType "Plan", version 1; mission version 2)."""
    items = []
    for seq, item in enumerate(mission.items, start=1):
        entry: dict[str, Any] = {}
        if item.has_coordinate:  # QGC stores these only for items that specify an altitude
            entry["AMSLAltAboveTerrain"] = None
            entry["Altitude"] = item.alt
            entry["AltitudeMode"] = _qgc_altitude_mode(item, f"items[{seq - 1}]")
        elif item.frame != Frame.MISSION:
            _qgc_altitude_mode(item, f"items[{seq - 1}]")
        entry.update({
            "autoContinue": bool(item.autocontinue),
            "command": int(item.command),
            "doJumpId": seq,
            "frame": int(item.frame),
            "params": [*map(float, item.params), item.lat, item.lon, item.alt],
            "type": "SimpleItem",
        })
        items.append(entry)
    global_mode = {"relative": 1, "amsl": 2}.get(mission.altitude_mode, 0)  # 0: QGC's "mixed"
    return {
        "fileType": "Plan",
        "geoFence": {"circles": [], "polygons": [], "version": 2},
        "groundStation": "vistrack",
        "mission": {
            "cruiseSpeed": mission.cruise_speed,
            "firmwareType": FIRMWARE_TYPES[mission.firmware],
            "globalPlanAltitudeMode": global_mode,
            "hoverSpeed": mission.hover_speed,
            "items": items,
            "plannedHomePosition": list(mission.home),
            "vehicleType": VEHICLE_FIXED_WING,
            "version": 2,
        },
        "rallyPoints": {"points": [], "version": 2},
        "version": 1,
    }


def _number_text(value: float) -> str:
    """Shortest text that reads back to the same double (never 6-decimal rounding)."""
    return repr(float(value))


def waypoints_text(mission: Mission) -> str:
    """QGC WPL 110: header, home as row 0 (current = 1, frame 0, AMSL), then the items; 12
    tab-separated fields per row, full double precision."""
    lat, lon, alt = mission.home
    rows = [(0, 1, int(Frame.GLOBAL), int(Command.NAV_WAYPOINT), (0.0, 0.0, 0.0, 0.0), lat, lon, alt, 1)]
    for seq, item in enumerate(mission.items, start=1):
        rows.append((seq, 0, int(item.frame), int(item.command), item.params, item.lat, item.lon, item.alt,
                     int(bool(item.autocontinue))))
    lines = [WPL_HEADER]
    for seq, current, frame, command, params, lat, lon, alt, autocontinue in rows:
        fields = [str(seq), str(current), str(frame), str(command), *map(_number_text, params),
                  _number_text(lat), _number_text(lon), _number_text(alt), str(autocontinue)]
        lines.append("\t".join(fields))
    return "\n".join(lines) + "\n"


def load(path: str | Path) -> Mission:
    """Read a mission from a QGroundControl .plan or a QGC WPL 110 file (.waypoints / .txt;
    anything MAVWPLoader reads: tabs or spaces, '#' comment lines). The home position is the
    plan's plannedHomePosition or the text file's row 0. A .plan's null parameters
    (QGroundControl's NaN, "unchanged") read as 0."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in (".plan", ".waypoints", ".txt"):
        raise fail("path", str(path), "unknown mission format; load reads .plan, .waypoints and .txt")
    text = read_text(path, "path")
    return _plan_from_json(text, str(path)) if suffix == ".plan" else _mission_from_waypoints(text, str(path))


def _mission_from_waypoints(text: str, source: str) -> Mission:
    lines = text.splitlines()
    if not lines or lines[0].strip() != WPL_HEADER:
        raise fail(f"{source}: line 1", lines[0] if lines else "", f"must be {WPL_HEADER!r}")
    rows: list[tuple[int, list[str]]] = []
    for number_, line in enumerate(lines[1:], start=2):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        fields = line.split()
        if len(fields) != 12:
            raise fail(f"{source}: line {number_}", line, f"a row has 12 tab-separated fields, found {len(fields)}")
        rows.append((number_, fields))
    if not rows:
        raise fail(f"{source}: home", "missing", "row 0 (the home position) is missing")
    items: list[MissionItem] = []
    home: tuple[float, float, float] = (0.0, 0.0, 0.0)
    for index, (line_number, f) in enumerate(rows):
        key = f"{source}: line {line_number}"
        try:
            command, frame, autocontinue = int(f[3]), int(f[2]), int(f[11])
            values = [float(v) for v in f[4:11]]
        except ValueError:
            raise fail(key, " ".join(f), "fields 1-4 and 12 must be integers, 5-11 numbers") from None
        if index == 0:
            home = (values[4], values[5], values[6])
            continue
        items.append(MissionItem(command, frame, (values[0], values[1], values[2], values[3]),
                                 values[4], values[5], values[6], bool(autocontinue)))
    if not items:
        raise fail(f"{source}: items", [], "the file holds only the home position; a mission needs at least one item")
    speeds = [i.params[1] for i in items if i.command == Command.DO_CHANGE_SPEED and i.params[1] > 0]
    return Mission(items, home, cruise_speed=speeds[0] if speeds else 15.0)


def _plan_from_json(text: str, source: str) -> Mission:
    try:
        document = json.loads(text)
    except json.JSONDecodeError as error:
        raise fail(source, f"line {error.lineno}", f"not valid JSON ({error.msg})") from None
    except RecursionError:
        raise fail(source, "JSON", "nested too deeply") from None
    except ValueError:  # after JSONDecodeError, its subclass: integers of more than 4300 digits
        raise fail(source, "JSON", "holds a number too long to read") from None
    if not isinstance(document, dict) or document.get("fileType") != "Plan":
        raise fail(f"{source}: fileType", document.get("fileType") if isinstance(document, dict) else document,
                   'must be "Plan" (a QGroundControl plan)')
    if document.get("version") != 1:
        raise fail(f"{source}: version", document.get("version"), "vistrack reads plan version 1")
    mission = document.get("mission")
    if not isinstance(mission, dict) or mission.get("version") != 2:
        raise fail(f"{source}: mission.version", mission.get("version") if isinstance(mission, dict) else mission,
                   "vistrack reads mission version 2")
    firmware = {code: name for name, code in FIRMWARE_TYPES.items()}.get(mission.get("firmwareType", -1))
    if firmware is None:
        raise fail(f"{source}: mission.firmwareType", mission.get("firmwareType"), "must be 3 (ArduPilot) or 12 (PX4)")
    raw_items = mission.get("items")
    if not isinstance(raw_items, list):
        raise fail(f"{source}: mission.items", raw_items, "must be a list")
    items = [_item_from_json(entry, f"{source}: mission.items[{i}]") for i, entry in enumerate(raw_items)]
    home = mission.get("plannedHomePosition")
    if not isinstance(home, list) or len(home) != 3:
        raise fail(f"{source}: mission.plannedHomePosition", home, "must be [lat, lon, alt]")
    if not items:
        raise fail(f"{source}: mission.items", [], "a mission needs at least one item")
    return Mission(items, tuple(home), cruise_speed=mission.get("cruiseSpeed", 15.0),
                   hover_speed=mission.get("hoverSpeed", 5.0), firmware=firmware)


def _item_from_json(entry: Any, key: str) -> MissionItem:
    if not isinstance(entry, dict) or entry.get("type") != "SimpleItem":
        kind = entry.get("type") if isinstance(entry, dict) else entry
        raise fail(f"{key}.type", kind, 'vistrack reads "SimpleItem" items (not surveys or other ComplexItems)')
    params = entry.get("params")
    if not isinstance(params, list) or len(params) != 7:
        raise fail(f"{key}.params", params, "must be 7 numbers (null for NaN)")
    values = [0.0 if p is None else number(f"{key}.params[{i}]", p) for i, p in enumerate(params)]
    for name in ("command", "frame"):
        if isinstance(entry.get(name), bool) or not isinstance(entry.get(name), int):
            raise fail(f"{key}.{name}", entry.get(name), "must be an integer (MAV_CMD / MAV_FRAME)")
    mode = entry.get("AltitudeMode")
    if mode is not None and mode not in (1, 2):
        raise fail(f"{key}.AltitudeMode", mode, "vistrack reads altitude modes 1 (relative) and 2 (AMSL)")
    return MissionItem(entry["command"], entry["frame"], (values[0], values[1], values[2], values[3]),
                       values[4], values[5], values[6], bool(entry.get("autoContinue", True)))


# ---------------------------------------------------------------------------------------------
# Building missions from local metres (the API planners use in their to_mission)
# ---------------------------------------------------------------------------------------------


def _point(key: str, value: Any) -> np.ndarray:
    point = np.asarray(value, dtype=float).reshape(-1)
    if point.size < 2 or not np.all(np.isfinite(point[:2])):
        raise fail(key, value, "must be a finite point (x, y) in local metres")
    return point[:2]


def _direction(value: str, key: str = "direction") -> int:
    """+1 for counter-clockwise ("ccw"), -1 for clockwise ("cw")."""
    if value not in ("ccw", "cw"):
        raise fail(key, value, 'must be "ccw" or "cw"')
    return 1 if value == "ccw" else -1


def tangent_entry(start: ArrayLike, center: ArrayLike, radius: float,
                  direction: str = "ccw") -> np.ndarray:
    """Where a straight line from ``start`` joins the circle tangentially, travelling around it
    in ``direction``; the nearest point of the circle when ``start`` is on or inside it."""
    p, c = _point("start", start), _point("center", center)
    radius = number("radius", radius, low=0.0, low_open=True)
    offset = p - c
    distance = float(np.hypot(*offset))
    if distance <= radius:
        return c + radius * (offset / distance if distance > 0 else np.array([1.0, 0.0]))
    base = math.atan2(offset[1], offset[0])
    spread = math.acos(radius / distance)
    sign = _direction(direction)
    for angle in (base + spread, base - spread):
        touch = c + radius * np.array([math.cos(angle), math.sin(angle)])
        # Arriving along +tangent: cross(touch - c, touch - p) has the circulation's sign.
        r, v = touch - c, touch - p
        if sign * (r[0] * v[1] - r[1] * v[0]) > 0:
            return touch
    return touch  # start on the circle to rounding: either point


def tangent_exit(center: ArrayLike, radius: float, direction: str, target: ArrayLike) -> np.ndarray:
    """Where the vehicle leaves the circle on a straight line to ``target`` (a tangent): the entry
    point of the reversed motion."""
    return tangent_entry(target, center, radius, "cw" if _direction(direction) > 0 else "ccw")


def arc_points(center: ArrayLike, radius: float, start: ArrayLike, end: ArrayLike,
               direction: str = "ccw", max_step_deg: float = 30.0) -> np.ndarray:
    """Points on the circle from the angle of ``start`` to the angle of ``end`` in ``direction``,
    at most ``max_step_deg`` apart, both ends included (one point when they coincide)."""
    c = _point("center", center)
    radius = number("radius", radius, low=0.0, low_open=True)
    step = math.radians(number("max_step_deg", max_step_deg, low=0.0, high=180.0, low_open=True))
    a0 = math.atan2(*(_point("start", start) - c)[::-1])
    a1 = math.atan2(*(_point("end", end) - c)[::-1])
    sign = _direction(direction)
    sweep = (sign * (a1 - a0)) % (2 * math.pi)
    if sweep < 1e-9:
        return (c + radius * np.array([math.cos(a0), math.sin(a0)]))[None, :]
    count = max(1, math.ceil(sweep / step))
    angles = a0 + sign * sweep * np.arange(count + 1) / count
    return c + radius * np.column_stack([np.cos(angles), np.sin(angles)])


class MissionBuilder:
    """Builds a :class:`Mission` from a route in local metres.

    ``altitude`` is the default local height z of the items (m above the ground at the origin);
    ``home`` the local (x, y) of the launch point (default: the origin); ``speed`` (m/s), when
    given, starts the mission with DO_CHANGE_SPEED and sets QGroundControl's cruise speed.
    Methods return the builder, so a planner's ``to_mission`` reads::

        b = MissionBuilder(georeference, altitude, speed=uav_speed)
        b.waypoints(route_points)                                   # lines: their end points
        b.arc(turn_center, turn_radius, here, there, direction="cw")  # a turn: waypoints along it
        b.loiter(center, radius, direction="ccw", turns=1, entry=p_in, exit=p_out)
        return b.return_to_launch().build()
    """

    def __init__(self, georeference: Georeference, altitude: float, *, altitude_mode: str = "relative",
                 speed: float | None = None, home: ArrayLike | None = None,
                 firmware: str = "ardupilot", hover_speed: float = 5.0) -> None:
        if not isinstance(georeference, Georeference):
            raise fail("georeference", georeference, "must be a vistrack.Georeference (the origin of the local frame)")
        if altitude_mode not in ALTITUDE_MODES:
            raise fail("altitude_mode", altitude_mode, "must be " + " or ".join(map(repr, ALTITUDE_MODES)))
        if firmware not in FIRMWARE_TYPES:
            raise fail("firmware", firmware, "must be " + " or ".join(map(repr, FIRMWARE_TYPES)))
        self.georeference = georeference
        self.altitude = number("altitude", altitude)
        self.altitude_mode = altitude_mode
        self.firmware = firmware
        self.hover_speed = number("hover_speed", hover_speed, low=0.0, low_open=True)
        self.home_xy = _point("home", home) if home is not None else np.zeros(2)
        self.cruise_speed = 15.0
        self.items: list[MissionItem] = []
        if speed is not None:
            self.change_speed(speed)
            self.cruise_speed = float(speed)

    # -- items ---------------------------------------------------------------------------------
    def _located(self, command: Command, point: Any, altitude: float | None, params: Iterable[float],
                 key: str) -> MissionBuilder:
        xy = _point(key, point)
        z = self.altitude if altitude is None else number(f"{key} altitude", altitude)
        lat, lon = self.georeference.to_latlon(xy[0], xy[1])
        alt = z if self.altitude_mode == "relative" else self.georeference.alt + z
        p = tuple(float(v) for v in params)
        self.items.append(MissionItem(int(command), int(ALTITUDE_MODES[self.altitude_mode]),
                                      (p[0], p[1], p[2], p[3]), lat, lon, alt))
        return self

    def waypoint(self, point: ArrayLike, altitude: float | None = None, *, hold: float = 0.0,
                 acceptance_radius: float = 0.0) -> MissionBuilder:
        """NAV_WAYPOINT at local (x, y): param1 hold time (s), param2 acceptance radius (m; 0: the
        autopilot's default)."""
        hold = number("hold", hold, low=0.0)
        acceptance_radius = number("acceptance_radius", acceptance_radius, low=0.0)
        return self._located(Command.NAV_WAYPOINT, point, altitude, (hold, acceptance_radius, 0.0, 0.0), "waypoint")

    def waypoints(self, points: Any, altitude: float | None = None) -> MissionBuilder:
        """One NAV_WAYPOINT per row (x, y[, ...]) of ``points``."""
        array = np.asarray(points, dtype=float)
        if array.ndim != 2 or array.shape[1] < 2:
            raise fail("points", points, "must be an array (n, 2) of local (x, y)")
        for row in array:
            self.waypoint(row[:2], altitude)
        return self

    def loiter(self, center: ArrayLike, radius: float, *, direction: str = "ccw",
               turns: float | None = None, seconds: float | None = None,
               entry: ArrayLike | None = None, exit: ArrayLike | None = None,
               altitude: float | None = None, max_step_deg: float = 30.0,
               heading_required: bool = False, fly_to_entry: bool = True,
               acceptance_radius: float = 0.0) -> MissionBuilder:
        """A loiter circle: NAV_LOITER_TURNS (``turns``), NAV_LOITER_TIME (``seconds``) or, with
        neither, NAV_LOITER_UNLIM. The radius is signed for the autopilot (MAVLink: positive
        clockwise, negative counter-clockwise).

        ``entry`` (a point on the circle, e.g. from :func:`tangent_entry`) adds a waypoint there
        first, so the vehicle joins the circle instead of flying to its centre (``fly_to_entry=False``
        when the route already ends there, e.g. after an entry turn). ``exit`` adds, after
        the loiter, waypoints along the circle from the entry (where full turns end) to the exit
        point every ``max_step_deg``, so the vehicle leaves where the planner leaves the circle
        (param4 = 1: converge from the exit location). ``turns=0`` flies only that arc (a
        fly-through). ArduPilot counts whole turns and whole seconds. ``acceptance_radius``: param2
        of the exit arc's waypoints (0: the autopilot's default)."""
        c = _point("center", center)
        radius = number("radius", radius, low=0.0, low_open=True)
        sign = _direction(direction)
        if turns is not None and seconds is not None:
            raise fail("turns", turns, "give turns or seconds, not both")
        if entry is not None and fly_to_entry:
            self.waypoint(_point("entry", entry), altitude)
        signed = -sign * radius  # MAVLink: positive = clockwise
        xtrack = 1.0 if exit is not None else 0.0
        heading = 1.0 if heading_required else 0.0
        if turns is not None:
            turns = number("turns", turns, low=0.0)
            if turns > 0:
                self._located(Command.NAV_LOITER_TURNS, c, altitude, (turns, heading, signed, xtrack), "center")
        elif seconds is not None:
            seconds = number("seconds", seconds, low=0.0, low_open=True)
            self._located(Command.NAV_LOITER_TIME, c, altitude, (seconds, heading, signed, xtrack), "center")
        else:
            self._located(Command.NAV_LOITER_UNLIM, c, altitude, (0.0, 0.0, signed, 0.0), "center")
        if exit is not None:
            start = (_point("entry", entry) if entry is not None
                     else tangent_entry(_point("exit", exit), c, radius, direction))
            self.arc(c, radius, start, exit, direction, altitude, max_step_deg, acceptance_radius=acceptance_radius)
        return self

    def arc(self, center: ArrayLike, radius: float, start: ArrayLike, end: ArrayLike, direction: str = "ccw",
            altitude: float | None = None, max_step_deg: float = 30.0, *,
            acceptance_radius: float = 0.0) -> MissionBuilder:
        """Waypoints along a circular arc from ``start`` (where the route already is: no waypoint)
        to ``end`` in ``direction``, at most ``max_step_deg`` apart: a turn of a Dubins-family
        path (an entry or exit turn, a fly-through arc) as the autopilot can fly it. Arcs of a full
        turn or more belong in :meth:`loiter`. ``acceptance_radius``: param2 of those waypoints."""
        for point in arc_points(center, radius, start, end, direction, max_step_deg)[1:]:
            self.waypoint(point, altitude, acceptance_radius=acceptance_radius)
        return self

    def change_speed(self, speed: float, *, ground_speed: bool = False) -> MissionBuilder:
        """DO_CHANGE_SPEED: param1 0 airspeed / 1 ground speed, param2 the speed (m/s), param3
        throttle -1 (unchanged)."""
        speed = number("speed", speed, low=0.0, low_open=True)
        self.items.append(MissionItem(int(Command.DO_CHANGE_SPEED), int(Frame.MISSION),
                                      (1.0 if ground_speed else 0.0, speed, -1.0, 0.0)))
        return self

    def return_to_launch(self) -> MissionBuilder:
        """NAV_RETURN_TO_LAUNCH (no parameters)."""
        self.items.append(MissionItem(int(Command.NAV_RETURN_TO_LAUNCH), int(Frame.MISSION)))
        return self

    def build(self) -> Mission:
        """The mission (home at the local home point, at the origin's altitude plus nothing:
        the ground at the origin)."""
        lat, lon = self.georeference.to_latlon(self.home_xy[0], self.home_xy[1])
        return Mission(list(self.items), (lat, lon, self.georeference.alt), cruise_speed=self.cruise_speed,
                       hover_speed=self.hover_speed, firmware=self.firmware)


# ---------------------------------------------------------------------------------------------
# Orbit plans (the tracking pipeline)
# ---------------------------------------------------------------------------------------------

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
    from . import io

    features = io.orbit_plan_geojson(plan, georeference)
    features += [f for f in io.mission_geojson(mission)["features"] if f["properties"]["kind"] in ("home", "route")]
    if simulation is not None:
        features.append(io.trajectory_geojson(simulation, georeference))
    io.write_geojson(io.feature_collection(features, origin=[georeference.lat, georeference.lon, georeference.alt]),
                     path)
    return f"wrote {path}: {len(features)} GeoJSON features in WGS84"


# ---------------------------------------------------------------------------------------------
# Loiter plans (vt.loiter, issue 14) and follow runs (vt.follow, issue 15)
# ---------------------------------------------------------------------------------------------

_TINY_ANGLE = 1e-6  # rad: a loiter remainder below this is a whole number of turns


def _arc_acceptance(radius: float, max_step_deg: float) -> float:
    """param2 of the waypoints along a turn: half their spacing, in whole metres (ArduPilot keeps
    the acceptance radius as an integer byte), at least 1 m. Without it ArduPlane accepts a
    waypoint within WP_RADIUS (90 m by default) scaled by the turn angle, more than the 24 m between
    the waypoints of a 46 m turn every 30 degrees, and cuts the turn."""
    chord = 2.0 * radius * math.sin(math.radians(max_step_deg) / 2.0)
    return float(min(255, max(1, math.floor(chord / 2.0))))


def _arc(segment: Any) -> tuple[np.ndarray, float, str]:
    """An arc segment's centre, radius and direction (a line has none)."""
    if segment.center is None or segment.radius is None or segment.direction is None:
        raise fail("plan.segments", segment, "an arc needs a centre, a radius and a direction")
    return np.asarray(segment.center, dtype=float), float(segment.radius), str(segment.direction)


def loiter_plan_mission(plan: LoiterPlan, georeference: Georeference | Sequence[float], altitude: float, *,
                        speed: float | None = None, max_step_deg: float = 30.0,
                        acceptance_radius: float | None = None, return_to_launch: bool = False,
                        firmware: str = "ardupilot", altitude_mode: str = "relative") -> Mission:
    """A loiter plan (``vt.loiter.plan``: Fly-Through, TLPP or LDLPP) as the mission an autopilot
    flies along the planned path, not towards the AOI centres.

    - DO_CHANGE_SPEED to the plan's speed (airspeed; ``speed`` overrides), home at the plan's start,
      and a first waypoint there.
    - Lines: a waypoint at their end. Turns at the turn radius r (the entry and exit turns, the
      Fly-Through's three-quarter turn): waypoints along the arc every ``max_step_deg`` with an
      acceptance radius of half their spacing (see ``_arc_acceptance``; ``acceptance_radius``
      overrides), so the autopilot flies the arc instead of cutting it.
    - Each AOI's loiter (its consecutive loiter arcs, swept angle S >= 2 pi turns): the route
      already ends at the loiter entry point (the tangent point of TLPP, the end of LDLPP's entry
      turn, the Fly-Through's offset point), where NAV_LOITER_TURNS starts: the aircraft is on the
      circle heading along it, so it circles at once instead of flying to the centre. Radius signed
      for the direction (MAVLink: positive clockwise), k = floor(S / 2 pi) whole turns (ArduPilot
      keeps an integer count, at most 255, and the radius in whole metres up to 255 m), param4 = 1
      (the next leg starts from where the aircraft leaves the circle). The remaining S - 2 pi k
      (TLPP's arc to the departure tangent, LDLPP's arc until the closing angle reaches alpha_ED,
      the Fly-Through's arc to its exit) follows as waypoints along the circle to the exit point.
      A whole number of turns ends where it started, so turns + remainder reproduce S exactly.
    - The last line ends at the plan's end; ``return_to_launch`` adds RTL.

    ``altitude``: the local height of the flight (the loiter camera's altitude above the AOIs);
    ``georeference``: vistrack.Georeference or (lat, lon[, alt]).
    """
    georeference = Georeference.from_value(georeference, "georeference")
    altitude = number("altitude", altitude)
    max_step_deg = number("max_step_deg", max_step_deg, low=0.0, high=180.0, low_open=True)
    accept = (_arc_acceptance(plan.turn_radius, max_step_deg) if acceptance_radius is None
              else number("acceptance_radius", acceptance_radius, low=0.0))
    builder = MissionBuilder(georeference, altitude, speed=plan.speed if speed is None else speed,
                             altitude_mode=altitude_mode, firmware=firmware, home=plan.start)
    builder.waypoint(plan.start)
    segments = list(plan.segments)
    i = 0
    while i < len(segments):
        s = segments[i]
        if s.role == "loiter":
            group = [s]
            while i + len(group) < len(segments) and segments[i + len(group)].role == "loiter" \
                    and segments[i + len(group)].aoi == s.aoi:
                group.append(segments[i + len(group)])
            sweep = sum(g.sweep for g in group)
            turns = math.floor(sweep / (2.0 * math.pi) + 1e-9)
            rest = sweep - 2.0 * math.pi * turns
            exit_point = group[-1].end if rest > _TINY_ANGLE else s.start
            center, radius, direction = _arc(s)
            builder.loiter(center, radius, direction=direction, turns=turns, entry=s.start, exit=exit_point,
                           fly_to_entry=False, max_step_deg=max_step_deg, acceptance_radius=accept)
            i += len(group)
            continue
        if s.kind == "arc":
            center, radius, direction = _arc(s)
            builder.arc(center, radius, s.start, s.end, direction, max_step_deg=max_step_deg, acceptance_radius=accept)
        else:
            builder.waypoint(s.end)
        i += 1
    if return_to_launch:
        builder.return_to_launch()
    return builder.build()


def simplify_route(points: ArrayLike, tolerance: float) -> np.ndarray:
    """The route's points that Douglas-Peucker (shapely/GEOS) keeps at ``tolerance`` metres: every
    dropped point lies within ``tolerance`` of the polyline of the kept ones, which are original
    points (the first and last included). ``tolerance`` 0 keeps them all."""
    array = np.asarray(points, dtype=float)
    if array.ndim != 2 or array.shape[1] < 2 or len(array) == 0 or not np.all(np.isfinite(array[:, :2])):
        raise fail("points", points, "must be an array (n, 2) of finite local (x, y)")
    tolerance = number("tolerance", tolerance, low=0.0)
    if tolerance == 0.0 or len(array) < 3:
        return array[:, :2].copy()
    from shapely.geometry import LineString

    kept = np.asarray(LineString(array[:, :2]).simplify(tolerance, preserve_topology=False).coords)
    return kept


def follow_mission(waypoints: ArrayLike, georeference: Georeference | Sequence[float], altitude: float, *,
                   home: ArrayLike | None = None, speed: float | None = None, tolerance: float = 1.0,
                   return_to_launch: bool = False, firmware: str = "ardupilot",
                   altitude_mode: str = "relative") -> Mission:
    """A follow run's generated waypoints (one per second, section V of the paper) as a mission.

    The planner issues a waypoint every second from where the vehicle is; as a mission they replay
    the planned route for that vehicle's recorded motion (a live follow needs a companion computer
    sending them as guided targets). At 21 m/s they are 21 m apart and mostly on straight or gently
    curving stretches, so by default they are decimated by Douglas-Peucker at ``tolerance`` = 1 m
    (:func:`simplify_route`): the route stays within 1 m of every generated waypoint with fewer
    items (ArduPilot boards hold a few hundred to a few thousand). ``tolerance=0`` keeps all.
    ``home``: the launch point (local x, y; default the first waypoint)."""
    kept = simplify_route(waypoints, tolerance)
    builder = MissionBuilder(Georeference.from_value(georeference, "georeference"), altitude, speed=speed,
                             altitude_mode=altitude_mode, firmware=firmware, home=kept[0] if home is None else home)
    builder.waypoints(kept)
    if return_to_launch:
        builder.return_to_launch()
    return builder.build()
