"""End to end: `vistrack demo` and `vistrack run` on the example scenarios write every report file
with sane numbers; errors give one clear line and a non-zero exit."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
import yaml

import vistrack as vt
from support.cli import one_line_error
from support.paths import DEMO_SCENARIO, REPO
from vistrack.cli import main
from vistrack.scenario import Scenario

REPORT_FILES = ["report.md", "metrics.json", "plan.json", "trajectory.csv", "city.png", "metric.png",
                "orbits.png", "radius.png", "trajectory.png", "errors.png", "volume3d.png"]


def check_report(out: Path, uav_speed: float) -> dict:
    for name in REPORT_FILES:
        path = out / name
        assert path.is_file() and path.stat().st_size > 0, name
        if name.endswith(".png"):
            assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
            assert path.stat().st_size > 20_000, f"{name} looks empty"
    meshes = sorted((out / "volumes").glob("*.ply"))
    assert meshes, "no VV meshes written"
    metrics = json.loads((out / "metrics.json").read_text())
    report = (out / "report.md").read_text()
    for name in REPORT_FILES[4:]:
        assert f"]({name})" in report  # every figure is embedded in the report

    plan = vt.OrbitPlan.from_json((out / "plan.json").read_text())
    assert len(plan.times) == metrics["plan"]["samples"]
    assert plan.radii[0] == pytest.approx(metrics["plan"]["initial_radius_m"])
    trajectory = np.genfromtxt(out / "trajectory.csv", delimiter=",", names=True)
    assert trajectory["t"][0] == pytest.approx(0.0)
    assert trajectory["t"][-1] == pytest.approx(metrics["poi"]["duration_s"], rel=1e-6)
    assert np.isfinite(trajectory["x"]).all() and np.isfinite(trajectory["radial_error"]).all()
    # The UAV flies at constant speed: consecutive samples are at most v * dt apart.
    step = np.hypot(np.diff(trajectory["x"]), np.diff(trajectory["y"]))
    assert step.max() <= np.diff(trajectory["t"]).max() * uav_speed * (1 + 1e-5)  # CSV rounding
    visible = metrics["simulation"]["visibility_fraction"]
    assert visible is not None and 0.0 <= visible <= 1.0
    return metrics


def test_demo_writes_a_complete_report(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "demo"
    assert main(["demo", "--out", str(out), "--quiet"]) == 0
    printed = capsys.readouterr().out
    assert f"report: {out / 'report.md'}" in printed
    metrics = check_report(out, Scenario.demo().uav.speed)
    plan = metrics["plan"]
    assert plan["feasible"], plan["infeasibility"]
    # Lemma 5 and Lemma 6 hold on the plan: rates within v - v_g, radii above the threshold.
    saved = vt.OrbitPlan.from_json((out / "plan.json").read_text())
    rates = np.diff(saved.radii) / np.diff(saved.times)
    assert np.abs(rates).max() <= 20.0 - 5.0 + 1e-9
    assert min(saved.radii) >= plan["min_feasible_radius_m"]
    # Tracking works: the visibility-informed orbit sees the POI most of the time, and more often
    # than the widest constant orbit (the paper's finding, here on the demo city).
    assert metrics["simulation"]["visibility_fraction"] > 0.9
    widest = max(metrics["baselines"].values(), key=lambda b: b["radius_m"])
    assert metrics["simulation"]["visibility_fraction"] > widest["visibility_fraction"]


def test_run_equals_python_api(tmp_path: Path) -> None:
    scenario = Scenario.demo()
    result = vt.run(scenario)  # no report folder
    assert result.out is None and result.files == []
    assert main(["run", str(Path(vt.__file__).parent / "scenarios" / "demo.yaml"), "--out",
                 str(tmp_path / "r"), "--quiet"]) == 0
    metrics = json.loads((tmp_path / "r" / "metrics.json").read_text())
    assert metrics["plan"]["samples"] == len(result.plan.times)
    assert metrics["simulation"]["visibility_fraction"] == pytest.approx(result.simulation.visibility_fraction)


@pytest.mark.parametrize("example", ["charlotte_paper_slow", "charlotte_paper_small", "campus_flight_test"])
def test_examples_run(example: str, shared_data: Path, tmp_path: Path) -> None:
    out = tmp_path / example
    assert main(["run", str(REPO / "examples" / f"{example}.yaml"), "--out", str(out), "--quiet"]) == 0
    metrics = check_report(out, Scenario.load(REPO / "examples" / f"{example}.yaml").uav.speed)
    assert metrics["plan"]["samples"] >= 2
    assert all(math.isfinite(v) for v in (metrics["plan"]["initial_radius_m"], metrics["plan"]["final_radius_m"]))


def test_print_defaults_is_a_valid_scenario(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["run", "--print-defaults"]) == 0
    text = capsys.readouterr().out
    path = tmp_path / "defaults.yaml"
    path.write_text(text)
    assert Scenario.load(path).uav.speed == vt.Uav().speed


@pytest.mark.parametrize(
    "text, message",
    [
        ("uav: {speed: -1}\n", "uav.speed = -1: must be a finite number in [1e-06, 10000] m/s"),
        ("planning: {cutof: 3}\n", "planning.cutof = 3: unknown key"),
        ("environment: {mesh: missing.obj}\n", "missing.obj"),
    ],
)
def test_run_errors_are_one_clear_line(text: str, message: str, tmp_path: Path,
                                       capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    assert main(["run", str(path), "--out", str(tmp_path / "o"), "--quiet"]) == 1  # input refused: a failure
    err = capsys.readouterr().err.strip()
    assert err.startswith("vistrack run: error:") and message in err
    assert len(err.splitlines()) == 1


def test_second_run_reads_the_volume_cache(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    scenario = Scenario.demo()
    scenario.planning.resolution_deg = 3.0  # small cache files
    cache = tmp_path / "cache"
    first = vt.run(scenario, cache_dir=cache)
    second = vt.run(scenario, cache_dir=cache)
    computed = first.metrics["volume_cache"]["misses"]
    assert computed > 0 and first.metrics["volume_cache"]["hits"] == 0
    assert second.metrics["volume_cache"] == {"folder": str(cache), "hits": computed, "misses": 0}
    assert list(second.plan.radii) == list(first.plan.radii)
    assert second.simulation.visibility_fraction == first.simulation.visibility_fraction
    # The command line says so too.
    path = tmp_path / "s.yaml"
    path.write_text(yaml.safe_dump(scenario.to_dict()))
    assert main(["run", str(path), "--out", str(tmp_path / "d"), "--quiet", "--cache", str(cache)]) == 0
    assert f"{computed} read, 0 computed" in capsys.readouterr().out


@pytest.mark.sanitize
def test_cli_run_with_tiny_spacing_is_one_line_before_the_work(tmp_path: Path,
                                                               capsys: pytest.CaptureFixture[str]) -> None:
    """`vistrack run` with spacing: 0.001 announced 240,840 VVs and an hour, then died with a traceback."""
    scenario = tmp_path / "tiny.yaml"
    scenario.write_text("name: tiny\nenvironment: {demo: true}\n"
                        "poi: {speed: 5.0, waypoints: [[-290, -210], [-100, -210], [-100, 50]]}\n"
                        "planning: {spacing: 0.001, min_spacing: 0.001}\n")
    one_line_error(["run", str(scenario), "--out", str(tmp_path / "out"), "--quiet"], capsys, 1,
                   "max_volumes")
    assert not any((tmp_path / "out").glob("*.png"))


@pytest.mark.sanitize
@pytest.mark.parametrize("kind", ["garbage", "not-utf8"])
def test_cli_run_on_a_file_that_is_not_a_scenario(kind: str, tmp_path: Path,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    """`run` on a 10 MB garbage file and on a non-UTF-8 YAML printed a traceback."""
    path = tmp_path / "bad.yaml"
    rng = np.random.default_rng(18)
    path.write_bytes(rng.integers(0, 256, 10 * 2**20, dtype=np.uint8).tobytes() if kind == "garbage"
                     else "name: caf\u00e9\n".encode("latin-1"))
    one_line_error(["run", str(path), "--out", str(tmp_path / "out"), "--quiet"], capsys, 1, str(path))


@pytest.mark.sanitize
def test_cli_out_pointing_at_a_file_fails_before_the_run(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """`run --out` pointing at an existing file failed only after the whole run."""
    existing = tmp_path / "file.txt"
    existing.write_text("keep me\n")
    one_line_error(["run", str(DEMO_SCENARIO), "--out", str(existing),
                    "--quiet"], capsys, 1, "--out", "is a file, not a folder")
    assert existing.read_text() == "keep me\n"
