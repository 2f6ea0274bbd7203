"""Visibility volumes, line of sight and visibility polygons through the Python API."""

from __future__ import annotations

import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.meshes import box
from support.refusal import refuses
from vistrack import cli
from vistrack.visibility import polygon_agreement, reference_rays, reference_volume


@pytest.fixture(scope="module")
def box_env() -> vt.Environment:
    return vt.Environment.from_triangles(*box((40, -20, 0), (60, 20, 30)))


@pytest.fixture(scope="module")
def open_field() -> vt.Environment:
    return vt.Environment.from_triangles(*box((5000, 5000, 0), (5010, 5010, 5)))


def segment_hits_box(p, q, lo, hi) -> bool:
    t0, t1 = 0.0, 1.0
    for k in range(3):
        d = q[k] - p[k]
        if d == 0.0:
            if p[k] < lo[k] or p[k] > hi[k]:
                return False
            continue
        a, c = sorted(((lo[k] - p[k]) / d, (hi[k] - p[k]) / d))
        t0, t1 = max(t0, a), min(t1, c)
        if t0 > t1:
            return False
    return True


def test_open_field_volume_is_the_cut_ball(open_field):
    r = 400.0
    vv = vt.visibility_volume(open_field, (0.0, 0.0, 0.0), r)
    assert vv.volume == pytest.approx(2.0 / 3.0 * np.pi * r**3, rel=0.005)
    # The trapezoid rule gives the half row below the horizon the horizon's d_max: 0.9 % more.
    assert vv.grid_volume() == pytest.approx(2.0 / 3.0 * np.pi * r**3, rel=0.01)
    lo, hi = 50.0, 200.0
    banded = vt.visibility_volume(open_field, (0.0, 0.0, 0.0), r, altitude_band=(lo, hi))
    exact = np.pi * ((r * r * hi - hi**3 / 3) - (r * r * lo - lo**3 / 3))
    assert banded.volume == pytest.approx(exact, rel=0.005)
    assert banded.vertices[:, 2].min() >= lo - 1e-9 and banded.vertices[:, 2].max() <= hi + 1e-9
    assert banded.check().valid
    assert vv.near.shape == (vv.grid.num_elevation + 1, vv.grid.num_azimuth)
    assert vv.faces.dtype == np.int32 and vv.vertices.shape[1] == 3


def test_scene_is_reused_and_batch_matches_single(box_env):
    scene = vt.visibility_scene(box_env)
    assert vt.visibility_scene(box_env).fingerprint == scene.fingerprint == box_env.fingerprint
    assert vt.visibility_scene(scene) is scene
    pois = np.array([[0.0, 0.0, 0.0], [10.0, 50.0, 0.0], [-30.0, -30.0, 2.0]])
    batch = vt.visibility_volumes(scene, pois, 150.0, (10.0, 80.0), 2.0)
    for poi, vv in zip(pois, batch):
        one = vt.visibility_volume(box_env, poi, 150.0, (10.0, 80.0), 2.0)
        assert one.volume == vv.volume
        np.testing.assert_array_equal(one.far, vv.far)
        np.testing.assert_array_equal(one.poi, poi)


def test_box_polygon_and_max_radius(box_env):
    vv = vt.visibility_volume(box_env, (0.0, 0.0, 0.0), 200.0, resolution_deg=0.5)
    assert vv.check().valid
    # Below the roof the wall x = 40 is nearest; above it the shadow starts at x = 40 h / 30.
    assert vt.max_inscribed_radius(vv.slice(20.0), (0.0, 0.0)) == pytest.approx(40.0, abs=1e-3)
    radius = vt.max_inscribed_radius(vv.slice(60.0), (0.0, 0.0))
    assert radius == pytest.approx(80.0, abs=80.0 * np.radians(0.5))
    polygons = vv.slice(60.0)
    assert len(polygons) == 1 and isinstance(polygons[0], vt.Polygon)
    # Brute force on a coarse grid: the VP matches exact segment-box tests.
    both = either = 0
    for x in np.arange(-200.0, 200.0, 4.0):
        for y in np.arange(-200.0, 200.0, 4.0):
            p = np.array([x + 0.3, y + 0.7, 60.0])
            truth = np.linalg.norm(p) <= 200.0 and not segment_hits_box((0, 0, 0), p, (40, -20, 0), (60, 20, 30))
            ours = polygons[0].contains(p[:2])
            both += truth and ours
            either += truth or ours
    assert both / either >= 0.99


def test_line_of_sight_matches_exact_test(box_env):
    rng = np.random.default_rng(5)
    a = np.column_stack([rng.uniform(-100, 100, 3000), rng.uniform(-100, 100, 3000), rng.uniform(0, 60, 3000)])
    b = np.column_stack([rng.uniform(-100, 100, 3000), rng.uniform(-100, 100, 3000), rng.uniform(0, 60, 3000)])
    def inside(p):
        return (p >= (40 - 0.01, -20 - 0.01, -1)).all() and (p <= (60.01, 20.01, 30.01)).all()
    keep = np.array([not inside(p) and not inside(q) for p, q in zip(a, b)])
    visible = box_env.line_of_sight(a[keep], b[keep])
    assert visible.dtype == bool
    truth = np.array([not segment_hits_box(p, q, (40, -20, 0), (60, 20, 30)) for p, q in zip(a[keep], b[keep])])
    assert (visible != truth).sum() <= 2  # grazing edges within float precision
    assert 0.2 < visible.mean() < 0.95
    scene = vt.visibility_scene(box_env)
    np.testing.assert_array_equal(scene.line_of_sight(b[keep], a[keep]), visible)
    with pytest.raises(vt.VistrackError, match=r"b\.rows"):
        box_env.line_of_sight(a[:3], b[:2])


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"g": (50.0, 0.0, 10.0), "d_max": 100.0}, "inside an obstacle"),
        ({"g": (0.0, 0.0, -1.0), "d_max": 100.0}, r"g\[2\]"),
        ({"g": (0.0, np.nan, 0.0), "d_max": 100.0}, r"g\[1\]"),
        ({"g": (0.0, 0.0, 0.0), "d_max": 0.0}, "d_max"),
        ({"g": (0.0, 0.0, 0.0), "d_max": np.nan}, "d_max"),
        ({"g": (0.0, 0.0, 0.0), "d_max": 100.0, "altitude_band": (60.0, 20.0)}, "altitude_band"),
        ({"g": (0.0, 0.0, 0.0), "d_max": 100.0, "resolution_deg": 0.0}, "resolution_deg"),
        ({"g": (0.0, 0.0), "d_max": 100.0}, "g must have 3"),
    ],
)
def test_bad_input_names_the_field(box_env, kwargs, field):
    with pytest.raises(vt.VistrackError, match=field):
        vt.visibility_volume(box_env, **kwargs)


def test_batch_errors_name_the_row(box_env):
    with pytest.raises(vt.VistrackError, match=r"pois\[1\]"):
        vt.visibility_volumes(box_env, np.array([[0.0, 0.0, 0.0], [50.0, 0.0, 5.0]]), 100.0)
    with pytest.raises(vt.VistrackError, match="pois"):
        vt.visibility_volumes(box_env, np.zeros((3, 2)), 100.0)


def test_vv_memory_is_estimated_from_above(charlotte):
    # What visibility_volumes and the planner's work estimate budget per VV (test_work_estimates: the refusals).
    env = vt.Environment.from_mesh(str(charlotte / "uptown_charlotte.obj"), up="y")
    scene = vt.visibility_scene(env)
    poi = vt.PoiPath.from_csv(str(charlotte / "paths" / "paper_slow.csv"), speed=5.0)
    for res in (5.0, 2.0, 1.0):
        for t in np.linspace(0.0, poi.duration, 4):
            vv = vt.visibility_volume(scene, poi.position(t), 400.0, None, res)  # a ground POI: the most walls
            held = (vv.vertices.nbytes + vv.faces.nbytes + vv.near.nbytes + vv.far.nbytes
                    + 4 * len(vv.mesh_triangle_faces) + 8 * len(vv.mesh_row_sines))
            assert held <= vt.volume_bytes(res), (res, t, held, vt.volume_bytes(res))
            bare = vt.visibility_volume(scene, poi.position(t), 400.0, None, res, with_mesh=False)
            assert bare.near.nbytes + bare.far.nbytes <= vt.volume_bytes(res, with_mesh=False) < held


def test_save_round_trip(open_field, tmp_path: Path):
    vv = vt.visibility_volume(open_field, (0.0, 0.0, 0.0), 100.0, resolution_deg=10.0)
    for name in ("vv.obj", "vv.ply"):
        vv.save(str(tmp_path / name))
        back = vt.Environment.from_mesh(str(tmp_path / name))
        assert back.num_triangles == len(vv.faces)
        assert vt.mesh_volume(back.vertices, back.faces) == pytest.approx(vv.volume, rel=1e-6)
    with pytest.raises(vt.VistrackError, match="path"):
        vv.save(str(tmp_path / "vv.stl"))


def test_long_calls_release_the_gil(open_field):
    from support.threads import ticks_during

    scene = vt.visibility_scene(open_field)
    pois = np.zeros((24, 3))
    ticks, seconds = ticks_during(lambda: vt.visibility_volumes(scene, pois, 300.0, None, 1.0))
    assert seconds > 0.02 and ticks >= 3, (ticks, seconds)


def test_charlotte_volumes_are_valid_and_converge(charlotte):
    env = vt.Environment.from_mesh(str(charlotte / "uptown_charlotte.obj"), up="y")
    scene = vt.visibility_scene(env)
    poi = vt.PoiPath.from_csv(str(charlotte / "paths" / "paper_slow.csv"), speed=5.0)
    rng = np.random.default_rng(3)
    pois = np.array([poi.position(t) for t in rng.uniform(0.0, poi.duration, 8)])
    for vv in vt.visibility_volumes(scene, pois, 400.0, (60.0, 300.0), 3.0):
        check = vv.check()
        assert check.valid, check.problem
        assert vv.volume == pytest.approx(check.volume, rel=1e-9)
    volumes = [vt.visibility_volume(scene, pois[0], 400.0, None, res).volume for res in (4.0, 2.0, 1.0, 0.5)]
    assert abs(volumes[3] - volumes[2]) < abs(volumes[1] - volumes[0])
    # The VP at 300 m contains the POI's vertical and gives a positive MaxRadius.
    vv = vt.visibility_volume(scene, pois[0], 400.0, None, 1.0)
    assert vt.max_inscribed_radius(vv.slice(300.0), pois[0][:2]) > 0.0


def test_cli_volumes_writes_results(charlotte, tmp_path: Path):
    import json

    from vistrack.cli import main

    out = tmp_path / "vols"
    code = main([
        "volumes", "--map", str(charlotte / "buildings.geojson"), "--points=-150,-45;-50,45,0.5",
        "--d-max", "300", "--altitude", "50", "--resolution", "3", "--out", str(out), "--check", "--quiet",
    ])
    assert code == 0
    summary = json.loads((out / "volumes.json").read_text())
    assert len(summary["points"]) == 2
    for record in summary["points"]:
        assert record["mesh_valid"], record["mesh_problem"]
        assert record["poi"][2] == pytest.approx(0.5)
        assert record["max_radius"] > 0.0
        assert (out / record["mesh"]).is_file()
        # MaxRadius is the distance from the POI to the nearest ring of its VP.
        polygon = vt.Polygon(np.array(record["visibility_polygon"][0]["outer"]),
                             [np.array(h) for h in record["visibility_polygon"][0]["holes"]])
        assert polygon.distance_to_boundary(np.array(record["poi"][:2])) == pytest.approx(record["max_radius"])
    assert (out / "plan.png").stat().st_size > 10_000 and (out / "vv3d.png").stat().st_size > 10_000
    assert main(["volumes", "--map", str(tmp_path / "missing.geojson"), "--points", "0,0", "--out", str(out)]) == 1
    assert main(["volumes", "--map", str(charlotte / "buildings.geojson"), "--points", "a,b", "--out", str(out)]) == 2


def test_standalone_vistrack_vv_matches_python(charlotte, tmp_path):
    """vistrack_vv (no Python) gives the same VV volume and MaxRadius as the bindings."""
    import json
    import subprocess

    from support.build_tree import standalone_executable

    exe = standalone_executable("vistrack_vv")
    if exe is None:
        pytest.skip("vistrack_vv not built (set VISTRACK_BUILD_DIR or install the package)")
    city = charlotte / "buildings.geojson"
    done = subprocess.run([str(exe), "--map", str(city), "--points", "-150,-45,0.5;-45,430,0.5", "--d-max", "400",
                           "--altitude", "300", "--out", str(tmp_path), "--no-meshes"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    points = json.loads((tmp_path / "volumes.json").read_text())["points"]
    scene = vt.VisibilityScene(vt.Environment.from_geojson(str(city)))
    for row in points:
        vv = vt.visibility_volume(scene, np.asarray(row["poi"]), 400.0)
        assert row["volume"] == pytest.approx(vv.volume, rel=1e-12)
        expected = vt.max_inscribed_radius(vv.slice(300.0), np.asarray(row["poi"])[:2])
        assert row["max_radius"] == pytest.approx(expected, rel=1e-9)
    assert points[0]["max_radius"] == pytest.approx(180.0, abs=0.5)  # exact MaxRadius, paper example 1
    bad = subprocess.run([str(exe), "--map", str(tmp_path / "missing.geojson"), "--points", "0,0"],
                         capture_output=True, text=True, timeout=60)
    assert bad.returncode != 0 and "missing.geojson" in bad.stderr


@pytest.fixture(scope="module")
def charlotte_scene(charlotte):
    env = vt.Environment.from_mesh(str(charlotte / "uptown_charlotte.obj"), up="y")
    return vt.visibility_scene(env)


def path_pois(scene, csv, times):
    poi = vt.PoiPath.from_csv(str(csv), speed=5.0)
    return np.array([np.ravel(scene.poi_on_surface(np.ravel(poi.position(t)))) for t in times]), poi


def test_charlotte_mesh_holds_the_volume_of_a_fine_grid(charlotte, charlotte_scene):
    """The 1-degree mesh (corner rays, walls at the silhouettes) against the per-direction
    volume of a 0.2-degree grid (brute force, reference_volume): within 0.2 % (measured <= 0.05 %;
    the corner mesh without walls held 0.2-2.4 % less); the grid's trapezoid rule within 0.5 %."""
    pois, _ = path_pois(charlotte_scene, charlotte / "paths" / "paper_slow.csv", [0.0, 20.0, 45.0])
    for g in pois:
        reference = reference_volume(charlotte_scene, g, 400.0)
        vv = vt.visibility_volume(charlotte_scene, g, 400.0, None, 1.0)
        assert vv.volume == pytest.approx(reference, rel=2e-3), g
        assert vv.grid_volume() == pytest.approx(reference, rel=5e-3), g


@pytest.mark.parametrize(
    ("name", "d_max", "points", "bound"),
    [
        # measured <= 0.041 %: bench/vv_error_sources.py --path paper_slow --d-max 400 --points 20
        ("paper_slow", 400.0, 20, 5e-4),
        # issue 35's bound at bench/accuracy.py's 10 POIs: measured <= 0.087 % (0.110 % before
        # edges were split at the buildings' feet)
        ("paper_small", 100.0, 10, 1.1e-3),
    ],
)
def test_charlotte_mesh_meets_the_fine_grid_volume(charlotte, charlotte_scene, name, d_max, points, bound):
    """The accuracy bounds: the 1-degree mesh volume within 0.05 % (d_max 400 m) and 0.11 % (d_max
    100 m) of the per-direction volume of a 0.2-degree grid (brute force, reference_volume) at POIs
    evenly spaced in time along the path."""
    path = vt.PoiPath.from_csv(str(charlotte / "paths" / f"{name}.csv"), speed=5.0)
    pois, _ = path_pois(charlotte_scene, charlotte / "paths" / f"{name}.csv", np.linspace(0.0, path.duration, points))
    for g in pois:
        reference = reference_volume(charlotte_scene, g, d_max)
        volume = vt.visibility_volume(charlotte_scene, g, d_max, None, 1.0).volume
        assert abs(volume / reference - 1) <= bound, (g, volume / reference - 1)


def test_mesh_bends_at_a_buildings_foot(box_env):
    """Seen from 0.5 m above the ground, r = min(ground, wall) bends where the box's wall meets the
    ground (elevation -0.72 degrees at 40 m). The mesh has vertices on that foot line, and in the
    directions around it (elevations -2..0 degrees, azimuths -20..20) it holds the volume of a
    0.1-degree brute-force grid to 0.1 % (without the vertices at the foot the mesh cut the corner
    between ground and wall: this assertion fails on such a build, with 17 % less)."""
    scene = vt.visibility_scene(box_env)
    g = np.array([0.0, 0.0, 0.5])
    vv = vt.visibility_volume(scene, g, 100.0, None, 1.0)
    # The mesh's volume per direction (whole mesh rows and columns bound the region, and every face
    # stays inside its grid slot) against the reference's cones there.
    rays = reference_rays(scene, g, 100.0, 0.1)
    elevation = np.degrees(np.arcsin(rays.directions[:, 2]))
    azimuth = np.degrees(np.arctan2(rays.directions[:, 1], rays.directions[:, 0]))
    inside = (elevation > -2.0) & (elevation < 0.0) & (np.abs(azimuth) < 20.0)
    reference = np.sum(rays.solid_angles[inside] * rays.distances[inside] ** 3) / 3.0
    mesh = rays.mesh_volumes(vv)
    assert mesh.sum() == pytest.approx(vv.volume, rel=1e-12)  # every face lands in some cell
    assert mesh[inside].sum() == pytest.approx(reference, rel=1e-3)
    vertices = np.asarray(vv.vertices)
    foot = (vertices[:, 2] == 0.0) & (np.abs(vertices[:, 0] - 40.0) < 1e-6) & (np.abs(vertices[:, 1]) <= 20.0)
    assert foot.sum() >= 20  # the wall spans 53 columns


def test_reference_rays_cover_the_sphere(open_field):
    """reference_rays: unit directions whose cells tile the sphere, distances within [0, d_max],
    their cones the reference volume; in an open field 150 m up they hold the ball of d_max to
    0.01 % (sampled, not interpolated: no chord deficit)."""
    scene = vt.visibility_scene(open_field)
    g = np.array([0.0, 0.0, 150.0])
    rays = reference_rays(scene, g, 100.0, 1.0)
    assert rays.directions.shape == (rays.num_elevation * rays.num_azimuth, 3)
    assert np.allclose(np.linalg.norm(rays.directions, axis=1), 1.0)
    assert rays.solid_angles.sum() == pytest.approx(4.0 * np.pi, rel=1e-12)
    assert np.all((rays.distances >= 0.0) & (rays.distances <= 100.0))
    # The cells in the grid's row-major order: reference_volume is the grid's rows' cones.
    grid = vt.DirectionGrid.from_resolution(1.0)
    rows = rays.distances.reshape(rays.num_elevation, rays.num_azimuth) ** 3 / 3.0
    by_rows = sum(grid.solid_angle(i) * rows[i].sum() for i in range(grid.num_elevation))
    assert reference_volume(scene, g, 100.0, 1.0) == pytest.approx(by_rows, rel=1e-12)
    assert rays.volume == reference_volume(scene, g, 100.0, 1.0)
    assert rays.volume == pytest.approx(4.0 / 3.0 * np.pi * 100.0**3, rel=1e-4)
    # Near the ground the downward rays end on it: the cut ball.
    low = reference_rays(scene, np.array([0.0, 0.0, 30.0]), 100.0, 0.5)
    cap = np.pi * 70.0**2 * (3 * 100.0 - 70.0) / 3
    assert low.volume == pytest.approx(4.0 / 3.0 * np.pi * 100.0**3 - cap, rel=2e-3)


def test_low_altitude_vp_matches_line_of_sight(charlotte, charlotte_scene):
    """VPs cut from 1-degree VVs at 20 and 50 m (paper_small's d_max 100 m) against line-of-sight
    queries on a 1 m lattice: IoU >= 0.99 (measured 0.9968-0.9997 by bench/accuracy.py)."""
    pois, _poi = path_pois(charlotte_scene, charlotte / "paths" / "paper_small.csv", [0.0, 25.0, 50.0, 75.0])
    for g in pois:
        vv = vt.visibility_volume(charlotte_scene, g, 100.0, None, 1.0)
        for h in (20.0, 50.0):
            iou = polygon_agreement(charlotte_scene, vv, h)
            assert iou >= 0.99, (g, h, iou)


def test_intervals_lie_on_the_grid_corners(box_env):
    """near/far are sampled at the grid's corners: corner(i, j) at elevation -pi/2 + i d_el and
    azimuth j d_az, the poles repeated; brute-force first hits along those rays give the same far."""
    grid = vt.DirectionGrid.from_resolution(2.0)
    ne, na = grid.num_elevation, grid.num_azimuth
    assert grid.num_corners == (ne + 1) * na
    for i, j in [(1, 0), (7, 100), (45, 3), (89, 179)]:
        d = np.ravel(grid.corner(i, j))
        assert d[2] == pytest.approx(np.sin(-np.pi / 2 + i * np.pi / ne), abs=1e-12)
        assert np.mod(np.arctan2(d[1], d[0]), 2 * np.pi) == pytest.approx(j * 2 * np.pi / na, abs=1e-12)
    assert sum(grid.corner_weight(i) for i in range(ne + 1)) * na == pytest.approx(4 * np.pi, rel=1e-12)
    with pytest.raises(vt.VistrackError, match="row"):
        grid.corner(ne + 1, 0)
    scene = vt.visibility_scene(box_env)
    g = np.array([0.0, 0.0, 2.0])
    vv = vt.visibility_volume(scene, g, 150.0, None, 2.0)
    assert np.mean(np.abs(traced_far(scene, g, grid, 150.0) - vv.far.ravel()) < 1e-3) >= 0.997


def traced_far(scene, g, grid, d_max):
    """far at every corner of `grid` (row-major, as VisibilityVolume.far) by Embree tracing each
    corner's ray (first_hits) and the exact ground plane, for a POI in the band."""
    ne, na = grid.num_elevation, grid.num_azimuth
    dirs = np.array([np.ravel(grid.corner(i, j)) for i in range(ne + 1) for j in range(na)])
    far = np.minimum(np.asarray(scene.first_hits(g, dirs, d_max)).ravel(), d_max)
    down = dirs[:, 2] < 0
    far[down] = np.minimum(far[down], (scene.ground_level - g[2]) / dirs[down, 2])
    return far


@pytest.mark.parametrize(("path", "d_max"), [("paper_slow", 400.0), ("paper_small", 100.0)])
def test_corner_hits_match_traced_rays_on_charlotte(charlotte, charlotte_scene, path, d_max):
    """The corner rays' first hits come from per-triangle tests (a z-buffer on the sphere,
    corner_hits.cpp), not from Embree: on Charlotte every corner's far agrees with Embree tracing
    the same direction (first_hits) to 1 mm (they differ by float rounding only). A missed
    triangle, a wrong nearest or a column lost where a footprint wraps past azimuth 0 would put
    whole buildings out (scanning only the first of a footprint's two column runs fails here by
    375 m)."""
    pois, _poi = path_pois(charlotte_scene, charlotte / "paths" / f"{path}.csv", [0.0, 40.0])
    for g in pois:
        vv = vt.visibility_volume(charlotte_scene, g, d_max, None, 1.0)
        far = traced_far(charlotte_scene, g, vv.grid, d_max)
        error = np.abs(far - vv.far.ravel())
        assert np.count_nonzero(far < d_max - 1.0) > 1000  # buildings in view, not an open field
        assert error.max() < 1e-3, (g, int(np.argmax(error)), float(error.max()))


@pytest.mark.parametrize(("path", "d_max", "band"), [("paper_slow", 400.0, None), ("paper_small", 100.0, (0.0, 60.0))])
def test_predicted_refine_rays_match_traced_rays_on_charlotte(charlotte, charlotte_scene, path, d_max, band):
    """The ray just before an occluder's edge (the second aimed probe of a wall) is predicted, not
    traced: it lies inside the occluder's cone, so it meets the occluder at its plane. Traced as
    well (check_predicted), at most 0.1 % of them disagree with Embree by more than 0.1 % (those
    graze the occluder's edge closer than Embree's float test resolves; bench/visibility_bench.py
    counts 0 of 14.3k at 1 degree, 2 of 28.3k at 0.5), the VV is the same as without the check,
    and each predicted ray is traced exactly once more. Predicting from the wrong side of the edge
    (the probe past it) fails this test: most predicted rays then miss."""
    pois, _poi = path_pois(charlotte_scene, charlotte / "paths" / f"{path}.csv", np.linspace(0.0, 60.0, 7))
    predicted = misses = 0
    for g in pois:
        plain, cost = vt._core.visibility_volume_cost(charlotte_scene, g, d_max, band, 1.0, False)
        vv, checked = vt._core.visibility_volume_cost(charlotte_scene, g, d_max, band, 1.0, False, check_predicted=True)
        assert vv.volume == plain.volume and np.array_equal(vv.faces, plain.faces)
        assert checked.refine_predicted == cost.refine_predicted
        assert checked.refine_rays == cost.refine_rays + cost.refine_predicted
        assert cost.predicted_misses == 0 and cost.predicted_error == 0.0  # not checked
        assert checked.predicted_misses == 0 or checked.predicted_error > 1e-3
        predicted += checked.refine_predicted
        misses += checked.predicted_misses
    assert predicted > 2000 and misses <= 1e-3 * predicted, (predicted, misses)


@pytest.mark.parametrize(("path", "d_max", "band"), [("paper_slow", 400.0, None), ("paper_small", 100.0, None),
                                                   ("paper_slow", 300.0, (0.0, 60.0)),
                                                   ("paper_slow", 300.0, (40.0, 80.0))])
def test_volume_without_mesh_is_the_meshs_on_charlotte(charlotte, charlotte_scene, tmp_path, path, d_max, band):
    """with_mesh=False skips the mesh but not its volume: the sums of the fill pass over the points
    its faces would join. Equal to the last bit to the meshed VV's (star VVs with walls and split
    slots, and shells, the POI below the band (40, 80)), alone and in a batch, with the same
    intervals; leaving out the walls' and split slots' faces would change it. What reads the mesh
    refuses the VV, naming it; the XOR too unless asked for the grid's, which reads the intervals
    (no silent switch from the exact radial XOR)."""
    pois, poi = path_pois(charlotte_scene, charlotte / "paths" / f"{path}.csv", [0.0, 30.0, 60.0])
    meshed = vt.visibility_volumes(charlotte_scene, pois, d_max, band, 1.0)
    bare = vt.visibility_volumes(charlotte_scene, pois, d_max, band, 1.0, with_mesh=False)
    for g, a, b in zip(pois, meshed, bare):
        alone = vt.visibility_volume(charlotte_scene, g, d_max, band, 1.0, with_mesh=False)
        assert a.has_mesh and not b.has_mesh and not alone.has_mesh
        assert a.volume > 0.0 and b.volume == a.volume and alone.volume == a.volume
        assert np.array_equal(b.near, a.near) and np.array_equal(b.far, a.far)
        assert len(b.mesh_row_sines) == 0 and len(b.mesh_triangle_faces) == 0
    if band is None:
        assert len(meshed[0].mesh_row_sines) > 0  # star VVs: the walls and splits were there to add up
    # The timed path too: the volume pass stands in for the mesh's.
    timed, cost = vt._core.visibility_volume_cost(charlotte_scene, pois[0], d_max, band, 1.0, False, with_mesh=False)
    assert not timed.has_mesh and timed.volume == meshed[0].volume
    if len(meshed[0].mesh_row_sines) > 0:  # a star VV (a shell's volume still comes from its mesh)
        assert cost.mesh_s == 0.0 and cost.fill_s == 0.0 and cost.volume_s > 0.0
    b = bare[0]
    refuses(lambda: b.vertices, "vv.vertices", "with_mesh")
    refuses(lambda: b.faces, "vv.faces", "with_mesh")
    refuses(lambda: b.slice(20.0), "vv:", "with_mesh")
    refuses(lambda: vt.plane_visibility_polygon(b, 20.0), "vv:", "with_mesh")
    refuses(lambda: b.check(), "vv:", "with_mesh")
    refuses(lambda: b.save(str(tmp_path / "vv.obj")), "vv:", "with_mesh")
    refuses(lambda: b.save_binary(tmp_path / "vv.bin"), "vv:", "with_mesh")
    refuses(lambda: vt.radial_xor_volume(b, meshed[1]), "a:", "with_mesh")
    refuses(lambda: vt.xor_volume(meshed[1], b, method="mesh"), "b:", "with_mesh")
    refuses(lambda: vt.xor_volume(b, bare[1]), "a:", "with_mesh")
    refuses(lambda: vt.visibility_volume(charlotte_scene, pois[0], d_max, band, 1.0, with_mesh="False"),
            "with_mesh", "'False'")
    uav = vt.Uav(speed=20.0, min_turn_radius=50.0, altitude=300.0)
    refuses(lambda: vt.plan_on_volumes(poi, uav, vt.Planning(), [0.0, 10.0], [meshed[0], b]), "volumes[1]",
            "with_mesh")
    assert not list(tmp_path.iterdir())  # nothing written
    assert vt.xor_volume(b, bare[1], method="grid") == vt.grid_xor_volume(meshed[0], meshed[1]) > 0.0


def test_polygon_agreement_sees_a_wrong_polygon(box_env, open_field):
    """The VP-against-line-of-sight score: near 1 for a VV in its own scene, clearly lower for an
    open-field VV scored against a scene with a box in front of the POI."""
    g = np.array([0.0, 0.0, 0.5])
    boxed = vt.visibility_scene(box_env)
    vv = vt.visibility_volume(boxed, g, 120.0, None, 1.0)
    assert polygon_agreement(boxed, vv, 20.0) >= 0.99
    wrong = vt.visibility_volume(vt.visibility_scene(open_field), g, 120.0, None, 1.0)
    assert polygon_agreement(boxed, wrong, 20.0) < 0.95
    with pytest.raises(vt.VistrackError, match="step"):
        polygon_agreement(boxed, vv, 20.0, step=0.0)


def test_volume_cost_accounts_for_every_ray_and_returns_the_same_vv(charlotte, charlotte_scene):
    """visibility_volume_cost (the benchmarks' breakdown): the same VV as visibility_volume, every
    corner ray (the mesh's vertex rows, plus the grid's corner rows that are none of them) either
    traced or decided without Embree, Embree's time inside the phases that trace, on the calling
    thread with parallel=False."""
    pois, _ = path_pois(charlotte_scene, charlotte / "paths" / "paper_slow.csv", [0.0, 30.0])
    for g in pois:
        vv, cost = vt._core.visibility_volume_cost(charlotte_scene, g, 400.0, None, 1.0, False)
        plain = vt.visibility_volume(charlotte_scene, g, 400.0, None, 1.0)
        assert vv.volume == plain.volume and np.array_equal(vv.faces, plain.faces) and np.array_equal(vv.far, plain.far)
        ne, na = vv.grid.num_elevation, vv.grid.num_azimuth
        grid_sines = np.sin(-np.pi / 2 + np.arange(ne + 1) * np.pi / ne)
        missing = sum(1 for x in grid_sines if np.min(np.abs(np.asarray(vv.mesh_row_sines) - x)) > 1e-9)
        corners = 2 + (len(vv.mesh_row_sines) - 2) * na + missing * na
        assert cost.rays_traced + cost.rays_skipped == corners
        # The mesh's corner rays come from the triangle tests; only the grid's other rows reach Embree.
        assert cost.rays_traced <= missing * na and cost.corner_tests > 0 and cost.refine_rays > 0
        phases = [cost.bounds_s, cost.trace_s, cost.refine_s, cost.mesh_s, cost.volume_s]
        assert all(p >= 0.0 for p in phases) and sum(phases) > 0.0
        assert 0.0 < cost.embree_s <= cost.trace_s + cost.refine_s


_KERNELS = """
import sys
sys.path.insert(0, sys.argv[1])
import conftest  # vistrack from the build tree when VISTRACK_BUILD_DIR is set
import hashlib
import numpy as np
import vistrack as vt
env = vt.Environment.from_mesh(sys.argv[2], up="y")
vv = vt.visibility_volume(vt.VisibilityScene(env), (-150.0, -45.0, 0.5), 400.0, None, 1.0)
q0 = np.random.default_rng(3).uniform(-30.0, 30.0, (999, 3))
lengths, _ = vt.dubins.shortest_lengths(np.ascontiguousarray(q0), np.ascontiguousarray(q0[::-1]), 7.0)
print(hashlib.sha256(vv.far.tobytes() + vv.vertices.tobytes() + np.float64(vv.volume).tobytes()
                     + lengths.tobytes()).hexdigest())
"""


def test_the_plain_loops_give_the_same_results(charlotte, tmp_path: Path):
    """VISTRACK_SCALAR_KERNELS=1 keeps the plain loops where the CPU has AVX2 (how the kernels are
    timed against them): the same Charlotte VV (intervals, mesh, volume) and Dubins lengths to the
    bit as with the AVX2 kernels. That the variable switches the kernels off is
    CpuCheck.ScalarKernelsVariableTurnsAvx2Off (visibility_test)."""
    if " avx2" not in Path("/proc/cpuinfo").read_text():
        pytest.skip("this CPU has no AVX2: only the plain loops run either way")
    script = tmp_path / "kernels.py"
    script.write_text(_KERNELS)
    here, city = str(Path(__file__).parent), str(charlotte / "uptown_charlotte.obj")
    digests = {}
    for value in ("0", "1"):
        env = {**os.environ, "VISTRACK_SCALAR_KERNELS": value}
        digests[value] = subprocess.run([sys.executable, str(script), here, city], check=True, capture_output=True,
                                        text=True, env=env).stdout.split()[-1]
    assert digests["0"] == digests["1"]


_RETAINED = """
import os, sys
sys.path.insert(0, sys.argv[2])
import conftest  # vistrack from the build tree when VISTRACK_BUILD_DIR is set
import numpy as np
import vistrack as vt
def rss():
    return int(open("/proc/self/statm").read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
if sys.argv[1] == "keep" and not vt.keep_freed_memory():
    print("unsupported")
    raise SystemExit
for _ in range(3):
    arrays = [np.ones(200_000) for _ in range(4)]  # four 1.6 MB arrays, as a VV's (mesh, intervals)
    alive = rss()
    del arrays
print(alive - rss())  # what freeing them handed back to the kernel
"""


def test_keep_freed_memory_keeps_what_a_batch_frees(tmp_path: Path):
    """After keep_freed_memory() the pages of freed VV-sized arrays stay in the process (the next
    batch reuses them without page faults); without it glibc returns them to the kernel."""
    script = tmp_path / "retained.py"
    script.write_text(_RETAINED)
    here = str(Path(__file__).parent)
    # glibc's defaults in the child, whatever this process was started with.
    env = {k: v for k, v in os.environ.items()
           if k not in ("GLIBC_TUNABLES", "LD_PRELOAD") and not k.startswith("MALLOC_")}
    out = {mode: subprocess.run([sys.executable, str(script), mode, here], check=True, capture_output=True, text=True,
                                env=env).stdout.split()[-1] for mode in ("plain", "keep")}
    if out["keep"] == "unsupported":
        pytest.skip("no glibc mallopt here")
    returned = {mode: int(text) for mode, text in out.items()}
    assert returned["keep"] < 1_000_000, returned  # kept in the process for the next batch
    assert returned["plain"] >= 5_000_000, returned  # the control: glibc's default hands it back


def test_keep_freed_memory_checks_its_argument_and_the_cli_calls_it(monkeypatch, tmp_path: Path):
    with pytest.raises(vt.VistrackError, match="max_bytes = -1"):
        vt.keep_freed_memory(-1)
    with pytest.raises(vt.VistrackError, match="max_bytes"):
        vt.keep_freed_memory(2**31)
    with pytest.raises(vt.VistrackError, match="max_bytes"):
        vt.keep_freed_memory("1")  # type: ignore[arg-type]
    assert vt.keep_freed_memory(np.int64(1 << 30)) == vt.keep_freed_memory(1 << 30)  # numpy integers too

    calls = []
    monkeypatch.setattr(cli, "keep_freed_memory", lambda: calls.append(1) or True)
    assert cli.main(["volumes", "--map", str(tmp_path / "none.geojson"), "--points", "0,0",
                              "--out", str(tmp_path / "out")]) == 1
    assert calls == [1]


@pytest.mark.sanitize
def test_visibility_volume_with_a_huge_range() -> None:
    """visibility_volume(env, (-150,-45,.5), 1e300).volume was NaN; an XOR against it returned the other's volume."""
    env = vt.Environment.demo()
    refuses(lambda: vt.visibility_volume(env, (-150.0, -45.0, 0.5), 1e300), "d_max = 1e+300", "[1e-06, 1e+07] m")
    refuses(lambda: vt.visibility_volume(env, (math.nan, -45.0, 0.5), 100.0), "nan")


@pytest.mark.sanitize
def test_direction_grid_refuses_indices_out_of_range() -> None:
    """DirectionGrid.elevation(10**9) answered instead of refusing the index."""
    grid = vt.DirectionGrid.from_resolution(10.0)
    refuses(lambda: grid.elevation(10**9), "1000000000")
    refuses(lambda: grid.elevation(-1), "-1")
    refuses(lambda: grid.azimuth(10**9), "1000000000")
    assert math.isfinite(grid.elevation(0))


def test_shapely_region_keeps_holes_and_joins_polygons() -> None:
    import shapely

    from vistrack.visibility import shapely_region

    square = np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]])
    hole = np.array([[2.0, 2.0], [4.0, 2.0], [4.0, 4.0], [2.0, 4.0]])
    region = shapely_region([vt.Polygon(square, [hole]), vt.Polygon(square + np.array([20.0, 0.0]))])
    assert region.area == pytest.approx(100.0 - 4.0 + 100.0)
    assert not region.contains(shapely.Point(3.0, 3.0))  # in the hole
    assert shapely_region([]).is_empty
