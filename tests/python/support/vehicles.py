"""Ground vehicles for the follow planner's tests."""

from __future__ import annotations

import vistrack as vt


def east_truck() -> vt.follow.GroundVehicle:
    """A vehicle driving east from the origin at 5 m/s for a minute."""
    return vt.follow.GroundVehicle.from_legs([vt.follow.VehicleLeg(heading=0.0, speed=5.0, duration=60.0)], (0.0, 0.0))
