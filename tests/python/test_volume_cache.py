"""On-disk VV cache through the Python planner: a second planner on the same folder reads every VV."""

from __future__ import annotations

from pathlib import Path

import pytest

import vistrack as vt
from support.cities import STREET_BETWEEN_BLOCKS, four_blocks
from vistrack import _core


@pytest.fixture(scope="module")
def small_city():
    env = four_blocks()
    poi = vt.PoiPath(STREET_BETWEEN_BLOCKS, 5.0)
    uav = vt.Uav(speed=20.0, min_turn_radius=5.0, altitude=50.0)
    sensor = vt.Sensor(d_max=100.0)
    planning = vt.Planning(spacing=30.0, cutoff=2e5, resolution_deg=4.0)
    return env, poi, uav, sensor, planning


def _assert_same_plan(a, b) -> None:
    assert list(a.times) == list(b.times)
    assert list(a.radii) == list(b.radii)
    assert list(a.max_radii) == list(b.max_radii)
    assert list(a.metric) == list(b.metric)
    assert a.feasible == b.feasible


def test_second_planner_reads_every_vv_from_disk(small_city, tmp_path: Path) -> None:
    env, poi, uav, sensor, planning = small_city
    folder = tmp_path / "vv-cache" / "nested"  # created on demand; a Path is accepted
    cold = _core.OrbitPlanner(env, sensor, cache_dir=folder)
    a = cold.plan(poi, uav, planning)
    n = a.num_volumes
    assert n > 7  # refined beyond the initial samples
    assert (cold.disk_hits, cold.disk_misses) == (0, n)
    assert sorted(p.name for p in folder.iterdir()) == sorted(p.name for p in folder.glob("vv-*.bin"))
    assert len(list(folder.iterdir())) == n

    warm = _core.OrbitPlanner(env, sensor, cache_dir=str(folder))
    b = warm.plan(poi, uav, planning)
    assert (warm.disk_hits, warm.disk_misses) == (n, 0)
    _assert_same_plan(a, b)

    # Without a cache folder nothing is counted, and the plan is the same.
    plain = _core.OrbitPlanner(env, sensor)
    _assert_same_plan(a, plain.plan(poi, uav, planning))
    assert (plain.disk_hits, plain.disk_misses) == (0, 0)

    # vt.plan_orbits takes the folder too.
    _assert_same_plan(a, vt.plan_orbits(env, poi, uav, sensor, planning, cache_dir=folder))
    assert len(list(folder.iterdir())) == n


def test_changed_inputs_miss_and_bad_files_are_recomputed(small_city, tmp_path: Path) -> None:
    env, poi, uav, sensor, planning = small_city
    first = _core.OrbitPlanner(env, sensor, cache_dir=tmp_path)
    a = first.plan(poi, uav, planning)
    n = a.num_volumes
    first_files = sorted(tmp_path.glob("vv-*.bin"))
    sizes = {f: f.stat().st_size for f in first_files}
    # Another altitude band is another VV: every file misses and is added beside the first ones.
    banded = _core.OrbitPlanner(env, vt.Sensor(d_max=100.0, altitude_band=(20.0, 120.0)), cache_dir=tmp_path)
    banded.plan(poi, uav, planning)
    assert banded.disk_hits == 0 and banded.disk_misses > 0
    assert len(list(tmp_path.glob("vv-*.bin"))) == n + banded.disk_misses
    # Truncate one of the first plan's files and garble another: both are recomputed and rewritten.
    victims = first_files[:2]
    victims[0].write_bytes(victims[0].read_bytes()[:100])
    victims[1].write_bytes(b"not a VV file")
    again = _core.OrbitPlanner(env, sensor, cache_dir=tmp_path)
    b = again.plan(poi, uav, planning)
    _assert_same_plan(a, b)
    assert all(v.stat().st_size == sizes[v] for v in victims)  # rewritten whole
    assert (again.disk_hits, again.disk_misses) == (n - 2, 2)


def test_unusable_cache_dir_is_an_error_naming_it(small_city, tmp_path: Path) -> None:
    env, _, _, sensor, _ = small_city
    blocker = tmp_path / "a-file"
    blocker.write_text("x")
    with pytest.raises(vt.VistrackError, match="cache_dir"):
        _core.OrbitPlanner(env, sensor, cache_dir=blocker)
    with pytest.raises(vt.VistrackError, match="cache_dir"):
        _core.OrbitPlanner(env, sensor, cache_dir=blocker / "sub")
    assert blocker.read_text() == "x"
    with pytest.raises(TypeError):
        _core.OrbitPlanner(env, sensor, cache_dir=12)


def test_charlotte_second_plan_is_identical_and_all_hits(charlotte: Path, tmp_path: Path) -> None:
    env = vt.Environment.from_mesh(str(charlotte / "uptown_charlotte.obj"), "y")
    poi = vt.PoiPath.from_csv(str(charlotte / "paths" / "paper_small.csv"), 5.0)
    uav = vt.Uav(speed=20.0, min_turn_radius=5.0, altitude=50.0)
    sensor = vt.Sensor(d_max=100.0)
    planning = vt.Planning(spacing=20.0, cutoff=500e3, resolution_deg=2.0)
    cold = vt.OrbitPlanner(env, sensor, cache_dir=tmp_path)
    a = cold.plan(poi, uav, planning)
    assert cold.disk_misses == a.num_volumes > 0 and cold.disk_hits == 0
    warm = vt.OrbitPlanner(env, sensor, cache_dir=tmp_path)
    b = warm.plan(poi, uav, planning)
    assert warm.disk_misses == 0 and warm.disk_hits == a.num_volumes
    _assert_same_plan(a, b)
    assert a.feasible, a.infeasibility
