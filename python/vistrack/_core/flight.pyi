"""
The flight layer: a Dubins vehicle (airspeed v, turn rate <= v/R) in wind (constant plus seeded Dryden gusts, MIL-F-8785C) flown by a guidance law, with the paper's discrete update or Dormand-Prince 5(4). Every planner flies here.
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
import vistrack._core
__all__: list[str] = ['CurveL1', 'DrydenLowAltitude', 'FlightGuidance', 'FlightSmoothness', 'FlightTrajectory', 'Gusts', 'L1Line', 'LineFeedback', 'LineFeedbackTerms', 'PathFollower', 'PathTracking', 'RollModel', 'TurnRateHold', 'WaypointFollower', 'Wind', 'WindField', 'coordinated_bank', 'dryden_low_altitude', 'flight_smoothness', 'fly', 'paper_gains']
class Gusts:
    """
    Dryden turbulence (MIL-F-8785C, horizontal): RMS intensity sigma_u = sigma_v (speed units), length scale L_u = L_v (length units), seed. Reproducible from the seed.
    """
    @staticmethod
    def mil_f_8785c(altitude: typing.SupportsFloat | typing.SupportsIndex, wind_speed_20ft: typing.SupportsFloat | typing.SupportsIndex, seed: typing.SupportsIndex = 0, length_unit: typing.SupportsFloat | typing.SupportsIndex = 1.0, speed_unit: typing.SupportsFloat | typing.SupportsIndex = 1.0) -> Gusts:
        """
        Gusts of the MIL-F-8785C low-altitude model at `altitude` (m, 3.05-304.8) for the wind speed at 20 ft W20 (m/s; light 7.7, moderate 15.4, severe 23.2), in flight units: speeds divided by speed_unit (m/s per unit), lengths by length_unit (m per unit).
        """
    def __init__(self, *, seed: typing.SupportsIndex = 0, intensity: typing.SupportsFloat | typing.SupportsIndex = 1.0, length_scale: typing.SupportsFloat | typing.SupportsIndex = 200.0, sample_step: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        """
        seed; intensity sigma (speed units); length_scale L (length units); sample_step (s) of the precomputed series, 0: L / (20 V).
        """
    def __repr__(self) -> str:
        ...
    @property
    def intensity(self) -> float:
        """
        sigma_u = sigma_v, speed units
        """
    @intensity.setter
    def intensity(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def length_scale(self) -> float:
        """
        L_u = L_v, length units
        """
    @length_scale.setter
    def length_scale(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def sample_step(self) -> float:
        """
        s between precomputed samples; 0: L / (20 V)
        """
    @sample_step.setter
    def sample_step(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def seed(self) -> int:
        """
        random seed
        """
    @seed.setter
    def seed(self, arg1: typing.SupportsIndex) -> None:
        ...
class Wind:
    """
    Wind the vehicle does not know: constant (east, north) plus optional Gusts.
    """
    def __init__(self, east: typing.SupportsFloat | typing.SupportsIndex = 0.0, north: typing.SupportsFloat | typing.SupportsIndex = 0.0, gusts: Gusts | None = None) -> None:
        """
        Constant wind (east, north) in speed units; gusts: Gusts or None.
        """
    def __repr__(self) -> str:
        ...
    @property
    def east(self) -> float:
        """
        east component, speed units
        """
    @east.setter
    def east(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def gusts(self) -> Gusts | None:
        """
        Gusts or None
        """
    @gusts.setter
    def gusts(self, arg0: Gusts | None) -> None:
        ...
    @property
    def north(self) -> float:
        """
        north component, speed units
        """
    @north.setter
    def north(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class DrydenLowAltitude:
    """
    MIL-F-8785C low-altitude turbulence at one altitude.
    """
    @property
    def length_u(self) -> float:
        """
        longitudinal length scale, m
        """
    @property
    def length_v(self) -> float:
        """
        lateral length scale (= length_u), m
        """
    @property
    def length_w(self) -> float:
        """
        vertical length scale (= altitude), m
        """
    @property
    def sigma_u(self) -> float:
        """
        longitudinal RMS intensity, m/s
        """
    @property
    def sigma_v(self) -> float:
        """
        lateral RMS intensity (= sigma_u), m/s
        """
    @property
    def sigma_w(self) -> float:
        """
        vertical RMS intensity, m/s
        """
class WindField:
    """
    w(t) for one flight: the constant wind plus the precomputed gust series.
    """
    def __init__(self, wind: Wind, airspeed: typing.SupportsFloat | typing.SupportsIndex, t0: typing.SupportsFloat | typing.SupportsIndex, duration: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Precomputes the gusts on [t0, t0 + duration] for a vehicle of that airspeed (Taylor's frozen field). VistrackError when the wind speed reaches the airspeed.
        """
    def at(self, times: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex]) -> numpy.typing.NDArray[numpy.float64]:
        """
        Wind (east, north) at each time: array (n, 2).
        """
    @property
    def has_gusts(self) -> bool:
        """
        whether gusts were generated
        """
    @property
    def max_speed(self) -> float:
        """
        largest wind speed over the span
        """
    @property
    def sample_step(self) -> float:
        """
        s between gust samples (0 without gusts)
        """
class LineFeedbackTerms:
    """
    Every term of the law (5) at one state.
    """
    @property
    def cross_track(self) -> float:
        """
        s
        """
    @property
    def cross_track_step(self) -> float:
        """
        s_dot dt
        """
    @property
    def reference_angle(self) -> float:
        """
        phi_R, rad
        """
    @property
    def saturated(self) -> bool:
        """
        whether the clamp acted
        """
    @property
    def target_angle(self) -> float:
        """
        phi_T, rad
        """
    @property
    def turn(self) -> float:
        """
        psi_turn, clamped to +-psi_max, rad
        """
    @property
    def unsaturated(self) -> float:
        """
        phi_T + phi_R, rad
        """
class LineFeedback:
    """
    The paper's feedback law (5): psi_turn = clamp(phi_T + |g s + h s_dot dt| sign(phi_T), +-v dt / R) towards the line whose end is the target; turn rate psi_turn / dt.
    """
    def __init__(self, speed: typing.SupportsFloat | typing.SupportsIndex, turn_radius: typing.SupportsFloat | typing.SupportsIndex, dt: typing.SupportsFloat | typing.SupportsIndex, gains: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (0.1, 5.25), smooth_sign: bool = False) -> None:
        """
        speed v, turn_radius R, law step dt (psi_max = v dt / R <= pi/2), gains (g, h); smooth_sign: sign(phi_T) -> clamp(phi_T / psi_max, -1, 1) for continuous flight.
        """
    def set_wind(self, mean_wind: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> None:
        """
        Wind-aware (beyond the paper): phi_T and s_dot from the course over the ground with this known mean wind (east, north), as navigate(wind_aware=True) flies.
        """
    def terms(self, state: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], line_start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], target: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> LineFeedbackTerms:
        """
        Every term of (5) at state (x, y, psi) for the line line_start -> target (LineFeedbackTerms).
        """
    def turn_rate(self, state: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], line_start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], target: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> float:
        """
        psi_turn / dt, rad/s.
        """
    @property
    def dt(self) -> float:
        """
        law step, s
        """
    @property
    def gains(self) -> tuple[float, float]:
        """
        (g, h)
        """
    @property
    def max_turn(self) -> float:
        """
        psi_max = v dt / R, rad per step
        """
    @property
    def smooth_sign(self) -> bool:
        """
        whether sign(phi_T) is smoothed
        """
    @property
    def speed(self) -> float:
        """
        v
        """
    @property
    def turn_radius(self) -> float:
        """
        R
        """
    @property
    def wind_aware(self) -> bool:
        """
        whether set_wind was called
        """
class L1Line:
    """
    L1 line tracking as ArduPlane flies a leg (Park, Deyst & How 2004; AP_L1_Control): lateral acceleration 4 damping^2 v^2 / L1 sin(eta) towards the point L1 = damping period v / pi ahead on the line; continuous in the state (no chatter).
    """
    def __init__(self, speed: typing.SupportsFloat | typing.SupportsIndex, period: typing.SupportsFloat | typing.SupportsIndex = 17.0, damping: typing.SupportsFloat | typing.SupportsIndex = 0.75) -> None:
        """
        speed v; period (s, ArduPlane NAVL1_PERIOD 17) and damping (NAVL1_DAMPING 0.75).
        """
    def set_wind(self, mean_wind: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> None:
        """
        Wind-aware (beyond the paper, as ArduPlane flies L1): steer the ground velocity with this known mean wind (east, north), as navigate(wind_aware=True) flies.
        """
    def turn_rate(self, state: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], line_start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], target: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> float:
        """
        Turn rate a / v, rad/s.
        """
    @property
    def distance(self) -> float:
        """
        L1, length units
        """
    @property
    def wind_aware(self) -> bool:
        """
        whether set_wind was called
        """
class FlightGuidance:
    """
    A guidance law for fly(): turn-rate command and target from (x, y, psi) and t; its stateful logic runs only after accepted steps.
    """
    def advance(self, state: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], t: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        The stateful logic (switch targets, finish) at an accepted state (an outside vehicle model: vistrack.fdm).
        """
    def command(self, state: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], t: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> tuple[float, tuple[float, float], int]:
        """
        (turn_rate, (target_x, target_y), target_index) at a state.
        """
    def start(self, state: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], t: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        """
        Reset the discrete state for a flight from (x, y, psi) at t (an outside vehicle model: vistrack.fdm).
        """
    @property
    def done(self) -> bool:
        """
        True once there is nothing more to fly
        """
    @property
    def revision(self) -> int:
        """
        counts changes of the active target
        """
class CurveL1(FlightGuidance):
    """
    L1 guidance on a curve (Park, Deyst & How 2004): the reference point is where the circle of radius L1 = damping period v / pi about the vehicle leaves the path ahead of its closest point; turn rate 4 damping^2 v / L1 sin(eta). The path (a polyline) may be replaced during flight (set_path from on_step).
    """
    def __init__(self, speed: typing.SupportsFloat | typing.SupportsIndex, path: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], period: typing.SupportsFloat | typing.SupportsIndex = 17.0, damping: typing.SupportsFloat | typing.SupportsIndex = 0.75) -> None:
        """
        speed v; path: array (n, 2); period (s) and damping of L1.
        """
    def reference_point(self, position: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        The L1 reference point, (2,).
        """
    def set_path(self, path: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> None:
        """
        Replace the path (array (n, 2), n >= 1; one point: fly to it).
        """
    @property
    def distance(self) -> float:
        """
        L1, length units
        """
    @property
    def path(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        array (n, 2)
        """
class TurnRateHold(FlightGuidance):
    """
    Holds a commanded turn rate, set during flight (set_turn_rate from on_step): the roll model banks towards atan(v rate / g), the Dubins vehicle turns at once. Never done by itself.
    """
    def __init__(self, turn_rate: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        """
        turn_rate: rad/s, finite (the vehicle clamps it).
        """
    def set_turn_rate(self, turn_rate: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        From the next step on (rad/s).
        """
    @property
    def turn_rate(self) -> float:
        """
        rad/s
        """
class WaypointFollower(FlightGuidance):
    """
    Classical waypoint navigation on the law (5): the line from the previous waypoint (the start for the first) to the active one; next waypoint when within waypoint_radius. finish_at_last=False holds at the last waypoint until add_waypoint() gives more (feed it from fly()'s on_step).
    """
    @typing.overload
    def __init__(self, law: LineFeedback, waypoints: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], waypoint_radius: typing.SupportsFloat | typing.SupportsIndex, finish_at_last: bool = True) -> None:
        """
        law: LineFeedback; waypoints: array (n, 2); waypoint_radius R_WP >= 0.
        """
    @typing.overload
    def __init__(self, law: L1Line, waypoints: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], waypoint_radius: typing.SupportsFloat | typing.SupportsIndex, finish_at_last: bool = True) -> None:
        """
        The same with each leg flown by L1 line tracking (law: L1Line).
        """
    def add_waypoint(self, point: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], available_from: typing.SupportsFloat | typing.SupportsIndex = ...) -> None:
        """
        Append a waypoint usable from time available_from on (non-decreasing); allowed during flight.
        """
    @property
    def accepted_at(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        time each waypoint was accepted (NaN: not yet)
        """
    @property
    def active(self) -> int:
        """
        index of the active waypoint
        """
    @property
    def finish_line(self) -> bool:
        """
        the flight ends past the last waypoint's perpendicular line, not inside R_WP of it
        """
    @finish_line.setter
    def finish_line(self, arg1: bool) -> None:
        ...
    @property
    def passed_line(self) -> bool:
        """
        ArduPlane's switching: a waypoint is also done once past the line through it perpendicular to its leg, and the turn is anticipated (waypoint_nav's 'wn_passed_line')
        """
    @passed_line.setter
    def passed_line(self, arg1: bool) -> None:
        ...
    @property
    def waypoint_radius(self) -> float:
        """
        R_WP
        """
    @property
    def waypoints(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        array (n, 2)
        """
class FlightSmoothness:
    """
    How smoothly a flight banks (flight_smoothness).
    """
    def __repr__(self) -> str:
        ...
    def as_dict(self) -> dict:
        """
        The measures as a dict (metrics.json).
        """
    @property
    def bank_rms_deg(self) -> float:
        """
        RMS of the bank about its moving mean over the window, degrees
        """
    @property
    def max_roll_rate_deg_s(self) -> float:
        """
        largest |bank change / time| between successive samples, deg/s
        """
    @property
    def roll_reversals(self) -> int:
        """
        their count
        """
    @property
    def roll_reversals_per_s(self) -> float:
        """
        reversals of the bank (deadband: successive extrema that far apart) per second
        """
class FlightTrajectory:
    """
    One sample per output time: state, the turn rate applied from there, the bank, the active target and the wind.
    """
    def __len__(self) -> int:
        ...
    def smoothness(self, window: typing.SupportsFloat | typing.SupportsIndex = 5.0, deadband_deg: typing.SupportsFloat | typing.SupportsIndex = 1.0) -> FlightSmoothness:
        """
        How smoothly this flight banks (FlightSmoothness of its bank history).
        """
    @property
    def array(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, 4): t, x, y, psi
        """
    @property
    def bank(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        bank (n,), rad, positive left wing down: the roll model's state, or the Dubins model's coordinated bank of the turn rate applied from each sample
        """
    @property
    def bank_command(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        the coordinated bank of the guidance's clamped turn-rate command (n,), rad
        """
    @property
    def command(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        turn rate applied from each sample (clamped to +-v/R), rad/s
        """
    @property
    def end_time(self) -> float:
        """
        time of the last sample, s
        """
    @property
    def finished(self) -> bool:
        """
        the guidance said done (else max_time was reached)
        """
    @property
    def psi(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        heading (n,), rad, as integrated (not wrapped)
        """
    @property
    def statistics(self) -> vistrack._core.OdeStatistics:
        """
        integrator work, vistrack.OdeStatistics (continuous flights)
        """
    @property
    def switch_times(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        times where the guidance changed its target
        """
    @property
    def t(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        times (n,), s
        """
    @property
    def target(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        active target (n, 2)
        """
    @property
    def target_index(self) -> numpy.typing.NDArray[numpy.int32]:
        """
        active target's index (n,), -1: none
        """
    @property
    def wind(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        wind (east, north) at each sample (n, 2)
        """
    @property
    def x(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        x (n,)
        """
    @property
    def y(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        y (n,)
        """
class RollModel:
    """
    The roll model of a Uav: bank command atan(v r / g) within +-phi_max, phi_dot = clamp((phi_c - phi) / tau, +-p_max), psi_dot = g tan(phi) / v.
    """
    def __init__(self, uav: vistrack._core.Uav, gravity: typing.SupportsFloat | typing.SupportsIndex = 9.80665) -> None:
        """
        The model of uav (its speed, min_turn_radius, roll_time_constant, max_roll_rate_deg_s).
        """
    def bank_command(self, turn_rate: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        atan(v r / g) within +-phi_max, rad
        """
    def bank_rate(self, bank: typing.SupportsFloat | typing.SupportsIndex, bank_command: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        clamp((phi_c - phi) / tau, +-p_max), rad/s
        """
    def step(self, bank: typing.SupportsFloat | typing.SupportsIndex, bank_command: typing.SupportsFloat | typing.SupportsIndex, dt: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        The bank after dt with the command held (closed form), rad.
        """
    def turn_rate(self, bank: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        g tan(phi) / v, rad/s
        """
    @property
    def max_bank(self) -> float:
        """
        phi_max = atan(v^2 / (g R)), rad
        """
    @property
    def max_roll_rate(self) -> float:
        """
        p_max, rad/s
        """
    @property
    def time_constant(self) -> float:
        """
        tau, s
        """
class PathTracking:
    """
    Where a state is relative to the path.
    """
    @property
    def along(self) -> float:
        """
        signed distance ahead of the path point (non-zero only at the ends), m
        """
    @property
    def cross_track(self) -> float:
        """
        m, positive to the left of the path
        """
    @property
    def heading_error(self) -> float:
        """
        psi - psi_path, wrapped, rad
        """
    @property
    def piece(self) -> int:
        """
        index of the piece
        """
    @property
    def s(self) -> float:
        """
        progress along the path, m
        """
class PathFollower(FlightGuidance):
    """
    Follows a path of lines and arcs: cross-track and heading feedback with curvature feed-forward, psi_d = psi_path - atan(e / (lookahead_radii R)), rate = v kappa cos(psi - psi_path) / (1 - kappa e) + heading_gain (v / R) wrap(psi_d - psi). Knows the heading, not the wind. Done at the path's end.
    """
    def __init__(self, pieces: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 5]"], speed: typing.SupportsFloat | typing.SupportsIndex, turn_radius: typing.SupportsFloat | typing.SupportsIndex, lookahead_radii: typing.SupportsFloat | typing.SupportsIndex = 1.0, heading_gain: typing.SupportsFloat | typing.SupportsIndex = 3.0, anticipation: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        """
        pieces: (n, 5) rows x0, y0, heading, length, curvature (0 lines, +1/radius ccw, -1/radius cw), each starting where the one before ends; speed v and turn_radius R of the vehicle; anticipation (s): the curvature feed-forward reads the path v * anticipation ahead (a banking vehicle's roll lag; 0: none).
        """
    def track(self, state: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex]) -> PathTracking:
        """
        Projection of (x, y, psi) near the current progress (PathTracking).
        """
    @property
    def length(self) -> float:
        """
        Path length, m.
        """
    @property
    def progress(self) -> float:
        """
        Arc length reached, m.
        """
def coordinated_bank(speed: typing.SupportsFloat | typing.SupportsIndex, turn_rate: typing.SupportsFloat | typing.SupportsIndex, gravity: typing.SupportsFloat | typing.SupportsIndex = 9.80665) -> float:
    """
    Bank of a coordinated turn, atan(v psi_dot / g), rad (positive left).
    """
def dryden_low_altitude(altitude: typing.SupportsFloat | typing.SupportsIndex, wind_speed_20ft: typing.SupportsFloat | typing.SupportsIndex) -> DrydenLowAltitude:
    """
    MIL-F-8785C low-altitude intensities (m/s) and length scales (m) at altitude (m) for W20 (m/s).
    """
def flight_smoothness(t: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], bank: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 1]"], window: typing.SupportsFloat | typing.SupportsIndex = 5.0, deadband_deg: typing.SupportsFloat | typing.SupportsIndex = 1.0) -> FlightSmoothness:
    """
    How smoothly a bank history (t in s, increasing; bank in rad) banks: bank_rms_deg about its moving mean over a centred window (s), roll_reversals_per_s with a deadband (successive extrema at least deadband_deg apart), max_roll_rate_deg_s between samples.
    """
def fly(guidance: FlightGuidance, start: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], speed: typing.SupportsFloat | typing.SupportsIndex, turn_radius: typing.SupportsFloat | typing.SupportsIndex, wind: Wind | None = None, dt: typing.SupportsFloat | typing.SupportsIndex = 0.02, max_time: typing.SupportsFloat | typing.SupportsIndex = 3600.0, integration: str = 'discrete', t0: typing.SupportsFloat | typing.SupportsIndex = 0.0, on_step: collections.abc.Callable[[float, tuple[float, float, float]], None] | None = None, progress: collections.abc.Callable[[int, int], None] | None = None, rtol: typing.SupportsFloat | typing.SupportsIndex = 1e-09, atol: typing.SupportsFloat | typing.SupportsIndex = 1e-12, uav: vistrack._core.Uav | None = None) -> FlightTrajectory:
    """
    Fly the vehicle (speed v, turn_radius R; uav: a Uav whose dynamics and roll parameters to use, its speed and radius replaced by these, None: the Dubins model) from start (x, y, psi) at t0 under the guidance until it is done or t0 + max_time. integration 'discrete' (the paper's update, step dt) or 'continuous' (Dormand-Prince, output every dt). on_step(t, state) runs after each accepted step (it may feed the guidance); progress(done, total) in per mille of max_time. Releases the GIL (callbacks take it).
    """
def paper_gains(turn_radius: typing.SupportsFloat | typing.SupportsIndex) -> tuple[float, float]:
    """
    The law (5)'s gains (g, h) for turn radius R: the paper's (0.1, 5.25), given for its R = 0.7, scaled by 0.7 / R (both multiply lengths).
    """
