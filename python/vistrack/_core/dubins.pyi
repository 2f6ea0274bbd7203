"""
Dubins paths (shortest of LSL, LSR, RSL, RSR, RLR, LRL), batch lengths, shortest path to a point on a circle and the optimal intercept of a target moving on a circle (Manyam et al., Algorithm 1). Configurations are (x, y, psi), psi in rad counter-clockwise from +x; rho is the minimum turn radius. Snapping tolerance: eps = 1e-11 * (1 + max|coordinate| / rho) (see dubins.hpp).
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
__all__: list[str] = ['DubinsPath', 'InterceptResult', 'SNAP', 'WORDS', 'four_rho_condition', 'intercept_circle', 'intercept_travel_times', 'length_to_circle', 'path', 'path_to_circle', 'shortest_length', 'shortest_lengths', 'shortest_path', 'word_lengths']
class DubinsPath:
    """
    One Dubins path: start, goal, turn radius, word and segment lengths.
    """
    def __repr__(self) -> str:
        ...
    def at(self, s: typing.SupportsFloat | typing.SupportsIndex) -> tuple:
        """
        (x, y, psi) after arc length s in [0, length]; the goal exactly at s = length. Headings continue from start.psi (not wrapped).
        """
    def sample(self, step: typing.SupportsFloat | typing.SupportsIndex) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 3]"]:
        """
        Array (n, 3) of (x, y, psi) at s = 0, step, 2 step, ... and the goal exactly as the last row.
        """
    def sample_at(self, arc_lengths: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex]) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 3]"]:
        """
        Array (n, 3) of (x, y, psi) at the given arc lengths (each in [0, length]).
        """
    @property
    def goal(self) -> tuple:
        """
        (x, y, psi) at s = length.
        """
    @property
    def length(self) -> float:
        """
        Total length (m), the sum of segment_lengths.
        """
    @property
    def rho(self) -> float:
        """
        Minimum turn radius (m).
        """
    @property
    def segment_lengths(self) -> tuple[float, float, float]:
        """
        Arc lengths of the three segments (m).
        """
    @property
    def segment_types(self) -> tuple[str, str, str]:
        """
        ('L'|'S'|'R',) * 3: left arc, straight, right arc.
        """
    @property
    def start(self) -> tuple:
        """
        (x, y, psi) at s = 0.
        """
    @property
    def word(self) -> str:
        """
        'LSL', 'LSR', ...
        """
class InterceptResult:
    """
    Optimal interception of a target moving on a circle.
    """
    @property
    def alpha_min(self) -> float:
        """
        argmin of D(alpha) over [0, 2 pi).
        """
    @property
    def angle(self) -> float:
        """
        alpha*: interception angular position (rad, unwrapped).
        """
    @property
    def bisection_steps(self) -> int:
        """
        Bisection iterations.
        """
    @property
    def bracket_windows(self) -> int:
        """
        Periods skipped by Algorithm 1's bracket.
        """
    @property
    def four_rho_condition(self) -> bool:
        """
        True: optimal (Proposition 1). False: feasible, optimality not guaranteed.
        """
    @property
    def optimal(self) -> bool:
        """
        Alias of four_rho_condition: whether optimality is guaranteed.
        """
    @property
    def path(self) -> DubinsPath:
        """
        The pursuer's Dubins path to the interception point.
        """
    @property
    def period(self) -> float:
        """
        Period of D(alpha) used to step the brackets (2 pi).
        """
    @property
    def residual(self) -> float:
        """
        T_p - T_t at the returned angle (s), <= 0 and tiny.
        """
    @property
    def swept_angle(self) -> float:
        """
        Angle the target travels before interception (rad).
        """
    @property
    def time(self) -> float:
        """
        Interception time (s), equal for pursuer and target.
        """
def four_rho_condition(p: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], rho: typing.SupportsFloat | typing.SupportsIndex, center: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], radius: typing.SupportsFloat | typing.SupportsIndex) -> bool:
    """
    Whether every point of the circle is farther than 4 rho from p (the paper's assumption).
    """
def intercept_circle(pursuer: tuple[float, float, float], rho: typing.SupportsFloat | typing.SupportsIndex, pursuer_speed: typing.SupportsFloat | typing.SupportsIndex, center: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], radius: typing.SupportsFloat | typing.SupportsIndex, target_angle0: typing.SupportsFloat | typing.SupportsIndex, target_speed: typing.SupportsFloat | typing.SupportsIndex, direction: str = 'cw', angle_tolerance: typing.SupportsFloat | typing.SupportsIndex = 1e-12, scan_samples: typing.SupportsInt | typing.SupportsIndex = 2048) -> InterceptResult:
    """
    Earliest interception of a target starting at angle target_angle0 on the circle and moving at target_speed in `direction`, by a Dubins pursuer (Algorithm 1: brackets one period of D(alpha) apart, first sign change, bisection to angle_tolerance rad).
    """
def intercept_travel_times(pursuer: tuple[float, float, float], rho: typing.SupportsFloat | typing.SupportsIndex, pursuer_speed: typing.SupportsFloat | typing.SupportsIndex, center: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], radius: typing.SupportsFloat | typing.SupportsIndex, target_angle0: typing.SupportsFloat | typing.SupportsIndex, target_speed: typing.SupportsFloat | typing.SupportsIndex, direction: str, swept_angles: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex]) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    Figure 7a data: for swept target angles, (alpha, T_p(alpha) = D(alpha)/v_p, T_t(alpha)).
    """
def length_to_circle(q0: tuple[float, float, float], rho: typing.SupportsFloat | typing.SupportsIndex, center: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], radius: typing.SupportsFloat | typing.SupportsIndex, angles: collections.abc.Sequence[typing.SupportsFloat | typing.SupportsIndex], direction: str = 'cw', csc_only: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    D(alpha) for each angle: the length of the shortest path to the circle point (all six words), or with csc_only=True the paper's D_CSC(alpha) (min of LSL, LSR, RSL, RSR). Both agree and are continuous when the 4 rho condition holds; period exactly 2 pi.
    """
def path(q0: tuple[float, float, float], q1: tuple[float, float, float], rho: typing.SupportsFloat | typing.SupportsIndex, word: str) -> DubinsPath:
    """
    The path of one given word ('LSL', ...); VistrackError when that word has no path.
    """
def path_to_circle(q0: tuple[float, float, float], rho: typing.SupportsFloat | typing.SupportsIndex, center: typing.Annotated[numpy.typing.ArrayLike, numpy.float64, "[2, 1]"], radius: typing.SupportsFloat | typing.SupportsIndex, angle: typing.SupportsFloat | typing.SupportsIndex, direction: str = 'cw') -> DubinsPath:
    """
    Shortest Dubins path from q0 to the point at `angle` (rad, about the centre) on the circle, arriving tangent to it in the travel direction ('cw': heading angle - pi/2, 'ccw': angle + pi/2).
    """
def shortest_length(q0: tuple[float, float, float], q1: tuple[float, float, float], rho: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    Length of the shortest Dubins path (no path object; the batch kernel for one pair).
    """
def shortest_lengths(q0s: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], q1s: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], rho: typing.SupportsFloat | typing.SupportsIndex, threads: typing.SupportsInt | typing.SupportsIndex = 0) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.uint8]]:
    """
    Batch: arrays (n, 3) of start and goal configurations -> (lengths (n,), words (n,) uint8 indexing WORDS). Multi-threaded (TBB; threads=0 uses all cores, else at most `threads`), releases the GIL.
    """
def shortest_path(q0: tuple[float, float, float], q1: tuple[float, float, float], rho: typing.SupportsFloat | typing.SupportsIndex) -> DubinsPath:
    """
    Shortest of the six Dubins words from q0 to q1.
    """
def word_lengths(q0: tuple[float, float, float], q1: tuple[float, float, float], rho: typing.SupportsFloat | typing.SupportsIndex) -> dict[str, float]:
    """
    Length of every word (inf where it does not exist), keyed by word.
    """
SNAP: float = 1e-11
WORDS: tuple = ('LSL', 'LSR', 'RSL', 'RSR', 'RLR', 'LRL')
