"""Building missions from local metres, the API planners use in their ``to_mission``: waypoints,
arcs, loiter circles joined at an entry point and left at an exit point (so the autopilot does
not fly to the centre first), speed changes, return to launch; and Douglas-Peucker route
simplification."""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ..georeference import Georeference
from ..schema import fail, number
from .items import ALTITUDE_MODES, FIRMWARE_TYPES, Command, Frame, MissionItem
from .model import Mission

__all__ = ["MissionBuilder", "arc_points", "simplify_route", "tangent_entry", "tangent_exit"]


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

    def roi(self, point: ArrayLike, altitude: float = 0.0) -> MissionBuilder:
        """DO_SET_ROI_LOCATION at local (x, y) and ``altitude`` (default 0: the ground, in the
        mission's altitude mode): the autopilot points a gimbal there from the next items on."""
        return self._located(Command.DO_SET_ROI_LOCATION, point, altitude, (0.0, 0.0, 0.0, 0.0), "roi")

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
