"""The two unit systems of waypoint-navigation runs, shared by ``vistrack waypoints`` and the
waypoint sweeps: metres (the default aircraft on the roll model, each leg by L1) or the waypoint
paper's dimensionless units (its section 3: the Dubins vehicle, each leg by the law (5))."""

from __future__ import annotations

from typing import Optional

import numpy as np

from .._core import Uav
from .._core.flight import paper_gains
from .navigation import Options

__all__ = ["ALTITUDE", "L1_PERIOD", "leg_gains", "leg_guidance", "route_scale_error", "units_uav"]

# In metres: the follow runs' L1 period (FollowFlight.l1): L1 = 0.75 * 8 * v / pi = 38 m at 20 m/s,
# under R = 50 m; and the flight altitude, which places the gusts and exported missions.
L1_PERIOD = 8.0
ALTITUDE = 60.0


def units_uav(paper: bool) -> Uav:
    """The vehicle of the units: the paper's section 3 (R 0.7, v 0.8), or in metres the default
    aircraft at ``ALTITUDE``."""
    if paper:
        d = Options()
        return Uav(speed=d.speed, min_turn_radius=d.turn_radius)
    uav = Uav()
    uav.altitude = ALTITUDE
    return uav


def leg_gains(paper: bool, turn_radius: float) -> tuple[float, float]:
    """The law (5)'s gains (g, h): the paper's (0.1, 5.25) in its units, scaled by 0.7 / R in metres."""
    if paper:
        g, h = Options().gains
        return float(g), float(h)
    return paper_gains(turn_radius)


def leg_guidance(paper: bool) -> str:
    """The law flying each leg unless asked: the paper's law (5) in its units, L1 in metres."""
    return "law5" if paper else "l1"


def route_scale_error(route: np.ndarray, turn_radius: float, paper: bool) -> Optional[str]:
    """Why a route's scale does not fit its units (None when it does): in metres a longest leg under
    2 R, in the paper's units one over 100 R, suggests the other units were meant. The caller adds
    how to switch them."""
    longest = float(np.max(np.linalg.norm(np.diff(route, axis=0), axis=1)))
    if not paper and longest < 2.0 * turn_radius:
        return (f"its longest leg, {longest:.4g} m, is under 2 R = {2 * turn_radius:.4g} m: a route in the paper's "
                "units?")
    if paper and longest > 100.0 * turn_radius:
        return (f"its longest leg is {longest:.4g} = {longest / turn_radius:.4g} R with the paper's units "
                f"(R = {turn_radius:g}): a route in metres?")
    return None
