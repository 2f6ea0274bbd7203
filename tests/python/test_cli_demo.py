"""`vistrack demo` end to end: both files written, numbers consistent with the library."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from vistrack.cli import main


def test_demo_writes_png_and_summary(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "demo"
    assert main(["demo", "--out", str(out), "--quiet"]) == 0
    png, summary_path = out / "city.png", out / "summary.json"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert png.stat().st_size > 20_000  # a real figure, not an empty canvas
    printed = capsys.readouterr().out
    assert str(png) in printed and str(summary_path) in printed

    summary = json.loads(summary_path.read_text())
    env = vt.Environment.demo()
    city = summary["city"]
    assert city["buildings"] == env.num_buildings
    assert city["triangles"] == env.num_triangles
    assert city["tallest_m"] == pytest.approx(150.0)
    assert np.allclose(city["bounds_m"], env.bounds)
    assert city["fingerprint"] == f"{env.fingerprint:016x}"

    path = summary["poi_path"]
    assert 600.0 <= path["length_m"] <= 1000.0
    assert path["speed_mps"] == pytest.approx(5.0)
    assert path["duration_s"] == pytest.approx(path["length_m"] / 5.0)
    assert path["turns"] >= 2
    # The waypoints are road nodes joined by road edges.
    poi = vt.PoiPath.from_nodes(env.roads, path["road_nodes"], 5.0)
    assert np.allclose(poi.waypoints[:, :2], path["waypoints_m"])
    waypoints = np.asarray(path["waypoints_m"])
    assert np.sum(np.linalg.norm(np.diff(waypoints, axis=0), axis=1)) == pytest.approx(path["length_m"])


def test_demo_is_deterministic(tmp_path: Path) -> None:
    for name in ("a", "b"):
        assert main(["demo", "--out", str(tmp_path / name), "--quiet"]) == 0
    a = json.loads((tmp_path / "a" / "summary.json").read_text())
    b = json.loads((tmp_path / "b" / "summary.json").read_text())
    a.pop("stage_seconds"), b.pop("stage_seconds")
    assert a == b


def test_demo_reports_unwritable_output(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("not a folder")
    assert main(["demo", "--out", str(blocker / "demo"), "--quiet"]) == 2
    assert "vistrack demo: error" in capsys.readouterr().err
