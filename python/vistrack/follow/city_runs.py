"""A city follower's run, shared by the city orbit (follow.city_orbit) and the horizon follower
(follow.city_horizon): the updates, the flight scored with the camera and Embree rays at every
sample, and whether a flyable visible circle existed (the issue's measure of the city)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Optional, Sequence

import numpy as np

from .._core import Uav, VisibilityScene, VistrackError
from ..city_orbits import OrbitRoom
from ..preview import preview
from .simulation import DownwardCamera, FollowFlight, FollowParameters, GroundVehicle, camera_sees

__all__ = ["CityOrbitResult", "OrbitUpdate", "UpdateClock", "circle_exists", "city_defaults", "scored_flight",
           "start_pose"]


def start_pose(vehicle: GroundVehicle, start: Optional[Sequence[float]]) -> tuple[float, float, float]:
    """A city follower's start (x, y, psi): ``start`` checked, or by default 200 m ahead of the vehicle
    along its heading, heading its way."""
    if start is None:
        t0 = vehicle.start_time
        heading = float(vehicle.heading(t0))
        ahead = np.asarray(vehicle.position(t0)) + 200.0 * np.array([math.cos(heading), math.sin(heading)])
        return float(ahead[0]), float(ahead[1]), heading
    pose = np.asarray(start, dtype=float)
    if pose.shape != (3,) or not np.all(np.isfinite(pose)):
        raise VistrackError(f"start = {preview(start)}: expected (x, y, psi), finite")
    return float(pose[0]), float(pose[1]), float(pose[2])


def city_defaults(uav: Uav, parameters: Optional[FollowParameters], flight: Optional[FollowFlight],
                  camera: Optional[DownwardCamera], wind_estimate: Optional[Sequence[float]]
                  ) -> tuple[FollowParameters, FollowFlight, DownwardCamera, np.ndarray]:
    """A city follower's inputs with their defaults, checked: the UAV, and the wind the planner knows
    as (east, north) (zero for None)."""
    uav.validate()
    air = np.zeros(2) if wind_estimate is None else np.asarray(wind_estimate, dtype=float)
    if air.shape != (2,) or not np.all(np.isfinite(air)):
        raise VistrackError(f"wind_estimate = {preview(wind_estimate)}: expected (east, north), finite m/s")
    return parameters or FollowParameters(), flight or FollowFlight(), camera or DownwardCamera(), air


class UpdateClock:
    """When a city follower updates: at the vehicle's start time, then every ``period`` while the flight
    lasts (the vehicle's track, or ``flight.max_time`` when set), never at its last instant. ``duration``:
    the flight's; ``total``: how many updates it makes."""

    def __init__(self, vehicle: GroundVehicle, flight: FollowFlight, period: float) -> None:
        self.t0, self.period = vehicle.start_time, period
        self.duration = flight.max_time if flight.max_time > 0.0 else vehicle.end_time - vehicle.start_time
        self.end = min(vehicle.end_time, self.t0 + self.duration)
        self.total = max(1, math.ceil((self.end - self.t0) / period - 1e-9))
        self.next = self.t0 + period

    def due(self, t: float) -> bool:
        """Whether the flight's step at ``t`` is an update (then the next one is set)."""
        if t < self.next - 1e-9 or t >= self.end - 1e-9:
            return False
        while self.next <= t + 1e-9:
            self.next += self.period
        return True


@dataclass
class OrbitUpdate:
    """One update: the orbit's centre offset from the vehicle, its radius, MaxRadius about the
    predicted position, the turn-limited radius, whether a flyable circle fits about the vehicle
    and anywhere in the VP, and how many VVs this update cast."""

    t: float
    shift: tuple[float, float]
    radius: float
    max_radius: float
    turn_radius: float
    fits_about: bool
    fits_anywhere: bool
    new_volumes: int


@dataclass
class CityOrbitResult:
    """A flown city follower (``strategy``: "city_orbit" or "city_horizon"): samples (t, state x y
    psi, bank, vehicle), the updates, and per sample the line of sight and whether the camera sees
    the vehicle."""

    t: np.ndarray
    state: np.ndarray
    bank: np.ndarray
    vehicle: np.ndarray
    updates: list[Any]  # OrbitUpdate (the city orbit) or city_horizon.HorizonUpdate
    line_of_sight: np.ndarray
    in_view: np.ndarray
    volumes: int
    strategy: str = "city_orbit"
    notes: list[str] = field(default_factory=list)

    @property
    def metrics(self) -> dict[str, Any]:
        weights = np.diff(self.t, append=self.t[-1])  # each sample holds until the next
        total = float(weights.sum()) or 1.0
        times = np.array([u.t for u in self.updates])
        held = np.diff(times, append=float(self.t[-1]))  # each update holds until the next
        span = float(held.sum()) or 1.0
        return {
            "strategy": self.strategy, "duration_s": float(self.t[-1] - self.t[0]),
            "camera_fraction": float(weights @ self.in_view) / total,
            "line_of_sight_fraction": float(weights @ self.line_of_sight) / total,
            "camera_and_line_of_sight_fraction": float(weights @ (self.in_view & self.line_of_sight)) / total,
            "flyable_circle_about_vehicle_fraction": float(held @ [u.fits_about for u in self.updates]) / span,
            "flyable_circle_in_polygon_fraction": float(held @ [u.fits_anywhere for u in self.updates]) / span,
            **({"updates_heading_for_vehicle": sum(u.heading_for_vehicle for u in self.updates)}
               if self.strategy == "city_horizon" else
               {"mean_radius_m": float(np.mean([u.radius for u in self.updates]))}),
            "mean_vehicle_distance_m": float(weights @ np.hypot(*(self.state[:, :2] - self.vehicle).T)) / total,
            "updates": len(self.updates), "volumes": self.volumes,
            "max_new_volumes_per_update": int(max((u.new_volumes for u in self.updates), default=0)),
        }


def circle_exists(room: OrbitRoom, turn: float, margin: float) -> tuple[bool, bool]:
    """Whether a flyable circle (radius ``turn``, ``margin`` inside the VP) fits about the room's
    vehicle, and whether one fits anywhere in its VP."""
    about = room.max_radius - margin >= turn
    return about, about or room.flyable_circle(turn + margin) is not None


def scored_flight(trajectory: Any, vehicle: GroundVehicle, scene: VisibilityScene, uav: Uav, camera: DownwardCamera,
                  vehicle_height: float, updates: Sequence[Any], volumes: int,
                  strategy: str = "city_orbit") -> CityOrbitResult:
    """A city follower's flight (a FlightTrajectory) scored at every sample: the camera (at the
    sample's heading and bank) and a ray from the UAV at ground level + ``uav.altitude`` to the
    vehicle ``vehicle_height`` above the surface under it."""
    t = np.asarray(trajectory.t)
    state = np.column_stack([trajectory.x, trajectory.y, trajectory.psi])
    bank = np.asarray(trajectory.bank)
    where = np.asarray(vehicle.sample(t))
    in_view = np.array([camera_sees(camera, np.array([x, y, uav.altitude]), psi, b, np.array([gx, gy, 0.0]))
                        for (x, y, psi), b, (gx, gy) in zip(state, bank, where)], dtype=bool)
    n = len(t)
    ground = np.asarray(scene.poi_on_surface(np.column_stack([where, np.full(n, vehicle_height)])))
    sky = np.column_stack([state[:, :2], np.full(n, scene.ground_level + uav.altitude)])
    visible = np.asarray(scene.line_of_sight(sky, ground), dtype=bool)
    return CityOrbitResult(t, state, bank, where, list(updates), visible, in_view, volumes, strategy)
