"""Loiter over a city (beyond every anchor): each AOI's loiter circle inside its visibility polygon.

The paper flies 61 m over open ground. Over a city at the flight altitude ``uav.altitude`` (world z
above the city's ground), an AOI at street level is seen only from its visibility polygon (VP) at
that altitude; a loiter circle about the AOI keeps the line of sight when it lies inside the VP,
i.e. when its radius is at most the tracking paper's MaxRadius about the AOI
(:mod:`vistrack.city_orbits`). An AOI is flyable when MaxRadius, less a ``margin`` for the VV's
1-degree grid, is at least the turn radius; the others are reported and left out of the plan.

The loiter planners fly one circle radius R for every AOI (``Parameters.aoi_radius``), so the plan's
R is the scenario's ``aoi_radius`` cut to the smallest room of the flyable AOIs (never below the turn
radius). Coverage (:mod:`.city_coverage`) uses that R as the AOI disk and counts only disk points
the camera sees through the buildings.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Optional, Sequence

import numpy as np

from .._core import Environment, PoiMotion, Polygon, VisibilityScene, VistrackError
from ..city_orbits import OrbitRoom, orbit_room
from .city_coverage import CityCoverage, city_coverage
from .planning import Camera, Plan, plan
from .scenario import Scenario

__all__ = ["DEFAULT_MARGIN", "AoiRoom", "CityLoiter", "CityRun", "aoi_rooms", "loiter_radius", "move_off_centre",
           "plan_city", "random_street_aois"]

DEFAULT_MARGIN = 3.0  # m kept between a loiter circle and its VP's boundary (the VV's 1-degree grid)
REACH = 400.0  # m: MaxRadius is measured out to this far (the VV's range is set so that it reaches it)
MAX_SHIFT = 150.0  # m: the farthest an off-centre loiter circle's centre may be from its AOI


@dataclass
class AoiRoom:
    """One AOI over the city: where it stands (on the surface), its VP at the flight altitude,
    MaxRadius about it, whether a flyable circle fits (else ``reason``) and the loiter circle's
    centre (the AOI's, or off it by ``shift`` m when only an off-centre circle fits)."""

    index: int
    point: tuple[float, float, float]
    polygons: list[Polygon]
    max_radius: float
    flyable: bool
    reason: Optional[str] = None
    center: tuple[float, float] = (0.0, 0.0)
    shift: float = 0.0
    room: Optional[OrbitRoom] = field(default=None, repr=False)


@dataclass
class CityRun:
    """One method's city plan (over the flyable AOIs) and its scores."""

    method: str
    plan: Plan
    coverage: CityCoverage
    centre_line_of_sight: list[float]  # per flyable AOI: share of its loiter time it is seen

    def record(self) -> dict[str, object]:
        return {"method": self.method, "flight_time_s": self.plan.flight_time, "loiter_time_s": self.plan.loiter_time,
                **self.coverage.record(), "centre_line_of_sight_in_loiter": self.centre_line_of_sight}


@dataclass
class CityLoiter:
    """A scenario's AOIs over a city: each AOI's room, the common loiter radius, every method's run
    (indices in ``runs``' plans are positions in ``flyable``) and the methods that could not fly."""

    altitude: float  # world z of the flight
    rooms: list[AoiRoom]
    radius: Optional[float]
    runs: list[CityRun] = field(default_factory=list)
    refused: dict[str, str] = field(default_factory=dict)

    @property
    def volumes(self) -> int:
        """VVs computed: one per AOI."""
        return len(self.rooms)

    @property
    def flyable(self) -> list[int]:
        return [room.index for room in self.rooms if room.flyable]

    def record(self) -> dict[str, object]:
        return {
            "altitude_m": self.altitude, "loiter_radius_m": self.radius, "flyable_aois": self.flyable,
            "volumes": self.volumes,
            "aois": [{"aoi": r.index, "point": list(r.point), "max_radius_m": r.max_radius, "flyable": r.flyable,
                      "loiter_center": list(r.center), "off_centre_m": r.shift, "reason": r.reason}
                     for r in self.rooms],
            "runs": [run.record() for run in self.runs], "refused": dict(self.refused),
        }


def _street_point(scene: VisibilityScene, x: float, y: float, height: float) -> tuple[tuple[float, float, float], bool]:
    """The point ``height`` above the surface at (x, y), and whether it stands in the street: the
    surface there is the ground (not a roof) and the point is in no building."""
    px, py, pz = (float(v) for v in np.asarray(scene.poi_on_surface(np.array([[x, y, height]])))[0])
    street = not (pz > scene.ground_level + height + 0.5 or scene.inside_obstacle(np.array([px, py, pz])))
    return (px, py, pz), street


def aoi_rooms(scene: VisibilityScene, aois: np.ndarray, altitude: float, turn_radius: float,
              margin: float = DEFAULT_MARGIN, height: float = PoiMotion().height) -> list[AoiRoom]:
    """Each AOI (x, y) placed ``height`` above the surface, its VP at world z = ``altitude`` and
    MaxRadius; flyable about its centre when MaxRadius - margin >= turn_radius. VistrackError
    naming ``aois[i]`` for an AOI on a roof or inside a building, ``uav.altitude`` when the flight
    is not above it."""
    rooms = []
    ground = scene.ground_level
    for i, (x, y) in enumerate(np.asarray(aois, dtype=float)):
        point, in_street = _street_point(scene, x, y, height)
        if not in_street:
            raise VistrackError(f"aois[{i}] = ({x:g}, {y:g}): on or inside a building (surface at "
                                f"{point[2] - height:.1f} m, the ground at {ground:.1f} m); city AOIs stand in the "
                                "street")
        if not altitude > point[2]:
            raise VistrackError(f"uav.altitude = {altitude - ground:g}: the flight must be above aois[{i}] "
                                f"(z = {point[2]:.1f} m)")
        room = orbit_room(scene, point, altitude, d_max=math.hypot(altitude - point[2], REACH))
        flyable = room.max_radius - margin >= turn_radius
        reason = None if flyable else (
            f"aoi {i}: no flyable circle about it in its visibility polygon at {altitude - ground:g} m: MaxRadius "
            f"{room.max_radius:.1f} m - margin {margin:g} m < turn radius {turn_radius:g} m")
        rooms.append(AoiRoom(i, room.point, room.polygons, room.max_radius, flyable, reason, (float(x), float(y)),
                             0.0, room))
    return rooms


def loiter_radius(rooms: Sequence[AoiRoom], preferred: float, turn_radius: float,
                  margin: float = DEFAULT_MARGIN) -> float:
    """The plan's one loiter radius: ``preferred`` cut to the MaxRadius - margin of every AOI
    flyable about its centre, never below the turn radius (the turn radius when none is)."""
    rooms_left = [r.max_radius - margin for r in rooms if r.flyable]
    return max(turn_radius, min([preferred, *rooms_left])) if rooms_left else turn_radius


def move_off_centre(rooms: Sequence[AoiRoom], radius: float, margin: float = DEFAULT_MARGIN,
                    max_shift: float = MAX_SHIFT) -> None:
    """Give each AOI without a circle about it the circle of ``radius`` (+ margin) inside its VP
    whose centre is nearest the AOI, when that centre is within ``max_shift`` m (the camera still
    reaches the AOI from there); the others keep their reason."""
    for r in rooms:
        if r.flyable or r.room is None:
            continue
        circle = r.room.flyable_circle(radius + margin)
        shift = math.inf if circle is None else math.dist(circle.center, r.point[:2])
        if circle is not None and shift <= max_shift:
            r.flyable, r.center, r.shift = True, circle.center, shift
            r.reason = None
        else:
            r.reason = (f"{r.reason}; no {radius + margin:.0f} m circle in it within {max_shift:g} m either")


def plan_city(scenario: Scenario, methods: Sequence[str], env: Optional[Environment | VisibilityScene] = None,
              order: str = "given", margin: float = DEFAULT_MARGIN, altitude: Optional[float] = None,
              rays: int = 48, off_centre: Optional[bool] = None, max_shift: float = MAX_SHIFT) -> CityLoiter:
    """Plan every method over the scenario's flyable AOIs with circles inside their VPs, and score
    each plan with line of sight. ``env``: the city (default: the scenario's ``city`` block);
    ``altitude``: the flight's height above the city's ground (default the camera's, uav.altitude);
    ``off_centre`` (None: the scenario's ``off_centre``): an AOI without a circle about it may
    loiter on the nearest circle inside its VP within ``max_shift`` m (beyond the issue's rule:
    the circle is inside the VP, so it still sees the AOI)."""
    if env is None:
        if scenario.city is None:
            raise VistrackError("city = None: the scenario has no city block")
        env = scenario.city.load(scenario.origin)
    scene = env if isinstance(env, VisibilityScene) else VisibilityScene(env)
    height = scenario.camera.altitude if altitude is None else float(altitude)
    world = scene.ground_level + height
    rooms = aoi_rooms(scene, scenario.aois, world, scenario.turn_radius, margin)
    radius = loiter_radius(rooms, scenario.aoi_radius, scenario.turn_radius, margin)
    if scenario.off_centre if off_centre is None else off_centre:
        move_off_centre(rooms, radius, margin, max_shift)
    result = CityLoiter(world, rooms, radius if any(r.flyable for r in rooms) else None)
    if result.radius is None:
        return result
    flyable = result.flyable
    targets = scenario.aois[flyable]
    centres = np.array([rooms[i].center for i in flyable])
    z = np.array([rooms[i].point[2] for i in flyable])
    camera = Camera(scenario.camera.fov_deg, scenario.camera.max_gimbal_deg, world - float(np.mean(z)),
                    scenario.camera.levelled)
    for method in methods:
        try:
            p = plan(centres, method, scenario.start, scenario.end, scenario.turn_radius, scenario.speed, radius,
                     scenario.turns, order)
        except VistrackError as error:
            result.refused[method] = str(error)
            continue
        cov = city_coverage(p, scene, camera, world, scenario.threshold, scenario.dt, rays, targets=targets)
        seen = centre_line_of_sight(p, scene, targets, z, world, scenario.dt)
        result.runs.append(CityRun(method, p, cov, seen))
    return result


def centre_line_of_sight(p: Plan, scene: VisibilityScene, targets: np.ndarray, z: np.ndarray, altitude: float,
                         dt: float) -> list[float]:
    """For each AOI of the plan: the share of the time steps on its loiter arcs at which the AOI
    (``targets`` (n, 2) at heights ``z``; the plan's circles may be off them) is in line of sight
    from the aircraft (at world z = altitude)."""
    samples = p.sample_states(dt, False)
    poses, segments = np.asarray(samples.poses), np.asarray(samples.segment)
    pieces = p.segments
    loiter_aoi = np.array([s.aoi if s.role == "loiter" and s.aoi is not None else -1 for s in pieces])[segments]
    on = loiter_aoi >= 0
    uav = np.column_stack([poses[on, :2], np.full(int(on.sum()), altitude)])
    centres = np.column_stack([np.asarray(targets)[loiter_aoi[on]], z[loiter_aoi[on]]])
    seen = np.asarray(scene.line_of_sight(uav, centres), dtype=bool)
    shares = []
    for a in range(len(z)):
        mine = loiter_aoi[on] == a
        shares.append(float(seen[mine].mean()) if mine.any() else 0.0)
    return shares


def random_street_aois(scene: VisibilityScene, count: int, rng: np.random.Generator, half_size: float = 400.0,
                       separation: float = 160.0, clearance: float = 80.0, height: float = PoiMotion().height,
                       attempts: int = 100000) -> np.ndarray:
    """``count`` AOI centres uniform in the square of half-width ``half_size`` about the origin,
    each at street level (the surface there is the ground and the point is in no building), at
    least ``separation`` apart and ``clearance`` from the origin (the start and end); (count, 2).
    The defaults keep every printed method flyable at R = r = 46 m (as ``random_aois``)."""
    chosen: list[np.ndarray] = []
    for _ in range(attempts):
        c = rng.uniform(-half_size, half_size, 2)
        if np.hypot(*c) < clearance or any(np.hypot(*(c - o)) < separation for o in chosen):
            continue
        if not _street_point(scene, c[0], c[1], height)[1]:
            continue
        chosen.append(c)
        if len(chosen) == count:
            return np.array(chosen)
    raise VistrackError(f"count = {count}: could not place that many street-level AOIs {separation:g} m apart")
