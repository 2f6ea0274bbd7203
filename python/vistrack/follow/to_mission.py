"""A follow run's generated waypoints as an autopilot mission
(``vt.follow.FollowResult.to_mission``)."""

from __future__ import annotations

from collections.abc import Sequence

from numpy.typing import ArrayLike

from ..georeference import Georeference
from ..mission.builder import MissionBuilder, simplify_route
from ..mission.model import Mission

__all__ = ["follow_mission"]


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
