"""Loiter over a city (issue 33 part 4): loiter circles inside the AOIs' visibility polygons, AOIs
without a flyable circle reported, coverage with line of sight (oracles: the paper's coverage for
the footprint, brute-force Embree rays for the line of sight)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.paths import EXAMPLES
from support.refusal import refuses
from vistrack.cli import main as cli_main
from vistrack.loiter import Scenario
from vistrack.loiter.city import plan_city, random_street_aois


def _box(x0: float, x1: float, y0: float, y1: float) -> np.ndarray:
    return np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])


@pytest.fixture(scope="module")
def town() -> vt.VisibilityScene:
    """Three AOIs on open ground; towers (400 m, above the flight) 30 m from AOI 1 on two sides,
    so no 46 m circle fits about it; a 100 m block 25 m from AOI 2 (MaxRadius 75 m) hides part of
    its disk."""
    return vt.VisibilityScene(vt.Environment.from_buildings([
        (_box(630, 700, 300, 700), 400.0), (_box(400, 630, 530, 600), 400.0), (_box(1025, 1035, 185, 215), 100.0)]))


def _scenario(aois: np.ndarray | None = None, off_centre: bool = False) -> Scenario:
    """The town's three AOIs (or ``aois``), circles about each AOI only unless ``off_centre``."""
    camera = vt.loiter.Camera(74.0, 25.0, 300.0, True)
    return Scenario(aois=np.array([[300.0, 200.0], [600.0, 500.0], [1000.0, 200.0]]) if aois is None else aois,
                    camera=camera, off_centre=off_centre)


def test_an_aoi_without_a_flyable_circle_is_reported_and_the_rest_planned(town: vt.VisibilityScene) -> None:
    result = plan_city(_scenario(), ["tlpp", "ldlpp"], town)  # circles about the AOIs only
    assert result.flyable == [0, 2]
    assert result.rooms[1].max_radius == pytest.approx(30.0, abs=0.5)
    assert result.rooms[2].max_radius == pytest.approx(25.0 * 299.5 / 99.5, rel=0.02)  # D h / H from 0.5 m up
    assert "aoi 1" in (result.rooms[1].reason or "") and "turn radius 46" in (result.rooms[1].reason or "")
    assert result.radius == pytest.approx(46.0)
    assert [run.method for run in result.runs] == ["tlpp", "ldlpp"]
    for run in result.runs:
        assert run.plan.aoi_radius <= min(result.rooms[i].max_radius for i in result.flyable)
        assert min(run.centre_line_of_sight) == 1.0


def test_coverage_counts_only_what_the_camera_sees(town: vt.VisibilityScene) -> None:
    run = plan_city(_scenario(), ["ldlpp"], town).runs[0]
    cov = run.coverage
    # The sampled footprint agrees with the paper's exact disk-in-ellipse area (sampling error only).
    assert np.mean(np.abs(cov.in_footprint - np.asarray(cov.paper.fraction))) < 0.01
    assert cov.open_time == pytest.approx(cov.paper.time, rel=0.03)
    assert np.all(cov.seen <= cov.in_footprint + 1e-12)
    assert np.array_equal(cov.seen[:, 0], cov.in_footprint[:, 0])  # open ground: nothing hidden
    assert cov.seen[:, 1].sum() < 0.99 * cov.in_footprint[:, 1].sum()  # the block hides part of AOI 2's disk
    assert cov.time <= cov.open_time


def test_off_centre_circle_keeps_the_aoi_in_sight(town: vt.VisibilityScene) -> None:
    result = plan_city(_scenario(), ["tlpp"], town, off_centre=True)
    room = result.rooms[1]
    assert room.flyable and 0.0 < room.shift <= 150.0
    assert result.runs[0].centre_line_of_sight[1] >= 0.99


def test_bad_city_input_names_the_field(town: vt.VisibilityScene) -> None:
    refuses(lambda: plan_city(_scenario(np.array([[650.0, 400.0]])), ["tlpp"], town), "aois[0]", "building")
    refuses(lambda: plan_city(_scenario(), ["tlpp"]), "city = None")


@pytest.fixture(scope="module")
def charlotte_scene(charlotte: Path) -> vt.VisibilityScene:
    return vt.VisibilityScene(vt.Environment.from_mesh(charlotte / "uptown_charlotte.obj", up="y"))


@pytest.mark.parametrize("seed", [7, 31, 2024])  # layouts never tuned on (bench/loiter_city_random.py: 50 more)
def test_charlotte_street_level_layouts(charlotte_scene: vt.VisibilityScene, seed: int) -> None:
    """Six random street-level AOIs at 300 m, as the files plan them (off_centre): at least 5 get a flyable
    circle inside their VP (at least 4 about their centres) and each flyable AOI's centre is in line of
    sight >= 99 % of its loiter time (brute-force rays)."""
    aois = random_street_aois(charlotte_scene, 6, np.random.default_rng(seed))
    result = plan_city(_scenario(aois, off_centre=True), ["tlpp", "ldlpp_best"], charlotte_scene)
    assert len(result.flyable) >= 5, result.record()["aois"]
    assert sum(room.flyable and room.shift == 0.0 for room in result.rooms) >= 4
    assert result.runs
    for run in result.runs:
        assert min(run.centre_line_of_sight) >= 0.99


def test_cli_on_the_charlotte_example(charlotte: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status = cli_main(["loiter", str(EXAMPLES / "loiter_charlotte_city.yaml"), "--method", "tlpp", "ldlpp",
                       "--out", str(tmp_path / "city")])
    out = capsys.readouterr().out
    assert status == 0
    assert "aoi 4: no flyable circle about it; loiters on one" in out  # off_centre, the default
    assert "(city, R 46 m" in out
    assert (tmp_path / "city" / "city_tlpp.png").is_file()
    assert "visibility polygon" in (tmp_path / "city" / "report.md").read_text()


def test_off_centre_key_on_charlotte(charlotte: Path, charlotte_scene: vt.VisibilityScene, tmp_path: Path) -> None:
    """``off_centre`` (true by default): the example's AOI 4 (MaxRadius 41.7 m) loiters on a circle off it
    inside its polygon, and is still seen >= 99 % of its loiter time; false leaves it out; a bad value
    names the key."""
    text = (EXAMPLES / "loiter_charlotte_city.yaml").read_text()
    text = text.replace("../../shared/data", str(charlotte.parent))
    (tmp_path / "city.yaml").write_text(text)
    scenario = vt.loiter.load_scenario(tmp_path / "city.yaml")
    result = plan_city(scenario, ["tlpp"], charlotte_scene)
    assert result.flyable == list(range(6)) and 0.0 < result.rooms[4].shift <= 150.0
    assert min(result.runs[0].centre_line_of_sight) >= 0.99
    (tmp_path / "strict.yaml").write_text(text.replace("# off_centre: false", "off_centre: false"))
    strict = plan_city(vt.loiter.load_scenario(tmp_path / "strict.yaml"), ["tlpp"], charlotte_scene)
    assert strict.flyable == [0, 1, 2, 3, 5] and "aoi 4" in (strict.rooms[4].reason or "")
    (tmp_path / "bad.yaml").write_text(text.replace("# off_centre: false", "off_centre: maybe"))
    refuses(lambda: vt.loiter.load_scenario(tmp_path / "bad.yaml"), "off_centre")
