"""
Loiter planning over areas of interest (Wilhelm, Clem, Eberhart 2017): Fly-Through, TLPP and LDLPP as exact paths of lines and arcs, the visiting order search, a conic camera's footprint on a roll gimbal and the 75 % coverage rule. Units m, s, rad; headings counter-clockwise from +x.
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
import vistrack.georeference
import vistrack.mission.model
__all__: list[str] = ['BEYOND_PAPER_METHODS', 'Camera', 'Coverage', 'CoverageOptions', 'EXACT_ORDER_LIMIT', 'Footprint', 'METHODS', 'ORDERS', 'Parameters', 'Plan', 'STANDARD_GRAVITY', 'Samples', 'Segment', 'bank_angle', 'best_order', 'ellipse_disk_area', 'entry_angle', 'entry_distance', 'order_length', 'plan', 'plan_coverage', 'plan_in_order', 'sample_coverage', 'turn_angle']
class Parameters:
    """
    The vehicle and the loiters of a plan; the defaults (section 4.1's Raven RQ-11B, R = r, one loiter) are those of plan() and of a loiter scenario.
    """
    def __init__(self, *, turn_radius: typing.SupportsFloat | typing.SupportsIndex = 46.0, speed: typing.SupportsFloat | typing.SupportsIndex = 12.0, aoi_radius: typing.SupportsFloat | typing.SupportsIndex = 46.0, turns: typing.SupportsIndex = 1) -> None:
        """
        turn_radius r (m), speed v (m/s), aoi_radius R >= r (m), turns: full loiters per AOI (>= 1).
        """
    def __repr__(self) -> str:
        ...
    def validate(self) -> None:
        """
        Raise VistrackError naming the first invalid field.
        """
    @property
    def aoi_radius(self) -> float:
        """
        R >= r: the loiter circle about each AOI, m.
        """
    @aoi_radius.setter
    def aoi_radius(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def speed(self) -> float:
        """
        v: constant airspeed, m/s.
        """
    @speed.setter
    def speed(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def turn_radius(self) -> float:
        """
        r: the aircraft's minimum turn radius, m.
        """
    @turn_radius.setter
    def turn_radius(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def turns(self) -> int:
        """
        Full loiters flown around each AOI (at least 1).
        """
    @turns.setter
    def turns(self, arg1: typing.SupportsIndex) -> None:
        ...
class CoverageOptions:
    """
    Section 4.1's coverage rule: an AOI is covered at a time step when at least `threshold` of its disk lies in the footprint; steps dt apart (the paper: 1 s).
    """
    def __init__(self, *, threshold: typing.SupportsFloat | typing.SupportsIndex = 0.75, dt: typing.SupportsFloat | typing.SupportsIndex = 1.0, gravity: typing.SupportsFloat | typing.SupportsIndex = 9.80665) -> None:
        """
        threshold: a fraction in (0, 1]; dt (s); gravity (m/s^2) for the bank of a coordinated turn.
        """
    def __repr__(self) -> str:
        ...
    def validate(self) -> None:
        """
        Raise VistrackError naming the first invalid field.
        """
    @property
    def dt(self) -> float:
        """
        Time step, s.
        """
    @dt.setter
    def dt(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def gravity(self) -> float:
        """
        m/s^2, for the bank angle of a coordinated turn.
        """
    @gravity.setter
    def gravity(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def threshold(self) -> float:
        """
        Share of an AOI's disk in view to count, (0, 1].
        """
    @threshold.setter
    def threshold(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Segment:
    """
    One piece of a plan: a line or an arc (radius r for turns, R around an AOI).
    """
    def __repr__(self) -> str:
        ...
    def at(self, s: typing.SupportsFloat | typing.SupportsIndex) -> tuple[float, float, float]:
        """
        (x, y, psi) after arc length s along the segment.
        """
    @property
    def aoi(self) -> int | None:
        """
        Index of the AOI this piece enters, circles or leaves; None for transit.
        """
    @property
    def center(self) -> tuple | None:
        """
        Arc centre (x, y), m; None for lines.
        """
    @property
    def direction(self) -> str | None:
        """
        'ccw' or 'cw' for arcs; None for lines.
        """
    @property
    def end(self) -> tuple:
        """
        (x, y) at the end, m.
        """
    @property
    def end_heading(self) -> float:
        """
        Heading at the end, rad.
        """
    @property
    def kind(self) -> str:
        """
        'line' or 'arc'.
        """
    @property
    def length(self) -> float:
        """
        Length, m.
        """
    @property
    def radius(self) -> float | None:
        """
        Arc radius, m; None for lines.
        """
    @property
    def role(self) -> str:
        """
        'transit' (lines between AOIs), 'entry' (turns and lines onto a loiter circle), 'loiter' (arcs on an AOI's loiter circle), 'exit' (turns leaving it).
        """
    @property
    def start(self) -> tuple:
        """
        (x, y) at the start, m.
        """
    @property
    def start_heading(self) -> float:
        """
        Heading at the start, rad (continuous along the plan).
        """
    @property
    def sweep(self) -> float:
        """
        Angle turned on an arc, rad (0 for lines).
        """
class Samples:
    """
    A plan sampled in time.
    """
    @property
    def poses(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 3]"]:
        """
        (n, 3): x, y, psi (continuous).
        """
    @property
    def segment(self) -> numpy.typing.NDArray[numpy.int32]:
        """
        Index of that segment.
        """
    @property
    def t(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Times, s.
        """
    @property
    def turn_rate(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Turn rate of the segment each sample lies on, rad/s.
        """
class Plan:
    """
    A loiter plan: the path as segments, its length and times.
    """
    def __repr__(self) -> str:
        ...
    def at_time(self, t: typing.SupportsFloat | typing.SupportsIndex) -> tuple[float, float, float]:
        """
        (x, y, psi) at time t in [0, flight_time].
        """
    def sample(self, dt: typing.SupportsFloat | typing.SupportsIndex = 1.0) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 3]"]:
        """
        (n, 3) array of x, y, psi (continuous) at t = 0, dt, 2 dt, ... and the end point last.
        """
    def sample_states(self, dt: typing.SupportsFloat | typing.SupportsIndex = 1.0, include_end: bool = True) -> Samples:
        """
        Samples (t, poses, turn_rate, segment) at t = 0, dt, ...; include_end appends the end point.
        """
    def to_mission(self, georeference: vistrack.georeference.Georeference | typing.Sequence[float], altitude: float, *, speed: float | None = None, max_step_deg: float = 30.0, acceptance_radius: float | None = None, return_to_launch: bool = False, firmware: str = 'ardupilot', altitude_mode: str = 'relative') -> vistrack.mission.model.Mission:
        """
        A loiter plan (``vt.loiter.plan``: Fly-Through, TLPP or LDLPP) as the mission an autopilot
            flies along the planned path, not towards the AOI centres.
        
            - DO_CHANGE_SPEED to the plan's speed (airspeed; ``speed`` overrides), home at the plan's start,
              and a first waypoint there.
            - Lines: a waypoint at their end. Turns at the turn radius r (the entry and exit turns, the
              Fly-Through's three-quarter turn): waypoints along the arc every ``max_step_deg`` with an
              acceptance radius of half their spacing (see ``_arc_acceptance``; ``acceptance_radius``
              overrides), so the autopilot flies the arc instead of cutting it.
            - Each AOI's loiter (its consecutive loiter arcs, swept angle S >= 2 pi turns): the route
              already ends at the loiter entry point (the tangent point of TLPP, the end of LDLPP's entry
              turn, the Fly-Through's offset point), where NAV_LOITER_TURNS starts: the aircraft is on the
              circle heading along it, so it circles at once instead of flying to the centre. Radius signed
              for the direction (MAVLink: positive clockwise), k = floor(S / 2 pi) whole turns (ArduPilot
              keeps an integer count, at most 255, and the radius in whole metres up to 255 m), param4 = 1
              (the next leg starts from where the aircraft leaves the circle). The remaining S - 2 pi k
              (TLPP's arc to the departure tangent, LDLPP's arc until the closing angle reaches alpha_ED,
              the Fly-Through's arc to its exit) follows as waypoints along the circle to the exit point.
              A whole number of turns ends where it started, so turns + remainder reproduce S exactly.
            - The last line ends at the plan's end; ``return_to_launch`` adds RTL.
        
            ``altitude``: the local height of the flight (the loiter camera's altitude above the AOIs);
            ``georeference``: vistrack.Georeference or (lat, lon[, alt]).
            
        """
    @property
    def aoi_radius(self) -> float:
        """
        R, m.
        """
    @property
    def aois(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 2]"]:
        """
        (n, 2) AOI centres, m.
        """
    @property
    def directions(self) -> list[str]:
        """
        Loiter direction of each AOI ('ccw' or 'cw'), indexed like aois.
        """
    @property
    def end(self) -> tuple:
        """
        (x, y), m.
        """
    @property
    def flight_time(self) -> float:
        """
        length / speed, s.
        """
    @property
    def length(self) -> float:
        """
        Path length, m.
        """
    @property
    def loiter_sweep(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Angle flown on each AOI's loiter circle, rad (indexed like aois).
        """
    @property
    def loiter_time(self) -> float:
        """
        Time on the AOIs' loiter circles, s.
        """
    @property
    def method(self) -> str:
        """
        'fly_through', 'tlpp' or 'ldlpp'.
        """
    @property
    def order(self) -> list[int]:
        """
        Visiting order: indices into aois.
        """
    @property
    def segment_offsets(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Arc length at the start of each segment, m.
        """
    @property
    def segments(self) -> list[Segment]:
        """
        The path: list of Segment.
        """
    @property
    def speed(self) -> float:
        """
        v, m/s.
        """
    @property
    def start(self) -> tuple:
        """
        (x, y), m.
        """
    @property
    def transit_time(self) -> float:
        """
        Time off them, s (flight_time - loiter_time).
        """
    @property
    def turn_radius(self) -> float:
        """
        r, m.
        """
    @property
    def turns(self) -> int:
        """
        Full loiters per AOI.
        """
class Footprint:
    """
    A camera's ground footprint: an ellipse with axes along and across the heading.
    """
    def disk_area(self, center: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], radius: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        Exact area of the disk (center, radius) inside the footprint, m^2.
        """
    @property
    def along(self) -> tuple:
        """
        Unit vector of the heading.
        """
    @property
    def area(self) -> float:
        """
        pi * semi_along * semi_across, m^2.
        """
    @property
    def center(self) -> tuple:
        """
        (x, y), m.
        """
    @property
    def semi_across(self) -> float:
        """
        Semi-axis across it, m.
        """
    @property
    def semi_along(self) -> float:
        """
        Semi-axis along the heading, m.
        """
class Camera:
    """
    Section 2.2's camera: circular field of view fov_deg, roll gimbal +-max_gimbal_deg, altitude above the AOIs (61 m gives the paper's 6,638 m^2 nadir footprint).
    """
    def __init__(self, fov_deg: typing.SupportsFloat | typing.SupportsIndex = 74.0, max_gimbal_deg: typing.SupportsFloat | typing.SupportsIndex = 25.0, altitude: typing.SupportsFloat | typing.SupportsIndex = 61.0, levelled: bool = True) -> None:
        """
        fov_deg (full angle), max_gimbal_deg, altitude (m); levelled: the gimbal angle is measured from the vertical (the paper), else the gimbal sits under the banked body (its belly faces out of turns).
        """
    def __repr__(self) -> str:
        ...
    def footprint(self, pose: typing.Annotated[collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], "FixedSize(3)"], tilt: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> Footprint:
        """
        Ground footprint (an ellipse) at pose (x, y, psi) with the axis tilted `tilt` rad to the left.
        """
    def tilt(self, bank: typing.SupportsFloat | typing.SupportsIndex, gimbal: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        The axis' tilt to the left of vertical, rad, for a bank and a gimbal angle (rad, positive left).
        """
    def validate(self) -> None:
        """
        Raise VistrackError naming the first invalid field.
        """
    @property
    def altitude(self) -> float:
        """
        Height above the AOIs' ground, m.
        """
    @altitude.setter
    def altitude(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def fov_deg(self) -> float:
        """
        Full angle of the circular field of view, degrees.
        """
    @fov_deg.setter
    def fov_deg(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def levelled(self) -> bool:
        """
        True: the gimbal angle is measured from the vertical (the paper's camera); False: the gimbal rolls with the banked body, so the axis tilts by gimbal - bank.
        """
    @levelled.setter
    def levelled(self, arg0: bool) -> None:
        ...
    @property
    def max_gimbal_deg(self) -> float:
        """
        Largest gimbal roll either side, degrees.
        """
    @max_gimbal_deg.setter
    def max_gimbal_deg(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Coverage:
    """
    Camera coverage of the AOIs along a path (section 4.1).
    """
    @property
    def area(self) -> float:
        """
        The paper's 'AOI coverage (m^2)': the area of each covered AOI inside the footprint, summed over time steps and AOIs, times dt (m^2 s; m^2 at the paper's 1 s).
        """
    @property
    def area_per_aoi(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        That sum for each AOI.
        """
    @property
    def bank(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Per step: bank angle of the coordinated turn, rad, positive to the left.
        """
    @property
    def fraction(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (steps, AOIs): fraction of each AOI's disk in the footprint at each step.
        """
    @property
    def gimbal(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Per step: gimbal roll, rad, positive to the left.
        """
    @property
    def pointed(self) -> numpy.typing.NDArray[numpy.int32]:
        """
        Per step: the AOI the gimbal serves, -1 when none is in reach.
        """
    @property
    def steps(self) -> int:
        """
        Number of time steps.
        """
    @property
    def tilt(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Per step: the camera axis' tilt to the left of vertical, rad (Camera.tilt of bank and gimbal).
        """
    @property
    def time(self) -> float:
        """
        Covered time summed over the AOIs, s.
        """
    @property
    def time_per_aoi(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Covered time of each AOI, s.
        """
def bank_angle(speed: typing.SupportsFloat | typing.SupportsIndex, turn_rate: typing.SupportsFloat | typing.SupportsIndex, gravity: typing.SupportsFloat | typing.SupportsIndex = 9.80665) -> float:
    """
    Bank of a coordinated turn, atan(v psi_dot / g), rad, positive to the left.
    """
def best_order(aois: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], method: str = 'ldlpp', exact: bool = True, start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., end: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., turn_radius: typing.SupportsFloat | typing.SupportsIndex = 46.0, speed: typing.SupportsFloat | typing.SupportsIndex = 12.0, aoi_radius: typing.SupportsFloat | typing.SupportsIndex = 46.0, turns: typing.SupportsIndex = 1) -> list[int]:
    """
    The visiting order with the shortest plan: exact branch and bound (at most 12 AOIs) or the 2-opt heuristic.
    """
def ellipse_disk_area(a: typing.SupportsFloat | typing.SupportsIndex, b: typing.SupportsFloat | typing.SupportsIndex, cx: typing.SupportsFloat | typing.SupportsIndex, cy: typing.SupportsFloat | typing.SupportsIndex, rho: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    Exact area of the ellipse x^2/a^2 + y^2/b^2 <= 1 intersected with the disk of radius rho at (cx, cy).
    """
def entry_angle(aoi_radius: typing.SupportsFloat | typing.SupportsIndex, turn_radius: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    LDLPP's alpha_ED = asin(r / (R + r)) (14), rad.
    """
def entry_distance(aoi_radius: typing.SupportsFloat | typing.SupportsIndex, turn_radius: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    LDLPP's D_Entry = (R + r) cos(alpha_ED) (15), m.
    """
def order_length(aois: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], order: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex], method: str = 'ldlpp', start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., end: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., turn_radius: typing.SupportsFloat | typing.SupportsIndex = 46.0, speed: typing.SupportsFloat | typing.SupportsIndex = 12.0, aoi_radius: typing.SupportsFloat | typing.SupportsIndex = 46.0, turns: typing.SupportsIndex = 1) -> float:
    """
    Path length of a visiting order (no validation of the order's geometry): inf when the method cannot fly it.
    """
def plan(aois: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], method: str = 'ldlpp', start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., end: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., turn_radius: typing.SupportsFloat | typing.SupportsIndex = 46.0, speed: typing.SupportsFloat | typing.SupportsIndex = 12.0, aoi_radius: typing.SupportsFloat | typing.SupportsIndex = 46.0, turns: typing.SupportsIndex = 1, order: str = 'given') -> Plan:
    """
    Plan a loiter mission. aois: (n, 2) AOI centres (POIs), m; start, end: (x, y), m; turn_radius r (m), speed v (m/s), aoi_radius R >= r (m), turns: full loiters per AOI (>= 1). method: 'fly_through', 'tlpp' or 'ldlpp'; order: 'given' or 'best' (shortest plan: exact up to 9 AOIs, 2-opt/or-opt above).
    """
def plan_coverage(plan: Plan, camera: Camera = ..., threshold: typing.SupportsFloat | typing.SupportsIndex = 0.75, dt: typing.SupportsFloat | typing.SupportsIndex = 1.0) -> Coverage:
    """
    Coverage of a plan sampled every dt (t = 0, dt, ... up to the flight time), exact turn rates.
    """
def plan_in_order(aois: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], order: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex], method: str = 'ldlpp', start: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., end: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"] = ..., turn_radius: typing.SupportsFloat | typing.SupportsIndex = 46.0, speed: typing.SupportsFloat | typing.SupportsIndex = 12.0, aoi_radius: typing.SupportsFloat | typing.SupportsIndex = 46.0, turns: typing.SupportsIndex = 1) -> Plan:
    """
    Plan visiting the AOIs in this order (a permutation of 0..n-1).
    """
def sample_coverage(poses: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[m, 3]"], turn_rates: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], aois: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], aoi_radius: typing.SupportsFloat | typing.SupportsIndex = 46.0, speed: typing.SupportsFloat | typing.SupportsIndex = 12.0, camera: Camera = ..., threshold: typing.SupportsFloat | typing.SupportsIndex = 0.75, dt: typing.SupportsFloat | typing.SupportsIndex = 1.0) -> Coverage:
    """
    Coverage of poses (n, 3) sampled every dt with their turn rates (rad/s, for the bank angle).
    """
def turn_angle(aoi_radius: typing.SupportsFloat | typing.SupportsIndex, turn_radius: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    Heading change of LDLPP's entry and exit turns, pi/2 - alpha_ED, rad.
    """
BEYOND_PAPER_METHODS: tuple = ('tlpp_best', 'ldlpp_best')
EXACT_ORDER_LIMIT: int = 9
METHODS: tuple = ('fly_through', 'tlpp', 'ldlpp')
ORDERS: tuple = ('given', 'best')
STANDARD_GRAVITY: float = 9.80665
