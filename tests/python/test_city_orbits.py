"""MaxRadius at a flight altitude (vistrack.city_orbits): analytic radii, brute-force line of sight,
and the tracking pipeline's own MaxRadius on Charlotte."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.refusal import refuses
from vistrack import city_orbits as co


def _box(x0: float, x1: float, y0: float, y1: float) -> np.ndarray:
    return np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])


def test_open_ground_radius_is_the_slice_bound() -> None:
    env = vt.Environment.from_buildings([(_box(3000, 3010, 0, 10), 20.0)])  # far away
    room = co.orbit_room(env, (0.0, 0.0, 0.0), 300.0, d_max=500.0)
    bound = co.slice_radius_bound(0.0, 300.0, 500.0)
    assert bound == pytest.approx(400.0)
    # The faceted sphere of the 1-degree grid lies inside the true one: within 1 - cos(1 deg).
    assert bound * math.cos(math.radians(1.0)) <= room.max_radius <= bound + 1e-6
    big = room.largest_circle()
    assert big.radius == pytest.approx(room.max_radius, rel=1e-3)
    assert np.hypot(*big.center) < 2.0


@pytest.mark.parametrize("distance", [60.0, 95.0, 150.0])
def test_tower_at_known_distance(distance: float) -> None:
    """A tower taller than the flight altitude, its face `distance` m east: MaxRadius = distance."""
    env = vt.Environment.from_buildings([(_box(distance, distance + 30, -80, 80), 400.0)])
    room = co.orbit_room(env, (0.0, 0.0, 0.0), 300.0, d_max=500.0)
    assert room.max_radius == pytest.approx(distance, abs=0.01 * distance)


def test_low_building_shadow_starts_where_the_ray_clears_its_roof() -> None:
    """A building of height H < altitude h at distance D: the ray from the point to (x, 0, h) just
    grazes the near roof edge at x = D h / H, so MaxRadius = D h / H."""
    env = vt.Environment.from_buildings([(_box(80, 100, -60, 60), 200.0)])
    room = co.orbit_room(env, (0.0, 0.0, 0.0), 300.0, d_max=500.0)
    assert room.max_radius == pytest.approx(80 * 300 / 200, rel=0.01)


def test_flyable_circle_off_centre_stays_in_the_polygon_and_sees_the_point() -> None:
    env = vt.Environment.from_buildings([(_box(60, 90, -80, 80), 400.0)])
    scene = vt.VisibilityScene(env)
    room = co.orbit_room(scene, (0.0, 0.0, 0.0), 300.0, d_max=500.0)
    assert room.flyable_circle(40.0) == co.Circle((0.0, 0.0), 40.0)  # fits about the point
    circle = room.flyable_circle(120.0)
    assert circle is not None and circle.center[0] < -55.0  # moved away from the tower
    theta = np.linspace(0, 2 * np.pi, 720, endpoint=False)
    ring = np.column_stack([circle.center[0] + 119.0 * np.cos(theta), circle.center[1] + 119.0 * np.sin(theta),
                            np.full(theta.size, 300.0)])
    g = np.zeros((theta.size, 3))
    assert scene.line_of_sight(ring, g).all()  # oracle: one ray per point of the circle
    assert room.flyable_circle(1000.0) is None


def test_cache_counts_volumes_and_snaps_points() -> None:
    env = vt.Environment.from_buildings([(_box(60, 90, -80, 80), 400.0)])
    cache = co.VolumeCache(env, d_max=500.0, grid=5.0)
    a = co.orbit_room(env, (0.4, 0.3, 0.0), 300.0, cache=cache)
    b = co.orbit_room(env, (1.1, -0.9, 0.0), 300.0, cache=cache)  # same 5 m cell
    co.orbit_room(env, (20.0, 0.0, 0.0), 300.0, cache=cache)
    assert (cache.computed, cache.lookups) == (2, 3)
    assert a.polygons[0].area == pytest.approx(b.polygons[0].area)


def test_a_point_whose_cell_lies_in_a_wall_is_cast_from_itself() -> None:
    """The cell's point (59.0 -> 60 on the 5 m grid) is inside the wall starting at x = 59.5: the VV
    is cast from the point itself (uncached), whose MaxRadius is its distance to the face behind it."""
    env = vt.Environment.from_buildings([(_box(59.5, 90, -80, 80), 400.0)])
    cache = co.VolumeCache(env, d_max=500.0, grid=5.0)
    room = co.orbit_room(env, (59.0, 0.0, 0.0), 300.0, cache=cache)
    assert room.point == (59.0, 0.0, 0.0) and cache.computed == 0
    assert room.max_radius == pytest.approx(0.5, abs=0.05)


def test_bad_input_names_the_field() -> None:
    env = vt.Environment.from_buildings([(_box(60, 90, -80, 80), 100.0)])
    refuses(lambda: co.orbit_room(env, (0.0, 0.0, -5.0), 300.0), "point z", "-5")
    refuses(lambda: co.orbit_room(env, (70.0, 0.0, 10.0), 300.0), "point", "inside a building")
    refuses(lambda: co.orbit_room(env, (0.0, 0.0, 0.0), 0.0), "altitude = 0")
    refuses(lambda: co.orbit_room(env, (0.0, 0.0), 300.0), "point")
    refuses(lambda: co.VolumeCache(env, d_max=-1.0), "d_max = -1")
    refuses(lambda: co.orbit_room(env, (0.0, 0.0, 0.0), 300.0).flyable_circle(0.0), "radius = 0")


def test_charlotte_matches_the_tracking_pipeline_and_line_of_sight(charlotte: Path) -> None:
    """On uptown Charlotte at 300 m: the helper's MaxRadius is the pipeline's (plan_on_volumes on the
    same VVs), and a brute-force ray cast agrees: a circle just inside sees the point everywhere,
    one just outside (when the polygon, not d_max, binds) somewhere not."""
    env = vt.Environment.from_mesh(charlotte / "uptown_charlotte.obj", up="y")
    scene = vt.VisibilityScene(env)
    poi = vt.PoiPath.from_csv(charlotte / "paths" / "3d.csv", speed=5.0)
    uav, sensor = vt.Uav(speed=20.0, min_turn_radius=50.0, altitude=300.0), vt.Sensor(d_max=500.0)
    arcs = np.linspace(0.0, poi.length, 12)
    points = np.array([poi.position(s / poi.speed) for s in arcs])
    points = np.asarray(scene.poi_on_surface(points))
    volumes = vt.visibility_volumes(scene, points, sensor.d_max)
    plan = vt.plan_on_volumes(poi, uav, vt.Planning(), list(arcs), volumes)
    bound = co.slice_radius_bound(0.0, 300.0, sensor.d_max)
    below_bound = 0
    for k, point in enumerate(points):
        room = co.orbit_room(scene, point, uav.altitude, d_max=sensor.d_max)
        assert room.max_radius == pytest.approx(plan.max_radii[k], abs=1e-6)
        if room.max_radius < 5.0:
            continue
        theta = np.linspace(0, 2 * np.pi, 1440, endpoint=False)
        for factor, expect_all in ((0.97, True), (1.05, False)):
            r = factor * room.max_radius
            if not expect_all and r > 0.98 * bound:
                continue
            ring = np.column_stack([point[0] + r * np.cos(theta), point[1] + r * np.sin(theta),
                                    np.full(theta.size, uav.altitude)])
            seen = scene.line_of_sight(ring, np.repeat(point[None], theta.size, 0))
            if expect_all:
                assert seen.mean() >= 0.995, (k, room.max_radius, seen.mean())
            else:
                below_bound += 1
                assert not seen.all(), (k, room.max_radius)
    assert below_bound >= 3  # the buildings, not d_max, bound most of these points
