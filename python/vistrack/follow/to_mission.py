"""A follow run's generated waypoints as an autopilot mission
(``vt.follow.FollowResult.to_mission``)."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike

from ..georeference import Georeference
from ..mission.builder import MissionBuilder, simplify_route
from ..mission.model import Mission
from ..schema import fail

__all__ = ["follow_mission", "kept_indices"]


def kept_indices(points: np.ndarray, kept: np.ndarray) -> list[int]:
    """The indices in ``points`` of ``kept``, a subsequence of its rows in order (what
    :func:`simplify_route` returns)."""
    out, i = [], 0
    for row in kept:
        while i < len(points) and not np.array_equal(points[i, :2], row[:2]):
            i += 1
        out.append(i)
        i += 1
    return out


def follow_mission(waypoints: ArrayLike, georeference: Georeference | Sequence[float], altitude: float, *,
                   home: ArrayLike | None = None, speed: float | None = None, tolerance: float = 1.0,
                   return_to_launch: bool = False, firmware: str = "ardupilot",
                   altitude_mode: str = "relative", roi: ArrayLike | None = None) -> Mission:
    """A follow run's generated waypoints (one per second, section V of the paper) as a mission.

    The planner issues a waypoint every second from where the vehicle is; as a mission they replay
    the planned route for that vehicle's recorded motion (a live follow needs a companion computer
    sending them as guided targets). At 21 m/s they are 21 m apart and mostly on straight or gently
    curving stretches, so by default they are decimated by Douglas-Peucker at ``tolerance`` = 1 m
    (:func:`simplify_route`): the route stays within 1 m of every generated waypoint with fewer
    items (ArduPilot boards hold a few hundred to a few thousand). ``tolerance=0`` keeps all.
    ``home``: the launch point (local x, y; default the first waypoint). ``roi`` (one (x, y) per
    generated waypoint: the vehicle's predicted position; beyond the paper): before each kept
    waypoint a DO_SET_ROI_LOCATION on the ground there, so a gimbal points at the vehicle."""
    points = np.asarray(waypoints, dtype=float)
    kept = simplify_route(points, tolerance)
    targets = None
    if roi is not None:
        targets = np.asarray(roi, dtype=float)
        if targets.shape != (len(points), 2) or not np.all(np.isfinite(targets)):
            raise fail("roi", roi, f"must be one finite (x, y) per waypoint, an array ({len(points)}, 2)")
    builder = MissionBuilder(Georeference.from_value(georeference, "georeference"), altitude, speed=speed,
                             altitude_mode=altitude_mode, firmware=firmware, home=kept[0] if home is None else home)
    for k, index in enumerate(kept_indices(points, kept)):
        if targets is not None:
            builder.roi(targets[index])
        builder.waypoint(kept[k])
    if return_to_launch:
        builder.return_to_launch()
    return builder.build()
