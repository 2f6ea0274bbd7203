"""Every planner flown on a 6-DOF aircraft: JSBSim in the loop with vistrack's own autopilot.

The planner's lateral guidance gives a turn rate, the autopilot banks to its coordinated bank
(roll loop on the ailerons), holds altitude through pitch and elevator, airspeed through the
throttle and coordinates the turn with the rudder; JSBSim flies the airframe in the flight
layer's wind. Aircraft: ``aerosonde`` (the default: a small UAV written for vistrack from Beard
and McLain's Aerosonde data) and JSBSim's stock ``c172p``; each states its envelope, and a plan
outside it is refused (``Aircraft.check_plan``).

Example::

    import vistrack as vt
    from vistrack import fdm
    law = vt.flight.CurveL1(20.0, [[0, 0], [2000, 0]])
    traj = fdm.fly(fdm.FlightGuidanceLaw(law, (0, 0, 0)), (0, 0, 0), speed=20.0, altitude=300.0,
                   duration=60.0, turn_radius=50.0)
    traj.altitude_error_max, traj.airspeed_error_max
"""

from __future__ import annotations

from .aircraft import DEFAULT_AIRCRAFT, Aircraft, Envelope, Gains, aircraft, aircraft_names
from .fly import FdmTrajectory, FlightGuidanceLaw, Guidance, fly
from .trim import Trim

__all__ = [
    "DEFAULT_AIRCRAFT",
    "Aircraft",
    "Envelope",
    "FdmTrajectory",
    "FlightGuidanceLaw",
    "Gains",
    "Guidance",
    "Trim",
    "aircraft",
    "aircraft_names",
    "fly",
]
