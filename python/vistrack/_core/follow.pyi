"""
Following a ground vehicle (ground_vehicle_following paper): the sinusoid's amplitude from the speed ratio (eqs. 5, 9-10), loiter (circle or rose) above a threshold with hysteresis, an offset vector, wind compensation in the air mass, waypoints at 1 Hz, and the camera footprint metric.
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
import vistrack._core
import vistrack._core.flight
__all__: list[str] = ['DownwardCamera', 'FollowFlight', 'FollowMetrics', 'FollowObservation', 'FollowParameters', 'FollowPlanner', 'FollowRun', 'FollowTick', 'GroundVehicle', 'HorizonChoice', 'HorizonOptions', 'HorizonPlanner', 'HorizonSecond', 'LoiterShape', 'SinusoidShape', 'ThresholdChoice', 'VehicleLeg', 'VehicleReportOptions', 'along_track_rate', 'arc_length', 'camera_reach', 'camera_sees', 'camera_threshold', 'default_uav', 'follow', 'orbit_follow', 'phase_at_arc', 'sinusoid_amplitude', 'sinusoid_shape', 'sinusoid_slope', 'speed_ratio']
class VehicleLeg:
    """
    One leg of a route: heading (rad from east), speed at its start and end (m/s, linear in between; 0 and 0 is a stop), duration (s).
    """
    def __init__(self, heading: typing.SupportsFloat | typing.SupportsIndex, speed: typing.SupportsFloat | typing.SupportsIndex, duration: typing.SupportsFloat | typing.SupportsIndex, end_speed: typing.SupportsFloat | typing.SupportsIndex | None = None) -> None:
        """
        end_speed None: constant speed.
        """
    @property
    def duration(self) -> float:
        """
        s
        """
    @duration.setter
    def duration(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def end_speed(self) -> float:
        """
        m/s at the end (the start speed on a constant-speed leg; set None for constant speed)
        """
    @end_speed.setter
    def end_speed(self, arg1: typing.SupportsFloat | typing.SupportsIndex | None) -> None:
        ...
    @property
    def heading(self) -> float:
        """
        rad, counter-clockwise from east
        """
    @heading.setter
    def heading(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def speed(self) -> float:
        """
        m/s at the start
        """
    @speed.setter
    def speed(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class GroundVehicle:
    """
    A ground vehicle as a piecewise-linear track (t, x, y): position interpolated, velocity per segment, heading of the last moving segment.
    """
    @staticmethod
    def along_path(path: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], legs: collections.abc.Sequence[VehicleLeg], t0: typing.SupportsFloat | typing.SupportsIndex = 0.0, step: typing.SupportsFloat | typing.SupportsIndex = 0.1) -> GroundVehicle:
        """
        Along a road polyline (n, 2) with the legs' speed profile (their headings ignored).
        """
    @staticmethod
    def from_legs(legs: collections.abc.Sequence[VehicleLeg], start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., t0: typing.SupportsFloat | typing.SupportsIndex = 0.0, step: typing.SupportsFloat | typing.SupportsIndex = 0.1) -> GroundVehicle:
        """
        Drive the legs from `start` at t0 (speed ramps sampled every `step` s).
        """
    def __init__(self, t: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], xy: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> None:
        """
        Times (n,) strictly increasing and positions (n, 2).
        """
    def heading(self, t: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        Heading (rad) at t; a standing vehicle keeps its last.
        """
    def position(self, t: typing.SupportsFloat | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        Position (2,) at t (clamped to the track).
        """
    def sample(self, times: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        Positions (n, 2) at the given times.
        """
    def velocity(self, t: typing.SupportsFloat | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        Velocity (2,) of the segment at t (0 outside).
        """
    @property
    def end_time(self) -> float:
        """
        s
        """
    @property
    def headings(self) -> list[float]:
        """
        Heading per segment (rad).
        """
    @property
    def max_speed(self) -> float:
        """
        Largest segment speed (m/s).
        """
    @property
    def positions(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        Sample positions (n, 2).
        """
    @property
    def start_time(self) -> float:
        """
        s
        """
    @property
    def times(self) -> list[float]:
        """
        Sample times (s).
        """
class FollowParameters:
    """
    The follow planner's settings (defaults from the C++ struct). Angles in radians.
    """
    def __copy__(self) -> FollowParameters:
        """
        A copy (copy.copy): every field.
        """
    def __deepcopy__(self, memo: dict) -> FollowParameters:
        """
        A copy (copy.deepcopy): the fields are values.
        """
    def __init__(self, *, period: typing.SupportsFloat | typing.SupportsIndex = 30.0, turn_margin: typing.SupportsFloat | typing.SupportsIndex = 1.25, threshold: typing.Any = 'auto', hysteresis: typing.SupportsFloat | typing.SupportsIndex = 0.5, loiter_pattern: str = 'circle', loiter_radius: typing.SupportsFloat | typing.SupportsIndex = 0.0, loiter_direction: str = 'ccw', offset_distance: typing.SupportsFloat | typing.SupportsIndex = 0.0, offset_angle: typing.SupportsFloat | typing.SupportsIndex = 0.0, offset_reference: str = 'heading', wind_compensation: bool = True, update_period: typing.SupportsFloat | typing.SupportsIndex = 1.0, strategy: str = 'paper', strategy_margin: typing.SupportsFloat | typing.SupportsIndex = 0.05, standoff_radius: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        """
        Validated parameters.
        """
    def validate(self) -> None:
        """
        Raise VistrackError naming the first invalid field.
        """
    @property
    def hysteresis(self) -> float:
        """
        full width of the band about the threshold
        """
    @hysteresis.setter
    def hysteresis(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def loiter_direction(self) -> str:
        """
        'ccw' or 'cw'
        """
    @loiter_direction.setter
    def loiter_direction(self, arg0: str) -> None:
        ...
    @property
    def loiter_pattern(self) -> str:
        """
        'circle' or 'rose'
        """
    @loiter_pattern.setter
    def loiter_pattern(self, arg1: str) -> None:
        ...
    @property
    def loiter_radius(self) -> float:
        """
        m; 0: the smallest flyable
        """
    @loiter_radius.setter
    def loiter_radius(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def offset_angle(self) -> float:
        """
        theta, rad
        """
    @offset_angle.setter
    def offset_angle(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def offset_distance(self) -> float:
        """
        L, m
        """
    @offset_distance.setter
    def offset_distance(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def offset_reference(self) -> str:
        """
        'north' (theta from east on the map) or 'heading' (theta from the vehicle's heading)
        """
    @offset_reference.setter
    def offset_reference(self, arg1: str) -> None:
        ...
    @property
    def period(self) -> float:
        """
        T: time for the vehicle to cover one period, s
        """
    @period.setter
    def period(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def standoff_radius(self) -> float:
        """
        m; the standoff orbit's constant radius (the baseline's); 0: the smallest flyable per update
        """
    @standoff_radius.setter
    def standoff_radius(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def strategy(self) -> str:
        """
        'paper' (sinusoid and loiter), 'standoff' (vector field (74) about the offset point) or 'auto' (per update, the pattern predicted to see the vehicle most)
        """
    @strategy.setter
    def strategy(self, arg1: str) -> None:
        ...
    @property
    def strategy_margin(self) -> float:
        """
        strategy auto: switch only for this much more predicted camera fraction
        """
    @strategy_margin.setter
    def strategy_margin(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def threshold(self) -> typing.Any:
        """
        h_sigma: loiter above this speed ratio; 'auto': picked from the camera (camera_threshold)
        """
    @threshold.setter
    def threshold(self, arg1: typing.Any) -> None:
        ...
    @property
    def turn_margin(self) -> float:
        """
        tightest planned turn / r_min
        """
    @turn_margin.setter
    def turn_margin(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def update_period(self) -> float:
        """
        s between waypoints (1 Hz)
        """
    @update_period.setter
    def update_period(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def wind_compensation(self) -> bool:
        """
        plan in the air mass
        """
    @wind_compensation.setter
    def wind_compensation(self, arg0: bool) -> None:
        ...
class FollowFlight:
    """
    How a follow run is flown: integration ('discrete' | 'continuous'), step dt (s), max_time (s, 0: until the track ends), guidance of each 1 s leg ('law5': the paper's law (5); 'l1': L1 line tracking, beyond the paper) and the L1 gains (period s, damping).
    """
    def __init__(self, *, integration: str = 'discrete', dt: typing.SupportsFloat | typing.SupportsIndex = 0.02, max_time: typing.SupportsFloat | typing.SupportsIndex = 0.0, guidance: str = 'law5', l1_period: typing.SupportsFloat | typing.SupportsIndex = 8.0, l1_damping: typing.SupportsFloat | typing.SupportsIndex = 0.75) -> None:
        ...
    @property
    def dt(self) -> float:
        """
        s
        """
    @dt.setter
    def dt(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def guidance(self) -> str:
        """
        'law5' or 'l1'
        """
    @guidance.setter
    def guidance(self, arg0: str) -> None:
        ...
    @property
    def integration(self) -> str:
        ...
    @property
    def l1_damping(self) -> float:
        """
        L1 damping
        """
    @property
    def l1_period(self) -> float:
        """
        L1 period, s
        """
    @property
    def max_time(self) -> float:
        """
        s; 0: until the track ends
        """
    @max_time.setter
    def max_time(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class DownwardCamera:
    """
    Downward conic camera (fov the full cone angle) on its mount: 'roll' (a roll gimbal that points it at the target as far as max_gimbal allows), 'pan_tilt' (pointed at the target, at most max_gimbal from the body's down axis) or 'fixed' (the paper's body-fixed camera).
    """
    def __init__(self, *, fov: typing.SupportsFloat | typing.SupportsIndex = 1.2915436464758039, max_gimbal: typing.SupportsFloat | typing.SupportsIndex = 0.4363323129985824, mount: str = 'roll') -> None:
        """
        fov: full angle (rad, default 74 degrees); max_gimbal: the gimbal's range (rad, default 25 degrees); mount: 'roll', 'pan_tilt' or 'fixed'.
        """
    @property
    def fov(self) -> float:
        """
        rad
        """
    @fov.setter
    def fov(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_gimbal(self) -> float:
        """
        rad
        """
    @max_gimbal.setter
    def max_gimbal(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def mount(self) -> str:
        """
        'roll', 'pan_tilt' or 'fixed'
        """
    @mount.setter
    def mount(self, arg1: str) -> None:
        ...
class SinusoidShape:
    """
    The sinusoid the planner flies at a speed ratio.
    """
    @property
    def amplitude(self) -> float:
        """
        A, m
        """
    @property
    def curvature_limited(self) -> bool:
        """
        D is the curvature floor 2 pi a rho
        """
    @property
    def period_distance(self) -> float:
        """
        D, m
        """
    @property
    def slope(self) -> float:
        """
        a = A' = 2 pi A / D
        """
class ThresholdChoice:
    """
    The threshold the planner uses and the numbers behind it.
    """
    @property
    def amplitude(self) -> float:
        """
        A at sigma_u, m
        """
    @property
    def automatic(self) -> bool:
        """
        picked from the camera
        """
    @property
    def beyond_reach(self) -> bool:
        """
        A > w
        """
    @property
    def reach(self) -> float:
        """
        w, the camera's lateral reach, m
        """
    @property
    def threshold(self) -> float:
        """
        h used
        """
    @property
    def upper_ratio(self) -> float:
        """
        sigma_u = h + band / 2
        """
class LoiterShape:
    """
    The loiter pattern about its centre by arc length (circle or rose).
    """
    def sample(self, arcs: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        Positions (n, 2) relative to the centre at the given arc lengths.
        """
    @property
    def delta(self) -> float:
        """
        rose: rotation of the line per pass beyond pi
        """
    @property
    def direction(self) -> int:
        """
        +1 counter-clockwise turns
        """
    @property
    def pattern(self) -> str:
        ...
    @property
    def piece_length(self) -> float:
        """
        circle: circumference; rose: one pass
        """
    @property
    def radius(self) -> float:
        """
        circle radius or the rose's extent, m
        """
    @property
    def turn_radius(self) -> float:
        """
        the rose's turn radius rho, m
        """
class VehicleReportOptions:
    """
    The vehicle's 1 Hz reports as a radio link delivers them (beyond the paper).
    """
    def __init__(self, *, position_noise: typing.SupportsFloat | typing.SupportsIndex = 0.0, velocity_noise: typing.SupportsFloat | typing.SupportsIndex = 0.0, latency: typing.SupportsFloat | typing.SupportsIndex = 0.0, dropout: typing.SupportsFloat | typing.SupportsIndex = 0.0, timeout: typing.SupportsFloat | typing.SupportsIndex = 5.0, seed: typing.SupportsInt | typing.SupportsIndex = 1) -> None:
        """
        position_noise m and velocity_noise m/s (standard deviations per axis), latency s, dropout (probability a report is lost), timeout s (no fresh report for this long: the vehicle is lost), seed.
        """
    @property
    def dropout(self) -> float:
        """
        probability
        """
    @property
    def latency(self) -> float:
        """
        s
        """
    @property
    def position_noise(self) -> float:
        """
        m
        """
    @property
    def seed(self) -> int:
        ...
    @property
    def timeout(self) -> float:
        """
        s
        """
    @property
    def velocity_noise(self) -> float:
        """
        m/s
        """
class FollowObservation:
    """
    What the planner sees at an update.
    """
    def __init__(self, *, vehicle_position: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], vehicle_velocity: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], vehicle_heading: typing.SupportsFloat | typing.SupportsIndex = 0.0, uav_position: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., uav_heading: typing.SupportsFloat | typing.SupportsIndex = 0.0, offset_rate: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ...) -> None:
        ...
    @property
    def lost(self) -> bool:
        """
        no fresh report: orbit the vehicle's estimate
        """
    @lost.setter
    def lost(self, arg0: bool) -> None:
        ...
    @property
    def offset_rate(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        ...
    @offset_rate.setter
    def offset_rate(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> None:
        ...
    @property
    def uav_heading(self) -> float:
        ...
    @uav_heading.setter
    def uav_heading(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def uav_position(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        ...
    @uav_position.setter
    def uav_position(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> None:
        ...
    @property
    def vehicle_heading(self) -> float:
        ...
    @vehicle_heading.setter
    def vehicle_heading(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def vehicle_position(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        ...
    @vehicle_position.setter
    def vehicle_position(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> None:
        ...
    @property
    def vehicle_velocity(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        ...
    @vehicle_velocity.setter
    def vehicle_velocity(self, arg0: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> None:
        ...
class FollowTick:
    """
    One update of the planner: mode, pattern parameters, state, waypoint.
    """
    @property
    def amplitude(self) -> float:
        """
        A, m
        """
    @property
    def arc(self) -> float:
        """
        loiter arc length, m
        """
    @property
    def capturing(self) -> bool:
        """
        holding the entry point until the UAV is close
        """
    @property
    def frame_velocity(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        offset point's velocity in the planning frame
        """
    @property
    def lost(self) -> bool:
        """
        orbiting the vehicle's estimate
        """
    @property
    def mode(self) -> str:
        """
        'sinusoid' | 'loiter' | 'straight'
        """
    @property
    def offset_point(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        O, m
        """
    @property
    def offset_vector(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        O - vehicle, m
        """
    @property
    def offset_velocity(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        O's velocity, m/s
        """
    @property
    def period(self) -> float:
        """
        s
        """
    @property
    def period_distance(self) -> float:
        """
        D, m
        """
    @property
    def phase(self) -> float:
        """
        sinusoid phase, rad
        """
    @property
    def predicted_camera(self) -> float:
        """
        strategy auto: the chosen pattern's predicted camera fraction (-1: none)
        """
    @property
    def radius(self) -> float:
        """
        standoff orbit radius, m
        """
    @property
    def speed_ratio(self) -> float:
        """
        sigma (inf when the offset point stands in the frame)
        """
    @property
    def t(self) -> float:
        """
        s
        """
    @property
    def track_angle(self) -> float:
        """
        direction of the sinusoid's axis, rad
        """
    @property
    def uav_speed(self) -> float:
        """
        v_p planned with, m/s
        """
    @property
    def vehicle_predicted(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        the vehicle update_period later, predicted (the waypoint's region of interest), m
        """
    @property
    def waypoint(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        the waypoint issued at t, m
        """
class FollowPlanner:
    """
    The 1 Hz follow planner of sections II-V.
    """
    def __init__(self, parameters: FollowParameters, uav: vistrack._core.Uav, wind_estimate: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., camera: DownwardCamera = ...) -> None:
        """
        wind_estimate (east, north) m/s is used with compensation; camera: what an 'auto' threshold is picked for.
        """
    def next_mode(self, current: str, speed_ratio: typing.SupportsFloat | typing.SupportsIndex) -> str:
        """
        The mode after `current` for sigma, with the hysteresis band.
        """
    def offset_vector(self, vehicle_heading: typing.SupportsFloat | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        O - vehicle for that heading.
        """
    def orbit_radius(self, frame_speed: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        Radius of the planner's orbits about an offset point moving at frame_speed (Lemma 6), m.
        """
    def planned_path(self, tick: FollowTick, horizon: typing.SupportsFloat | typing.SupportsIndex, step: typing.SupportsFloat | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        The planned ground path from the tick on, (n, 2): O + O_dot tau + relative_position(tick, tau) at tau = 0, step, ..., horizon (what flight.guidance l1 flies).
        """
    def predicted_camera(self, tick: FollowTick) -> float:
        """
        The camera fraction predicted over one steady cycle of the tick's pattern (strategy auto).
        """
    def relative_position(self, tick: FollowTick, tau: typing.SupportsFloat | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        Desired position relative to the offset point tau s after the tick.
        """
    def set_offset(self, distance: typing.SupportsFloat | typing.SupportsIndex, angle: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Change the offset's distance (m) and angle (rad) from the next update on.
        """
    def update(self, t: typing.SupportsFloat | typing.SupportsIndex, observation: FollowObservation) -> FollowTick:
        """
        The update at time t: mode with hysteresis, pattern advanced, next waypoint.
        """
    @property
    def loiter_shape(self) -> LoiterShape:
        """
        The loiter pattern in use.
        """
    @property
    def threshold_choice(self) -> ThresholdChoice:
        """
        The threshold in use.
        """
class FollowMetrics:
    """
    Scores of one follow run (lengths in m, times in s).
    """
    @property
    def camera_fraction(self) -> float:
        """
        time fraction with the vehicle in view
        """
    @property
    def duration(self) -> float:
        ...
    @property
    def final_along_track_lag(self) -> float:
        ...
    @property
    def lost_episodes(self) -> int:
        ...
    @property
    def lost_time(self) -> float:
        """
        s without a report younger than the timeout
        """
    @property
    def max_along_track_lag(self) -> float:
        ...
    @property
    def max_reacquire_time(self) -> float:
        """
        s
        """
    @property
    def max_tracking_error(self) -> float:
        ...
    @property
    def mean_along_track_lag(self) -> float:
        """
        mean lag behind the desired position
        """
    @property
    def mean_offset_distance(self) -> float:
        ...
    @property
    def mean_offset_error(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        mean of UAV - offset point (2,)
        """
    @property
    def mean_reacquire_time(self) -> float:
        """
        s from a fresh report to the camera
        """
    @property
    def mean_tracking_error(self) -> float:
        """
        mean distance from the planned path
        """
    @property
    def mean_vehicle_distance(self) -> float:
        ...
    @property
    def mode_switches(self) -> int:
        ...
    @property
    def time_capturing(self) -> float:
        """
        s holding an entry point until reached
        """
    @property
    def time_loiter(self) -> float:
        ...
    @property
    def time_sinusoid(self) -> float:
        ...
    @property
    def time_standoff(self) -> float:
        ...
    @property
    def time_straight(self) -> float:
        ...
class FollowRun:
    """
    One follow run: per-sample arrays, the 1 Hz updates and the metrics.
    """
    @property
    def along_track_lag(self) -> list[float]:
        """
        m, > 0 behind
        """
    @property
    def bank(self) -> list[float]:
        """
        coordinated-turn bank (rad)
        """
    @property
    def capturing(self) -> list[int]:
        """
        the update holds its entry point (0/1)
        """
    @property
    def desired(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        (n, 2) desired position
        """
    @property
    def in_view(self) -> list[int]:
        """
        vehicle in the camera footprint (0/1)
        """
    @property
    def lost(self) -> list[int]:
        """
        the vehicle is lost (0/1; empty: never)
        """
    @property
    def metrics(self) -> FollowMetrics:
        ...
    @property
    def mode(self) -> list[str]:
        """
        mode of the current update at each sample
        """
    @property
    def offset_point(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        (n, 2)
        """
    @property
    def state(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 3]"]:
        """
        (n, 3) x, y, psi
        """
    @property
    def t(self) -> list[float]:
        """
        sample times (s)
        """
    @property
    def target(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        (n, 2) the waypoint flown to
        """
    @property
    def threshold(self) -> ThresholdChoice:
        """
        the threshold the planner used
        """
    @property
    def ticks(self) -> list[FollowTick]:
        """
        the 1 Hz updates
        """
    @property
    def tracking_error(self) -> list[float]:
        """
        distance from the planned path (m)
        """
    @property
    def turn_rate(self) -> list[float]:
        """
        applied turn rate (rad/s)
        """
    @property
    def vehicle(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        (n, 2) vehicle position
        """
    @property
    def waypoint_times(self) -> list[float]:
        """
        when each waypoint was issued (s)
        """
    @property
    def waypoints(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        (k, 2) the generated waypoints
        """
    @property
    def wind(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        (n, 2) true wind
        """
class HorizonOptions:
    """
    The horizon follower's programme: horizon (s, whole), the relative-position grid (spacing and half_width, m), heading_step_deg, vehicle_height (m above the surface, where the rays end) and the integration step dt (s) of a second's flight.
    """
    def __init__(self, *, horizon: typing.SupportsInt | typing.SupportsIndex = 24, spacing: typing.SupportsFloat | typing.SupportsIndex = 20.0, half_width: typing.SupportsFloat | typing.SupportsIndex = 400.0, heading_step_deg: typing.SupportsFloat | typing.SupportsIndex = 10.0, vehicle_height: typing.SupportsFloat | typing.SupportsIndex = 0.5, dt: typing.SupportsFloat | typing.SupportsIndex = 0.02) -> None:
        """
        Every field by keyword; VistrackError naming a bad one.
        """
    @property
    def dt(self) -> float:
        """
        s
        """
    @property
    def half_width(self) -> float:
        """
        m, the grid's half-width about the vehicle
        """
    @property
    def heading_step_deg(self) -> float:
        """
        degrees
        """
    @property
    def horizon(self) -> int:
        """
        s of prediction
        """
    @property
    def spacing(self) -> float:
        """
        m, the grid's step
        """
    @property
    def vehicle_height(self) -> float:
        """
        m above the surface
        """
class HorizonSecond:
    """
    The UAV after a second with a bank command held.
    """
    @property
    def bank(self) -> float:
        """
        rad
        """
    @property
    def heading(self) -> float:
        """
        rad (not wrapped)
        """
    @property
    def position(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        (2,), m
        """
class HorizonChoice:
    """
    The horizon follower's command for the next second.
    """
    @property
    def bank_command(self) -> float:
        """
        rad, positive left wing down
        """
    @property
    def heading_for_vehicle(self) -> bool:
        """
        nothing in sight from any command's end: the command steers for the vehicle
        """
    @property
    def next(self) -> HorizonSecond:
        """
        the UAV a second later as planned (HorizonSecond)
        """
    @property
    def turn_rate(self) -> float:
        """
        rad/s, g tan(bank_command) / v
        """
    @property
    def value(self) -> float:
        """
        seconds in sight the programme expects over the horizon
        """
class HorizonPlanner:
    """
    Receding-horizon dynamic programming over bank commands (one per second, five levels) with the vehicle predicted over the horizon; a second scores when a ray reaches the vehicle and the camera sees it.
    """
    def __init__(self, scene: vistrack._core.VisibilityScene, uav: vistrack._core.Uav, camera: DownwardCamera, flight_altitude: typing.SupportsFloat | typing.SupportsIndex, options: HorizonOptions = ...) -> None:
        """
        flight_altitude: world z of the flight (ground level + uav.altitude). The camera table is built here.
        """
    def choose(self, vehicle: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], wind: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], position: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], heading: typing.SupportsFloat | typing.SupportsIndex, bank: typing.SupportsFloat | typing.SupportsIndex) -> HorizonChoice:
        """
        The command for the next second (HorizonChoice). vehicle: (horizon + 1, 2), its predicted positions at 0, 1, ..., horizon s; wind: (2,), the wind the follower knows; the UAV's position (2,), heading, bank.
        """
    def first_values(self, vehicle: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], wind: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> numpy.typing.NDArray[numpy.float32]:
        """
        V_1: (bank level, heading index, east index, north index), the seconds in sight from each state a second ahead over the rest of the horizon.
        """
    def fly_second(self, position: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], heading: typing.SupportsFloat | typing.SupportsIndex, bank: typing.SupportsFloat | typing.SupportsIndex, bank_command: typing.SupportsFloat | typing.SupportsIndex, wind: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> HorizonSecond:
        """
        The UAV's second with bank_command held (HorizonSecond), integrated as the flight layer's discrete step.
        """
    def value_at(self, values: typing.Annotated[numpy.typing.ArrayLike, numpy.float32], relative: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], heading: typing.SupportsFloat | typing.SupportsIndex, bank: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        first_values at a continuous state (relative: UAV - vehicle, (2,)): linear in bank and heading, bilinear in position, 0 off the grid.
        """
    @property
    def banks(self) -> list[float]:
        """
        the five bank levels, rad
        """
    @property
    def grid_side(self) -> int:
        """
        grid points per axis
        """
    @property
    def heading_count(self) -> int:
        """
        headings on the grid
        """
    @property
    def options(self) -> HorizonOptions:
        """
        HorizonOptions
        """
def along_track_rate(x: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], amplitude: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], period_distance: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], uav_speed: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> typing.Any:
    """
    eq. (5): x_dot = v_p / sqrt(1 + A'^2 cos^2(2 pi x / D)), m/s.
    """
def arc_length(x: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], amplitude: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], period_distance: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> typing.Any:
    """
    Arc length of the sinusoid from 0 to x (incomplete elliptic integral of the second kind).
    """
def camera_reach(camera: DownwardCamera, altitude: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    w = altitude tan(fov / 2 + max_gimbal): how far to the side a level UAV's camera sees, m.
    """
def camera_sees(camera: DownwardCamera, uav: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"], psi: typing.SupportsFloat | typing.SupportsIndex, bank: typing.SupportsFloat | typing.SupportsIndex, target: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"]) -> bool:
    """
    Whether the ground point target (3,) is in the footprint of the camera at uav (3,).
    """
def camera_threshold(parameters: FollowParameters, uav: vistrack._core.Uav, camera: DownwardCamera = ...) -> ThresholdChoice:
    """
    The threshold h the planner uses: with threshold 'auto' the largest whose sinusoid's amplitude at h + band/2 stays within camera_reach; else the user's, with its amplitude and reach.
    """
def default_uav() -> vistrack._core.Uav:
    """
    The follower's vehicle where a scenario gives none, as a new Uav(speed=21, min_turn_radius=50, altitude=200, dynamics='dubins') (the paper's UAV flies at 20-23 m/s).
    """
def follow(vehicle: GroundVehicle, uav: vistrack._core.Uav, parameters: FollowParameters, wind: vistrack._core.flight.Wind = ..., *, wind_estimate: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] | None = None, flight: FollowFlight = ..., camera: DownwardCamera = ..., start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"] | None = None, path_window: typing.SupportsFloat | typing.SupportsIndex = 10.0, offset_schedule: collections.abc.Sequence[tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex]] = [], reports: VehicleReportOptions = ...) -> FollowRun:
    """
    Fly the follow planner's 1 Hz waypoints with the flight layer (the waypoint paper's law (5), a WaypointFollower fed during the flight). wind: the true wind (vistrack.flight.Wind); wind_estimate (east, north): what the planner compensates (None: the true constant wind). start: (x, y, psi) or None (on the planned path). offset_schedule: (t, distance, angle) keys, linear in between. reports: what the UAV knows of the vehicle (VehicleReportOptions; default: the truth at each update).
    """
def orbit_follow(vehicle: GroundVehicle, uav: vistrack._core.Uav, control: vistrack._core.Control, radius: typing.SupportsFloat | typing.SupportsIndex, parameters: FollowParameters, wind: vistrack._core.flight.Wind = ..., *, flight: FollowFlight = ..., camera: DownwardCamera = ..., start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[3, 1]"] | None = None, path_window: typing.SupportsFloat | typing.SupportsIndex = 10.0, offset_schedule: collections.abc.Sequence[tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex]] = [], reports: VehicleReportOptions = ...) -> FollowRun:
    """
    The baseline follower: the tracking paper's vector field (74) and steering law (86) orbiting the offset point (from parameters and offset_schedule) at a constant radius, flown by the flight layer in the true wind, knowing the vehicle from the same reports as the planner (at each update, carried along its velocity in between). The result's desired position is the orbit's nearest point.
    """
def phase_at_arc(arc: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], amplitude: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], period_distance: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> typing.Any:
    """
    The phase 2 pi x / D at which the arc length from 0 is `arc`.
    """
def sinusoid_amplitude(speed_ratio: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], period_distance: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> typing.Any:
    """
    Amplitude A (m) of y = A sin(2 pi x / D) whose arc length over one period D is speed_ratio * D (eqs. 9-10: sigma = (2/pi) E(-A'^2), A' = 2 pi A / D), to 1e-12 relative. speed_ratio >= 1 (1 gives 0). Scalars or numpy arrays.
    """
def sinusoid_shape(speed_ratio: typing.SupportsFloat | typing.SupportsIndex, uav_speed: typing.SupportsFloat | typing.SupportsIndex, period: typing.SupportsFloat | typing.SupportsIndex, turn_radius: typing.SupportsFloat | typing.SupportsIndex) -> SinusoidShape:
    """
    D = max(v_p T / sigma, 2 pi a rho) and A = a D / (2 pi): the sinusoid the planner flies (rho = turn_margin r_min).
    """
def sinusoid_slope(speed_ratio: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> typing.Any:
    """
    A' = 2 pi A / D for a speed ratio (independent of D).
    """
def speed_ratio(amplitude: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], period_distance: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> typing.Any:
    """
    sigma = v_p / v_g of eqs. (9)-(10) for amplitude A and period distance D. Scalars or arrays.
    """
