"""MaxRadius at a flight altitude: the room a UAV has to circle a ground point in a city.

The tracking paper's MaxRadius (section IV, line 1 of Algorithm 1) for one point: the point's
visibility volume (VV, eq. 4), sliced at the flight altitude into its visibility polygon (VP), and
the radius of the largest circle about the point inside that polygon. Every point of such a circle
sees the point, so an orbit inside it keeps the line of sight. The pieces are the pipeline's own
(``visibility_volume``, ``plane_visibility_polygon``, ``max_inscribed_radius``); this module puts
them behind one call, caches VVs by position (planners moving along a road ask for the same spot
again), and finds circles off the point when the one about it is too small to fly.

>>> import vistrack as vt
>>> room = vt.city_orbits.orbit_room(env, (120.0, -40.0, 0.0), altitude=300.0, d_max=500.0)
>>> room.max_radius, room.polygons, room.largest_circle()      # MaxRadius, VP, the widest circle
>>> room.flyable_circle(60.0)                                  # a 60 m circle nearest the point

Used by the loiter planner's city mode and by the follower's city orbit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Optional, Sequence, Union

import numpy as np

from . import _core
from ._core import Environment, Polygon, VisibilityScene, VisibilityVolume, VistrackError
from .visibility import shapely_region, visibility_scene, visibility_volume

__all__ = ["Circle", "OrbitRoom", "VolumeCache", "orbit_room", "slice_radius_bound"]

Scene = Union[Environment, VisibilityScene]


@dataclass
class Circle:
    """A circle at the flight altitude: centre (x, y) and radius, m."""

    center: tuple[float, float]
    radius: float


@dataclass
class OrbitRoom:
    """The visibility polygon of a ground point at a flight altitude and the circles it holds.

    ``point``: the ground point (x, y, z) the VV was cast from; ``altitude``: world z of the
    slice; ``polygons``: the VP (one or more polygons with holes); ``max_radius``: the largest
    inscribed radius about (x, y) (0 when the polygon does not contain it): MaxRadius."""

    point: tuple[float, float, float]
    altitude: float
    polygons: list[Polygon]
    max_radius: float
    _region: object = field(default=None, repr=False)
    _inner: dict[float, Any] = field(default_factory=dict, repr=False)
    _boundary: object = field(default=None, repr=False)

    def region(self) -> object:
        """The VP as one shapely geometry (built once)."""
        if self._region is None:
            self._region = shapely_region(self.polygons)
        return self._region

    def fits(self, centre: Sequence[float], radius: float) -> bool:
        """Whether a circle of ``radius`` about ``centre`` (x, y) lies in the VP: its centre at least
        that far from the boundary, to the inward buffer's chord error (arcs of 8 segments a quarter
        turn lie within 0.5 % of the radius inside; the polygon simplified by 0.1 m), which tells a
        real piece of :meth:`inner` from a GEOS sliver."""
        import shapely

        if self._boundary is None:
            self._boundary = self.region().boundary  # type: ignore[attr-defined]
        boundary: Any = self._boundary
        return bool(boundary.distance(shapely.Point(float(centre[0]), float(centre[1]))) >= radius * (1.0 - 6e-3) - 0.1)

    def inner(self, radius: float) -> Any:
        """The centres of the circles of ``radius`` inside the VP: its inward buffer (of the polygon
        simplified to 0.1 m), kept per radius. GEOS can leave slivers in narrow wedges: check a
        centre against the boundary (:meth:`fits`) before flying it."""
        key = round(float(radius), 3)
        if key not in self._inner:
            import shapely

            region = shapely.simplify(self.region(), 0.1)
            self._inner[key] = shapely.buffer(region, -float(radius), quad_segs=8)
        return self._inner[key]

    def largest_circle(self, tolerance: float = 0.5) -> Circle:
        """The largest circle anywhere inside the VP (its pole of inaccessibility, to ``tolerance``
        m): where an off-centre orbit has the most room. Radius 0 for an empty VP."""
        import shapely

        region = self.region()
        if region.is_empty:  # type: ignore[attr-defined]
            return Circle((self.point[0], self.point[1]), 0.0)
        line = shapely.maximum_inscribed_circle(region, tolerance)
        (cx, cy), _ = np.asarray(line.coords)
        return Circle((float(cx), float(cy)), float(line.length))

    def flyable_circle(self, radius: float) -> Optional[Circle]:
        """A circle of ``radius`` inside the VP whose centre is nearest the point (the point itself
        when ``radius`` <= MaxRadius), or None when no circle that large fits anywhere."""
        radius = float(radius)
        if not radius > 0.0:
            raise VistrackError(f"radius = {radius}: must be > 0")
        if radius <= self.max_radius:
            return Circle((self.point[0], self.point[1]), radius)
        import shapely

        room = self.inner(radius)
        here = shapely.Point(self.point[0], self.point[1])
        # GEOS's inward buffer can leave slivers in narrow wedges of the polygon: take the nearest
        # piece whose nearest point really fits the circle.
        pieces = sorted((p for p in shapely.get_parts(room) if not p.is_empty), key=lambda piece: piece.distance(here))
        for piece in pieces:
            nearest = shapely.shortest_line(piece, here).coords[0]  # on the piece, nearest the point
            if self.fits(nearest, radius):
                return Circle((float(nearest[0]), float(nearest[1])), radius)
        return None


def slice_radius_bound(point_z: float, altitude: float, d_max: float) -> float:
    """The VP's radius over open ground: the slice of the sphere of radius ``d_max`` about the
    point at the altitude, sqrt(d_max^2 - (altitude - z)^2) (0 when out of reach)."""
    rise = float(altitude) - float(point_z)
    return math.sqrt(max(0.0, float(d_max) ** 2 - rise ** 2))


class VolumeCache:
    """VVs of ground points on one scene, keyed by position rounded to ``grid`` m, so a planner that
    comes back to a spot (or moves less than ``grid``) reuses the volume. ``computed`` counts the
    VVs cast; ``lookups`` the requests."""

    def __init__(self, env: Scene, d_max: float, resolution_deg: float = _core.Planning().resolution_deg,
                 grid: float = 5.0, altitude_band: Optional[tuple[float, float]] = None) -> None:
        if not (math.isfinite(float(d_max)) and float(d_max) > 0.0):
            raise VistrackError(f"d_max = {d_max}: must be a finite length > 0")
        if not (math.isfinite(float(grid)) and float(grid) > 0.0):
            raise VistrackError(f"grid = {grid}: must be a finite length > 0")
        self.scene = visibility_scene(env)
        self.d_max, self.resolution_deg, self.grid = float(d_max), float(resolution_deg), float(grid)
        self.altitude_band = altitude_band
        self.computed = 0
        self.lookups = 0
        self._volumes: dict[tuple[int, int, int], VisibilityVolume] = {}
        self.rooms: dict[tuple[tuple[int, int, int], float], OrbitRoom] = {}  # by cell and altitude

    def key(self, point: Sequence[float]) -> tuple[int, int, int]:
        """The cell: x and y in ``grid`` steps, z in decimetres."""
        return round(float(point[0]) / self.grid), round(float(point[1]) / self.grid), round(float(point[2]) * 10.0)

    def snapped(self, point: Sequence[float]) -> tuple[float, float, float]:
        """The cell's point: the one whose VV serves every point of the cell."""
        k = self.key(point)
        return (k[0] * self.grid, k[1] * self.grid, float(point[2]))

    def has(self, point: Sequence[float]) -> bool:
        """Whether the VV of ``point``'s cell is cast already (asking for it costs nothing)."""
        return self.key(point) in self._volumes

    def volume(self, point: Sequence[float]) -> VisibilityVolume:
        """The VV of ``point`` (x, y, z) snapped to the grid in x and y (z as given), cast once."""
        self.lookups += 1
        k = self.key(point)
        vv = self._volumes.get(k)
        if vv is None:
            vv = visibility_volume(self.scene, self.snapped(point), self.d_max, self.altitude_band,
                                   self.resolution_deg)
            self._volumes[k] = vv
            self.computed += 1
        return vv


def _ground_point(scene: VisibilityScene, point: Sequence[float], altitude: float) -> tuple[float, float, float]:
    try:
        x, y, z = (float(v) for v in point)
    except (TypeError, ValueError):
        raise VistrackError(f"point = {point!r}: expected (x, y, z) numbers") from None
    if not all(math.isfinite(v) for v in (x, y, z)):
        raise VistrackError(f"point = {(x, y, z)}: must be finite")
    if z < scene.ground_level - 1e-9:
        raise VistrackError(f"point z = {z:g}: below the ground ({scene.ground_level:g} m)")
    if scene.inside_obstacle(np.array([x, y, z])):
        raise VistrackError(f"point = ({x:g}, {y:g}, {z:g}): inside a building")
    if not (math.isfinite(float(altitude)) and float(altitude) > z):
        raise VistrackError(f"altitude = {altitude}: must be above the point (z = {z:g} m)")
    return x, y, z


def orbit_room(env: Scene, point: Sequence[float], altitude: float, d_max: float = _core.Sensor().d_max,
               resolution_deg: float = _core.Planning().resolution_deg,
               cache: Optional[VolumeCache] = None) -> OrbitRoom:
    """The VP of the ground ``point`` (x, y, z world) at world z = ``altitude`` and MaxRadius about
    it: the VV within ``d_max`` (from ``cache`` when given: its d_max and resolution apply, the
    point snaps to its grid and the room is kept per cell and altitude), sliced by
    ``plane_visibility_polygon`` as the tracking pipeline does, and ``max_inscribed_radius`` about
    (x, y). VistrackError naming the field for a point below
    the ground or inside a building, or an altitude not above the point."""
    scene = cache.scene if cache is not None else visibility_scene(env)
    x, y, z = _ground_point(scene, point, altitude)
    band = cache.altitude_band if cache is not None else None
    if cache is not None and scene.inside_obstacle(np.add(cache.snapped((x, y, z)), (0.0, 0.0, 0.05))):
        # The cell's point is inside a wall (the point is near one; 5 cm up, as a point on the ground is on
        # a footprint's boundary): cast from the point itself, uncached.
        d_max, resolution_deg, cache = cache.d_max, cache.resolution_deg, None
    if cache is None:
        vv = visibility_volume(scene, (x, y, z), d_max, band, resolution_deg)
    else:
        key = (cache.key((x, y, z)), float(altitude))
        if key in cache.rooms:  # the cell's VP at this altitude, sliced already
            cache.lookups += 1
            return cache.rooms[key]
        x, y, _ = cache.snapped((x, y, z))  # the cell's point: MaxRadius about the point the VV is cast from
        vv = cache.volume((x, y, z))
    polygons = list(_core.plane_visibility_polygon(vv, float(altitude)))
    radius = float(_core.max_inscribed_radius(polygons, np.array([x, y])))
    room = OrbitRoom((x, y, z), float(altitude), polygons, radius)
    if cache is not None:
        cache.rooms[(cache.key((x, y, z)), float(altitude))] = room
    return room
