"""What moves in a run, described once for every renderer: the plan-view GIF
(:mod:`.animation`) and the interactive 3D view (:mod:`.interactive`) draw the same
:class:`MotionScene`.

A scene holds static paths (a planned route, the POI's road, AOI boundaries), tracks (bodies
moving over time: the UAV, the POI, a ground vehicle), overlays whose shapes change with time
(the visibility polygon and orbit of the moment, a camera footprint), an optional line of sight
between two tracks (green while visible, red while occluded) and an optional wind arrow. Any
planner builds one in a few lines; :func:`tracking_scene` builds the tracking run's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, Optional, Sequence, Union

import numpy as np

from .._core import Environment, OrbitPlan, Polygon, SimulationResult, VisibilityOrbitPlan

# Colours shared by the GIF and the 3D view.
VISIBLE_COLOR = "#1a9850"
OCCLUDED_COLOR = "#d73027"

Shapes = Callable[[float], Sequence[np.ndarray]]  # time -> closed rings, each (m, 2) east-north
WindField = Union[tuple[float, float], Callable[[float], tuple[float, float]]]  # m/s east, north


@dataclass
class Track:
    """A body moving in the plan: positions ``xy`` (n, 2) or (n, 3) at increasing times ``t`` (n,),
    drawn as a marker with a trail (the GIF) or with its whole path (the 3D view). ``z`` is its
    height in 3D when ``xy`` has two columns. With ``flag`` (e.g. the POI in line of sight), the
    path is drawn in ``on_color`` where it holds and ``off_color`` elsewhere."""

    label: str
    t: np.ndarray
    xy: np.ndarray
    color: str = "tab:red"
    marker: str = "o"
    z: float = 0.0
    trail: Optional[float] = None  # seconds of trail behind the marker; None: the whole past
    width: float = 1.5  # of the trail / path
    flag: Optional[np.ndarray] = None  # (n,) bool: colours the path (segment i -> i+1 by flag[i])
    on_color: str = VISIBLE_COLOR
    off_color: str = OCCLUDED_COLOR

    def __post_init__(self) -> None:
        self.t = np.asarray(self.t, dtype=float)
        self.xy = np.asarray(self.xy, dtype=float)
        if self.t.ndim != 1 or len(self.t) < 1 or self.xy.shape[0] != len(self.t) or self.xy.shape[1] not in (2, 3):
            raise ValueError(f"Track {self.label!r}: t (n,) and xy (n, 2|3) must match, got {self.t.shape} "
                             f"and {self.xy.shape}")
        if self.flag is not None:
            self.flag = np.asarray(self.flag, dtype=bool)
            if self.flag.shape != self.t.shape:
                raise ValueError(f"Track {self.label!r}: flag {self.flag.shape} must match t {self.t.shape}")

    def xyz(self) -> np.ndarray:
        """(n, 3) positions, z from the data or the constant ``z``."""
        if self.xy.shape[1] == 3:
            return self.xy
        return np.column_stack([self.xy, np.full(len(self.xy), self.z)])

    def at(self, times: np.ndarray) -> np.ndarray:
        """(m, 3) positions at ``times``, linearly interpolated (held at the ends)."""
        p = self.xyz()
        return np.column_stack([np.interp(times, self.t, p[:, i]) for i in range(3)])


@dataclass
class Line:
    """A static path in the plan: (n, 2) or (n, 3) points; z as for :class:`Track`.
    ``fill`` fills the closed ring lightly (areas of interest)."""

    label: Optional[str]
    xy: np.ndarray
    color: str = "0.35"
    style: str = "--"
    width: float = 1.2
    z: float = 0.0
    fill: bool = False

    def xyz(self) -> np.ndarray:
        xy = np.asarray(self.xy, dtype=float)
        return xy if xy.shape[1] == 3 else np.column_stack([xy, np.full(len(xy), self.z)])


@dataclass
class Overlay:
    """Shapes that change with time (a camera footprint, the VP and orbit of the moment): ``shapes(t)``
    gives closed rings (m, 2) drawn at height ``z``, filled when ``fill``."""

    label: str
    shapes: Shapes
    color: str = "tab:orange"
    fill: bool = True
    style: str = "-"
    z: float = 0.0


@dataclass
class Sight:
    """The line of sight from ``tracks[observer]`` to ``tracks[target]``: green where ``visible`` (at
    the sample times ``t``) holds, red elsewhere."""

    observer: int
    target: int
    t: np.ndarray
    visible: np.ndarray

    def at(self, time: float) -> bool:
        """Visibility at the sample at or before ``time``."""
        k = int(np.searchsorted(self.t, time, side="right")) - 1
        return bool(self.visible[min(max(k, 0), len(self.visible) - 1)])


@dataclass
class MotionScene:
    """Everything a plan-view animation or a 3D view draws; see the module docstring."""

    tracks: Sequence[Track]
    lines: Sequence[Line] = ()
    overlays: Sequence[Overlay] = ()
    sight: Optional[Sight] = None
    wind: Optional[WindField] = None
    env: Optional[Environment] = None
    extent: Optional[tuple[float, float, float, float]] = None  # xmin, xmax, ymin, ymax; None: fit
    title: str = ""
    credit: Optional[str] = None
    time_label: str = "t"
    notes: list[str] = field(default_factory=list)

    def time_span(self) -> tuple[float, float]:
        starts = [float(tr.t[0]) for tr in self.tracks]
        ends = [float(tr.t[-1]) for tr in self.tracks]
        return min(starts), max(ends)

    def frame_times(self, frames: int) -> np.ndarray:
        """``frames`` evenly spaced times over the tracks' span, first and last included."""
        if frames < 2:
            raise ValueError(f"frames = {frames}: must be at least 2")
        t0, t1 = self.time_span()
        return np.linspace(t0, t1, frames)

    def wind_at(self, time: float) -> Optional[tuple[float, float]]:
        if self.wind is None:
            return None
        w = self.wind(time) if callable(self.wind) else self.wind
        return float(w[0]), float(w[1])

    def fit_extent(self, margin: float = 0.06) -> tuple[float, float, float, float]:
        """``extent`` or a square box around every track, line and overlay at the frame times."""
        if self.extent is not None:
            return self.extent
        points = [tr.xy[:, :2] for tr in self.tracks] + [np.asarray(ln.xy)[:, :2] for ln in self.lines]
        for overlay in self.overlays:
            for time in self.frame_times(12):
                points += [np.asarray(r)[:, :2] for r in overlay.shapes(float(time)) if len(r)]
        xy = np.vstack(points)
        lo, hi = xy.min(axis=0), xy.max(axis=0)
        center, half = (lo + hi) / 2, max(hi - lo) / 2 * (1 + margin) + 1.0
        return center[0] - half, center[0] + half, center[1] - half, center[1] + half


def circle_ring(center: Union[Sequence[float], np.ndarray], radius: float, points: int = 90) -> np.ndarray:
    """A closed circle as an (points, 2) ring."""
    a = np.linspace(0.0, 2 * math.pi, points, endpoint=False)
    return np.column_stack([center[0] + radius * np.cos(a), center[1] + radius * np.sin(a)])


def ellipse_ring(center: Union[Sequence[float], np.ndarray], semi_along: float, semi_across: float,
                 heading: float, points: int = 72) -> np.ndarray:
    """A closed ellipse as a (points, 2) ring, its ``semi_along`` axis at angle ``heading`` (rad,
    counter-clockwise from east): a camera footprint (loiter's ``Footprint``)."""
    a = np.linspace(0.0, 2 * math.pi, points, endpoint=False)
    along = np.array([math.cos(heading), math.sin(heading)])
    across = np.array([-along[1], along[0]])
    return (np.asarray(center, dtype=float)[None, :2] + np.outer(semi_along * np.cos(a), along)
            + np.outer(semi_across * np.sin(a), across))


def sampled(times: Sequence[float], shapes: Sequence[Sequence[np.ndarray]]) -> Shapes:
    """A :data:`Shapes` from shapes given at sample times: at time t, those of the last sample at or
    before t (e.g. camera footprints computed every second, or the VP of the current plan sample)."""
    t = np.asarray(times, dtype=float)
    items = list(shapes)
    if len(t) != len(items) or len(t) == 0:
        raise ValueError(f"sampled: {len(t)} times for {len(items)} shape lists")

    def at(time: float) -> Sequence[np.ndarray]:
        k = int(np.searchsorted(t, time, side="right")) - 1
        return items[min(max(k, 0), len(items) - 1)]

    return at


def polygon_rings(polygons: Sequence[Polygon]) -> list[np.ndarray]:
    """Outer rings and holes of polygons as plain rings."""
    rings: list[np.ndarray] = []
    for p in polygons:
        rings.append(np.asarray(p.outer))
        rings += [np.asarray(h) for h in p.holes]
    return rings


def tracking_scene(plan: Union[OrbitPlan, VisibilityOrbitPlan], simulation: SimulationResult,
                   env: Optional[Environment] = None, title: str = "", credit: Optional[str] = None) -> MotionScene:
    """The tracking run of the visibility-volume paper as a scene: the UAV (at its altitude) and the
    POI moving, their paths coloured by line of sight and the line of sight between them, the POI's
    route, and (for a visibility plan) the VP of the current plan sample and the orbit of
    the moment (circle of radius R(t) about g(t)) at the flight altitude."""
    t = np.asarray(simulation.t, dtype=float)
    state = np.asarray(simulation.state)
    poi = np.asarray(simulation.poi)
    radius = np.asarray(simulation.orbit_radius, dtype=float)
    altitude = float(plan.uav.altitude) if isinstance(plan, VisibilityOrbitPlan) else 0.0
    visible_raw = simulation.visible
    visible = np.ones(len(t), bool) if visible_raw is None else np.asarray(visible_raw, bool)
    flag = None if visible_raw is None else visible
    tracks = [Track("UAV", t, state[:, :2], color="tab:blue", marker="o", z=altitude, flag=flag),
              Track("POI", t, poi, color="crimson", marker="s", width=3.0, flag=flag)]
    road = np.asarray(plan.poi.waypoints)[:, :2]
    lines = [Line("POI route", road, color="0.45", style=":", width=1.0, z=float(poi[:, 2].min()))]

    def orbit(time: float) -> Sequence[np.ndarray]:
        k = min(int(np.searchsorted(t, time)), len(t) - 1)
        return [circle_ring(poi[k, :2], float(radius[k]))]

    overlays = [Overlay("orbit R(t)", orbit, color="black", fill=False, style="--", z=altitude)]
    if isinstance(plan, VisibilityOrbitPlan):
        rings = [polygon_rings(p) for p in plan.polygons]
        overlays.insert(0, Overlay("VP of the sample", sampled(plan.times, rings), color="tab:green",
                                   fill=True, z=altitude))
    sight = Sight(0, 1, t, visible) if visible_raw is not None else None
    return MotionScene(tracks, lines, overlays, sight, env=env, title=title, credit=credit)
