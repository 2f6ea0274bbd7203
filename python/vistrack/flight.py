"""The flight layer: one vehicle in wind, flown by a guidance law. Every planner flies here.

The vehicle has a constant airspeed ``speed`` (v), heading psi and turn rate bounded by v / R;
its ground velocity is v (cos psi, sin psi) + w(t). ``Uav.dynamics`` chooses how it turns:
``"dubins"`` follows the guidance's turn rate at once (the papers' vehicle), ``"roll"`` banks
towards the coordinated bank of that rate with a first-order, rate-limited response
(``RollModel``; Beard & McLain, *Small Unmanned Aircraft*, ch. 9) and turns at g tan(phi) / v;
pass ``fly(..., uav=vt.Uav(dynamics="roll"))``. Every trajectory has its ``bank``, and
``trajectory.smoothness()`` (``flight_smoothness``) says how it chatters. The wind w(t) is ``Wind(east, north)`` plus
optional ``Gusts`` (Dryden turbulence of MIL-F-8785C, horizontal components, seeded and
reproducible; ``Gusts.mil_f_8785c(altitude, wind_speed_20ft, seed)`` derives the intensity and
length scale from the low-altitude model). The guidance never sees the wind.

``fly(guidance, start, speed, turn_radius, wind=..., dt=..., integration=...)`` flies with the
paper's discrete update (``"discrete"``: psi_{i+1} = psi_i + psi_turn, |psi_turn| <= v dt / R) or
Dormand-Prince 5(4) (``"continuous"``) and returns a ``FlightTrajectory`` of numpy arrays
(``t``, ``x``, ``y``, ``psi``, ``command``, ``bank``, ``target``, ``target_index``, ``wind``; ``array`` is
(n, 4) t, x, y, psi).

Guidance laws: ``LineFeedback`` is the feedback law (5) of the Dubins waypoint navigation paper;
``WaypointFollower`` is classical waypoint navigation on it. A planner that produces waypoints
over time feeds a ``WaypointFollower(..., finish_at_last=False)`` with ``add_waypoint(point,
available_from)``, either before the flight (a timed plan) or from ``on_step(t, state)``, which
``fly`` calls after every accepted step.

Example::

    import vistrack as vt
    law = vt.flight.LineFeedback(speed=0.8, turn_radius=0.7, dt=0.02, gains=(0.1, 5.25))
    wn = vt.flight.WaypointFollower(law, [[5, 0], [8, 4]], waypoint_radius=0.35)
    traj = vt.flight.fly(wn, start=(0, 0, 0), speed=0.8, turn_radius=0.7,
                         wind=vt.flight.Wind(north=0.08), dt=0.02)
    traj.x, traj.y, traj.finished
"""

from __future__ import annotations

from ._core import flight as _flight

Gusts = _flight.Gusts
Wind = _flight.Wind
WindField = _flight.WindField
LineFeedback = _flight.LineFeedback
L1Line = _flight.L1Line
CurveL1 = _flight.CurveL1
FlightGuidance = _flight.FlightGuidance
WaypointFollower = _flight.WaypointFollower
PathFollower = _flight.PathFollower  # lines and arcs (flight.hpp, Path following; the loiter plans)
TurnRateHold = _flight.TurnRateHold  # a commanded turn rate held (the horizon city follower)
FlightTrajectory = _flight.FlightTrajectory
dryden_low_altitude = _flight.dryden_low_altitude
fly = _flight.fly
RollModel = _flight.RollModel
FlightSmoothness = _flight.FlightSmoothness
flight_smoothness = _flight.flight_smoothness
coordinated_bank = _flight.coordinated_bank
paper_gains = _flight.paper_gains

__all__ = [
    "CurveL1",
    "FlightGuidance",
    "FlightSmoothness",
    "FlightTrajectory",
    "Gusts",
    "L1Line",
    "LineFeedback",
    "PathFollower",
    "RollModel",
    "TurnRateHold",
    "WaypointFollower",
    "Wind",
    "WindField",
    "coordinated_bank",
    "dryden_low_altitude",
    "flight_smoothness",
    "fly",
    "paper_gains",
]
