"""A loiter plan flown on a 6-DOF JSBSim aircraft (``vistrack.fdm``).

The guidance is the kinematic flight's: ``vt.flight.PathFollower`` on the plan's lines and arcs (its
curvature feed-forward anticipating by the autopilot's roll response, as on the roll model). The flown
path is scored as a kinematic flight is (:func:`vistrack.loiter.flying.fly_and_score`): the camera's
coverage from the bank flown (given to the coverage as the turn rate g tan(bank) / v it stands for),
the loiter time covered, the cross-track distance from the plan.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .. import flight
from ..fdm import FdmTrajectory, FlightGuidanceLaw
from ..fdm import fly as fly_6dof
from ..fdm.aircraft import GRAVITY
from ..flight import flight_smoothness
from .flying import fly_and_score, path_pieces
from .planning import Coverage, Plan
from .scenario import Scenario

__all__ = ["FdmFlown", "fdm_score", "fly_fdm"]

# The PathFollower's anticipation on the 6-DOF aircraft: about the autopilot's roll response (s).
ANTICIPATION = 0.5


class FdmFlown:
    """A 6-DOF flight under the names a kinematic ``FlightTrajectory`` gives the loiter scoring."""

    def __init__(self, trajectory: FdmTrajectory, speed: float):
        self.fdm = trajectory
        self.t, self.x, self.y, self.psi = trajectory.t, trajectory.x, trajectory.y, trajectory.psi
        self.command = GRAVITY * np.tan(trajectory.bank) / speed  # the turn rate of the bank flown
        self.target_index = np.maximum(trajectory.target_index, 0)
        self.finished = trajectory.finished
        self.end_time = float(trajectory.t[-1])

    def __len__(self) -> int:
        return len(self.t)

    def smoothness(self) -> Any:
        return flight_smoothness(self.t, self.fdm.bank)


def fly_fdm(plan: Plan, wind: tuple[float, float], aircraft: str, altitude: float) -> FdmFlown:
    """Fly the plan on ``aircraft`` at ``altitude`` in the constant ``wind`` (east, north) m/s, unknown to
    the guidance; ends at the plan's end point (or after three times its flight time plus 10 minutes)."""
    follower = flight.PathFollower(path_pieces(plan), plan.speed, plan.turn_radius, anticipation=ANTICIPATION)
    start = tuple(float(v) for v in plan.at_time(0.0))
    pose = (start[0], start[1], start[2])
    air = flight.Wind(east=float(wind[0]), north=float(wind[1]))
    traj = fly_6dof(FlightGuidanceLaw(follower, pose), pose, speed=plan.speed, altitude=altitude,
                    duration=3.0 * plan.flight_time + 600.0, turn_radius=plan.turn_radius, aircraft=aircraft,
                    wind=air)
    return FdmFlown(traj, plan.speed)


def fdm_score(scenario: Scenario, plan: Plan, wind: tuple[float, float], planned: Coverage, aircraft: str,
              ) -> dict[str, Any]:
    """The 6-DOF flight's record: the kinematic flight's keys (``fly_and_score``) with the aircraft and
    its largest altitude and airspeed errors."""
    flown = fly_fdm(plan, wind, aircraft, scenario.camera.altitude)
    record = fly_and_score(scenario, plan, wind, planned=planned, keep_trajectory=False, trajectory=flown)
    record.update(aircraft=aircraft, altitude_error_max_m=flown.fdm.altitude_error_max,
                  airspeed_error_max_m_s=flown.fdm.airspeed_error_max,
                  real_time_factor=float((flown.t[-1] - flown.t[0]) / flown.fdm.seconds) if flown.fdm.seconds else
                  None)
    return record
