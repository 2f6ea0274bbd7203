"""Following over a city by receding-horizon bank commands (beyond every anchor, and beyond the
issue's orbit inside the visibility polygon, which it replaces as the default city follower).

At every update (1 Hz) the follower observes the vehicle (position and velocity), predicts it at
that velocity over the next ``horizon`` seconds, and asks the core's dynamic programme
(:class:`vistrack._core.follow.HorizonPlanner`, cpp/include/vistrack/follow.hpp) for the
bank command to hold over the next second: the one from which the most seconds of camera and line of
sight can follow over the horizon, with the UAV's roll model, its turn limit and the wind the follower
knows. A second is in sight when an Embree ray from the flight altitude reaches the predicted vehicle
and the camera sees it at that heading and bank. No visibility volume plans it (about 1,700 rays per
predicted second); one VV per update (cached by position) measures whether a flyable visible circle
existed, the issue's measure of the city, so the report reads as the city orbit's does.

The flight layer flies it: a ``TurnRateHold`` guidance holding g tan(bank) / v, renewed at every
update, so the roll model banks to the command. The planner knows the bank it commanded (the roll
model's response to it), as an autopilot reads its attitude.

Why beyond the orbit: with the vehicle's whole future known the same programme keeps 99 % of the
Charlotte runs in sight (bench/follow_city_bound.py), so the orbit's 85-97 % is not the aircraft's,
the camera's or the city's limit; the orbit fixes a circle where the vehicle will be, the programme
looks 24 s ahead (docs/following.md, "The horizon follower").
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Optional, Sequence

import numpy as np

from .. import flight as _flight
from .._core import Uav, VisibilityScene, VistrackError
from .._core.follow import HorizonOptions, HorizonPlanner
from ..city_orbits import VolumeCache, orbit_room
from .city_orbit import CityOrbitOptions
from .city_runs import CityOrbitResult, UpdateClock, circle_exists, city_defaults, scored_flight, start_pose
from .simulation import DownwardCamera, FollowFlight, FollowParameters, GroundVehicle, Wind

__all__ = ["HorizonUpdate", "city_horizon_follow"]


@dataclass
class HorizonUpdate:
    """One update: the bank commanded (rad), the seconds in sight the programme expected over the
    horizon, whether it steered for the vehicle (nothing in sight from any command), and as the
    city orbit's updates: MaxRadius about the vehicle's position ``lead`` s ahead, the
    turn-limited radius, whether a flyable visible circle fitted about it and anywhere in its
    visibility polygon, and how many VVs the update cast."""

    t: float
    bank_command: float
    expected_seconds: float
    heading_for_vehicle: bool
    max_radius: float
    turn_radius: float
    fits_about: bool
    fits_anywhere: bool
    new_volumes: int


def city_horizon_follow(vehicle: GroundVehicle, uav: Uav, scene: VisibilityScene, *,
                        parameters: Optional[FollowParameters] = None, wind: Optional[Wind] = None,
                        flight: Optional[FollowFlight] = None, camera: Optional[DownwardCamera] = None,
                        options: Optional[CityOrbitOptions] = None,
                        wind_estimate: Optional[Sequence[float]] = None,
                        progress: Optional[Callable[[int, int], None]] = None,
                        start: Optional[Sequence[float]] = None) -> CityOrbitResult:
    """Fly the horizon follower about ``vehicle`` at world z = ground + ``uav.altitude`` (see the
    module) in the true ``wind``; ``wind_estimate`` (east, north): what the planner knows of it (None:
    no wind). ``options``: the city block (its ``horizon``, ``reach``, ``grid``, ``margin``, ``lead``,
    ``vehicle_height`` and ``resolution_deg`` apply). ``progress(done, total)``: after each update;
    ``start``: the UAV's (x, y, psi), level (default: 200 m ahead of the vehicle along its heading)."""
    options = options or CityOrbitOptions()
    options.validate()
    parameters, flight, camera, air = city_defaults(uav, parameters, flight, camera, wind_estimate)
    period = 1.0  # the programme's step: one bank command per second
    if parameters.update_period != period:
        raise VistrackError(f"follow.update_period = {parameters.update_period}: the horizon city follower plans "
                            "one bank command per second (1 s), or use city_orbit.planner: orbit")
    altitude = scene.ground_level + uav.altitude
    steps = 1.0 / flight.dt
    # A second integrated in the flight's steps when they divide it (the planner's bank then is the flight's).
    dt = flight.dt if abs(steps - round(steps)) < 1e-6 else HorizonOptions().dt
    planner = HorizonPlanner(scene, uav, camera, altitude,
                             HorizonOptions(horizon=options.horizon, vehicle_height=options.vehicle_height, dt=dt))
    cache = VolumeCache(scene, math.hypot(uav.altitude, options.reach), options.resolution_deg, options.grid)
    turn = parameters.turn_margin * uav.min_turn_radius  # the smallest circle the UAV can fly (the planner's)
    clock = UpdateClock(vehicle, flight, period)
    ahead = np.arange(options.horizon + 1, dtype=float)
    updates: list[HorizonUpdate] = []

    def update(t: float, position: np.ndarray, heading: float, bank: float) -> float:
        """The bank command for the next second (and the update's record); returns its turn rate."""
        p, v = np.asarray(vehicle.position(t)), np.asarray(vehicle.velocity(t))
        choice = planner.choose(p + np.outer(ahead, v), air, position, heading, bank)
        before = cache.computed
        where = p + v * options.lead
        point = np.asarray(scene.poi_on_surface(np.array([[where[0], where[1], options.vehicle_height]])))[0]
        try:
            room = orbit_room(scene, point, altitude, cache=cache)
            about, anywhere = circle_exists(room, turn, options.margin + float(np.hypot(*v)) * options.lead)
            max_radius = room.max_radius
        except VistrackError:  # the prediction stands in a building: no room there
            about = anywhere = False
            max_radius = 0.0
        updates.append(HorizonUpdate(t, choice.bank_command, choice.value, choice.heading_for_vehicle, max_radius,
                                     turn, about, anywhere, cache.computed - before))
        held[0] = choice.next.bank  # the roll model's bank after the second with the command held
        if progress is not None:
            progress(min(len(updates), clock.total), clock.total)
        return choice.turn_rate

    pose = start_pose(vehicle, start)
    held = [0.0]  # the bank the planner commanded its way to (the flight starts level)
    guidance = _flight.TurnRateHold(update(clock.t0, np.array(pose[:2]), pose[2], 0.0))

    def on_step(t: float, q: Sequence[float]) -> None:
        if clock.due(t):
            guidance.set_turn_rate(update(t, np.array([q[0], q[1]]), float(q[2]), held[0]))

    trajectory = _flight.fly(guidance, pose, uav.speed, uav.min_turn_radius, wind=wind, dt=flight.dt,
                             max_time=clock.duration, integration=flight.integration, t0=clock.t0, on_step=on_step,
                             uav=uav)
    return scored_flight(trajectory, vehicle, scene, uav, camera, options.vehicle_height, updates, cache.computed,
                         strategy="city_horizon")
