"""Mission items: the MAVLink commands and frames vistrack writes, one item, and its checks."""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import IntEnum

from ..georeference import degrees
from ..schema import fail

__all__ = ["ALTITUDE_MODES", "FIRMWARE_TYPES", "MISSION_SUFFIXES", "VEHICLE_FIXED_WING", "WPL_HEADER", "Command",
           "Frame", "MissionItem", "check_item", "qgc_altitude_mode"]


class Command(IntEnum):
    """The MAVLink commands vistrack writes (MAV_CMD_*)."""

    NAV_WAYPOINT = 16
    NAV_LOITER_UNLIM = 17
    NAV_LOITER_TURNS = 18
    NAV_LOITER_TIME = 19
    NAV_RETURN_TO_LAUNCH = 20
    DO_CHANGE_SPEED = 178
    DO_SET_ROI_LOCATION = 195  # point a gimbal at a location (a region of interest)


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


def check_item(item: MissionItem, key: str) -> None:
    """An item's command, parameters and coordinates checked; errors name ``key``."""
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


def qgc_altitude_mode(item: MissionItem, key: str) -> int:
    """QGroundControl's AltitudeMode of an item with a coordinate."""
    try:
        return _QGC_ALTITUDE_MODE[Frame(item.frame)]
    except (ValueError, KeyError):
        raise fail(f"{key}.frame", item.frame, "unknown altitude mode for a .plan; vistrack writes frames "
                   "0 (AMSL) and 3 (relative to home) for items with a coordinate, 2 for commands") from None
