"""Issue 18's reproducers through the Python API and the CLI: no input crashes the interpreter, none
comes back as NaN or inf, every refusal is a VistrackError (or TypeError for a wrong Python type)
naming the field and the value, every CLI error is one line with exit status 2 (usage) or 1
(failure). Each test is one reproducer of the issue (the issue's wording in the docstring); the
C++ side of the same reproducers is tests/cpp/limits_test.cpp."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import vistrack as vt
from support.refusal import refuses
from vistrack import VistrackError, schema
from vistrack.cli import main as cli_main

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"


def cli(args: list[str], capsys: pytest.CaptureFixture[str]) -> tuple[int, str]:
    """Exit status and stderr of ``vistrack ARGS`` (in this process)."""
    status = cli_main(args)
    err = capsys.readouterr().err
    return status, err


def one_line_error(args: list[str], capsys: pytest.CaptureFixture[str], status: int, *fragments: str) -> str:
    code, err = cli(args, capsys)
    assert code == status, (code, err)
    assert err.count("\n") == 1 and "Traceback" not in err, err
    assert err.startswith("vistrack ") and ": error: " in err, err
    for fragment in fragments:
        assert fragment in err, f"{fragment!r} not in {err!r}"
    return err


# --- Crashes and unbounded memory ----------------------------------------------------------------


def test_huge_thread_counts_are_refused_not_a_segfault() -> None:
    """shortest_lengths(..., threads=100000) killed the interpreter with SIGSEGV."""
    q0, q1 = np.zeros((4, 3)), np.ones((4, 3))
    for threads in (100000, 2**31 - 1, -1):
        refuses(lambda t=threads: vt.dubins.shortest_lengths(q0, q1, 2.0, threads=t), f"threads = {threads}")
    lengths, _ = vt.dubins.shortest_lengths(q0, q1, 2.0, threads=1024)
    assert np.all(np.isfinite(lengths))


def test_huge_thread_count_in_a_fresh_interpreter() -> None:
    """The same call in its own process: it exits normally (a SIGSEGV would be returncode -11)."""
    code = ("import numpy as np, vistrack as vt\n"
            "try:\n vt.dubins.shortest_lengths(np.zeros((4,3)), np.ones((4,3)), 2.0, threads=100000)\n"
            "except vt.VistrackError as e:\n print(e)\n")
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    preload = "import sys; sys.path.insert(0, %r); import support.build_tree\n" % str(Path(__file__).resolve().parent)
    done = subprocess.run([sys.executable, "-c", preload + code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "threads = 100000" in done.stdout


def _paper_slow() -> vt.PoiPath:
    return vt.PoiPath(np.array([[0.0, 0.0], [1500.0, 0.0], [1500.0, 900.0]]), 5.0)


def test_work_estimate_refuses_tiny_spacing_before_any_volume() -> None:
    """Planning(spacing=0.01) grew until std::bad_alloc (tens of GB)."""
    poi = _paper_slow()
    planning = vt.Planning(spacing=0.01)
    work = vt.estimate_work(poi, planning)
    assert work.volumes > planning.max_volumes and work.bytes > 1e10
    env = vt.Environment.demo()
    message = refuses(lambda: vt.plan_orbits(env, poi, vt.Uav(), vt.Sensor(d_max=300.0), planning),
                      "planning.max_volumes = 20000", "GB", "raise planning.max_volumes")
    assert "\n" not in message


def test_work_estimate_refuses_a_10000_km_path() -> None:
    """A 10,000 km POI path grew until std::bad_alloc."""
    poi = vt.PoiPath(np.array([[0.0, 0.0], [1e7, 0.0]]), 5.0)
    refuses(lambda: vt.check_work(poi, vt.Planning()), "planning.max_volumes")
    raised = vt.Planning(max_volumes=10**12)
    vt.check_work(poi, raised)  # raising the limit explicitly allows it (nothing computed here)


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


# --- Silent NaN / inf / wrong answers ------------------------------------------------------------


@pytest.mark.parametrize("rho", [5e-324, 1e-300, 1e308, math.inf, math.nan, 0.0, -1.0])
def test_dubins_turn_radius_out_of_range(rho: float) -> None:
    """shortest_path((0,0,0),(10,5,1.0),5e-324).length was NaN; 1e-300 or 1e308 gave inf."""
    refuses(lambda: vt.dubins.shortest_path((0, 0, 0), (10, 5, 1.0), rho), "rho = ", "[1e-06, 1e+07] m")


def test_dubins_far_coordinates_and_huge_circles() -> None:
    """Coordinates 1e300 and path_to_circle(..., radius=1e300) gave inf."""
    refuses(lambda: vt.dubins.shortest_path((0, 0, 0), (1e300, 5, 1.0), 1.0), "q1.x = 1e+300")
    refuses(lambda: vt.dubins.path_to_circle((0, 0, 0), 1.0, (10, 0), 1e300, 0.5, "cw"), "radius = 1e+300")
    # Far from the origin on the scale of rho: refused naming rho and how far it may be.
    refuses(lambda: vt.dubins.shortest_path((2.6e6, 0, 0), (2.6e6 + 1, 0, 1.0), 1e-5), "rho = 1e-05",
            "translate the problem nearer the origin")


def test_visibility_volume_with_a_huge_range() -> None:
    """visibility_volume(env, (-150,-45,.5), 1e300).volume was NaN; an XOR against it returned the other's volume."""
    env = vt.Environment.demo()
    refuses(lambda: vt.visibility_volume(env, (-150.0, -45.0, 0.5), 1e300), "d_max = 1e+300", "[1e-06, 1e+07] m")
    refuses(lambda: vt.visibility_volume(env, (math.nan, -45.0, 0.5), 100.0), "nan")


def test_poi_path_polygon_and_angles_with_huge_values() -> None:
    """PoiPath([[-1e308,0],[1e308,0]]).velocity(0) was [nan, 0]; max_inscribed_radius on a 1e308
    polygon was inf; wrap_to_pi(inf) was NaN."""
    refuses(lambda: vt.PoiPath(np.array([[-1e308, 0.0], [1e308, 0.0]]), 5.0), "waypoints[0][0] = -1e+308",
            "[-1e+07, 1e+07] m")
    corners = np.array([[-1e308, -1e308], [1e308, -1e308], [1e308, 1e308], [-1e308, 1e308]])
    refuses(lambda: vt.max_inscribed_radius([vt.Polygon(corners)], (0.0, 0.0)), "outer[0][0] = -1e+308")
    refuses(lambda: vt.wrap_to_pi(math.inf), "angle = inf")
    refuses(lambda: vt.wrap_to_pi(math.nan), "angle = nan")


def test_line_of_sight_callable_returning_nan() -> None:
    """A line-of-sight callable returning NaN counted as visible (visibility_fraction 1.0)."""
    poi = vt.PoiPath(np.array([[-290.0, -210.0], [-100.0, -210.0]]), 5.0)
    uav = vt.Uav(altitude=200.0)
    plan = vt.constant_radius_plan(poi, 120.0, uav)

    def nan_sight(a: np.ndarray, b: np.ndarray) -> np.ndarray:
        return np.full(len(a), np.nan)

    refuses(lambda: vt.simulate(plan, uav, (-170.0, -210.0, 1.57), vt.Control(), line_of_sight=nan_sight),
            "line_of_sight")


def test_simulate_refuses_a_uav_under_the_ground() -> None:
    """simulate accepted a UAV below the ground (fraction 0.0) that plan_orbits rejects."""
    env = vt.Environment.demo()
    poi = vt.PoiPath(np.array([[-290.0, -210.0], [-100.0, -210.0]]), 5.0)
    plan = vt.constant_radius_plan(poi, 120.0, vt.Uav())
    refuses(lambda: vt.simulate(plan, vt.Uav(altitude=-5.0), (-170.0, -210.0, 1.57), vt.Control(), env),
            "uav.altitude = -5", "above the ground")


def test_mesh_xor_with_a_huge_perturbation() -> None:
    """xor_volume(..., method="mesh", perturbation=1e300) returned a wrong volume."""
    env = vt.Environment.demo()
    a = vt.visibility_volume(env, (-290.0, -210.0, 0.5), 200.0, resolution_deg=30.0)
    b = vt.visibility_volume(env, (-280.0, -210.0, 0.5), 200.0, resolution_deg=30.0)
    refuses(lambda: vt.xor_volume(a, b, method="mesh", perturbation=1e300), "perturbation = 1e+300")
    refuses(lambda: vt.xor_volume(a, b, method="mesh", perturbation=math.nan), "perturbation = nan")


def test_direction_grid_refuses_indices_out_of_range() -> None:
    """DirectionGrid.elevation(10**9) answered instead of refusing the index."""
    grid = vt.DirectionGrid.from_resolution(10.0)
    refuses(lambda: grid.elevation(10**9), "1000000000")
    refuses(lambda: grid.elevation(-1), "-1")
    refuses(lambda: grid.azimuth(10**9), "1000000000")
    assert math.isfinite(grid.elevation(0))


def test_csv_first_row_with_a_bad_number_is_not_a_header(tmp_path: Path) -> None:
    """A CSV whose first row is 0,0,0.5abc was silently taken as a header."""
    path = tmp_path / "a.csv"
    path.write_text("0,0,0.5abc\n10,0,0.5\n20,0,0.5\n")
    refuses(lambda: vt.PoiPath.from_csv(path, 5.0), "0.5abc", "not a number")
    header = tmp_path / "h.csv"
    header.write_text("x,y,z\n0,0,0.5\n10,0,0.5\n")
    assert vt.PoiPath.from_csv(header, 5.0).waypoints.shape == (2, 3)


def test_scenario_with_a_duplicated_section(tmp_path: Path) -> None:
    """A scenario YAML with a duplicated section kept the last one without a word."""
    from vistrack.scenario import Scenario

    path = tmp_path / "twice.yaml"
    path.write_text("environment: {demo: true}\nplanning: {spacing: 20.0}\nplanning: {spacing: 5.0}\n")
    refuses(lambda: Scenario.load(path), "planning", "twice")


def test_road_networks_are_checked_when_they_enter() -> None:
    """RoadNetwork accepted NaN nodes and out-of-range edges until later."""
    refuses(lambda: vt.RoadNetwork(np.array([[math.nan, 0.0], [1.0, 1.0]]), np.array([[0, 1]])), "nodes[0][0] = nan")
    refuses(lambda: vt.RoadNetwork(np.array([[0.0, 0.0], [1.0, 1.0]]), np.array([[0, 5]])), "edges[0]",
            "out of range")


# --- Wrong exception types and messages ----------------------------------------------------------


def _square_collection(height: str) -> str:
    return ('{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"height": ' + height
            + '}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,10],[0,10]]]}}]}')


def test_geojson_height_1e999(tmp_path: Path) -> None:
    """A GeoJSON height of 1e999 raised a bare RuntimeError."""
    path = tmp_path / "big.geojson"
    path.write_text(_square_collection("1e999"))
    refuses(lambda: vt.Environment.from_geojson(path), "not valid JSON")


def test_non_utf8_csv(tmp_path: Path) -> None:
    """A non-UTF-8 CSV raised UnicodeDecodeError (its byte position past the file's end)."""
    path = tmp_path / "u.csv"
    path.write_bytes(b"0,0\n\xff\xfe,1\n")
    message = refuses(lambda: vt.PoiPath.from_csv(path, 5.0), "\\xff\\xfe")
    message.encode("utf-8")


def test_a_folder_is_not_a_file(tmp_path: Path) -> None:
    """A directory passed as a file read "the GeoJSON file is empty"."""
    refuses(lambda: vt.Environment.from_geojson(tmp_path), "is a folder, not a GeoJSON file")
    refuses(lambda: vt.Environment.from_mesh(tmp_path, up="z"), "is a folder")
    refuses(lambda: vt.PoiPath.from_csv(tmp_path, 5.0), "is a folder")


def test_mesh_with_nan_vertices_or_bad_faces(tmp_path: Path) -> None:
    """A mesh with NaN vertices or out-of-range faces said only "cannot read a mesh from this file"."""
    nan = tmp_path / "n.obj"
    nan.write_text("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n")
    refuses(lambda: vt.Environment.from_mesh(nan, up="z"), "n.obj:2", "not finite")
    face = tmp_path / "f.obj"
    face.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    refuses(lambda: vt.Environment.from_mesh(face, up="z"), "f.obj:4", "names no vertex")


def test_ode_tolerances_out_of_range() -> None:
    """ODE tolerances of 1e-300 reported "ode.rhs = -nan"."""
    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        return -y

    refuses(lambda: vt.solve_ode(rhs, (0.0, 1.0), np.array([1.0]), rtol=1e-300), "rtol = 1e-300")
    refuses(lambda: vt.solve_ode(rhs, (0.0, 1.0), np.array([1.0]), atol=math.nan), "atol = nan")


@pytest.mark.parametrize("kind", ["garbage", "not-utf8"])
def test_cli_run_on_a_file_that_is_not_a_scenario(kind: str, tmp_path: Path,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    """`run` on a 10 MB garbage file and on a non-UTF-8 YAML printed a traceback."""
    path = tmp_path / "bad.yaml"
    rng = np.random.default_rng(18)
    path.write_bytes(rng.integers(0, 256, 10 * 2**20, dtype=np.uint8).tobytes() if kind == "garbage"
                     else "name: caf\u00e9\n".encode("latin-1"))
    one_line_error(["run", str(path), "--out", str(tmp_path / "out"), "--quiet"], capsys, 1, str(path))


@pytest.mark.parametrize("args, option", [
    (["orbits", "--from-plan", "{bin}"], "--from-plan"),
    (["simulate", "--plan", "{bin}"], "--plan"),
    (["intercept", "--config", "{bin}"], "--config"),
    (["volumes", "--map", "{city}", "--path", "{bin}"], "binary.dat:2"),
    (["volumes", "--map", "{huge}", "--path", "{csv}"], "huge.geojson"),
])
def test_cli_binary_and_overflowing_inputs_are_one_line(args: list[str], option: str, tmp_path: Path,
                                                        capsys: pytest.CaptureFixture[str]) -> None:
    """orbits --from-plan, simulate --plan, intercept --config and volumes --path with binary files,
    and volumes --map with the 1e999 GeoJSON, printed tracebacks: now one line naming the option
    (or, for a bad value inside a file, the file)."""
    binary = tmp_path / "binary.dat"
    binary.write_bytes(bytes(range(256)) * 64)
    huge = tmp_path / "huge.geojson"
    huge.write_text(_square_collection("1e999"))
    city = tmp_path / "city.geojson"
    city.write_text(_square_collection("10"))
    csv = tmp_path / "path.csv"
    csv.write_text("0,0\n10,0\n")
    argv = [a.format(bin=binary, huge=huge, csv=csv, city=city) for a in args]
    argv += ["--out", str(tmp_path / "out")] if args[0] not in ("intercept",) else []
    code, err = cli(argv, capsys)
    assert code in (1, 2), (code, err)
    assert err.count("\n") == 1 and "Traceback" not in err, err
    assert option in err, err


def test_cli_out_pointing_at_a_file_fails_before_the_run(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """`run --out` pointing at an existing file failed only after the whole run."""
    existing = tmp_path / "file.txt"
    existing.write_text("keep me\n")
    one_line_error(["run", str(REPO / "python" / "vistrack" / "scenarios" / "demo.yaml"), "--out", str(existing),
                    "--quiet"], capsys, 1, "--out", "is a file, not a folder")
    assert existing.read_text() == "keep me\n"


def test_cli_usage_errors_exit_2(capsys: pytest.CaptureFixture[str]) -> None:
    """Usage errors are exit status 2, one line, naming the option and the value."""
    one_line_error(["run"], capsys, 2, "scenario file is required")
    one_line_error(["run", "x.yaml", "--max-volumes", "-3"], capsys, 2, "--max-volumes")
    one_line_error(["intercept", "--rho", "nan"], capsys, 2, "--rho")
    # Ranges the library would refuse only after the inputs were read are the parser's too.
    one_line_error(["orbits", "--rate-margin", "1"], capsys, 2, "--rate-margin = 1.0", "[0, 1)")
    one_line_error(["simulate", "--plan", "p.json", "--fixed-step", "1e-10"], capsys, 2, "--fixed-step = 1e-10")
    one_line_error(["simulate", "--plan", "p.json", "--atol", "1e7"], capsys, 2, "--atol")
    one_line_error(["simulate", "--plan", "p.json", "--k-psi", "0"], capsys, 2, "--k-psi")
    one_line_error(["tune", "--beta", "1e4"], capsys, 2, "--beta")
    one_line_error(["tune", "--sweep", "0.01,5000"], capsys, 2, "--sweep = '5000'")


def test_gain_and_tolerance_ranges_are_the_same_everywhere() -> None:
    """beta, k_psi, rtol and atol have one range (limits.hpp), whichever entry point takes them."""
    lim = vt._core.limits
    assert (lim.MIN_GAIN, lim.MAX_BETA, lim.MAX_HEADING_GAIN) == (1e-9, 1e3, 1e6)
    assert (lim.MIN_RTOL, lim.MAX_RTOL, lim.MIN_ATOL, lim.MAX_ATOL) == (1e-13, 1.0, 1e-15, 1e6)
    too_big = lim.MAX_ATOL * 10
    refuses(lambda: vt.SimulationOptions(atol=too_big), "simulation.atol", "1e+06")  # the constructor checks
    refuses(lambda: vt.solve_ode(lambda t, y: -y, (0.0, 1.0), np.array([1.0]), atol=too_big), "ode.atol", "1e+06")
    refuses(lambda: vt.Control(beta=lim.MAX_BETA * 2), "control.beta", "1000")
    refuses(lambda: vt.Control(k_psi=0.0), "control.k_psi", "1e-09")
    refuses(lambda: vt.lemma7_min_gain(20.0, lim.MAX_BETA * 2), "beta", "1000")
    for section, key, value in [("control", "beta", 2e3), ("control", "k_psi", 0.0), ("simulation", "rtol", 1e-14),
                                ("simulation", "atol", 1e7), ("planning", "rate_margin", 1.0)]:
        refuses(lambda s=section, k=key, v=value: vt.Scenario.from_dict({s: {k: v}}), f"{section}.{key} = {value!r}")
    # The follow scenario's baseline controller and the beta sweep of `tune` take the same range.
    import yaml

    from vistrack.follow_scenario import FollowScenario
    from vistrack.tuning import default_sweep, tune_beta

    follow = yaml.safe_load((EXAMPLES / "follow_straight.yaml").read_text())
    follow["baseline"] = {"beta": 5000.0}
    refuses(lambda: FollowScenario.from_mapping(follow, EXAMPLES), "baseline.beta = 5000.0")
    follow["baseline"] = {"k_psi": 0.0}
    refuses(lambda: FollowScenario.from_mapping(follow, EXAMPLES), "baseline.k_psi = 0.0")
    refuses(lambda: tune_beta(85.9, 1.3, 20.0, 5.0, 50.0, 0.025, sweep=[0.01, 5000.0]), "sweep[1] = 5000.0")
    wide = default_sweep(500.0)  # tune_beta's sweep when none is given
    assert max(wide) == pytest.approx(lim.MAX_BETA) and min(wide) == pytest.approx(50.0)
    assert len(default_sweep(0.025)) == 30 and default_sweep(0.025)[0] == pytest.approx(0.0025)
    for check, low, high in [(schema.beta, lim.MIN_GAIN, lim.MAX_BETA),
                             (schema.heading_gain, lim.MIN_GAIN, lim.MAX_HEADING_GAIN),
                             (schema.relative_tolerance, lim.MIN_RTOL, lim.MAX_RTOL),
                             (schema.absolute_tolerance, lim.MIN_ATOL, lim.MAX_ATOL)]:
        assert check("k", low) == low and check("k", high) == high
        for outside in (low / 2, high * 2):
            refuses(lambda c=check, v=outside: c("k", v), f"k = {outside!r}")


# --- Wrong Python types --------------------------------------------------------------------------


@pytest.mark.parametrize("bad", [None, "abc", (1.0, 2.0), np.array([object(), 1, 2], dtype=object)])
def test_wrong_python_types_name_the_parameter(bad: Any) -> None:
    """None, a string, a 2-tuple where 3 are needed, an object array read as clearly as wrong values."""
    with pytest.raises((VistrackError, TypeError)) as raised:
        vt.dubins.shortest_path(bad, (10.0, 5.0, 1.0), 2.0)
    message = str(raised.value)
    assert "q0" in message or "incompatible function arguments" in message, message


# --- The new planners (waypoints, loiter, follow) get the same treatment -------------------------


@pytest.mark.parametrize("kwargs, fragment", [
    ({"turn_radius": 1e300}, "turn_radius = 1e+300"),
    ({"speed": math.nan}, "speed = nan"),
    ({"dt": 1e-12}, "more than 1e8 steps"),
    ({"start": (0.0, 0.0, math.inf)}, "start.psi = inf"),
    ({"start": (1e300, 0.0, 0.0)}, "start.x = 1e+300"),
])
def test_waypoint_navigation_refuses_out_of_range_inputs(kwargs: dict[str, Any], fragment: str) -> None:
    refuses(lambda: vt.waypoint_nav.fly([[0.0, 0.0], [200.0, 0.0], [200.0, 200.0]], **kwargs), fragment)


def test_waypoint_navigation_refuses_far_or_missing_waypoints() -> None:
    refuses(lambda: vt.waypoint_nav.fly([[0.0, 0.0], [1e300, 0.0]]), "1e+300")
    refuses(lambda: vt.waypoint_nav.fly([[math.nan, 0.0], [200.0, 0.0]]), "nan")
    with pytest.raises(VistrackError):
        vt.waypoint_nav.fly(np.zeros((0, 2)))
    refuses(lambda: vt.flight.Wind(east=1e300, north=0.0), "wind.east = 1e+300", "[-10000, 10000] m/s")
    # Fuzz finding (tests/fuzz/regressions/arrays/reachability-nan-pose): a NaN pose gave NaNs.
    wn = vt.waypoint_nav
    refuses(lambda: wn.reachability((math.nan, 0.0, 0.0), np.zeros((2, 2)), 10.0), "pose[0] = nan")
    refuses(lambda: wn.reachability((0.0, 0.0, 0.0), np.array([[1e300, 0.0]]), 10.0), "points[0][0] = 1e+300")
    refuses(lambda: wn.reachability((0.0, 0.0, 0.0), np.zeros((1, 2)), 1e300), "turn_radius = 1e+300")
    refuses(lambda: wn.turning_point((0.0, 0.0, 0.0), (1e300, 0.0), (0.0, 5.0), 1.0), "w_next.x = 1e+300")
    refuses(lambda: wn.turning_point((0.0, 0.0, 0.0), (9e6, 0.0), (9e6, 5.0), 1.0), "turn_radius = 1",
            "at most 1e6 turn radii")
    assert np.all(np.isfinite(wn.reachability((0.0, 0.0, 1e9), np.array([[1e7, -1e7], [0.0, 0.0]]), 1e-6)))


AOIS = [[200.0, 0.0], [500.0, 0.0], [500.0, 300.0]]


@pytest.mark.parametrize("kwargs, fragment", [
    ({"turn_radius": 1e300, "aoi_radius": 1e300}, "turn_radius = 1e+300"),
    ({"speed": 1e300}, "speed = 1e+300"),
    ({"start": "ab"}, "start = 'ab'"),
    ({"start": (math.nan, 0.0)}, "start[0] = nan"),
])
def test_loiter_plans_refuse_out_of_range_inputs(kwargs: dict[str, Any], fragment: str) -> None:
    refuses(lambda: vt.loiter.plan(AOIS, **kwargs), fragment)


def test_loiter_refuses_far_aois_too_many_and_nan_thresholds() -> None:
    refuses(lambda: vt.loiter.plan([[1e300, 0.0], [400.0, 0.0]]), "aois[0][0] = 1e+300")
    refuses(lambda: vt.loiter.plan(None), "aois = None")  # type: ignore[arg-type]
    many = np.column_stack([np.arange(10001) * 100.0, np.zeros(10001)])
    refuses(lambda: vt.loiter.plan(many, turn_radius=40.0, aoi_radius=40.0), "at most 10000 AOIs")
    plan = vt.loiter.plan(AOIS)
    refuses(lambda: vt.loiter.metrics(plan, threshold=math.nan), "threshold = nan")
    refuses(lambda: vt.loiter.fly(plan, wind=(1e300, 0.0)), "wind.east = 1e+300")


def _truck() -> Any:
    return vt.follow.GroundVehicle.from_legs([vt.follow.VehicleLeg(heading=0.0, speed=5.0, duration=60.0)], (0.0, 0.0))


def test_follow_refuses_out_of_range_inputs_and_wrong_shapes() -> None:
    F = vt.follow
    uav = vt.Uav(speed=20.0, min_turn_radius=40.0, altitude=100.0)
    truck = _truck()
    # update_period 1e-12 meant 6e13 planner updates: it hung.
    refuses(lambda: F.simulate(truck, uav, F.FollowParameters(update_period=1e-12)), "follow.update_period = 1e-12",
            "more than 1e8 planner updates")
    refuses(lambda: F.FollowParameters(offset_distance=1e300), "follow.offset_distance = 1e+300")
    refuses(lambda: F.simulate(truck, uav, wind=(1, 2, 3)), "wind = (1, 2, 3)")
    refuses(lambda: F.simulate(truck, uav, start=(0.0, 0.0)), "start = (0.0, 0.0)", "(x, y, psi)")
    refuses(lambda: F.simulate(truck, uav, start=(1e300, 0.0, 0.0)), "start[0] = 1e+300")
    refuses(lambda: F.baseline(truck, uav, 1e-300), "baseline.radius = 1e-300")
    refuses(lambda: F.GroundVehicle.from_legs([F.VehicleLeg(heading=0.0, speed=1e300, duration=60.0)], (0.0, 0.0)),
            "legs[0].speed = 1e+300")
    refuses(lambda: F.GroundVehicle.from_legs([F.VehicleLeg(heading=0.0, speed=1.0, duration=1e300, end_speed=2.0)],
                                              (0.0, 0.0)), "legs[0].duration = 1e+300", "more than 1e7 samples")
    refuses(lambda: F.GroundVehicle(np.array([0.0, 1.0]), np.array([[0.0, 0.0], [1e300, 0.0]])), "track.x")
    # A constant-speed leg is one piece whatever its length (only ramps are sampled every step).
    assert F.GroundVehicle.from_legs([F.VehicleLeg(heading=0.0, speed=1.0, duration=2e6)], (0.0, 0.0)).end_time == 2e6


def test_a_constant_speed_leg_reads_its_speed_not_nan() -> None:
    """VehicleLeg keeps NaN for "constant speed" inside; Python reads the effective end speed."""
    leg = vt.follow.VehicleLeg(heading=0.0, speed=8.0, duration=40.0)
    assert leg.end_speed == 8.0
    leg.end_speed = 3.0
    assert leg.end_speed == 3.0
    leg.end_speed = None
    leg.speed = 5.0
    assert leg.end_speed == 5.0
    truck = vt.follow.GroundVehicle.from_legs([leg], (0.0, 0.0))
    assert np.allclose(truck.position(20.0), (100.0, 0.0))


@pytest.mark.parametrize("args, status, fragment", [
    (["waypoints", "{route}", "--monte-carlo", "1000000000"], 2, "--monte-carlo = 1000000000"),
    (["waypoints", "{route}", "--turn-radius", "1e300"], 2, "--turn-radius = 1e+300"),
    (["waypoints", "{route}", "--out", "{file}"], 1, "--out"),
    (["loiter", "--random", "100000000", "--out", "{out}"], 2, "--random = 100000000"),
    (["loiter", "--random", "1", "--wind", "nan,0", "--out", "{out}"], 2, "--wind"),
    (["loiter", "--random", "1", "--out", "{file}"], 1, "is a file, not a folder"),
    (["follow", "{binary}"], 1, "not UTF-8"),
    (["sweep", "{binary}"], 1, "not UTF-8"),
])
def test_new_commands_bad_invocations_are_one_line(args: list[str], status: int, fragment: str, tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    """A monte-carlo count of 10^9 hung; --out on a file failed after the work (a Python errno line)."""
    route = tmp_path / "route.csv"
    route.write_text("x,y\n0,0\n200,0\n200,200\n")
    file = tmp_path / "afile"
    file.write_text("keep\n")
    binary = tmp_path / "binary.yaml"
    binary.write_bytes(b"garbage\x00\xff\n")
    argv = [a.format(route=route, file=file, out=tmp_path / "out", binary=binary) for a in args]
    one_line_error(argv, capsys, status, fragment)
    assert file.read_text() == "keep\n"


def test_yaml_keys_that_are_numbers_name_the_key(tmp_path: Path) -> None:
    """Found by the fuzzer (tests/fuzz/regressions/intercept/fuzz-integer-key.yaml): a YAML key
    such as ``0:`` raised TypeError while sorting the unknown keys."""
    from vistrack.follow_scenario import FollowScenario
    from vistrack.intercept import InterceptProblem

    path = tmp_path / "keys.yaml"
    path.write_text("0: w\nradius: 1.0\n")
    refuses(lambda: InterceptProblem.load(path, {}), "config.0")
    refuses(lambda: FollowScenario.load(path), "0 = 'w'", "unknown key")
    # The same in every loader that lists unknown keys (tests/fuzz/regressions/loiter/number-key.yaml).
    from vistrack.io import read_loiter_scenario
    from vistrack.scenario import Scenario
    from vistrack.sweep.spec import SweepSpec

    refuses(lambda: read_loiter_scenario(path), "0 = 'w'", "unknown key")
    refuses(lambda: Scenario.load(path), "0 = 'w'", "unknown section")
    refuses(lambda: SweepSpec.load(path), "0 = 'w'", "unknown key")
    loiter_sweep = tmp_path / "sweep.yaml"
    loiter_sweep.write_text("kind: loiter\nbase: {aois: [[300, 300]], 1: 2}\nparameters: {speed: [10, 12]}\n")
    refuses(lambda: SweepSpec.load(loiter_sweep), "1 = 2", "unknown key")


def test_numbers_too_long_for_python_are_refused(tmp_path: Path) -> None:
    """Found in review: Python reads at most 4300-digit integers and float() overflows past 1e308;
    both escaped as ValueError/OverflowError from the YAML and JSON loaders."""
    from vistrack import schema
    from vistrack.io import read_plan
    from vistrack.scenario import Scenario

    digits = "1" * 5000
    scenario = tmp_path / "long.yaml"
    scenario.write_text(f"poi: {{speed: {digits}}}\n")
    refuses(lambda: Scenario.load(scenario), "not valid YAML", "too long")
    plan = tmp_path / "long.json"
    plan.write_text(f'{{"format": {digits}}}')
    refuses(lambda: read_plan(plan), "not JSON", "too long")
    mission = tmp_path / "long.plan"
    mission.write_text(f'{{"fileType": {digits}}}')
    refuses(lambda: vt.mission.load(mission), "too long")
    refuses(lambda: schema.number("poi.speed", 10**400), "poi.speed = 'an integer of 401 digits'", "finite")


def test_python_values_of_the_wrong_kind_name_the_parameter() -> None:
    """Found in review: follow's radius and offset keys, and numpy thresholds (which are valid)."""
    truck = _truck()
    uav = vt.Uav(speed=20.0, min_turn_radius=40.0, altitude=100.0)
    refuses(lambda: vt.follow.baseline(truck, uav, "abc"), "baseline.radius = 'abc'")
    refuses(lambda: vt.follow.simulate(truck, uav, offset_schedule=[(0.0, 1.0)]), "offset_schedule[0]")
    plan = vt.loiter.plan(np.array([[300.0, 0.0]]), "tlpp")
    assert vt.loiter.coverage(plan, np.array([[300.0, 0.0]]), threshold=np.float32(0.75)).time > 0.0
    poi = vt.PoiPath(np.array([[0.0, 0.0], [1e6, 0.0]]), 5.0)
    refuses(lambda: vt.visibility.check_count(poi, 1.0, 100), "max_volumes = 100", "raise max_volumes")
