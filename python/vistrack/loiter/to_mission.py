"""A loiter plan as the mission an autopilot flies along the planned path
(``vt.loiter.Plan.to_mission``: see ``methods``)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from .._core.loiter import Plan as LoiterPlan
from ..georeference import Georeference
from ..mission.builder import MissionBuilder
from ..mission.model import Mission
from ..schema import fail, number

__all__ = ["loiter_plan_mission"]


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
