"""The Mission (items after take-off from home) and how it is written: a QGroundControl ``.plan``
(JSON), ``QGC WPL 110`` text (``.waypoints`` / ``.txt``: tab-separated, home as row 0, every number
at full double precision) or ``.geojson`` (the route and items over a map)."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..georeference import Georeference
from ..io.geojson import feature_collection
from ..schema import fail, number
from .items import (
    ALTITUDE_MODES,
    FIRMWARE_TYPES,
    MISSION_SUFFIXES,
    VEHICLE_FIXED_WING,
    WPL_HEADER,
    Command,
    Frame,
    MissionItem,
    check_item,
    qgc_altitude_mode,
)

__all__ = ["Mission", "mission_geojson", "plan_json", "waypoints_text"]


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
            check_item(item, f"items[{i}]")

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
            text = json.dumps(mission_geojson(self), indent=1, allow_nan=False) + "\n"
        else:
            raise fail("path", str(path),
                       "unknown mission format; the suffix must be one of " + ", ".join(MISSION_SUFFIXES))
        try:
            path.write_text(text, encoding="utf-8")
        except OSError as error:
            raise fail("path", str(path), f"cannot write the file ({error.strerror})") from None
        return path



def plan_json(mission: Mission) -> dict[str, Any]:
    """The QGroundControl .plan document (fileType "Plan", version 1; mission version 2)."""
    items = []
    for seq, item in enumerate(mission.items, start=1):
        entry: dict[str, Any] = {}
        if item.has_coordinate:  # QGC stores these only for items that specify an altitude
            entry["AMSLAltAboveTerrain"] = None
            entry["Altitude"] = item.alt
            entry["AltitudeMode"] = qgc_altitude_mode(item, f"items[{seq - 1}]")
        elif item.frame != Frame.MISSION:
            qgc_altitude_mode(item, f"items[{seq - 1}]")
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


def mission_geojson(mission: Mission) -> dict[str, Any]:
    """A mission over a map: the home Point, the route (LineString from home through every item
    with a coordinate) and one Point per such item (command, its parameters, altitude)."""
    lat, lon, alt = mission.home
    features: list[dict[str, Any]] = [{"type": "Feature",
                                       "properties": {"kind": "home", "altitude_amsl_m": alt},
                                       "geometry": {"type": "Point", "coordinates": [lon, lat]}}]
    route = [[lon, lat]]
    mode = {int(Frame.GLOBAL): "amsl", int(Frame.GLOBAL_RELATIVE_ALT): "relative"}
    for seq, item in enumerate(mission.items, start=1):
        if not item.has_coordinate:
            continue
        if item.command != Command.DO_SET_ROI_LOCATION:  # where a gimbal looks, not where the route goes
            route.append([item.lon, item.lat])
        features.append({"type": "Feature",
                         "properties": {"kind": "mission_item", "seq": seq, "command": item.command,
                                        "name": item.name, "params": list(item.params), "altitude_m": item.alt,
                                        "altitude_mode": mode[item.frame]},
                         "geometry": {"type": "Point", "coordinates": [item.lon, item.lat]}})
    features.insert(1, {"type": "Feature", "properties": {"kind": "route"},
                        "geometry": {"type": "LineString", "coordinates": route}})
    return feature_collection(features)
