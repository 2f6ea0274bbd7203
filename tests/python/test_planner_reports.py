"""report.md, trajectory.gif and report.html of ``vistrack loiter`` and ``vistrack follow``: the
files exist as the options ask (frames, duration, --no-animation, --no-html), the page is
self-contained, and what the figure plots is what was flown: the aircraft and vehicle markers of
its frames against the run's CSV files, the camera footprints against the metric that scored them
(loiter's coverage fractions, follow's camera_sees), the line of sight against its CSV column."""

from __future__ import annotations

import csv
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from shapely.geometry import Point, Polygon

import vistrack as vt
from support.paths import EXAMPLES
from support.report_checks import check_gif, check_page
from vistrack.cli import main
from vistrack.io import load_environment
from vistrack.plotting.interactive import DEFAULT_TIME_STEPS, decode_array
from vistrack.report.loiter import footprint_shapes

LOITER = EXAMPLES / "loiter_4aoi.yaml"
FAST = ["--frames", "5", "--duration", "1.5"]


def columns(path: Path) -> dict[str, np.ndarray]:
    """The numeric columns of a CSV file with a header, by name (text columns left out)."""
    with open(path, encoding="utf-8") as file:
        rows = list(csv.DictReader(file))
    out = {}
    for key in rows[0]:
        try:
            out[key] = np.array([float(r[key]) for r in rows])
        except ValueError:
            continue
    return out


def marker_positions(figure: dict[str, Any], name: str) -> np.ndarray:
    """(frames, 3) the marker trace called ``name`` in every frame of the figure."""
    index = [t.get("name") for t in figure["data"]].index(name)
    rows = []
    for frame in figure["frames"]:
        trace = frame["data"][frame["traces"].index(index)]
        assert trace["mode"] == "markers"
        rows.append([float(decode_array(trace[c])[0]) for c in "xyz"])
    return np.array(rows)


def frame_trace(figure: dict[str, Any], frame: int, name: str) -> dict[str, Any]:
    index = [t.get("name") for t in figure["data"]].index(name)
    data = figure["frames"][frame]
    return data["data"][data["traces"].index(index)]


def assert_follows(positions: np.ndarray, t: np.ndarray, x: np.ndarray, y: np.ndarray, times: np.ndarray) -> None:
    """The markers sit where the samples (t, x, y), interpolated at the frame times, put them
    (float32 in the figure)."""
    assert positions[:, 0] == pytest.approx(np.interp(times, t, x), abs=2e-3)
    assert positions[:, 1] == pytest.approx(np.interp(times, t, y), abs=2e-3)


# ---- loiter ------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def loiter_report(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("loiter") / "one"
    assert main(["loiter", str(LOITER), "--method", "tlpp", "ldlpp", "--out", str(out), "--quiet", *FAST]) == 0
    return out


def test_loiter_report_files_and_gif(loiter_report: Path) -> None:
    check_gif(loiter_report / "trajectory.gif", 5, 1.5)
    _, figure = check_page(loiter_report)  # self-contained, every figure of report.md embedded
    markdown = (loiter_report / "report.md").read_text()
    for text in ("| TLPP |", "| LDLPP |", "![Plans (the paper's Figures 6, 9, 12)](plans.png)",
                 "![Animation](trajectory.gif)", "| report.html |"):
        assert text in markdown, text
    names = [t.get("name") for t in figure["data"]]
    for name in ("AOI", "TLPP plan", "LDLPP plan", "TLPP", "LDLPP", "TLPP camera footprint",
                 "LDLPP camera footprint"):
        assert name in names, name
    assert not any(str(n).startswith("wind") for n in names)  # no wind given: no arrow
    low, top = figure["layout"]["scene"]["zaxis"]["range"]
    assert low <= 0.0 and top > vt.loiter.load_scenario(LOITER).camera.altitude  # footprints on the ground in view


def test_loiter_figure_plots_the_sampled_plans(loiter_report: Path) -> None:
    """Each method's marker over the frames against its path CSV (the samples the coverage
    scored), the aircraft at the camera's altitude."""
    _, figure = check_page(loiter_report)
    paths = {m: columns(loiter_report / f"path_{m}.csv") for m in ("tlpp", "ldlpp")}
    t0 = min(float(p["t"][0]) for p in paths.values())
    t1 = max(float(p["t"][-1]) for p in paths.values())
    times = np.linspace(t0, t1, DEFAULT_TIME_STEPS)
    assert len(figure["frames"]) == DEFAULT_TIME_STEPS
    altitude = vt.loiter.load_scenario(LOITER).camera.altitude
    for method, name in (("tlpp", "TLPP"), ("ldlpp", "LDLPP")):
        p = paths[method]
        positions = marker_positions(figure, name)
        assert_follows(positions, p["t"], p["x"], p["y"], times)
        assert positions[:, 2] == pytest.approx(altitude)


def test_loiter_footprints_are_the_ones_scored() -> None:
    """The drawn footprint at each step (camera tilted by cov.tilt) holds, of each AOI, the
    fraction the coverage metric counted (a 72-gon against the exact ellipse: within 2 %)."""
    scenario = vt.loiter.load_scenario(LOITER)
    plan = scenario.plan("fly_through")
    cov = scenario.coverage(plan)
    samples = plan.sample_states(scenario.dt, False)
    t, poses = np.asarray(samples.t), np.asarray(samples.poses)
    shapes = footprint_shapes(scenario.camera, t, poses, cov)
    disks = [Point(c).buffer(scenario.aoi_radius, 256) for c in np.asarray(scenario.aois)]
    checked = 0
    for k in range(0, len(poses), 7):
        footprint = Polygon(shapes(float(t[k]))[0])
        for i, disk in enumerate(disks):
            expected = float(cov.fraction[k, i])
            if expected > 0.05:
                assert footprint.intersection(disk).area / disk.area == pytest.approx(expected, abs=0.02)
                checked += 1
    assert checked > 10


def test_loiter_in_wind_animates_the_flown_path(tmp_path: Path) -> None:
    out = tmp_path / "wind"
    assert main(["loiter", str(LOITER), "--method", "ldlpp", "--wind", "6,-2", "--out", str(out), "--quiet",
                 "--no-animation"]) == 0
    assert not (out / "trajectory.gif").exists()
    assert "trajectory.gif" not in (out / "report.md").read_text()
    _, figure = check_page(out)
    names = [t.get("name") for t in figure["data"]]
    assert "wind 6.3 m/s" in names
    scenario = vt.loiter.load_scenario(LOITER)
    rows, _ = vt.loiter.flown_samples(vt.loiter.fly(scenario.plan("ldlpp"), (6.0, -2.0), uav=scenario.uav()),
                                      scenario.dt)
    t = scenario.dt * np.arange(len(rows))
    plan = columns(out / "path_ldlpp.csv")
    assert len(rows) != len(plan["t"])  # the wind changed the flight: not the plan's samples
    assert_follows(marker_positions(figure, "LDLPP"), t, rows[:, 0], rows[:, 1],
                   np.linspace(t[0], t[-1], DEFAULT_TIME_STEPS))


def test_loiter_no_html_and_several_scenarios(tmp_path: Path) -> None:
    out = tmp_path / "two"
    assert main(["loiter", str(LOITER), str(EXAMPLES / "loiter_5aoi.yaml"), "--method", "ldlpp", "--out", str(out),
                 "--quiet", "--no-html", "--frames", "3", "--duration", "0.6"]) == 0
    folders = sorted(p for p in out.iterdir() if p.is_dir())
    assert len(folders) == 2
    for folder in folders:
        assert not (folder / "report.html").exists()
        check_gif(folder / "trajectory.gif", 3, 0.6)
        assert "![Animation](trajectory.gif)" in (folder / "report.md").read_text()


# ---- follow ------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def follow_report(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("follow") / "wind"
    assert main(["follow", str(EXAMPLES / "follow_wind.yaml"), "--out", str(out), "--no-city", "--quiet",
                 *FAST]) == 0
    return out


def test_follow_report_files_and_gif(follow_report: Path) -> None:
    check_gif(follow_report / "trajectory.gif", 5, 1.5)
    assert not (follow_report / "trajectory_open.gif").exists()  # no city: the open-ground run is the main one
    _, figure = check_page(follow_report)
    names = [t.get("name") for t in figure["data"]]
    for name in ("planned path", "UAV path", "vehicle path", "UAV", "vehicle", "camera footprint", "wind 10 m/s"):
        assert name in names, name
    assert "line of sight" not in names  # only with a city
    markdown = (follow_report / "report.md").read_text()
    for text in ("| sinusoid planner (the paper) |", "| vector field (74), constant radius |",
                 "![Paths (the paper's view)](follow_paths.png)", "![Animation](trajectory.gif)"):
        assert text in markdown, text


def test_follow_figure_plots_the_flown_run(follow_report: Path) -> None:
    """The UAV and vehicle markers against trajectory.csv; the footprint of a frame holds the
    vehicle exactly when the CSV's in_view (the metric's camera_sees) says so."""
    _, figure = check_page(follow_report)
    flown = columns(follow_report / "trajectory.csv")
    times = np.linspace(flown["t"][0], flown["t"][-1], DEFAULT_TIME_STEPS)
    uav = marker_positions(figure, "UAV")
    assert_follows(uav, flown["t"], flown["x"], flown["y"], times)
    assert uav[:, 2] == pytest.approx(200.0)
    assert_follows(marker_positions(figure, "vehicle"), flown["t"], flown["vehicle_x"], flown["vehicle_y"], times)
    agree = 0
    for k in range(0, DEFAULT_TIME_STEPS, 3):
        ring = frame_trace(figure, k, "camera footprint")
        xy = np.column_stack([decode_array(ring["x"]), decode_array(ring["y"])])
        footprint = Polygon(xy[np.isfinite(xy).all(axis=1)])
        sample = int(np.searchsorted(flown["t"], times[k], side="right")) - 1
        vehicle = Point(flown["vehicle_x"][sample], flown["vehicle_y"][sample])
        if footprint.exterior.distance(vehicle) > 3.0:  # simplified ring: skip the boundary
            assert footprint.contains(vehicle) == bool(flown["in_view"][sample]), k
            agree += 1
    assert agree > 20


@pytest.mark.parametrize("psi, bank, target", [(0.3, 0.0, (40.0, 20.0)), (1.2, 0.35, (-150.0, 90.0)),
                                               (-2.0, -0.6, (120.0, -60.0)), (0.0, 0.75, (0.0, -400.0))])
def test_follow_camera_footprint_is_the_cone_camera_sees(psi: float, bank: float,
                                                         target: tuple[float, float]) -> None:
    """Points on a grid are inside the footprint ring exactly where camera_sees says they are in
    view (the gimbal pointed at ``target``); where the cone's section is bounded, the ring lies on
    loiter's exact ellipse for the same tilt (an independent formula)."""
    camera = vt.follow.DownwardCamera()
    uav = (10.0, -5.0, 200.0)
    ring = vt.follow.camera_footprint(camera, uav, psi, bank, target, points=360)
    footprint = Polygon(ring)
    # camera_sees points the gimbal at the point it tests: fix the gimbal by aiming it at target,
    # then test each point against the cone about that axis, as the drawing does.
    left = np.array([-math.sin(psi), math.cos(psi)])
    lateral = math.atan2(float((np.asarray(target) - uav[:2]) @ left), uav[2])
    tilt = min(max(bank + lateral, -camera.max_gimbal), camera.max_gimbal) - bank  # to the left of vertical
    half = 0.5 * camera.fov
    axis = np.array([-math.sin(tilt) * math.sin(psi), math.sin(tilt) * math.cos(psi), -math.cos(tilt)])
    grid = np.stack(np.meshgrid(np.linspace(-700, 700, 71), np.linspace(-700, 700, 71)), axis=-1).reshape(-1, 2)
    inside_cone = []
    for p in grid:
        r = np.array([p[0] - uav[0], p[1] - uav[1], -uav[2]])
        inside_cone.append(r @ axis >= math.cos(half) * np.linalg.norm(r))
    reach = 4.0 * uav[2]
    for p, seen in zip(grid, inside_cone):
        near = footprint.exterior.distance(Point(p)) < 4.0
        beyond = math.hypot(p[0] - uav[0], p[1] - uav[1]) > reach - 5.0
        if not near and not beyond:
            assert footprint.contains(Point(p)) == seen, (p, seen)
    if abs(tilt) + half < math.radians(80):  # bounded, and within the 4 h reach
        f = vt.loiter.Camera(fov_deg=math.degrees(camera.fov), altitude=uav[2]).footprint((uav[0], uav[1], psi), tilt)
        d = ring - np.asarray(f.center)
        along = np.asarray(f.along)
        u, v = d @ along, d @ np.array([-along[1], along[0]])
        assert (u / f.semi_along) ** 2 + (v / f.semi_across) ** 2 == pytest.approx(np.ones(len(ring)), abs=1e-9)
    # camera_sees itself (gimbal pointed at the tested point) agrees at the aimed target.
    assert vt.follow.camera_sees(camera, uav, psi, bank, (*target, 0.0)) == footprint.contains(Point(target))


def test_follow_city_animates_line_of_sight(charlotte: Path, tmp_path: Path) -> None:
    """A minute on the Charlotte road: buildings, the line of sight green or red as the city
    trajectory's column says, the UAV at the scenario's altitude, and the open-ground run as a second GIF."""
    scenario = tmp_path / "city.yaml"
    scenario.write_text(
        "uav: {speed: 21.0, min_turn_radius: 50.0, altitude: 150.0}\n"
        "vehicle: {start: [0, 0], legs: [{heading: north, speed: 10.0, duration: 60.0}]}\n"
        "baseline: false\n"
        f"city: {{mesh: {charlotte / 'uptown_charlotte.obj'}, up: y, road: {charlotte / 'paths' / '3d.csv'}}}\n")
    out = tmp_path / "city"
    assert main(["follow", str(scenario), "--out", str(out), "--quiet", "--frames", "4", "--duration", "1"]) == 0
    check_gif(out / "trajectory.gif", 4, 1.0)
    check_gif(out / "trajectory_open.gif", 4, 1.0)
    _, figure = check_page(out)
    names = [t.get("name") for t in figure["data"]]
    assert any(str(n).startswith("buildings (") for n in names)
    flown = columns(out / "city_trajectory.csv")
    times = np.linspace(flown["t"][0], flown["t"][-1], DEFAULT_TIME_STEPS)
    uav = marker_positions(figure, "UAV")
    assert_follows(uav, flown["t"], flown["x"], flown["y"], times)
    env = load_environment(charlotte / "uptown_charlotte.obj", up="y")
    assert uav[:, 2] == pytest.approx(env.ground_level + 150.0, abs=1e-3)
    colors = []
    for k in range(DEFAULT_TIME_STEPS):
        sample = int(np.searchsorted(flown["t"], times[k], side="right")) - 1
        color = frame_trace(figure, k, "line of sight")["line"]["color"]
        assert (color == "#1a9850") == bool(flown["line_of_sight"][sample]), k
        colors.append(color)
    assert set(colors) == {"#1a9850", "#d73027"}  # this minute has both (60 % of it in sight)
    assert "![Animation on open ground (the paper's setting)](trajectory_open.gif)" in (out / "report.md").read_text()
