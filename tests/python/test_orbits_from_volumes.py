"""`vistrack orbits --from-volumes`: the orbit plan from saved VV files, without the map, must be the
planner's plan over the same samples (same VVs, same slicer, same metric, same Algorithm 1)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.cities import STREET_BETWEEN_BLOCKS, four_blocks
from vistrack import _core
from vistrack.cli import main
from vistrack.saved_volumes import arc_length_on_path

POI_SPEED, RESOLUTION = 5.0, 4.0


@pytest.fixture(scope="module")
def city(tmp_path_factory):
    env = four_blocks()
    poi = vt.PoiPath(STREET_BETWEEN_BLOCKS, POI_SPEED)
    uav = vt.Uav(speed=20.0, min_turn_radius=5.0, altitude=50.0)
    sensor = vt.Sensor(d_max=100.0)
    root = tmp_path_factory.mktemp("from-volumes")
    csv = root / "path.csv"
    csv.write_text("".join(f"{x},{y}\n" for x, y in STREET_BETWEEN_BLOCKS))
    return env, poi, uav, sensor, csv


def _orbits(folder: Path, csv: Path, uav: vt.Uav, out: Path) -> int:
    return main(["orbits", "--from-volumes", str(folder), "--path", str(csv), "--poi-speed", str(POI_SPEED),
                 "--speed", str(uav.speed), "--min-turn-radius", str(uav.min_turn_radius),
                 "--altitude", str(uav.altitude), "--out", str(out)])


def _assert_reproduces(saved: vt.VisibilityOrbitPlan, plan: vt.VisibilityOrbitPlan) -> None:
    # Same VVs and slicer: MaxRadius and the metric are bit-identical; s_k comes back from a
    # projection onto the path, so times (and the radii built from them) agree to rounding.
    assert list(saved.max_radii) == list(plan.max_radii)
    assert list(saved.metric) == list(plan.metric)
    np.testing.assert_allclose(saved.arc_lengths, plan.arc_lengths, rtol=0, atol=1e-9)
    np.testing.assert_allclose(saved.times, plan.times, rtol=0, atol=1e-9)
    # Algorithm 1 on them. (The smooth R(t) on top differs: the planner checks MaxRadius between the
    # samples by line of sight, which saved VVs alone cannot; see _check_smooth_locus_from_volumes.)
    np.testing.assert_allclose(saved.orbits.radii, plan.orbits.radii, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(saved.radius_rates, plan.radius_rates, rtol=1e-9, atol=1e-9)
    # (Algorithm 1's own verdict is its failing samples, compared below; plan.json keeps one
    # `feasible` for the whole plan, the smooth R(t)'s included.)
    assert saved.min_feasible_radius == plan.min_feasible_radius
    assert list(saved.failing_samples) == list(plan.failing_samples)


def test_from_volumes_reproduces_fixed_spacing_plan(city, tmp_path: Path) -> None:
    env, poi, uav, sensor, csv = city
    cache = tmp_path / "vv"
    planner = _core.OrbitPlanner(env, sensor, cache_dir=cache)
    # A cutoff nothing exceeds: the planner's samples are the fixed 30 m ones.
    plan = planner.plan(poi, uav, vt.Planning(spacing=30.0, cutoff=1e12, resolution_deg=RESOLUTION))
    assert set(plan.depths) == {0} and plan.num_volumes == len(list(cache.glob("vv-*.bin"))) > 5
    fixed = planner.fixed(poi, 30.0, RESOLUTION)
    assert list(fixed.times) == list(plan.times)

    out = tmp_path / "out"
    assert _orbits(cache, csv, uav, out) == 0
    saved = vt.VisibilityOrbitPlan.from_json((out / "plan.json").read_text())
    _assert_reproduces(saved, plan)
    # The same numbers built by hand from the fixed samples and Algorithm 1.
    max_radii = [vt.max_inscribed_radius(vt.plane_visibility_polygon(fixed.volume(k), uav.altitude),
                                         fixed.points[k, :2]) for k in range(len(fixed.times))]
    assert list(saved.max_radii) == max_radii
    orbits = vt.circular_orbits(list(fixed.times), max_radii, uav, POI_SPEED)
    np.testing.assert_allclose(saved.orbits.radii, orbits.radii, rtol=1e-12, atol=1e-9)
    _check_smooth_locus_from_volumes(saved)
    assert len(set(np.round(saved.max_radii, 6))) > 1  # the city matters: not one constant radius

    summary = json.loads((out / "summary.json").read_text())
    assert summary["samples"] == len(plan.times) and summary["inserted"] == 0
    assert summary["volumes_computed"] == 0
    assert (out / "radius.png").stat().st_size > 0
    assert (out / "orbits.png").stat().st_size > 0  # Figure 5 without the map
    assert saved.uav.altitude == uav.altitude and saved.sensor.d_max == sensor.d_max
    assert saved.planning.resolution_deg == RESOLUTION and saved.planning.spacing == pytest.approx(30.0)


def test_from_volumes_keeps_the_adaptively_inserted_samples(city, tmp_path: Path) -> None:
    env, poi, uav, sensor, csv = city
    cache = tmp_path / "vv"
    planner = _core.OrbitPlanner(env, sensor, cache_dir=cache)
    plan = planner.plan(poi, uav, vt.Planning(spacing=30.0, cutoff=2e5, resolution_deg=RESOLUTION))
    assert max(plan.depths) > 0  # some samples were inserted; their VVs are in the folder too
    out = tmp_path / "out"
    assert _orbits(cache, csv, uav, out) == 0
    _assert_reproduces(vt.VisibilityOrbitPlan.from_json((out / "plan.json").read_text()), plan)


def test_save_binary_load_round_trip(city, tmp_path: Path) -> None:
    env, _, _, sensor, _ = city
    vv = vt.visibility_volume(vt.VisibilityScene(env), np.array([0.0, 0.0, 0.5]), sensor.d_max, None, RESOLUTION)
    vv.save_binary(tmp_path / "a.bin")
    back = vt.VisibilityVolume.load(tmp_path / "a.bin")
    assert back.volume == vv.volume and back.d_max == vv.d_max and back.altitude_band is None
    assert np.array_equal(back.poi, vv.poi) and np.array_equal(back.near, vv.near) and np.array_equal(back.far, vv.far)
    assert np.array_equal(back.vertices, vv.vertices) and np.array_equal(back.faces, vv.faces)
    with pytest.raises(vt.VistrackError, match=r"missing\.bin.*does not exist"):
        vt.VisibilityVolume.load(tmp_path / "missing.bin")
    (tmp_path / "bad.bin").write_bytes((tmp_path / "a.bin").read_bytes()[:-9] + b"x" * 9)
    with pytest.raises(vt.VistrackError, match=r"bad\.bin"):
        vt.VisibilityVolume.load(str(tmp_path / "bad.bin"))
    with pytest.raises(vt.VistrackError, match="no-such-folder"):
        vv.save_binary(tmp_path / "no-such-folder" / "a.bin")


def test_arc_length_on_path_projects_onto_the_polyline() -> None:
    assert arc_length_on_path(STREET_BETWEEN_BLOCKS, np.array([-45.0, 0.3])) == pytest.approx((45.0, 0.3))
    assert arc_length_on_path(STREET_BETWEEN_BLOCKS, np.array([0.0, 60.0])) == pytest.approx((150.0, 0.0))
    assert arc_length_on_path(STREET_BETWEEN_BLOCKS, np.array([-100.0, 0.0])) == pytest.approx((0.0, 10.0))  # clamped
    assert arc_length_on_path(STREET_BETWEEN_BLOCKS, np.array([3.0, 100.0])) == pytest.approx((180.0, np.hypot(3, 10)))


def _error_line(capsys) -> str:
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    return err[0]


def test_from_volumes_errors(city, tmp_path: Path, capsys) -> None:
    env, poi, uav, sensor, csv = city
    empty = tmp_path / "empty"
    empty.mkdir()
    assert _orbits(empty, csv, uav, tmp_path / "out") == 1
    assert "no VV files" in _error_line(capsys)
    assert not (tmp_path / "out").exists()

    scene = vt.VisibilityScene(env)
    good = tmp_path / "good"
    good.mkdir()
    for k, s in enumerate([0.0, 45.0]):
        p = poi.position(s / POI_SPEED)
        vt.visibility_volume(scene, np.array([p[0], p[1], 0.5]), sensor.d_max, None, RESOLUTION) \
            .save_binary(good / f"vv-{k}.bin")
    assert _orbits(good, csv, uav, tmp_path / "ok") == 0
    capsys.readouterr()

    corrupt = tmp_path / "corrupt"
    corrupt.mkdir()
    (corrupt / "vv-0.bin").write_bytes((good / "vv-0.bin").read_bytes())
    (corrupt / "vv-1.bin").write_bytes((good / "vv-1.bin").read_bytes()[:200])
    assert _orbits(corrupt, csv, uav, tmp_path / "out") == 1
    assert "vv-1.bin" in _error_line(capsys)

    off = tmp_path / "off"
    off.mkdir()
    (off / "vv-0.bin").write_bytes((good / "vv-0.bin").read_bytes())
    vt.visibility_volume(scene, np.array([-45.0, 1.5, 0.5]), sensor.d_max, None, RESOLUTION) \
        .save_binary(off / "vv-far.bin")
    assert _orbits(off, csv, uav, tmp_path / "out") == 1
    line = _error_line(capsys)
    assert "vv-far.bin" in line and "1.500 m from the POI path" in line

    mixed = tmp_path / "mixed"
    mixed.mkdir()
    (mixed / "vv-0.bin").write_bytes((good / "vv-0.bin").read_bytes())
    vt.visibility_volume(scene, np.array([-45.0, 0.0, 0.5]), sensor.d_max, None, 6.0).save_binary(mixed / "vv-1.bin")
    assert _orbits(mixed, csv, uav, tmp_path / "out") == 1
    assert "vv-1.bin" in _error_line(capsys)

    assert main(["orbits", "--from-volumes", str(good), "--out", str(tmp_path / "out")]) == 2
    assert "--path" in _error_line(capsys)
    assert not (tmp_path / "out").exists()


def test_charlotte_volumes_save_then_orbits_from_volumes(charlotte: Path, tmp_path: Path) -> None:
    """`vistrack volumes --save-volumes` on the real city, then planning from those files alone: the
    MaxRadius values match the ones `volumes` measured with CGAL's slicer (vv.slice)."""
    path = charlotte / "paths" / "paper_small.csv"
    common = ["--path", str(path), "--altitude", "50"]
    assert main(["volumes", "--map", str(charlotte / "buildings.geojson"), "--spacing", "50", "--d-max", "100",
                 "--resolution", "3", "--save-volumes", str(tmp_path / "vv"), "--no-meshes", "--quiet",
                 "--out", str(tmp_path / "volumes"), *common]) == 0
    assert main(["orbits", "--from-volumes", str(tmp_path / "vv"), "--poi-speed", "5", "--speed", "20",
                 "--min-turn-radius", "5", "--out", str(tmp_path / "orbits"), *common]) == 0
    measured = [p["max_radius"] for p in json.loads((tmp_path / "volumes" / "volumes.json").read_text())["points"]]
    plan = vt.VisibilityOrbitPlan.from_json((tmp_path / "orbits" / "plan.json").read_text())
    assert len(measured) == len(plan.times) > 3
    np.testing.assert_allclose(plan.max_radii, measured, rtol=1e-6, atol=1e-6)
    # `volumes` spaces its points evenly (at most 50 m) from one end of the path to the other.
    length = vt.PoiPath.from_csv(path, 5.0).length
    np.testing.assert_allclose(plan.arc_lengths, np.linspace(0.0, length, len(measured)), atol=1e-6)
    assert all(r <= m + 1e-9 for r, m in zip(plan.orbits.radii, plan.max_radii))  # Algorithm 1 only lowers radii
    # Two samples fail Lemma 6 (MaxRadius 7.4 m < r_min (1 + v_g/v)^2 = 7.8 m) and the smooth R(t) under
    # tracking_margin would go below 0 there: the plan keeps Algorithm 1's radii (a readable file) and says so.
    assert not plan.feasible and "Lemma 6" in plan.infeasibility and "would fall to" in plan.infeasibility
    assert not plan.reference.smooth and list(plan.radii) == list(plan.orbits.radii)


def _check_smooth_locus_from_volumes(saved: vt.VisibilityOrbitPlan) -> None:
    """Without VVs between the samples the smooth R(t) is bounded by the samples' MaxRadius and the
    slope rule only: below it by tracking_margin at the samples, and flyable (Lemma 5, d2R/dt2)."""
    # (Here the slope rule between samples 30 m apart dips the ceiling to 2 m, under Lemma 6's 7.8 m:
    # the plan is reported infeasible, and still well formed.)
    assert saved.planning.locus == "smooth" and saved.reference.smooth
    assert saved.feasible or "Lemma 6" in saved.infeasibility
    assert (np.asarray(saved.radii) <= np.asarray(saved.max_radii) - saved.planning.tracking_margin + 1e-6).all()
    assert np.abs(saved.reference.rates).max() <= saved.uav.speed - POI_SPEED + 1e-9
