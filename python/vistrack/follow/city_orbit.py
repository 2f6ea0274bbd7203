"""Following over a city (beyond every anchor): an orbit about the vehicle inside the visibility
polygon of its predicted position, computed online.

At every update (1 Hz) the follower observes the vehicle (position and velocity), predicts where it
will be half an update later, and asks :mod:`vistrack.city_orbits` for that point's visibility
polygon (VP) at the flight altitude and MaxRadius about it (VVs cached by position on a grid, so at
most one new VV per update). The orbit's radius is the turn-limited radius R_turn (Lemma 6 at the
vehicle's current speed, with the planner's turn margin) when MaxRadius - margin >= R_turn: a circle
about the vehicle inside its VP, so the line of sight holds; ``radius="max"`` flies MaxRadius -
margin instead (the tracking paper's choice, farthest from the vehicle); the radius grows by at most
``grow`` m per update. Where no such circle fits, the flyable circle of radius R_turn inside the VP
nearest the vehicle (off-centre, moving with it) or the largest flyable about the vehicle, whichever
the flight predicted along the field (74)/(86) keeps in line of sight and camera more over the
look-ahead; where none fits anywhere, R_turn about the vehicle (the line of sight may break).

The orbit is flown by the flight layer as the follower flies its plan: L1 guidance (``CurveL1``)
along the orbit's predicted ground track, renewed at every update.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Optional, Sequence

import numpy as np

from .. import flight as _flight
from .._core import Control, GuidanceGains, OrbitState, Uav, VisibilityScene, VistrackError, steering
from .._core.follow import HorizonOptions
from .._core.loiter import STANDARD_GRAVITY
from ..city_orbits import OrbitRoom, VolumeCache, orbit_room
from .city_runs import (
    CityOrbitResult,
    OrbitUpdate,
    UpdateClock,
    circle_exists,
    city_defaults,
    scored_flight,
    start_pose,
)
from .simulation import (
    DownwardCamera,
    FollowFlight,
    FollowParameters,
    GroundVehicle,
    Wind,
    camera_reach,
    camera_sees,
    coordinated_bank,
)

__all__ = ["CityOrbitOptions", "CityOrbitResult", "OrbitUpdate", "camera_radius", "city_orbit_follow", "orbit_track",
           "predicted_view"]

RADIUS_CHOICES = ("lemma6", "camera", "max")
PLANNERS = ("horizon", "orbit")


@dataclass
class CityOrbitOptions:
    """reach: the VP is measured out to this far at the altitude (the VV's d_max follows); grid:
    the VV cache's cell (m); margin: kept between the orbit and the VP's boundary (m); radius:
    "lemma6" (Lemma 6's at the vehicle's speed, cut to MaxRadius - margin), "camera" (the largest
    whose centre the camera sees at the steepest bank) or "max" (MaxRadius - margin); off_centre: where no circle
    fits about the vehicle, fly one off it inside the VP (off_centre_max_speed: only about a vehicle at most that
    fast, m/s); lead: how far ahead (s) the VV is cast."""

    reach: float = 400.0
    resolution_deg: float = 1.0
    grid: float = 5.0
    margin: float = 3.0
    radius: str = "lemma6"
    off_centre: bool = True
    lead: float = 0.5
    vehicle_height: float = 0.5
    guidance: str = "field"
    lookahead: tuple[float, ...] = (3.0, 6.0)
    camera_reach: bool = False  # True: an off-centre circle only as far as the camera sees the vehicle from it
    l1_period: float = 12.0  # s, the L1 period flying the orbit (0: the flight's, FollowFlight.l1_period)
    grow: float = 1.0  # m per update the orbit's radius may grow by (it shrinks at once, to keep in its VP)
    # m/s: an off-centre circle only about a vehicle this slow or slower (None: at any speed). A parked
    # vehicle's polygon stands still; a moving one's sweeps along the street and the circle jumps with it.
    off_centre_max_speed: Optional[float] = None
    choose: str = "predicted"  # where no circle fits about the vehicle: "predicted" (off-centre or about, by
    # the predicted flight's line of sight and camera) or "off_centre" (always off-centre when one fits)
    # The city follower: "horizon" (follow.city_horizon: receding-horizon bank commands, the default) or
    # "orbit" (this module's orbit inside the visibility polygon, the part 6); its look-ahead, s.
    planner: str = "horizon"
    horizon: int = HorizonOptions().horizon

    def validate(self) -> None:
        for name in ("reach", "resolution_deg", "grid"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0.0):
                raise VistrackError(f"city_orbit.{name} = {value}: must be > 0")
        if self.choose not in ("predicted", "off_centre"):
            raise VistrackError(f"city_orbit.choose = {self.choose!r}: must be 'predicted' or 'off_centre'")
        limit = self.off_centre_max_speed
        if limit is not None and not (math.isfinite(limit) and limit >= 0.0):
            raise VistrackError(f"city_orbit.off_centre_max_speed = {limit}: must be >= 0 (m/s) or None")
        if not self.grow > 0.0:
            raise VistrackError(f"city_orbit.grow = {self.grow}: must be > 0 (m per update)")
        for name in ("margin", "lead", "vehicle_height"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value >= 0.0):
                raise VistrackError(f"city_orbit.{name} = {value}: must be >= 0")
        if not (math.isfinite(self.l1_period) and self.l1_period >= 0.0):
            raise VistrackError(f"city_orbit.l1_period = {self.l1_period}: must be >= 0")
        if self.guidance not in ("field", "circle"):
            raise VistrackError(f"city_orbit.guidance = {self.guidance!r}: must be 'field' or 'circle'")
        if any(not (math.isfinite(t) and t > 0.0) for t in self.lookahead):
            raise VistrackError(f"city_orbit.lookahead = {self.lookahead}: times must be > 0")
        if self.planner not in PLANNERS:
            raise VistrackError(f"city_orbit.planner = {self.planner!r}: must be one of " + ", ".join(PLANNERS))
        if isinstance(self.horizon, bool) or not isinstance(self.horizon, int) or not 1 <= self.horizon <= 600:
            raise VistrackError(f"city_orbit.horizon = {self.horizon!r}: must be a whole number of seconds, 1-600")
        if self.radius not in RADIUS_CHOICES:
            raise VistrackError(f"city_orbit.radius = {self.radius!r}: must be one of " + ", ".join(RADIUS_CHOICES))


def _reach_angle(camera: DownwardCamera) -> float:
    """The camera's farthest angle off the body's down axis (the core's camera_reach at 1 m up):
    half its field of view, plus the gimbal's range unless it is fixed to the body."""
    return math.atan(camera_reach(camera, 1.0))


def camera_radius(uav: Uav, camera: DownwardCamera, gravity: float = STANDARD_GRAVITY) -> float:
    """The largest orbit radius at which the camera sees the orbit's centre even at the steepest
    bank the UAV can fly, atan(v^2 / (g r_min)): the centre's angle off the vertical, atan(R / h),
    plus that bank within the half field of view plus the gimbal's range."""
    steepest = math.atan(uav.speed ** 2 / (gravity * uav.min_turn_radius))
    room = _reach_angle(camera) - steepest
    return uav.altitude * math.tan(max(room, 0.0))


def shift_reach(uav: Uav, camera: DownwardCamera, radius: float, gravity: float = STANDARD_GRAVITY) -> float:
    """How far an orbit of ``radius`` may be off the vehicle with the camera still seeing it from
    the far side in a steady turn: h tan(fov/2 + gimbal - bank) - radius, bank = atan(v^2/(g R))."""
    bank = math.atan(uav.speed ** 2 / (gravity * radius))
    return uav.altitude * math.tan(max(_reach_angle(camera) - bank, 0.0)) - radius


def common_shift(rooms: Sequence[tuple[np.ndarray, OrbitRoom]], radius: float, previous: np.ndarray,
                 hold: float = 20.0, reach: float = math.inf) -> Optional[np.ndarray]:
    """The offset from the vehicle of a circle of ``radius`` that moves with it and lies inside
    every room's VP at the vehicle's position there (the rooms of its predicted positions), nearest
    the vehicle, at most ``reach`` m from it; the ``previous`` offset while it still fits and is
    less than ``hold`` m farther (no jumps for a few metres); None when there is none."""
    import shapely

    common: Any = None
    for where, room in rooms:
        inner = shapely.affinity.translate(room.inner(radius), -where[0], -where[1])
        common = inner if common is None else shapely.intersection(common, inner)
        if common.is_empty:
            return None
    if common is None:
        return None
    target = shapely.Point(0.0, 0.0)
    if math.isfinite(reach):
        common = shapely.intersection(common, target.buffer(max(reach, 0.0), quad_segs=16))
        if common.is_empty:
            return None
    at, first = rooms[0]
    for piece in sorted((g for g in shapely.get_parts(common) if not g.is_empty), key=lambda g: g.distance(target)):
        x, y = shapely.shortest_line(piece, target).coords[0]
        if first.fits((x + at[0], y + at[1]), radius):  # not a buffer sliver
            best = np.array([x, y])
            if common.contains(shapely.Point(*previous)) and np.hypot(*previous) < np.hypot(*best) + hold:
                return np.asarray(previous, dtype=float)
            return best
    return None


def field_track(q: Sequence[float] | np.ndarray, center: np.ndarray, velocity: np.ndarray, radius: float,
                gains: GuidanceGains, horizon: float, step: float = 0.1) -> np.ndarray:
    """The ground path (n, 2) the tracking paper's vector field (74) and steering law (86) would
    fly from the UAV's pose ``q`` (x, y, psi) about a centre moving from ``center`` at ``velocity``
    at ``radius``, for ``horizon`` s (turn rate clamped as the gains say): a flyable path that
    joins the orbit, for L1 to follow."""
    x, y, psi = (float(v) for v in q[:3])
    points = [(x, y)]
    for k in range(math.ceil(horizon / step)):
        orbit = OrbitState(center=center + velocity * (k * step), center_velocity=velocity, radius=radius)
        rate = steering(np.array([x, y, psi]), orbit, gains).command
        x += gains.speed * math.cos(psi) * step
        y += gains.speed * math.sin(psi) * step
        psi += rate * step
        points.append((x, y))
    return np.array(points)


def predicted_view(path: np.ndarray, step: float, air: np.ndarray, p: np.ndarray, v: np.ndarray,
                   rooms: Sequence[tuple[np.ndarray, OrbitRoom]], times: np.ndarray, uav: Uav,
                   camera: DownwardCamera) -> float:
    """The fraction of the samples of ``path`` (n, 2), an air-mass path sampled every ``step`` s from
    now, at which the vehicle (at p + v tau) is inside the VP of the room nearest in time (``rooms[j]``
    = (the vehicle's position it was cast for, the room), reached at ``times[j]`` s) and in the camera.
    Over the ground the UAV is at path + air tau; its heading and coordinated bank are the air-mass
    path's (the body's, which the camera is fixed to: in wind the ground track's course and turn rate
    differ from them)."""
    import shapely

    tau = np.arange(len(path) - 1) * step
    if len(tau) == 0 or len(rooms) == 0:
        return 0.0
    ground = path[:-1] + np.outer(tau, air)  # the air-mass path drifts with the wind
    heading = np.unwrap(np.arctan2(*np.diff(path, axis=0).T[::-1]))
    rate = np.gradient(heading, step) if len(heading) > 1 else np.zeros_like(heading)
    where = p + np.outer(tau, v)
    nearest = np.argmin(np.abs(np.subtract.outer(tau, np.asarray(times)[: len(rooms)])), axis=1)
    inside = np.zeros(len(tau), dtype=bool)
    for j, (at, room) in enumerate(rooms):
        mine = nearest == j
        rel = ground[mine] - where[mine] + at  # the UAV where it stands from the vehicle, in the room's frame
        inside[mine] = shapely.contains_xy(room.region(), rel[:, 0], rel[:, 1])
    seen = sum(camera_sees(camera, np.array([ground[k, 0], ground[k, 1], uav.altitude]), heading[k],
                           coordinated_bank(uav.speed, rate[k]), np.array([where[k, 0], where[k, 1], 0.0]))
               for k in np.flatnonzero(inside))
    return seen / len(tau)


def orbit_track(center: np.ndarray, velocity: np.ndarray, radius: float, start: np.ndarray, speed: float,
                horizon: float, step: float = 0.25, ccw: bool = True) -> np.ndarray:
    """The ground track (n, 2) of a UAV at ground speed ``speed`` circling at ``radius`` a centre
    that moves from ``center`` at ``velocity``, from the bearing of ``start`` for ``horizon`` s."""
    sign = 1.0 if ccw else -1.0
    offset = np.asarray(start, dtype=float) - center
    theta = math.atan2(offset[1], offset[0]) if np.hypot(*offset) > 1e-9 else 0.0
    points = []
    for k in range(math.ceil(horizon / step) + 1):
        tau = k * step
        c = center + velocity * tau
        points.append(c + radius * np.array([math.cos(theta), math.sin(theta)]))
        along = sign * np.array([-math.sin(theta), math.cos(theta)])  # direction of travel on the circle
        v_along = float(velocity @ along)
        # |v_c + R w along| = speed, w >= 0 (a centre faster than the UAV: the circle is not flyable; hold w = 0).
        disc = v_along ** 2 - float(velocity @ velocity) + speed ** 2
        omega = max(0.0, (-v_along + math.sqrt(max(disc, 0.0))) / radius)
        theta += sign * omega * step
    return np.array(points)


def city_orbit_follow(vehicle: GroundVehicle, uav: Uav, scene: VisibilityScene, *,
                      parameters: Optional[FollowParameters] = None, wind: Optional[Wind] = None,
                      flight: Optional[FollowFlight] = None, camera: Optional[DownwardCamera] = None,
                      options: Optional[CityOrbitOptions] = None, ccw: bool = True,
                      wind_estimate: Optional[Sequence[float]] = None,
                      progress: Optional[Callable[[int, int], None]] = None,
                      start: Optional[Sequence[float]] = None) -> CityOrbitResult:
    """Fly the city orbit about ``vehicle`` at world z = ground + ``uav.altitude`` (see the module)
    in the true ``wind``; ``wind_estimate`` (east, north): what the planner knows of it (None: no
    wind), planned in the air mass as the follower does. ``progress(done, total)``: after each update;
    ``start``: the UAV's (x, y, psi) (default: on the first update's path, 200 m ahead of the vehicle)."""
    options = options or CityOrbitOptions()
    options.validate()
    parameters, flight, camera, air = city_defaults(uav, parameters, flight, camera, wind_estimate)
    altitude = scene.ground_level + uav.altitude
    cache = VolumeCache(scene, math.hypot(uav.altitude, options.reach), options.resolution_deg, options.grid)
    period = parameters.update_period
    clock = UpdateClock(vehicle, flight, period)
    l1_period = options.l1_period if options.l1_period > 0.0 else flight.l1_period
    horizon = 3.0 * flight.l1_damping * l1_period / math.pi + 2.0 * period
    updates: list[OrbitUpdate] = []
    seen_radius = camera_radius(uav, camera)

    gains = GuidanceGains.from_parameters(uav, Control(direction="ccw" if ccw else "cw"))

    def track(q: np.ndarray, center: np.ndarray, v: np.ndarray, radius: float) -> np.ndarray:
        """The path for L1 in the air mass (the centre moves at v - wind there), as it lies at the
        update; the air mass, and the path with it, drifts with the wind until the next."""
        if options.guidance == "field" and len(q) >= 3:
            return field_track(q, center, v - air, radius, gains, horizon)
        return orbit_track(center, v - air, radius, q[:2], uav.speed, horizon, ccw=ccw)

    # When the rooms of rooms_ahead are reached: the lead's, then the look-ahead's, farthest first.
    look_times = np.array([options.lead, *sorted(options.lookahead, reverse=True)])

    def rooms_ahead(p: np.ndarray, v: np.ndarray) -> list[tuple[np.ndarray, OrbitRoom]]:
        """(vehicle position, room) at the lead and at the look-ahead times: the lead's VV always
        (new when not cached), the farthest look-ahead's when no VV was cast yet in this update,
        the others only when cached: at most one new VV per update."""
        found: list[tuple[np.ndarray, OrbitRoom]] = []
        for k, tau in enumerate(look_times):
            where = p + v * tau
            point = np.asarray(scene.poi_on_surface(np.array([[where[0], where[1], options.vehicle_height]])))[0]
            if k > 0 and not cache.has(point) and (k > 1 or cache.computed > computed_before[0]):
                continue
            try:
                found.append((where, orbit_room(scene, point, altitude, cache=cache)))
            except VistrackError:  # a prediction inside a building: no room there
                if k == 0:
                    return []
        return found

    computed_before = [0]
    h_look = max(options.lookahead, default=options.lead) + period  # the choice's prediction

    def predicted_seen(q: np.ndarray, p: np.ndarray, v: np.ndarray, centre: np.ndarray, radius: float,
                       rooms: list[tuple[np.ndarray, OrbitRoom]]) -> float:
        """predicted_view of the field's path about ``centre`` from the UAV's pose ``q`` over the
        next h_look s, from the cast VVs only (no new one)."""
        step = 0.1
        return predicted_view(field_track(q, centre, v - air, radius, gains, h_look, step), step, air, p, v,
                              rooms, look_times[: len(rooms)], uav, camera)

    def record(done: OrbitUpdate) -> None:
        updates.append(done)
        if progress is not None:
            progress(min(len(updates), clock.total), clock.total)

    def update(t: float, q: np.ndarray) -> np.ndarray:
        p, v = np.asarray(vehicle.position(t)), np.asarray(vehicle.velocity(t))
        relative = float(np.hypot(*(v - air)))  # the vehicle's speed in the air mass
        # The smallest circle the UAV can fly (the planner's 1.25 r_min), and Lemma 6's radius at the
        # vehicle's speed through the air (the smallest it can hold about a vehicle moving that fast).
        turn = parameters.turn_margin * uav.min_turn_radius
        lemma6 = turn * (1.0 + min(relative / uav.speed, 1.0)) ** 2
        margin = options.margin + float(np.hypot(*v)) * options.lead  # the vehicle's way from the prediction
        computed_before[0] = cache.computed
        last = updates[-1] if updates else None
        rooms = rooms_ahead(p, v)
        if not rooms:  # the prediction stands in a building: keep the last orbit's shape
            shift, radius = (np.array(last.shift), last.radius) if last else (np.zeros(2), turn)
            record(OrbitUpdate(t, (float(shift[0]), float(shift[1])), radius, 0.0, turn, False, False,
                               cache.computed - computed_before[0]))
            return track(q, p + shift, v, radius)
        now = rooms[0][1]
        room_about = min(r.max_radius for _, r in rooms)  # the room about the vehicle over the look-ahead
        about, anywhere = circle_exists(now, turn, margin)
        wanted = max(turn, min(lemma6, seen_radius)) if options.radius == "camera" else lemma6
        shift, radius = np.zeros(2), lemma6
        if room_about - margin >= turn:
            radius = room_about - margin if options.radius == "max" else min(wanted, room_about - margin)
            if last is not None and not np.any(last.shift):
                radius = max(turn, min(radius, last.radius + options.grow))
        else:
            previous = np.zeros(2) if last is None else np.array(last.shift)
            for size in (wanted, lemma6, turn):
                found = common_shift(rooms, size + margin, previous,
                                     reach=shift_reach(uav, camera, size) if options.camera_reach else math.inf)
                if found is not None:
                    shift, radius = found, size
                    break
            centred = max(turn, min(lemma6, now.max_radius - margin))
            limit = options.off_centre_max_speed
            if not options.off_centre or (limit is not None and float(np.hypot(*v)) > limit):
                shift, radius = np.zeros(2), centred
            elif options.choose == "predicted" and np.any(shift) and len(q) >= 3:
                # Off-centre or about the vehicle: whichever flight (the field's path from the UAV)
                # is predicted to keep line of sight and camera more over the look-ahead.
                off = predicted_seen(q, p, v, p + shift, radius, rooms)
                if predicted_seen(q, p, v, p, centred, rooms) > off:
                    shift, radius = np.zeros(2), centred
        record(OrbitUpdate(t, (float(shift[0]), float(shift[1])), float(radius), now.max_radius, turn, about,
                           anywhere, cache.computed - computed_before[0]))
        return track(q, p + shift, v, radius)

    t0, pose = clock.t0, start_pose(vehicle, start)
    if start is None:  # the first path from the default start's position; the flight starts on it
        path = update(t0, np.array(pose[:2]))
        pose = (float(path[0, 0]), float(path[0, 1]), math.atan2(path[1, 1] - path[0, 1], path[1, 0] - path[0, 0]))
    else:
        path = update(t0, np.array(pose))
    guidance = _flight.CurveL1(uav.speed, path, l1_period, flight.l1_damping)
    planned: list[Any] = [t0, path]  # when the path was planned, and the path (in the air mass then)
    drifts = bool(np.any(air != 0.0))

    def on_step(t: float, q: Sequence[float]) -> None:
        if clock.due(t):
            planned[0], planned[1] = t, update(t, np.array([q[0], q[1], q[2]]))
        elif not drifts:
            return
        guidance.set_path(planned[1] + air * (t - planned[0]))

    trajectory = _flight.fly(guidance, pose, uav.speed, uav.min_turn_radius, wind=wind, dt=flight.dt,
                             max_time=clock.duration, integration=flight.integration, t0=t0, on_step=on_step, uav=uav)
    return scored_flight(trajectory, vehicle, scene, uav, camera, options.vehicle_height, updates, cache.computed)
