"""
Dubins waypoint navigation (Silverberg & Xu 2019) against classical waypoint navigation: the turning point of the 3-waypoint horizon (exact minimisation over theta, four turn cases), the reachability zone, DWN/WN flights on the flight layer and their metrics.
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
import vistrack._core.flight
__all__: list[str] = ['CASES', 'DubinsWaypointGuidance', 'HorizonPath', 'NavigationResult', 'Options', 'TurningPoint', 'TurningPointRecord', 'TurningPoints', 'air_mass_turning_point', 'horizon_lengths', 'horizon_path', 'navigate', 'navigation_guidance', 'navigation_metrics', 'navigation_time_limit', 'reachability', 'turning_point', 'turning_points']
class HorizonPath:
    """
    The horizon path C -> arc -> straight -> T_n -> arc through W_n -> straight -> W_{n+1}.
    """
    def __repr__(self) -> str:
        ...
    @property
    def arc_from_waypoint(self) -> float:
        """
        arc W_n -> exit
        """
    @property
    def arc_to_waypoint(self) -> float:
        """
        arc T_n -> W_n
        """
    @property
    def case(self) -> str:
        """
        'ccw-ccw', 'ccw-cw', 'cw-ccw' or 'cw-cw' (first arc, arc about W_n)
        """
    @property
    def circle_center(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        centre of the circle about W_n
        """
    @property
    def exit_point(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        where the path leaves the circle about W_n
        """
    @property
    def feasible(self) -> bool:
        """
        False when a tangent does not exist at this theta
        """
    @property
    def first_arc(self) -> float:
        """
        arc length on the vehicle's turning circle
        """
    @property
    def first_straight(self) -> float:
        """
        length of the straight to T_n
        """
    @property
    def heading_at_waypoint(self) -> float:
        """
        heading at W_n, rad
        """
    @property
    def last_straight(self) -> float:
        """
        straight exit -> W_{n+1}
        """
    @property
    def length(self) -> float:
        """
        weighted length w_a arcs + w_s straights (inf if infeasible)
        """
    @property
    def line_start(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        start of the first straight (end of the first arc)
        """
    @property
    def point(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        T_n: the turning point, end of the first straight
        """
    @property
    def theta(self) -> float:
        """
        circle about W_n centred at W_n + R (cos theta, sin theta), [0, 2 pi)
        """
class TurningPoint(HorizonPath):
    """
    The optimal horizon path over theta and the four cases.
    """
    @property
    def case_lengths(self) -> dict[str, float]:
        """
        best length found per case (exact for the winner; the others are refined only where they could win)
        """
    @property
    def evaluations(self) -> int:
        """
        F(h) evaluations spent
        """
class TurningPoints:
    """
    Turning points of many horizons, one row each.
    """
    @property
    def case(self) -> numpy.typing.NDArray[numpy.int32]:
        """
        (n,) its turn case, indexing CASES
        """
    @property
    def length(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n,) its weighted length
        """
    @property
    def point(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        (n, 2) the turning points T_n
        """
    @property
    def theta(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n,) theta of each optimum, rad
        """
class DubinsWaypointGuidance(vistrack._core.flight.FlightGuidance):
    """
    DWN as a flight guidance for vistrack.flight.fly: the law (5) to each turning point, the next one when it becomes unreachable; the last waypoint flown to directly.
    """
    @typing.overload
    def __init__(self, law: vistrack._core.flight.LineFeedback, waypoints: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], turn_radius: typing.SupportsFloat | typing.SupportsIndex, weights: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (1.0, 1.0)) -> None:
        ...
    @typing.overload
    def __init__(self, law: vistrack._core.flight.L1Line, waypoints: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], turn_radius: typing.SupportsFloat | typing.SupportsIndex, weights: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (1.0, 1.0)) -> None:
        """
        The same with each leg to a turning point flown by L1 line tracking (law: L1Line).
        """
    def set_path_following(self, speed: typing.SupportsFloat | typing.SupportsIndex, anticipation: typing.SupportsFloat | typing.SupportsIndex, lookahead_radii: typing.SupportsFloat | typing.SupportsIndex = 1.0, heading_gain: typing.SupportsFloat | typing.SupportsIndex = 3.0) -> None:
        """
        Beyond the paper: fly each planned horizon path (first arc, straight to T_n, arc through W_n, straight to W_{n+1}) with PathFollower at airspeed speed, its curvature feed-forward anticipation s ahead (a banking vehicle's roll lag), instead of the leg law to T_n; the last waypoint along the last plan's tail.
        """
    def set_wind(self, mean_wind: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], speed: typing.SupportsFloat | typing.SupportsIndex) -> None:
        """
        Plan every turning point in the air mass of the mean wind (east, north) at airspeed speed, the law flying the air frame's line (give it a law without wind); (0, 0): the paper's planning.
        """
    @property
    def active(self) -> int:
        """
        index of the waypoint being approached
        """
    @property
    def path_following(self) -> bool:
        """
        True once set_path_following was called
        """
    @property
    def replan_interval(self) -> float:
        """
        re-plan the active turning point every so many s (section 2.1); 0: at the reachability switch
        """
    @replan_interval.setter
    def replan_interval(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def turning_points(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        (k, 2) every turning point planned so far
        """
class TurningPointRecord:
    """
    One turning point planned during a DWN flight.
    """
    @property
    def air_point(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        (x, y) the turning point as a point of the air mass when planned (drifts with wind)
        """
    @property
    def direct(self) -> bool:
        """
        the last waypoint, flown to directly
        """
    @property
    def path(self) -> HorizonPath:
        """
        the horizon path
        """
    @property
    def pose(self) -> tuple[float, float, float]:
        """
        (x, y, psi) of the vehicle when planned
        """
    @property
    def t(self) -> float:
        """
        when it was planned, s
        """
    @property
    def waypoint(self) -> int:
        """
        index of its waypoint in the flown list
        """
    @property
    def wind(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[2, 1]"]:
        """
        (east, north) mean wind it was planned in the air mass of; (0, 0): in still air
        """
class NavigationResult:
    """
    One WN or DWN flight and its metrics.
    """
    @property
    def all_reached(self) -> bool:
        ...
    @property
    def closest_times(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        time of each waypoint's closest approach, s
        """
    @property
    def duration(self) -> float:
        ...
    @property
    def fuel(self) -> float:
        """
        sum of v dt (w_s + (w_a - w_s) |r| / (v/R))
        """
    @property
    def max_time(self) -> float:
        """
        time limit used, s
        """
    @property
    def method(self) -> str:
        """
        'dwn' or 'wn'
        """
    @property
    def miss_distances(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        closest approach to each waypoint
        """
    @property
    def overshoot(self) -> float:
        """
        largest distance from the legs outside their turns
        """
    @property
    def overshoots(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        per waypoint: the largest distance outside the turn there
        """
    @property
    def path_length(self) -> float:
        ...
    @property
    def reached(self) -> numpy.typing.NDArray[numpy.bool]:
        """
        whether the guidance got past each waypoint in time
        """
    @property
    def swirls(self) -> int:
        """
        loops around the active waypoint: full turns of the bearing to it, either way, while it is the target
        """
    @property
    def trajectory(self) -> vistrack._core.flight.FlightTrajectory:
        """
        vistrack.flight.FlightTrajectory
        """
    @property
    def turning_points(self) -> list[TurningPointRecord]:
        """
        TurningPointRecord list (DWN)
        """
    @property
    def undershoot(self) -> float:
        """
        largest distance from the legs inside their turns
        """
    @property
    def waypoint_radius(self) -> float:
        """
        R_WP (WN)
        """
class Options:
    """
    One navigation flight's settings; the defaults (the paper's section 3) are those of navigate() and fly().
    """
    def __init__(self, *, method: str = 'dwn', turn_radius: typing.SupportsFloat | typing.SupportsIndex = 0.7, speed: typing.SupportsFloat | typing.SupportsIndex = 0.8, dt: typing.SupportsFloat | typing.SupportsIndex = 0.02, gains: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (0.1, 5.25), waypoint_radius: typing.SupportsFloat | typing.SupportsIndex | None = None, weights: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (1.0, 1.0), integration: str = 'discrete', max_time: typing.SupportsFloat | typing.SupportsIndex | None = None, dynamics: str = 'dubins', roll_time_constant: typing.SupportsFloat | typing.SupportsIndex = 0.5, max_roll_rate_deg_s: typing.SupportsFloat | typing.SupportsIndex = 70.0, guidance: str = 'law5', l1_period: typing.SupportsFloat | typing.SupportsIndex = 17.0, wind_aware: bool = False, replan_interval: typing.SupportsFloat | typing.SupportsIndex = 0.0, dwn_tracking: str = 'auto', path_anticipation: typing.SupportsFloat | typing.SupportsIndex | None = None) -> None:
        """
        method 'dwn', 'wn' or 'wn_passed_line'; turn_radius R; speed v; law step dt; gains (g, h); waypoint_radius: WN's R_WP (None: R); weights (w_a, w_s); integration 'discrete' or 'continuous'; max_time (None: 3 (route length + 2 pi R per waypoint) / v); dynamics 'dubins' or 'roll' (metres and seconds) with the roll model's roll_time_constant (s) and max_roll_rate_deg_s; guidance 'law5' (the paper's law (5) with gains) or 'l1' (L1 line tracking, period l1_period s, damping 0.75) on every leg; wind_aware: the leg law steers the course over the ground with the known mean wind (and DWN plans its turning points in the air mass); replan_interval: DWN re-plans the active turning point every so many seconds (0: only at the reachability switch, the paper's flights); dwn_tracking (beyond the paper) 'paper' (the leg law to each turning point), 'path' (the planned horizon path followed in closed loop, the roll anticipated path_anticipation s ahead, None: the roll model's lag) or 'auto' ('paper' on dubins, 'path' on roll).
        """
    def __repr__(self) -> str:
        ...
    def resolved_tracking(self) -> str:
        """
        What 'auto' means for this vehicle.
        """
    def roll_lag(self) -> float:
        """
        The roll model's lag, s: the heading lost to the bank's response to a step 0 -> phi_max, integral of (1 - phi / phi_max) dt (tau without the rate limit; 0 on dubins).
        """
    def validate(self) -> None:
        """
        Raise VistrackError naming the first invalid field.
        """
    @property
    def dt(self) -> float:
        """
        the law's step (and the discrete flight's)
        """
    @dt.setter
    def dt(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def dwn_tracking(self) -> str:
        """
        DWN: 'paper' (the leg law to each turning point), 'path' (the planned path followed, beyond the paper) or 'auto' ('paper' on dubins, 'path' on roll)
        """
    @dwn_tracking.setter
    def dwn_tracking(self, arg0: str) -> None:
        ...
    @property
    def dynamics(self) -> str:
        """
        'dubins' (the paper's) or 'roll' (the roll model: route in metres, speed in m/s)
        """
    @dynamics.setter
    def dynamics(self, arg0: str) -> None:
        ...
    @property
    def gains(self) -> tuple[float, float]:
        """
        (g, h) of the feedback law (5)
        """
    @gains.setter
    def gains(self, arg1: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex]) -> None:
        ...
    @property
    def guidance(self) -> str:
        """
        'law5' (the paper's law (5)) or 'l1' (L1 line tracking) on every leg
        """
    @guidance.setter
    def guidance(self, arg0: str) -> None:
        ...
    @property
    def integration(self) -> str:
        """
        'discrete' (the paper's) or 'continuous'
        """
    @integration.setter
    def integration(self, arg0: str) -> None:
        ...
    @property
    def l1_period(self) -> float:
        """
        guidance l1: the L1 period, s
        """
    @l1_period.setter
    def l1_period(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_roll_rate_deg_s(self) -> float:
        """
        roll model: p_max, deg/s
        """
    @max_roll_rate_deg_s.setter
    def max_roll_rate_deg_s(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_time(self) -> float | None:
        """
        time limit, s; None: from the route
        """
    @max_time.setter
    def max_time(self, arg0: typing.SupportsFloat | typing.SupportsIndex | None) -> None:
        ...
    @property
    def method(self) -> str:
        """
        'dwn' or 'wn'
        """
    @method.setter
    def method(self, arg0: str) -> None:
        ...
    @property
    def path_anticipation(self) -> float | None:
        """
        DWN 'path': the feed-forward's lead, s; None: roll_lag()
        """
    @path_anticipation.setter
    def path_anticipation(self, arg0: typing.SupportsFloat | typing.SupportsIndex | None) -> None:
        ...
    @property
    def replan_interval(self) -> float:
        """
        DWN: re-plan the active turning point every so many seconds; 0: at the reachability switch only
        """
    @replan_interval.setter
    def replan_interval(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def roll_time_constant(self) -> float:
        """
        roll model: tau, s
        """
    @roll_time_constant.setter
    def roll_time_constant(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def speed(self) -> float:
        """
        v
        """
    @speed.setter
    def speed(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def turn_radius(self) -> float:
        """
        R: minimum turn radius and DWN's turning circles
        """
    @turn_radius.setter
    def turn_radius(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def waypoint_radius(self) -> float | None:
        """
        WN's R_WP; None: R (DWN has none)
        """
    @waypoint_radius.setter
    def waypoint_radius(self, arg0: typing.SupportsFloat | typing.SupportsIndex | None) -> None:
        ...
    @property
    def weights(self) -> tuple[float, float]:
        """
        (w_a, w_s): fuel per unit length on arcs and straights
        """
    @weights.setter
    def weights(self, arg1: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex]) -> None:
        ...
    @property
    def wind_aware(self) -> bool:
        """
        the leg law knows the mean wind and steers the course over the ground (beyond the paper)
        """
    @wind_aware.setter
    def wind_aware(self, arg0: bool) -> None:
        ...
def air_mass_turning_point(pose: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], w_next: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], w_after: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], turn_radius: typing.SupportsFloat | typing.SupportsIndex, speed: typing.SupportsFloat | typing.SupportsIndex, wind: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], weights: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (1.0, 1.0)) -> TurningPoint:
    """
    Turning point planned in the air mass of the mean wind (east, north) at airspeed speed: the horizon solved for the waypoints as the air sees them (W - wind tau, tau from the path's arc lengths), mapped back to the ground (each point moved by wind x the time the vehicle reaches it). Wind (0, 0): turning_point.
    """
def horizon_lengths(pose: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], w_next: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], w_after: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], turn_radius: typing.SupportsFloat | typing.SupportsIndex, case: str, thetas: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], weights: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (1.0, 1.0)) -> numpy.typing.NDArray[numpy.float64]:
    """
    F(theta) of one case at each theta (inf where the path does not exist).
    """
def horizon_path(pose: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], w_next: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], w_after: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], turn_radius: typing.SupportsFloat | typing.SupportsIndex, case: str, theta: typing.SupportsFloat | typing.SupportsIndex, weights: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (1.0, 1.0)) -> HorizonPath:
    """
    The horizon path of one case at one theta.
    """
def navigate(waypoints: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], start: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], *, method: str = 'dwn', turn_radius: typing.SupportsFloat | typing.SupportsIndex = 0.7, speed: typing.SupportsFloat | typing.SupportsIndex = 0.8, dt: typing.SupportsFloat | typing.SupportsIndex = 0.02, gains: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (0.1, 5.25), waypoint_radius: typing.SupportsFloat | typing.SupportsIndex | None = None, weights: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (1.0, 1.0), wind: vistrack._core.flight.Wind | None = None, integration: str = 'discrete', max_time: typing.SupportsFloat | typing.SupportsIndex | None = None, dynamics: str = 'dubins', roll_time_constant: typing.SupportsFloat | typing.SupportsIndex = 0.5, max_roll_rate_deg_s: typing.SupportsFloat | typing.SupportsIndex = 70.0, guidance: str = 'law5', l1_period: typing.SupportsFloat | typing.SupportsIndex = 17.0, wind_aware: bool = False, replan_interval: typing.SupportsFloat | typing.SupportsIndex = 0.0, dwn_tracking: str = 'auto', path_anticipation: typing.SupportsFloat | typing.SupportsIndex | None = None) -> NavigationResult:
    """
    Fly every waypoint (n, 2) in order from start (x, y, psi) with 'dwn' or 'wn' on the 'dubins' or 'roll' vehicle, each leg by 'law5' or 'l1' (DWN: or its planned path followed, dwn_tracking 'path'; 'auto': on the roll model); returns NavigationResult. Releases the GIL.
    """
def navigation_guidance(waypoints: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], start: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], options: Options, wind: vistrack._core.flight.Wind | None = None) -> vistrack._core.flight.FlightGuidance:
    """
    The guidance navigate() flies for these waypoints (n, 2) from start (x, y, psi) with these Options: a DubinsWaypointGuidance or a WaypointFollower, for any vehicle that flies a FlightGuidance (vistrack.fdm's aircraft too); wind: its constant part is known to the guidance when options.wind_aware.
    """
def navigation_metrics(t: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], x: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], y: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], command: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], target_index: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex], finished: bool, start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], waypoints: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], speed: typing.SupportsFloat | typing.SupportsIndex, turn_radius: typing.SupportsFloat | typing.SupportsIndex, weights: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (1.0, 1.0)) -> dict:
    """
    The metrics of navigate() (miss distances, reached, over- and undershoot, swirls, path length, duration, fuel) of a flight flown elsewhere (vistrack.fdm): samples t, x, y, the turn-rate command and the guidance's target index, as a dict.
    """
def navigation_time_limit(waypoints: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], start: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], options: Options) -> float:
    """
    navigate()'s time limit (s): options.max_time, else 3 (route length from start + 2 pi R per waypoint) / v.
    """
def reachability(pose: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 2]"], turn_radius: typing.SupportsFloat | typing.SupportsIndex) -> numpy.typing.NDArray[numpy.float64]:
    """
    For each point (n, 2): <= 0 inside the reachability zone (unreachable), > 0 outside.
    """
def turning_point(pose: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex], w_next: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], w_after: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], turn_radius: typing.SupportsFloat | typing.SupportsIndex, weights: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (1.0, 1.0)) -> TurningPoint:
    """
    Turning point T_n over the horizon (pose C, W_n, W_{n+1}): minimises F = w_a L_a + w_s L_s over theta for the four cases; theta to 1e-12 rad.
    """
def turning_points(poses: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"], w_next: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 2]"], w_after: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 2]"], turn_radius: typing.SupportsFloat | typing.SupportsIndex, weights: tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex] = (1.0, 1.0)) -> TurningPoints:
    """
    Batch of turning points, one thread, GIL released: poses (n, 3), w_next and w_after (n, 2) -> TurningPoints.
    """
CASES: tuple = ('ccw-ccw', 'ccw-cw', 'cw-ccw', 'cw-cw')
