"""Reading missions back: a QGroundControl .plan or a QGC WPL 110 file (and files pymavlink's
``MAVWPLoader`` writes)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..io.documents import parse_json
from ..io.text import read_text
from ..schema import fail, number
from .items import FIRMWARE_TYPES, WPL_HEADER, Command, MissionItem
from .model import Mission

__all__ = ["load"]


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
    document = parse_json(text, "path", source)
    if not isinstance(document, dict) or document.get("fileType") != "Plan":
        raise fail(f"{source}: fileType", document.get("fileType") if isinstance(document, dict) else document,
                   'must be "Plan" (a QGroundControl plan)')
    if document.get("version") != 1:
        raise fail(f"{source}: version", document.get("version"), "vistrack reads plan version 1")
    mission = document.get("mission")
    if not isinstance(mission, dict) or mission.get("version") != 2:
        raise fail(f"{source}: mission.version", mission.get("version") if isinstance(mission, dict) else mission,
                   "vistrack reads mission version 2")
    code = mission.get("firmwareType", -1)
    names = {number: name for name, number in FIRMWARE_TYPES.items()}
    firmware = names.get(code) if isinstance(code, int) and not isinstance(code, bool) else None
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
