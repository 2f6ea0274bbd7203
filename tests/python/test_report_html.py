"""report.html and trajectory.gif of a tracking run: the page parses, needs no network, holds the
expected plotly traces (checked against the run's own files), stays under its size bound, loads in
headless Chromium without errors and shows the scene; the GIF has the frames asked for."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

import vistrack as vt
from support.headless_browser import find_chromium, load
from support.paths import REPO
from support.report_checks import check_gif, check_page, plotly_figure
from vistrack.cli import main
from vistrack.plotting.animation import write_gif
from vistrack.plotting.interactive import DEFAULT_TIME_STEPS, decode_array
from vistrack.plotting.motion import MotionScene, Overlay, Sight, Track, circle_ring
from vistrack.scenario import ReportOptions, Scenario


@pytest.fixture(scope="module")
def demo_report(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("demo") / "demo"
    assert main(["demo", "--out", str(out), "--quiet"]) == 0
    return out


@pytest.fixture(scope="module")
def charlotte_report(charlotte: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("charlotte") / "small"
    assert main(["run", str(REPO / "examples" / "charlotte_paper_small.yaml"), "--out", str(out), "--quiet"]) == 0
    return out


def check_figure(figure: dict[str, Any], out: Path, volumes: int) -> None:
    data = figure["data"]
    names = [t.get("name", "") for t in data]
    assert any(n.startswith("buildings (") for n in names)
    metrics = json.loads((out / "metrics.json").read_text())
    plan = vt.OrbitPlan.from_json((out / "plan.json").read_text())
    # The VVs: as many meshes as asked (or samples), one visible at a time, each inside the ball of
    # radius d_max about one of the plan's POIs, each coarse enough.
    meshes = [t for t in data if t["type"] == "mesh3d" and t["name"] == "visibility volume"]
    assert len(meshes) == min(volumes, metrics["plan"]["samples"])
    assert [m["visible"] for m in meshes] == [True] + [False] * (len(meshes) - 1)
    pois = np.array([plan.poi.position(t) for t in plan.times])
    d_max = json.loads((out / "plan.json").read_text())["sensor"]["d_max"]
    for mesh in meshes:
        v = np.column_stack([decode_array(mesh[c]) for c in "xyz"])
        faces = decode_array(mesh["i"])
        assert 1000 < len(faces) < 30_000  # a 1-degree VV has ~65k faces: recomputed coarser
        distance = np.linalg.norm(v[:, None, :] - pois[None, :, :], axis=2).max(axis=0)
        assert distance.min() <= d_max * (1 + 1e-4)  # float32 coordinates
    layer_slider = next(s for s in figure["layout"]["sliders"] if s["steps"][0]["method"] == "restyle")
    assert len(layer_slider["steps"]) == len(meshes)
    # The paths coloured by line of sight, and the moving parts.
    for name in ("UAV path, in line of sight", "POI path, in line of sight", "UAV", "POI", "line of sight",
                 "orbit R(t)", "VP of the sample"):
        assert name in names, name
    # Time slider and frames: the UAV marker of each frame is where trajectory.csv puts the UAV then,
    # and the line of sight is green or red as its visible column says.
    frames = figure["frames"]
    assert len(frames) == DEFAULT_TIME_STEPS
    time_slider = next(s for s in figure["layout"]["sliders"] if s["steps"][0]["method"] == "animate")
    assert [s["args"][0][0] for s in time_slider["steps"]] == [f["name"] for f in frames]
    csv = np.genfromtxt(out / "trajectory.csv", delimiter=",", names=True)
    times = np.linspace(csv["t"][0], csv["t"][-1], len(frames))
    uav_index = names.index("UAV")
    colors = set()
    for k in (0, len(frames) // 3, len(frames) - 1):
        frame = frames[k]
        uav = frame["data"][frame["traces"].index(uav_index)]
        x, y = float(decode_array(uav["x"])[0]), float(decode_array(uav["y"])[0])
        assert x == pytest.approx(np.interp(times[k], csv["t"], csv["x"]), abs=1e-3 * max(1.0, abs(x)))
        assert y == pytest.approx(np.interp(times[k], csv["t"], csv["y"]), abs=1e-3 * max(1.0, abs(y)))
        sight = frame["data"][frame["traces"].index(names.index("line of sight"))]
        sample = np.searchsorted(csv["t"], times[k], side="right") - 1
        colors.add(sight["line"]["color"])
        assert (sight["line"]["color"] == "#1a9850") == bool(csv["visible"][sample])


def test_demo_writes_report_html_and_gif(demo_report: Path) -> None:
    options = ReportOptions()
    _, figure = check_page(demo_report)
    check_figure(figure, demo_report, options.volumes)
    check_gif(demo_report / "trajectory.gif", options.frames, options.duration)
    made = json.loads((demo_report / "metrics.json").read_text())["report_files"]
    assert set(made) == {"report.html", "trajectory.gif"}
    assert made["report.html"]["bytes"] == (demo_report / "report.html").stat().st_size


def test_charlotte_report_html(charlotte_report: Path) -> None:
    _, figure = check_page(charlotte_report)
    check_figure(figure, charlotte_report, ReportOptions().volumes)
    check_gif(charlotte_report / "trajectory.gif", ReportOptions().frames, ReportOptions().duration)


def scene_shows_content(png: Path) -> dict[str, float]:
    """Fractions of the screenshot's plot area that are not background, green (VVs, VP, visible
    paths) and grey (buildings)."""
    with Image.open(png) as image:
        rgb = np.asarray(image.convert("RGB")).astype(int)
    plot = rgb[150:800, 150:1350]
    r, g, b = plot[..., 0], plot[..., 1], plot[..., 2]
    return {"content": float((plot.min(axis=2) < 235).mean()),
            "green": float(((g > r + 35) & (g > b + 15)).mean()),
            "grey": float(((abs(r - g) < 14) & (abs(g - b) < 18) & (r > 50) & (r < 200)).mean())}


@pytest.mark.parametrize("which", ["demo_report", "charlotte_report"])
def test_report_html_in_headless_chromium(which: str, request: pytest.FixtureRequest, tmp_path: Path) -> None:
    if find_chromium() is None:
        pytest.skip("headless Chromium not found (Debian: apt-get install chromium; .ci/run installs it)")
    out: Path = request.getfixturevalue(which)
    shot = tmp_path / "report.png"
    loaded = load(out / "report.html", shot, exercise=True)
    assert loaded.errors == [], loaded.errors
    figure = plotly_figure((out / "report.html").read_text(encoding="utf-8"))
    assert loaded.plot.get("traces") == len(figure["data"]), loaded.log[-2000:]
    assert loaded.plot.get("canvases", 0) >= 1
    # The sliders work in the browser: the time slider's last step puts the UAV where the last
    # frame says, the volume slider's last step shows the last VV alone.
    last = figure["frames"][-1]
    uav = last["data"][last["traces"].index([t.get("name") for t in figure["data"]].index("UAV"))]
    assert loaded.animated.get("frame") == last["name"], loaded.log[-2000:]
    assert float(loaded.animated["x"]) == pytest.approx(float(decode_array(uav["x"])[0]), abs=1e-3)
    assert float(loaded.animated["y"]) == pytest.approx(float(decode_array(uav["y"])[0]), abs=1e-3)
    volumes = sum(t.get("name") == "visibility volume" for t in figure["data"])
    assert loaded.layers == "0" * (volumes - 1) + "1"
    # Legend, sliders and axes alone cover about 3 % of that area, mostly dark grey text.
    seen = scene_shows_content(shot)
    assert seen["content"] > 0.08, seen
    assert seen["green"] > 0.02, seen  # a VV and the paths in line of sight
    assert seen["grey"] > 0.01, seen  # buildings


def test_report_options_from_the_command_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    scenario = Scenario.demo()
    scenario.planning.resolution_deg = 4.0
    scenario.baselines = []
    path = tmp_path / "s.yaml"
    import yaml

    path.write_text(yaml.safe_dump(scenario.to_dict()))
    out = tmp_path / "r"
    assert main(["run", str(path), "--out", str(out), "--quiet", "--no-html", "--frames", "7", "--duration",
                 "1.4"]) == 0
    assert not (out / "report.html").exists()
    check_gif(out / "trajectory.gif", 7, 1.4)
    assert "trajectory.gif" in (out / "report.md").read_text()
    out2 = tmp_path / "r2"
    assert main(["run", str(path), "--out", str(out2), "--quiet", "--no-animation", "--no-html"]) == 0
    assert not (out2 / "trajectory.gif").exists() and "trajectory.gif" not in (out2 / "report.md").read_text()
    capsys.readouterr()
    assert main(["run", str(path), "--out", str(out2), "--quiet", "--frames", "1"]) == 2
    assert "--frames = 1: must be an integer in [2, 1000]" in capsys.readouterr().err


@pytest.mark.parametrize("text, message", [
    ("report: {frames: 1}\n", "report.frames = 1: must be an integer in [2, 1000]"),
    ("report: {duration: 0}\n", "report.duration = 0: must be > 0"),
    ("report: {html: yes please}\n", "report.html = 'yes please': must be true or false"),
    ("report: {view: [100, 0]}\n", "report.view[0] = 100: must be <= 90"),
    ("report: {gif: true}\n", "report.gif = True: unknown key"),
])
def test_report_section_errors(text: str, message: str, tmp_path: Path) -> None:
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    with pytest.raises(vt.VistrackError) as error:
        Scenario.load(path)
    assert message in str(error.value)


def synthetic_scene(wind: bool = True) -> MotionScene:
    """A vehicle circling a point that drives east, with a footprint and wind (no city)."""
    t = np.linspace(0.0, 60.0, 601)
    target = np.column_stack([2.0 * t, np.zeros_like(t)])
    vehicle = target + 80.0 * np.column_stack([np.cos(0.2 * t), np.sin(0.2 * t)])
    visible = np.sin(0.3 * t) > -0.5

    def footprint(time: float) -> list[np.ndarray]:
        k = int(np.searchsorted(t, time).clip(0, len(t) - 1))
        return [circle_ring(vehicle[k], 25.0)]

    return MotionScene([Track("UAV", t, vehicle, z=100.0, flag=visible), Track("car", t, target, color="k")],
                       overlays=[Overlay("camera footprint", footprint)], sight=Sight(0, 1, t, visible),
                       wind=(3.0, -1.0) if wind else None, title="synthetic")


def test_gif_of_a_synthetic_scene(tmp_path: Path) -> None:
    path = write_gif(synthetic_scene(), tmp_path / "a.gif", frames=12, duration=3.0)
    check_gif(path, 12, 3.0)
    with pytest.raises(ValueError, match="frames = 1"):
        write_gif(synthetic_scene(), tmp_path / "b.gif", frames=1)


def test_html_of_a_synthetic_scene(tmp_path: Path) -> None:
    from vistrack.plotting.interactive import figure_3d
    from vistrack.report.document import Document, Picture, Table
    from vistrack.report.html import write_html

    scene = synthetic_scene()
    figure = figure_3d(scene, time_steps=20)
    write_gif(scene, tmp_path / "a.gif", frames=4)
    doc = Document("synthetic <test>", ["one `code` & **bold**"],
                   [Table(["a", "b"], [["1", "2"]]), Picture("a.gif", "GIF"), Picture("missing.png", "gone")])
    page = write_html(tmp_path / "report.html", doc, figure).read_text()
    assert "<title>synthetic &lt;test&gt;</title>" in page
    assert "<li>one <code>code</code> &amp; <strong>bold</strong></li>" in page
    assert "data:image/gif;base64," in page and "(missing.png was not written)" in page
    parsed = plotly_figure(page)
    names = [t.get("name", "") for t in parsed["data"]]
    assert "wind 3.2 m/s" in names and "camera footprint" in names and "UAV path, occluded" in names
    assert len(parsed["frames"]) == 20
    cone = parsed["data"][names.index("wind 3.2 m/s")]
    assert math.atan2(cone["v"][0], cone["u"][0]) == pytest.approx(math.atan2(-1.0, 3.0))
    # The markdown of the same document.
    markdown = doc.markdown()
    assert markdown.startswith("# synthetic <test>\n\n- one `code` & **bold**\n")
    assert "| a | b |\n|---|---|\n| 1 | 2 |" in markdown and "![GIF](a.gif)" in markdown


def test_clip_to_box_keeps_the_area_inside() -> None:
    """Clipped pieces against the exact areas: the right triangle with legs 2 cut by x, y <= 1
    keeps the unit square; one wholly inside stays whole; one outside goes; a wall is cut at the top."""
    from vistrack.plotting.volumes import clip_to_box

    def area(polygon: np.ndarray) -> float:
        return 0.5 * float(np.linalg.norm(sum(np.cross(polygon[0] - a, polygon[0] - b)
                                              for a, b in zip(polygon[1:], polygon[2:]))))

    cut = np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]])
    whole = cut * 0.25
    gone = cut + np.array([5.0, 0.0, 0.0])
    wall = np.array([[0.0, 0.5, 0.0], [0.5, 0.5, 0.0], [0.0, 0.5, 10.0]])  # vertical, 2.5 m^2
    pieces, origin = clip_to_box(np.array([cut, whole, gone, wall]), [-1, -1, -1], [1, 1, 4])
    assert sorted(origin.tolist()) == [0, 1, 3]
    by_origin = dict(zip(origin.tolist(), pieces))
    assert area(by_origin[0]) == pytest.approx(1.0)
    assert area(by_origin[1]) == pytest.approx(area(whole))
    assert area(by_origin[3]) == pytest.approx(2.5 - 0.5 * 0.3 * 6.0)  # the part above z = 4 is a 0.3 x 6 triangle
    assert all((p[:, 2] <= 4 + 1e-12).all() and (p[:, 0] <= 1 + 1e-12).all() for p in pieces)


def test_ellipse_ring_and_sampled_shapes() -> None:
    from vistrack.plotting.motion import ellipse_ring, sampled

    ring = ellipse_ring((10.0, -5.0), 30.0, 12.0, math.pi / 6)
    shoelace = 0.5 * abs(np.sum(ring[:, 0] * np.roll(ring[:, 1], -1) - np.roll(ring[:, 0], -1) * ring[:, 1]))
    assert shoelace == pytest.approx(math.pi * 30.0 * 12.0, rel=5e-3)  # inscribed 72-gon
    along = ring[0] - (10.0, -5.0)
    assert math.atan2(along[1], along[0]) == pytest.approx(math.pi / 6) and np.hypot(*along) == pytest.approx(30.0)
    shapes = sampled([0.0, 1.0, 2.0], [["a"], ["b"], ["c"]])  # type: ignore[list-item]
    assert [shapes(t)[0] for t in (-1.0, 0.0, 0.99, 1.0, 5.0)] == ["a", "a", "a", "b", "c"]


def test_write_media_adds_both_files_to_the_document(tmp_path: Path) -> None:
    from vistrack.report.document import Document, Picture
    from vistrack.report.media import write_media

    (tmp_path / "plans.png").write_bytes(b"\x89PNG\r\n\x1a\n" + b"0" * 100)
    doc = Document("planner", ["a line"], [Picture("plans.png", "Plans"), "closing words"])
    options = ReportOptions(frames=5, duration=1.0)
    made = write_media(tmp_path, synthetic_scene(), doc, options)
    assert set(made) == {"trajectory.gif", "report.html"}
    markdown = doc.markdown()
    assert markdown.index("![Plans](plans.png)") < markdown.index("![Animation](trajectory.gif)") \
        < markdown.index("closing words") < markdown.index("| report.html |")
    assert f"`report.html` ({made['report.html']['bytes'] / 1e6:.1f} MB" in markdown
    page = (tmp_path / "report.html").read_text()
    assert "| report.html |" not in page and "<td>trajectory.gif</td>" in page
    check_gif(tmp_path / "trajectory.gif", 5, 1.0)
    only_html = Document("planner", [], [])
    assert set(write_media(tmp_path / "b", synthetic_scene(), only_html, ReportOptions(animation=False))) == \
        {"report.html"}
    assert "| report.html |" in only_html.markdown()
