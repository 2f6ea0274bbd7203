"""The degenerate-geometry suite: the POI on a building's edge, corner and roof, on a wall,
inside a building, under an overhang and in a closed room (no visible direction out); zero-length
path edges and coincident waypoints; v_g equal to v; d_max that never reaches the flight plane.
Each case either gives a finite answer that an independent method confirms (a Monte Carlo
estimate by line of sight, or the analytic volume), or a VistrackError naming the field. The 10^6
random Dubins, path-to-circle and intercept cases are tests/cpp/limits_test.cpp (RandomCases)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.refusal import refuses

D_MAX = 100.0
SPHERE = 4.0 / 3.0 * math.pi * D_MAX**3

pytestmark = pytest.mark.sanitize  # the input-facing surface (scripts/sanitize.sh)


def boxes_obj(path: Path, boxes: list[tuple[tuple[float, ...], tuple[float, ...]]],
              hollow: tuple[tuple[float, ...], tuple[float, ...]] | None = None) -> Path:
    """Closed axis-aligned boxes as an OBJ mesh (outward faces); ``hollow`` adds a box with inward
    faces: a room carved out of the box around it."""
    vertices: list[tuple[float, float, float]] = []
    faces: list[tuple[int, int, int]] = []
    quads = ((0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5))
    for (lo, hi), inward in [(b, False) for b in boxes] + ([(hollow, True)] if hollow else []):
        base = len(vertices) + 1
        vertices += [tuple(hi[i] if (k >> i) & 1 else lo[i] for i in range(3)) for k in range(8)]  # type: ignore[misc]
        for a, b, c, d in quads:
            for tri in ((a, b, c), (a, c, d)):
                faces.append(tuple(base + i for i in (tri[::-1] if inward else tri)))  # type: ignore[arg-type]
    path.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in vertices)
                    + "".join(f"f {a} {b} {c}\n" for a, b, c in faces))
    return path


@pytest.fixture(scope="module")
def block(tmp_path_factory: pytest.TempPathFactory) -> vt.Environment:
    """One 20 x 40 x 30 m building on x in [40, 60], y in [-20, 20]."""
    path = tmp_path_factory.mktemp("block") / "block.geojson"
    ring = [[40, -20], [60, -20], [60, 20], [40, 20], [40, -20]]
    path.write_text(json.dumps({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"height": 30}, "geometry": {"type": "Polygon", "coordinates": [ring]}}]}))
    return vt.Environment.from_geojson(path)


def visible_fraction_by_line_of_sight(env: vt.Environment, g: tuple[float, float, float], n: int = 40000) -> float:
    """Share of the d_max ball around g that g sees, by line of sight to uniform random points:
    an estimate of V / (4/3 pi d^3) independent of the VV's ray grid and mesh."""
    rng = np.random.default_rng(7)
    directions = rng.normal(size=(n, 3))
    directions /= np.linalg.norm(directions, axis=1)[:, None]
    points = np.asarray(g) + directions * (D_MAX * rng.random(n) ** (1.0 / 3.0))[:, None]
    above = points[:, 2] > 0.0  # the ground hides everything under it
    seen = np.zeros(n, dtype=bool)
    starts = np.repeat(np.asarray(g, dtype=float)[None, :], int(above.sum()), axis=0)
    seen[above] = vt.visibility_scene(env).line_of_sight(starts, points[above])
    return float(seen.mean())


@pytest.mark.parametrize("where, g, low, high", [
    # On the building's vertical edge at (40, 20): the building's quarter of the upper half is hidden.
    ("vertical edge", (40.0, 20.0, 0.5), 0.375, 0.40),
    # On a wall: the half-space in front of it, above the ground (10 m below: a cap of 0.425 hidden).
    ("wall", (40.0, 0.0, 10.0), 0.2875, 0.30),
    # On the roof: the whole upper half, and a little past the roof's edges.
    ("roof", (50.0, 0.0, 30.0), 0.50, 0.52),
    # On the roof's corner: the upper half and three quarters of what lies below the roof.
    ("roof corner", (40.0, 20.0, 30.0), 0.60, 0.72),
])
def test_poi_on_a_building(block: vt.Environment, where: str, g: tuple[float, float, float],
                           low: float, high: float) -> None:
    volume = vt.visibility_volume(block, g, D_MAX, resolution_deg=1.0)
    share = volume.volume / SPHERE
    assert low <= share <= high, (where, share)
    estimate = visible_fraction_by_line_of_sight(block, g)
    assert share == pytest.approx(estimate, rel=0.025), (where, share, estimate)
    assert np.all(np.isfinite(np.asarray(volume.vertices)))


def test_poi_inside_a_building_or_under_the_ground_is_refused(block: vt.Environment) -> None:
    refuses(lambda: vt.visibility_volume(block, (50.0, 0.0, 10.0), D_MAX), "g = (50, 0, 10)", "inside an obstacle")
    refuses(lambda: vt.visibility_volume(block, (0.0, 0.0, -1.0), D_MAX), "g[2] = -1", "below the ground")


def test_poi_under_an_overhang(tmp_path: Path) -> None:
    """A 20 x 20 m slab 10-12 m up on two pillars: the POI under it sees out sideways only."""
    env = vt.Environment.from_mesh(boxes_obj(tmp_path / "overhang.obj", [
        ((-10, -10, 10), (10, 10, 12)), ((-10, -10, 0), (-9, -9, 10)), ((9, 9, 0), (10, 10, 10))]))
    g = (0.0, 0.0, 0.5)
    volume = vt.visibility_volume(env, g, D_MAX, resolution_deg=1.0)
    share = volume.volume / SPHERE
    open_field = vt.visibility_volume(vt.Environment.from_mesh(boxes_obj(tmp_path / "far.obj", [
        ((500, 500, 0), (501, 501, 1))])), g, D_MAX, resolution_deg=1.0).volume / SPHERE
    assert share < open_field - 0.1  # the slab hides the sky above 43.5 degrees of elevation
    assert share == pytest.approx(visible_fraction_by_line_of_sight(env, g), rel=0.025)
    # Nothing straight above is seen, while the same height beyond the slab's edge is.
    scene = vt.visibility_scene(env)
    seen = scene.line_of_sight(np.array([g, g]), np.array([[0.0, 0.0, 50.0], [60.0, 0.0, 20.0]]))
    assert list(seen) == [False, True]


def test_a_closed_room_has_no_visible_direction_out(tmp_path: Path) -> None:
    """A POI in a closed 18 x 18 x 8 m room: its VV is the room, and no slice above it has a
    polygon, so MaxRadius there is 0. (A POI *path* through the room stands on its roof: the
    planner reads a path's z as the height above the topmost surface, VisibilityScene.poi_on_surface.)"""
    env = vt.Environment.from_mesh(boxes_obj(tmp_path / "room.obj", [((-10, -10, 0), (10, 10, 10))],
                                             hollow=((-9, -9, 1), (9, 9, 9))))
    volume = vt.visibility_volume(env, (0.0, 0.0, 5.0), D_MAX, resolution_deg=1.0)
    assert volume.volume == pytest.approx(18 * 18 * 8, rel=0.005)
    assert volume.slice(50.0) == []
    assert len(volume.slice(5.0)) == 1
    assert vt.max_inscribed_radius(volume.slice(50.0), (0.0, 0.0)) == 0.0


def test_a_courtyard_shows_a_patch_of_sky_too_small_to_orbit(tmp_path: Path) -> None:
    """A 4 x 4 m courtyard at the bottom of a 100 m block: at h = 120 m the POI sees the opening
    projected from itself, (h - z) / (100 - z) times its size, so MaxRadius is analytic; no orbit
    fits (Lemma 6), and the plan says so instead of returning a radius."""
    outer = [[-50, -50], [50, -50], [50, 50], [-50, 50], [-50, -50]]
    hole = [[-2, -2], [-2, 2], [2, 2], [2, -2], [-2, -2]]
    path = tmp_path / "courtyard.geojson"
    path.write_text(json.dumps({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {
        "height": 100}, "geometry": {"type": "Polygon", "coordinates": [outer, hole]}}]}))
    env = vt.Environment.from_geojson(path)
    poi = vt.PoiPath(np.array([[-1.0, 0.0, 0.5], [1.0, 0.0, 0.5]]), 0.5)
    scale = (120.0 - 0.5) / (100.0 - 0.5)
    for locus in ("smooth", "paper"):
        plan = vt.plan_orbits(env, poi, vt.Uav(speed=20.0, min_turn_radius=10.0, altitude=120.0),
                              vt.Sensor(d_max=300.0), vt.Planning(spacing=1.0, resolution_deg=1.0, locus=locus))
        x = np.asarray(plan.centers)[:, 0]
        # The opening seen from x: [x + (-2 - x) scale, x + (2 - x) scale]; the nearer edge decides.
        expected = np.minimum(x - (x + (-2.0 - x) * scale), (x + (2.0 - x) * scale) - x)
        assert np.allclose(plan.max_radii, expected, rtol=0.02), (plan.max_radii, expected)
        assert not plan.feasible and "Lemma 6" in plan.infeasibility
        assert np.all(np.isfinite(plan.radii))


def test_zero_length_path_edges_change_nothing() -> None:
    """Repeated waypoints add zero-length edges: the path, its timing and its plan are those of
    the path without them."""
    once = np.array([[-290.0, -210.0], [-230.0, -210.0], [-230.0, -150.0]])
    twice = np.array([once[0], once[0], once[1], once[1], once[1], once[2], once[2]])
    a, b = vt.PoiPath(once, 5.0), vt.PoiPath(twice, 5.0)
    assert b.length == pytest.approx(a.length) and b.duration == pytest.approx(a.duration)
    for t in np.linspace(0.0, a.duration, 41):
        assert np.allclose(b.position(t), a.position(t))
        assert np.all(np.isfinite(b.velocity(t))) and np.linalg.norm(b.velocity(t)) == pytest.approx(5.0)
    env = vt.Environment.demo()
    args = (vt.Uav(altitude=200.0), vt.Sensor(d_max=300.0), vt.Planning(spacing=30.0, resolution_deg=10.0))
    plan_a, plan_b = vt.plan_orbits(env, a, *args), vt.plan_orbits(env, b, *args)
    assert np.allclose(plan_a.radii, plan_b.radii) and np.allclose(plan_a.times, plan_b.times)


def test_coincident_waypoints() -> None:
    refuses(lambda: vt.PoiPath(np.array([[1.0, 1.0], [1.0, 1.0]]), 5.0), "waypoints = 1", "two distinct points")
    # DWN: a repeated waypoint has no leg to fly; the index is the route's.
    refuses(lambda: vt.waypoint_nav.fly(np.array([[0.0, 0.0], [100.0, 0.0], [100.0, 0.0], [100.0, 100.0]]),
                                        turn_radius=10.0, speed=16.0),
            "waypoints[2] = (100, 0)", "waypoints[1]")
    refuses(lambda: vt.waypoint_nav.fly(np.array([[0.0, 0.0], [0.0, 0.0], [100.0, 0.0]]), turn_radius=10.0),
            "waypoints[1] = (0, 0)", "no heading")
    # Given a start, the first waypoint may be where the UAV starts.
    flight = vt.waypoint_nav.fly(np.array([[0.0, 0.0], [100.0, 0.0]]), start=(0.0, 0.0, 0.0), turn_radius=10.0,
                                 speed=16.0)
    assert flight.all_reached
    # Loiter: two AOIs at one place share one loiter circle, which the planners refuse.
    for method in ("fly_through", "tlpp", "ldlpp"):
        refuses(lambda m=method: vt.loiter.plan(np.array([[300.0, 0.0], [300.0, 0.0]]), m),
                "aois[1] = (300, 0)", "overlaps that of aois[0]")


def test_uav_no_faster_than_the_poi() -> None:
    env = vt.Environment.demo()
    poi = vt.PoiPath(np.array([[-290.0, -210.0], [-230.0, -210.0]]), 20.0)
    refuses(lambda: vt.plan_orbits(env, poi, vt.Uav(speed=20.0, altitude=200.0), vt.Sensor(d_max=300.0),
                                   vt.Planning(spacing=30.0, resolution_deg=10.0)),
            "uav.speed = 20", "must exceed the POI speed 20")
    refuses(lambda: vt.constant_radius_plan(poi, 60.0, vt.Uav(speed=20.0)), "uav.speed = 20")
    F = vt.follow
    truck = F.GroundVehicle.from_legs([F.VehicleLeg(heading=0.0, speed=10.0, duration=60.0)], (0.0, 0.0))
    # The orbit baseline needs v > v_g (Lemma 5) ...
    refuses(lambda: F.baseline(truck, vt.Uav(speed=10.0, min_turn_radius=40.0, altitude=100.0), 100.0),
            "uav.speed = 10", "must exceed the vehicle's top speed 10", "(Lemma 5)")
    # ... while the follow planner has a mode for a vehicle faster than the UAV (sigma < 1: straight
    # at the offset point, the lag reported; test_follow.py), so a slower UAV is a situation there.
    slow = F.simulate(truck, vt.Uav(speed=9.0, min_turn_radius=40.0, altitude=100.0))
    assert slow.metrics["final_along_track_lag_m"] == pytest.approx(60.0, rel=0.01)
    # v = v_g is the sinusoid's limit (sigma = 1): a straight line over the vehicle, no lag.
    same = F.simulate(truck, vt.Uav(speed=10.0, min_turn_radius=40.0, altitude=100.0))
    assert abs(same.metrics["max_along_track_lag_m"]) < 1e-6


def test_d_max_that_never_reaches_the_flight_plane() -> None:
    """A sensor whose range is shorter than the flight plane's height above the POI, or a band
    that excludes the plane, sees nothing there: every MaxRadius is 0 and the plan says why."""
    env = vt.Environment.demo()
    poi = vt.PoiPath(np.array([[-290.0, -210.0, 0.5], [-230.0, -210.0, 0.5]]), 5.0)
    planning = vt.Planning(spacing=30.0, resolution_deg=10.0)
    for sensor in (vt.Sensor(d_max=199.0), vt.Sensor(d_max=300.0, altitude_band=(20.0, 150.0))):
        plan = vt.plan_orbits(env, poi, vt.Uav(altitude=200.0), sensor, planning)
        assert not plan.feasible and "not visible from that altitude" in plan.infeasibility
        assert np.all(np.asarray(plan.max_radii) == 0.0) and np.all(np.isfinite(plan.radii))
    # 50 m more range than the height reaches the plane: a disk of MaxRadius > 0.
    reach = vt.plan_orbits(env, poi, vt.Uav(altitude=200.0), vt.Sensor(d_max=250.0), planning)
    assert min(reach.max_radii) > 0.0
