"""Following a ground vehicle: the planner's run, its result and scores, the vector-field baseline
and the camera's view (the API of ``vistrack.follow``)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Optional, Sequence

import numpy as np

from .._core import Control, Uav, VisibilityScene, VistrackError
from .._core import flight as _flight
from .._core import follow as _follow
from ..flight import Wind
from ..preview import preview
from ..schema import length
from .to_mission import follow_mission

if TYPE_CHECKING:
    from ..georeference import Georeference
    from ..mission.model import Mission

DownwardCamera = _follow.DownwardCamera
FollowFlight = _follow.FollowFlight
FollowMetrics = _follow.FollowMetrics
FollowObservation = _follow.FollowObservation
FollowParameters = _follow.FollowParameters
FollowPlanner = _follow.FollowPlanner
FollowRun = _follow.FollowRun
FollowTick = _follow.FollowTick
GroundVehicle = _follow.GroundVehicle
LoiterShape = _follow.LoiterShape
VehicleLeg = _follow.VehicleLeg
VehicleReportOptions = _follow.VehicleReportOptions
along_track_rate = _follow.along_track_rate
arc_length = _follow.arc_length
camera_reach = _follow.camera_reach
camera_sees = _follow.camera_sees
camera_threshold = _follow.camera_threshold
sinusoid_shape = _follow.sinusoid_shape
coordinated_bank = _flight.coordinated_bank  # one formula, the flight layer's
default_uav = _follow.default_uav  # a new Uav: the follower's where a scenario gives none
phase_at_arc = _follow.phase_at_arc
sinusoid_amplitude = _follow.sinusoid_amplitude
sinusoid_slope = _follow.sinusoid_slope
speed_ratio = _follow.speed_ratio

MODES = ("sinusoid", "loiter", "straight", "standoff")

__all__ = [
    "MODES", "DownwardCamera", "FollowFlight", "FollowMetrics", "FollowObservation", "FollowParameters",
    "FollowPlanner", "FollowResult", "FollowRun", "FollowTick", "GroundVehicle", "LoiterShape", "VehicleLeg",
    "VehicleReportOptions", "along_track_rate", "arc_length", "baseline", "baseline_infeasibility", "baseline_radius",
    "camera_footprint", "camera_reach", "camera_sees", "camera_threshold", "coordinated_bank", "default_uav",
    "line_of_sight", "phase_at_arc", "simulate", "sinusoid_amplitude", "sinusoid_record", "sinusoid_shape",
    "sinusoid_slope", "speed_ratio", "threshold_record", "threshold_warning",
]


@dataclass
class FollowResult:
    """One flown run (the planner's, or the baseline's) with numpy views of its samples.

    ``run`` is the core ``FollowRun``; ``line_of_sight`` (n,) is set when a scene was given."""

    run: FollowRun
    strategy: str = "sinusoid"  # "sinusoid" (the planner, any follow.strategy) or "orbit" (the baseline)
    line_of_sight: Optional[np.ndarray] = None

    @property
    def t(self) -> np.ndarray:
        return np.asarray(self.run.t)

    @property
    def state(self) -> np.ndarray:
        """(n, 3) x, y, psi."""
        return np.asarray(self.run.state)

    @property
    def trajectory(self) -> np.ndarray:
        """(n, 4) t, x, y, psi."""
        return np.column_stack([self.t, self.state])

    @property
    def mode(self) -> np.ndarray:
        """The mode of the current update at each sample ("sinusoid", "loiter", "straight")."""
        return np.asarray(self.run.mode)

    @property
    def desired(self) -> np.ndarray:
        return np.asarray(self.run.desired)

    @property
    def vehicle(self) -> np.ndarray:
        return np.asarray(self.run.vehicle)

    @property
    def offset_point(self) -> np.ndarray:
        return np.asarray(self.run.offset_point)

    @property
    def in_view(self) -> np.ndarray:
        """(n,) bool: the vehicle is inside the camera footprint."""
        return np.asarray(self.run.in_view, dtype=bool)

    @property
    def ticks(self) -> list[FollowTick]:
        return list(self.run.ticks)

    @property
    def waypoints(self) -> np.ndarray:
        """(k, 2) the waypoints the planner issued, one per update (what a mission exports)."""
        return np.asarray(self.run.waypoints)

    @property
    def waypoint_times(self) -> np.ndarray:
        """(k,) when each waypoint was issued (s)."""
        return np.asarray(self.run.waypoint_times)

    @property
    def roi(self) -> np.ndarray:
        """(k, 2) the vehicle's predicted position at each waypoint (where a gimbal should point)."""
        return np.array([k.vehicle_predicted for k in self.run.ticks], dtype=float).reshape(-1, 2)

    def to_mission(self, georeference: Georeference | Sequence[float], altitude: float, *,
                   speed: Optional[float] = None, tolerance: float = 1.0, return_to_launch: bool = False,
                   firmware: str = "ardupilot", altitude_mode: str = "relative", roi: bool = True) -> Mission:
        """The generated 1 Hz waypoints as an autopilot mission, decimated by Douglas-Peucker at
        ``tolerance`` m (0: every waypoint), home at the UAV's start; ``speed`` (the UAV's airspeed)
        adds DO_CHANGE_SPEED; ``roi``: a DO_SET_ROI_LOCATION before each waypoint at the vehicle's
        predicted position (beyond the paper). See :func:`vistrack.follow.to_mission.follow_mission`."""
        return follow_mission(self.waypoints, georeference, altitude, home=self.state[0, :2], speed=speed,
                              tolerance=tolerance, return_to_launch=return_to_launch, firmware=firmware,
                              altitude_mode=altitude_mode, roi=self.roi if roi else None)

    @property
    def metrics(self) -> dict[str, Any]:
        """The scores as plain data (metrics.json)."""
        m = self.run.metrics
        out: dict[str, Any] = {
            "strategy": self.strategy,
            "duration_s": m.duration,
            "mean_tracking_error_m": m.mean_tracking_error,
            "max_tracking_error_m": m.max_tracking_error,
            "along_track_lag_m": m.mean_along_track_lag,
            "max_along_track_lag_m": m.max_along_track_lag,
            "final_along_track_lag_m": m.final_along_track_lag,
            "mode_switches": m.mode_switches,
            "time_capturing_s": m.time_capturing,
            "time_in_mode_s": {"sinusoid": m.time_sinusoid, "loiter": m.time_loiter, "straight": m.time_straight,
                               "standoff": m.time_standoff},
            "camera_fraction": m.camera_fraction,
            "mean_vehicle_distance_m": m.mean_vehicle_distance,
            "mean_offset_distance_m": m.mean_offset_distance,
            "centre_offset_m": [float(v) for v in m.mean_offset_error],
            "lost_s": m.lost_time,
            "lost_episodes": m.lost_episodes,
            "reacquire_s": {"mean": m.mean_reacquire_time, "max": m.max_reacquire_time},
            "smoothness": _flight.flight_smoothness(self.run.t, self.run.bank).as_dict() if len(self.run.t) >= 2
            else None,
        }
        if self.strategy != "orbit":
            out["threshold"] = threshold_record(self.run.threshold)
            out["sinusoid"] = sinusoid_record(self.run.ticks)
        if self.line_of_sight is not None:
            weights = np.diff(self.t, append=self.t[-1])  # each sample holds until the next
            total = float(weights.sum()) or 1.0
            out["line_of_sight_fraction"] = float(weights @ self.line_of_sight) / total
            out["camera_and_line_of_sight_fraction"] = float(weights @ (self.line_of_sight & self.in_view)) / total
        return out


def threshold_record(choice: Any) -> dict[str, Any]:
    """The threshold the planner used (``FollowRun.threshold``) as plain data; ``camera_reach_m``
    is None (JSON null) for a camera whose cone reaches the horizon."""
    reach = choice.reach if math.isfinite(choice.reach) else None
    return {"h": choice.threshold, "automatic": choice.automatic, "upper_ratio": choice.upper_ratio,
            "amplitude_at_upper_m": choice.amplitude, "camera_reach_m": reach, "beyond_reach": choice.beyond_reach}


def sinusoid_record(ticks: Sequence[FollowTick]) -> Optional[dict[str, Any]]:
    """The effective sinusoid over the updates that flew it: min, median and max of sigma, T (s,
    after the curvature floor), D and A (m); None when no update did (per update: updates.csv)."""
    rows = np.array([(k.speed_ratio, k.period, k.period_distance, k.amplitude) for k in ticks if k.mode == "sinusoid"])
    if len(rows) == 0:
        return None
    names = ("speed_ratio", "period_s", "period_distance_m", "amplitude_m")
    return {name: [float(rows[:, i].min()), float(np.median(rows[:, i])), float(rows[:, i].max())]
            for i, name in enumerate(names)}


def threshold_warning(result: FollowResult) -> Optional[str]:
    """A warning when the user's threshold lets the sinusoid's amplitude exceed the camera's reach
    (with the numbers), else None (an "auto" threshold never does)."""
    if result.strategy == "orbit":
        return None
    c = result.run.threshold
    if c.automatic or not c.beyond_reach:
        return None
    return (f"follow.threshold = {c.threshold:g}: at the band's upper edge (sigma {c.upper_ratio:g}) the sinusoid's "
            f"amplitude is {c.amplitude:.0f} m, beyond the {c.reach:.0f} m the camera sees to the side at this "
            "altitude (threshold: auto keeps it within)")


def _wind(wind: Wind | Sequence[float] | None) -> Wind:
    if wind is None:
        return Wind()
    if isinstance(wind, Wind):
        return wind
    values = _numbers(wind, 2, "wind", "(east, north) m/s")
    return Wind(east=values[0], north=values[1])


def _numbers(value: Sequence[float], count: int, key: str, what: str) -> list[float]:
    """``count`` numbers, or VistrackError naming ``key`` (a wrong length or type reads as clearly
    as a wrong value)."""
    try:
        numbers = [float(v) for v in value]
    except (TypeError, ValueError):
        numbers = []
    if len(numbers) != count:
        raise VistrackError(f"{key} = {preview(value)}: expected {what}")
    return numbers


def _start(start: Optional[Sequence[float]]) -> Optional[np.ndarray]:
    return None if start is None else np.array(_numbers(start, 3, "start", "(x, y, psi)"))


def line_of_sight(scene: VisibilityScene, run: FollowRun, uav_altitude: float,
                  vehicle_height: float = 0.5) -> np.ndarray:
    """(n,) bool: the segment from the UAV (at the scene's ground level + uav_altitude, the
    altitude the tracking pipeline flies at) to the vehicle (vehicle_height above the surface
    under it) is clear of the buildings."""
    state = np.asarray(run.state)
    vehicle = np.asarray(run.vehicle)
    n = len(state)
    uav = np.column_stack([state[:, :2], np.full(n, scene.ground_level + uav_altitude)])
    ground = scene.poi_on_surface(np.column_stack([vehicle, np.full(n, vehicle_height)]))
    return np.asarray(scene.line_of_sight(uav, ground), dtype=bool)


def simulate(vehicle: GroundVehicle, uav: Uav, parameters: Optional[FollowParameters] = None, *,
             wind: Wind | Sequence[float] | None = None, wind_estimate: Optional[Sequence[float]] = None,
             flight: Optional[FollowFlight] = None, camera: Optional[DownwardCamera] = None,
             start: Optional[Sequence[float]] = None, offset_schedule: Sequence[tuple[float, float, float]] = (),
             scene: Optional[VisibilityScene] = None, vehicle_height: float = 0.5,
             reports: Optional[VehicleReportOptions] = None) -> FollowResult:
    """Plan and fly a follow run: the planner's 1 Hz waypoints flown by the flight layer.

    wind: the true wind (``vt.flight.Wind`` or (east, north) m/s); wind_estimate: what the
    planner compensates (default: the true constant wind; compensation is
    ``parameters.wind_compensation``). start: (x, y, psi), default on the planned path.
    offset_schedule: (t, distance, angle) keys, linear in between (Fig. 8 moves the loiter ahead).
    reports: what the UAV knows of the vehicle (noise, latency, dropouts, timeout; default the truth
    at each update). With a scene, ``line_of_sight`` is evaluated at every sample."""
    true_wind = _wind(wind)
    estimate = (None if wind_estimate is None
                else np.array(_numbers(wind_estimate, 2, "wind_estimate", "(east, north) m/s")))
    run = _follow.follow(vehicle, uav, parameters or FollowParameters(), true_wind, wind_estimate=estimate,
                         flight=flight or FollowFlight(), camera=camera or DownwardCamera(),
                         start=_start(start),
                         offset_schedule=[_offset_key(k, key) for k, key in enumerate(offset_schedule)],
                         reports=reports or VehicleReportOptions())
    visible = None if scene is None else line_of_sight(scene, run, uav.altitude, vehicle_height)
    return FollowResult(run, "sinusoid", visible)


def _offset_key(k: int, key: Any) -> tuple[float, float, float]:
    """One (t, distance, angle) key of an offset schedule; VistrackError naming it otherwise."""
    values = _numbers(key, 3, f"offset_schedule[{k}]", "(t s, distance m, angle rad)")
    return values[0], values[1], values[2]


def baseline_radius(vehicle: GroundVehicle, uav: Uav, parameters: Optional[FollowParameters] = None) -> float:
    """The smallest constant orbit the baseline can hold about the fastest vehicle: Lemma 6 of
    the tracking paper, r_min (1 + v_g/v)^2, with the planner's turn margin (the vehicle's speed
    capped at the UAV's: faster, no orbit is flyable)."""
    margin = (parameters or FollowParameters()).turn_margin
    ratio = min(vehicle.max_speed / uav.speed, 1.0)
    return margin * uav.min_turn_radius * (1.0 + ratio) ** 2


def baseline_infeasibility(vehicle: GroundVehicle, uav: Uav) -> Optional[str]:
    """Why the baseline cannot fly this vehicle, or None: a constant orbit about a vehicle at least
    as fast as the UAV is not flyable (Lemma 5 needs v - v_g > 0; :func:`baseline` refuses it). A
    situation, not bad input: a run reports the baseline infeasible with this reason and flies the
    planner (which chases in its straight mode)."""
    if uav.speed > vehicle.max_speed:
        return None
    return (f"uav.speed {uav.speed:g} m/s does not exceed the vehicle's top speed {vehicle.max_speed:g} m/s: "
            "no constant orbit about it is flyable (Lemma 5)")


def planner_note(result: FollowResult) -> Optional[str]:
    """A note when the planner flew its straight mode (the vehicle outran the UAV: sigma < 1, the
    lag grows), else None."""
    straight = result.run.metrics.time_straight
    if straight <= 0.0:
        return None
    return (f"straight mode for {straight:.0f} s: the vehicle outran the UAV (speed ratio below 1), "
            f"the along-track lag grows (final {result.run.metrics.final_along_track_lag:.0f} m)")


def baseline(vehicle: GroundVehicle, uav: Uav, radius: Optional[float] = None, *, control: Optional[Control] = None,
             parameters: Optional[FollowParameters] = None, wind: Wind | Sequence[float] | None = None,
             flight: Optional[FollowFlight] = None, camera: Optional[DownwardCamera] = None,
             start: Optional[Sequence[float]] = None, scene: Optional[VisibilityScene] = None,
             vehicle_height: float = 0.5, offset_schedule: Sequence[tuple[float, float, float]] = (),
             reports: Optional[VehicleReportOptions] = None) -> FollowResult:
    """The tracking pipeline's guidance vector field (74) and steering law (86) at a constant
    radius about the offset point of ``parameters`` and ``offset_schedule`` (default radius:
    :func:`baseline_radius`), flown by the flight layer in the true wind. A fair comparison: it
    knows the vehicle from the same reports as the planner (``reports``; at each update, carried
    along the reported velocity in between). Its desired position is the orbit's nearest point, so
    its tracking error is |r - R|."""
    parameters = parameters or FollowParameters()
    r = baseline_radius(vehicle, uav, parameters) if radius is None else length("baseline.radius", radius)
    run = _follow.orbit_follow(vehicle, uav, control or Control(), r, parameters, _wind(wind),
                               flight=flight or FollowFlight(), camera=camera or DownwardCamera(),
                               start=_start(start),
                               offset_schedule=[_offset_key(k, key) for k, key in enumerate(offset_schedule)],
                               reports=reports or VehicleReportOptions())
    visible = None if scene is None else line_of_sight(scene, run, uav.altitude, vehicle_height)
    return FollowResult(run, "orbit", visible)


def camera_footprint(camera: DownwardCamera, uav: Sequence[float], psi: float, bank: float,
                     target: Sequence[float], points: int = 72, max_range: Optional[float] = None) -> np.ndarray:
    """The ground footprint of :func:`camera_sees`' cone as a closed ring (points, 2) on the plane
    z = 0: the UAV at ``uav`` (x, y, z above that plane) with heading ``psi`` and bank ``bank``
    (left wing down positive), the gimbal rolled towards ``target`` (x, y[, z]) as far as its range
    allows. Each vertex is where one generator of the cone meets the ground; a generator that
    reaches the horizon or lands beyond ``max_range`` (default 4 x the height) from the nadir point is
    cut there, so a steep bank draws a bounded (clipped) footprint. Used to draw the camera's view."""
    x, y, z = (float(v) for v in uav[:3])
    if not z > 0.0:
        raise VistrackError(f"uav[2] = {z}: the camera must be above the ground (z > 0)")
    reach = 4.0 * z if max_range is None else float(max_range)
    up = np.array([0.0, 0.0, 1.0])
    forward = np.array([math.cos(psi), math.sin(psi), 0.0])
    left = np.array([-math.sin(psi), math.cos(psi), 0.0])
    tz = float(target[2]) if len(target) > 2 else 0.0
    r = np.array([float(target[0]) - x, float(target[1]) - y, tz - z])
    # As camera_sees (cpp/src/follow/camera.cpp): the body's down axis banked by phi; a roll gimbal
    # rolls by gamma = bank + the target's lateral angle within +-max_gimbal; a pan-tilt points at
    # the target within max_gimbal of the down axis; a fixed camera looks along it.
    body_down = -(math.cos(bank) * up + math.sin(bank) * left)
    if camera.mount == "fixed":
        axis = body_down
    elif camera.mount == "pan_tilt":
        to_target = r / max(float(np.linalg.norm(r)), 1e-12)
        off = math.acos(min(1.0, max(-1.0, float(to_target @ body_down))))
        side = to_target - (to_target @ body_down) * body_down
        norm = float(np.linalg.norm(side))
        turn = min(off, camera.max_gimbal)
        axis = body_down if norm < 1e-12 else math.cos(turn) * body_down + math.sin(turn) * side / norm
    else:
        lateral = math.atan2(float(r @ left), float(-(r @ up)))
        gamma = min(max(bank + lateral, -camera.max_gimbal), camera.max_gimbal)
        roll = bank - gamma
        axis = -(math.cos(roll) * up + math.sin(roll) * left)
    ahead = forward - (forward @ axis) * axis  # the cone's basis about its axis
    ahead /= max(float(np.linalg.norm(ahead)), 1e-12)
    across = np.cross(axis, ahead)
    half = 0.5 * camera.fov
    angles = np.linspace(0.0, 2.0 * math.pi, points, endpoint=False)
    rays = (math.cos(half) * axis[None, :] + math.sin(half) * (np.outer(np.cos(angles), ahead)
                                                              + np.outer(np.sin(angles), across)))
    down = -rays[:, 2]
    horizontal = np.hypot(rays[:, 0], rays[:, 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        distance = np.where(down > 0.0, z * horizontal / np.where(down > 0.0, down, 1.0), np.inf)
    distance = np.minimum(distance, reach)
    unit = rays[:, :2] / np.maximum(horizontal, 1e-12)[:, None]
    return np.array([x, y])[None, :] + distance[:, None] * unit
