"""vt.waypoint_nav: turning points, the paper's claims on the example route, the Monte Carlo,
route files, bad input and the ``vistrack waypoints`` command."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import vistrack as vt
from support.paths import REPO
from support.refusal import refuses
from vistrack import VistrackError
from vistrack import waypoint_nav as wn
from vistrack.cli import main
from vistrack.io import read_route

ROUTE = REPO / "examples" / "waypoints_paper.csv"
R = wn.DEFAULTS["turn_radius"]

pytestmark = pytest.mark.sanitize  # the input-facing surface (scripts/sanitize.sh)


@pytest.fixture(scope="module")
def route() -> np.ndarray:
    return read_route(ROUTE)


@pytest.fixture(scope="module")
def calm(route: np.ndarray) -> list[wn.NavigationFlight]:
    return wn.paper_flights(route)


@pytest.fixture(scope="module")
def windy(route: np.ndarray) -> list[wn.NavigationFlight]:
    # Unknown constant wind, 10 % of the airspeed, from the bottom of the figure (section 3.4).
    return wn.paper_flights(route, wind=vt.flight.Wind(north=0.1 * wn.DEFAULTS["speed"]))


def test_defaults_are_the_papers_section_3() -> None:
    assert wn.DEFAULTS["turn_radius"] == 0.7 and wn.DEFAULTS["speed"] == 0.8 and wn.DEFAULTS["dt"] == 0.02
    assert wn.DEFAULTS["gains"] == (0.1, 5.25)


def test_example_route_has_the_papers_geometry(route: np.ndarray) -> None:
    legs = np.diff(route, axis=0)
    assert len(route) == 6
    assert np.all(np.linalg.norm(legs, axis=1) >= 4 * R)
    headings = np.arctan2(legs[:, 1], legs[:, 0])
    turns = np.abs((np.diff(headings) + math.pi) % (2 * math.pi) - math.pi)
    assert np.all(turns <= math.pi / 2 + 1e-12)


def test_turning_point_api() -> None:
    tp = wn.turning_point((0.0, 0.0, 0.0), (4.0, 0.0), (9.0, 0.0), 1.0)
    assert tp.length == pytest.approx(9.0, abs=1e-12)
    assert tp.case in ("ccw-ccw", "cw-cw", "cw-ccw", "ccw-cw")
    np.testing.assert_allclose(tp.point, (4.0, 0.0), atol=1e-9)
    path = wn.horizon_path((0.0, 0.0, 0.0), (4.0, 0.0), (9.0, 0.0), 1.0, tp.case, tp.theta)
    assert path.length == pytest.approx(tp.length, abs=1e-12)
    lengths = wn.horizon_lengths((0.0, 0.0, 0.0), (4.0, 0.0), (9.0, 0.0), 1.0, tp.case, np.linspace(0, 6, 50))
    assert lengths.min() >= tp.length - 1e-12


def test_dwn_passes_every_waypoint_without_wind(calm: list[wn.NavigationFlight]) -> None:
    dwn = calm[0]
    assert dwn.method == "dwn" and dwn.all_reached and dwn.swirls == 0
    assert np.all(dwn.miss_distances < 0.05 * R)


def test_wn_at_a_tenth_of_r_overshoots_without_wind(calm: list[wn.NavigationFlight]) -> None:
    dwn, small, half, full = calm
    assert small.waypoint_radius == pytest.approx(0.1 * R)
    # Passes close but turns late: the overshoot is far larger than DWN's.
    assert small.overshoot > 2.5 * dwn.overshoot
    # Larger radii turn early: they miss the waypoints by about their radius (the undershoot).
    assert np.median(half.miss_distances) > 0.1 * R
    assert np.median(full.miss_distances) > 0.35 * R
    assert full.undershoot > 2.5 * dwn.undershoot


def test_with_unknown_wind_dwn_never_swirls(windy: list[wn.NavigationFlight]) -> None:
    dwn = windy[0]
    assert dwn.swirls == 0 and dwn.all_reached
    assert np.all(dwn.miss_distances < 0.25 * R)


def test_with_unknown_wind_our_wn_does_not_swirl_at_the_papers_radii(route: np.ndarray,
                                                                      windy: list[wn.NavigationFlight]) -> None:
    # At 0.1 R and above, the law (5) points the vehicle at the waypoint every step, and a pursuer
    # in a steady wind ends its approach heading into the wind: no swirl in 0.1 v wind.
    assert all(f.swirls == 0 and f.all_reached for f in windy[1:])
    tiny = wn.fly(route, method="wn", waypoint_radius=0.02 * R, wind=vt.flight.Wind(north=0.08))
    assert tiny.swirls == 0 and tiny.all_reached


def test_figure_12_wn_swirls_below_the_threshold_and_dwn_never(route: np.ndarray) -> None:
    """Issue 32: WN as printed swirls at R_WP = 0.01 R in 0.1 v wind (Fig. 12) and at 0.02 R in 0.2 v,
    counted as loops around the waypoint in either direction; DWN in the same winds does not."""
    v = wn.DEFAULTS["speed"]
    winds = [vt.flight.Wind(east=w * v * math.cos(a), north=w * v * math.sin(a))
             for w in (0.1, 0.2) for a in np.linspace(0.0, 2 * math.pi, 8, endpoint=False)]
    at_tenth = [wn.fly(route, method="wn", waypoint_radius=0.01 * R, wind=w).swirls for w in winds[:8]]
    at_fifth = [wn.fly(route, method="wn", waypoint_radius=0.02 * R, wind=w).swirls for w in winds[8:]]
    assert sum(s > 0 for s in at_tenth) >= 4 and max(at_tenth) >= 3
    assert sum(s > 0 for s in at_fifth) >= 3
    assert all(wn.fly(route, method="dwn", wind=w).swirls == 0 for w in winds)
    # Loops are counted, not the heading's excursion: a flight that swirls takes longer by about a
    # loop's time each (2 pi R / v = 5.5 s).
    calm = wn.fly(route, method="wn", waypoint_radius=0.1 * R)
    worst = wn.fly(route, method="wn", waypoint_radius=0.01 * R, wind=winds[int(np.argmax(at_tenth))])
    assert worst.duration > calm.duration + 2 * math.pi * R / v


def test_flight_result_shapes(calm: list[wn.NavigationFlight], route: np.ndarray) -> None:
    dwn = calm[0]
    traj = dwn.trajectory
    assert traj.shape[1] == 4 and traj[0, 0] == 0.0
    np.testing.assert_allclose(traj[0, 1:3], route[0])
    assert dwn.turning_points.shape == (len(route) - 1, 2)
    np.testing.assert_allclose(dwn.turning_points[-1], route[-1])  # the last is flown to directly
    m = dwn.metrics()
    json.dumps(m)
    assert m["max_miss_over_R"] < 0.05
    assert calm[1].turning_points.shape == (0, 2)
    assert dwn.fuel == pytest.approx(dwn.path_length)  # w_a = w_s = 1 and no wind: air distance


def test_start_pose_flies_every_waypoint(route: np.ndarray) -> None:
    f = wn.fly(route, start=(-3.0, 0.0, 0.0))
    assert len(f.miss_distances) == len(route) and f.all_reached


def test_continuous_integration_agrees(route: np.ndarray, calm: list[wn.NavigationFlight]) -> None:
    c = wn.fly(route, integration="continuous")
    assert c.all_reached and np.all(c.miss_distances < 0.05 * R)
    assert c.path_length == pytest.approx(calm[0].path_length, rel=0.01)


def test_fuel_weights_move_theta_less_than_four_degrees() -> None:
    data = wn.theta_against_weight()
    assert set(data["cases"]) == {"ccw-ccw"}
    assert 0.0 < data["theta_range_deg"] < 4.0


@pytest.mark.parametrize(
    ("call", "field"),
    [
        (lambda r: wn.fly(r[:1]), "waypoints"),
        (lambda r: wn.fly(np.vstack([r[:2], r[1:2]])), "waypoints[1]"),
        (lambda r: wn.fly(r, turn_radius=0.0), "turn_radius"),
        (lambda r: wn.fly(r, dt=2.0), "dt"),
        (lambda r: wn.fly(r, dt=0.0), "dt"),
        (lambda r: wn.fly(r, wind=vt.flight.Wind(east=0.8)), "wind"),
        (lambda r: wn.fly(np.vstack([r, [[math.nan, 1.0]]])), "waypoints[6].x"),
        (lambda r: wn.fly(r, start=(0.0, math.nan, 0.0)), "start.y"),
        (lambda r: wn.fly(r, method="dubins"), "method"),
        (lambda r: wn.fly(r, method="dwn", waypoint_radius=0.1), "waypoint_radius"),
        (lambda r: wn.turning_point((0.0, 0.0, 0.0), (1.0, 0.0), (2.0, 0.0), -1.0), "turn_radius"),
    ],
)
def test_bad_input_names_the_field(route: np.ndarray, call, field: str) -> None:
    with pytest.raises(vt.VistrackError, match=field.replace("[", r"\[").replace("]", r"\]")):
        call(route)


def test_monte_carlo_is_seeded_and_dwn_never_swirls() -> None:
    a = wn.monte_carlo(runs=4, seed=7)
    b = wn.monte_carlo(runs=4, seed=7)
    assert len(a.rows) == 4 * 2 * 4
    for x, y in zip(a.rows, b.rows):
        assert x["label"] == y["label"] and x["wind_speed"] == y["wind_speed"]
        np.testing.assert_array_equal(x["miss_over_R"], y["miss_over_R"])
    summary = {(s["gusts"], s["label"]): s for s in a.summary()}
    assert summary[(False, "DWN")]["swirl_rate"] == 0.0 and summary[(True, "DWN")]["swirl_rate"] == 0.0
    assert wn.monte_carlo(runs=2, seed=8).rows[0]["wind_speed"] != a.rows[0]["wind_speed"]


def test_read_route_errors(tmp_path: Path) -> None:
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y\n0,0\n1,abc\n")
    with pytest.raises(vt.VistrackError, match="line 3"):
        read_route(bad)
    bad.write_text("x,y\n0,0\n")
    with pytest.raises(vt.VistrackError, match="at least two"):
        read_route(bad)
    plain = tmp_path / "plain.csv"
    plain.write_text("0,0\n4,0\n")
    np.testing.assert_array_equal(read_route(plain), [[0, 0], [4, 0]])
    with pytest.raises(vt.VistrackError, match="route"):
        read_route(tmp_path / "missing.csv")


def test_cli_waypoints(tmp_path: Path) -> None:
    out = tmp_path / "wp"
    before = ROUTE.read_bytes()
    assert main(["waypoints", str(ROUTE), "--paper-units", "--method", "both", "--wind", "0,0.08", "--gusts", "3",
                 "--figure-weights", "--monte-carlo", "2", "--quiet", "--out", str(out)]) == 0
    assert ROUTE.read_bytes() == before
    assert "Monte Carlo over random routes and winds" in (out / "report.md").read_text()
    assert (out / "waypoints_zoom.png").stat().st_size > 10_000
    assert "waypoints_zoom.png" in (out / "report.md").read_text()
    assert "| swirl rate |" in (out / "report.md").read_text()
    record = json.loads((out / "metrics.json").read_text())
    assert [f["label"] for f in record["flights"]] == ["DWN", "WN R_WP=0.1R", "WN R_WP=0.5R", "WN R_WP=1R"]
    for name in ("paths.png", "fig10_theta_weight.png", "monte_carlo.png", "monte_carlo.json",
                 "trajectory_dwn.csv", "trajectory_wn_0.1R.csv", "turning_points_dwn.csv"):
        assert (out / name).is_file(), name
    header = (out / "trajectory_dwn.csv").read_text().splitlines()[0]
    assert header.startswith("t,x,y,psi,command")
    np.testing.assert_allclose(read_route(out / "turning_points_dwn.csv")[-1], read_route(ROUTE)[-1])


def test_dwn_mission_carries_the_turning_points_and_pymavlink_reads_it(tmp_path: Path,
                                                                         calm: list[wn.NavigationFlight]) -> None:
    mavwp = pytest.importorskip("pymavlink.mavwp", reason="pymavlink not installed")
    ref = vt.Georeference(35.2249, -80.8403)
    dwn = calm[0]
    assert dwn.method == "dwn"
    mission = dwn.to_mission(ref, 60.0, speed=0.8)
    path = mission.save(tmp_path / "route.waypoints")
    loader = mavwp.MAVWPLoader()
    assert loader.load(str(path)) == len(dwn.turning_points) + 2  # home, DO_CHANGE_SPEED, one per point
    lat, lon = ref.to_latlon(dwn.turning_points[:, 0], dwn.turning_points[:, 1])
    waypoints = [loader.wp(i) for i in range(loader.count()) if loader.wp(i).command == 16][1:]  # after home
    np.testing.assert_allclose([w.x for w in waypoints], lat, atol=1e-7)
    np.testing.assert_allclose([w.y for w in waypoints], lon, atol=1e-7)
    assert all(w.z == 60.0 and w.param2 == 0.0 for w in waypoints)
    # WN's mission is its waypoints, each with the acceptance radius it flew with.
    wn_flight = calm[1]
    wn_mission = wn_flight.to_mission(ref, 60.0)
    radii = [item.params[1] for item in wn_mission.items]
    assert radii == [wn_flight.waypoint_radius] * (len(wn_flight.waypoints) + 1)  # the start, then the waypoints


def test_cli_report_and_export(tmp_path: Path) -> None:
    out = tmp_path / "wp"
    assert main(["waypoints", str(ROUTE), "--paper-units", "--quiet", "--out", str(out), "--frames", "12", "--origin",
                 "35.2249,-80.8403", "--export", str(out / "route.plan")]) == 0
    for name in ("report.md", "report.html", "trajectory.gif", "route.plan"):
        assert (out / name).stat().st_size > 500, name
    assert "trajectory.gif" in (out / "report.md").read_text()
    plan = json.loads((out / "route.plan").read_text())
    assert plan["fileType"] == "Plan" and len(plan["mission"]["items"]) >= 5
    assert main(["waypoints", str(ROUTE), "--paper-units", "--quiet", "--out", str(tmp_path / "x"), "--export",
                 str(tmp_path / "x.plan")]) == 2  # no origin to georeference the route
    assert not (tmp_path / "x").exists()  # refused before any output


def test_cli_bad_route_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    bad = tmp_path / "r.csv"
    bad.write_text("x,y\n0,0\n")
    assert main(["waypoints", str(bad), "--out", str(tmp_path / "o")]) == 1
    assert "ROUTE" in capsys.readouterr().err


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


# ---------------------------------------------------------------------------------------------
# Routes in metres on the roll model (issue 28): the practitioner's default of the CLI.

METRES = REPO / "examples" / "waypoints_metres.csv"


def test_metres_example_is_the_paper_route_at_75_m_per_unit(route: np.ndarray) -> None:
    np.testing.assert_array_equal(read_route(METRES), 75.0 * route)


def test_paper_gains_scale_with_the_turn_radius() -> None:
    assert vt.flight.paper_gains(0.7) == pytest.approx(wn.DEFAULTS["gains"], rel=1e-15)
    g, h = vt.flight.paper_gains(50.0)
    assert (g, h) == pytest.approx((0.1 * 0.7 / 50.0, 5.25 * 0.7 / 50.0), rel=1e-15)
    # The law (5) is then the paper's at its proportions: a route scaled with R gives the same
    # flight on the Dubins vehicle when time is scaled too (same v dt / R per step).
    paper = wn.fly(read_route(ROUTE), method="wn", waypoint_radius=0.35)
    scaled = wn.fly(75.0 * read_route(ROUTE), method="wn", waypoint_radius=75.0 * 0.35, turn_radius=75.0 * 0.7,
                    speed=75.0 * 0.8, gains=vt.flight.paper_gains(75.0 * 0.7))
    np.testing.assert_allclose(scaled.trajectory[:, 1:3] / 75.0, paper.trajectory[:, 1:3], atol=1e-9)


@pytest.mark.parametrize("method, radius", [("dwn", None), ("wn", 5.0), ("wn", 50.0)])
def test_roll_model_flies_a_metre_route_smoothly_with_l1(method: str, radius: float | None) -> None:
    uav = vt.Uav()
    route = read_route(METRES)
    flight = wn.fly(route, method=method, waypoint_radius=radius, turn_radius=uav.min_turn_radius, speed=uav.speed,
                    dynamics="roll", guidance="l1", l1_period=8.0, wind=vt.flight.Wind(north=2.0))
    assert flight.all_reached and flight.finished and flight.swirls == 0
    smooth = flight.flight.smoothness()
    assert smooth.roll_reversals_per_s < 1.0
    assert smooth.max_roll_rate_deg_s <= uav.max_roll_rate_deg_s * (1 + 1e-9)
    bank = np.asarray(flight.flight.bank)
    assert np.abs(bank).max() <= math.atan(uav.speed**2 / (9.80665 * uav.min_turn_radius)) + 1e-12
    # The same flight on the Dubins vehicle turns at once: its command jumps where the roll model ramps.
    dubins = wn.fly(route, method=method, waypoint_radius=radius, turn_radius=uav.min_turn_radius, speed=uav.speed,
                    dynamics="dubins", guidance="l1", l1_period=8.0, wind=vt.flight.Wind(north=2.0))
    assert dubins.flight.smoothness().max_roll_rate_deg_s > 5 * uav.max_roll_rate_deg_s


def test_law5_flies_on_the_roll_model_too_and_chatters_more_than_l1() -> None:
    route = read_route(METRES)
    common = {"turn_radius": 50.0, "speed": 20.0, "dynamics": "roll", "integration": "continuous"}
    law5 = wn.fly(route, method="wn", waypoint_radius=5.0, gains=vt.flight.paper_gains(50.0), guidance="law5",
                  **common)
    l1 = wn.fly(route, method="wn", waypoint_radius=5.0, guidance="l1", **common)
    assert law5.all_reached and l1.all_reached
    assert law5.flight.smoothness().roll_reversals_per_s > 2 * l1.flight.smoothness().roll_reversals_per_s
    with pytest.raises(VistrackError, match="guidance"):
        wn.fly(route, guidance="pid", **common)
    with pytest.raises(VistrackError, match="roll_time_constant"):
        wn.fly(route, roll_time_constant=-1.0, **common)


def test_options_carry_the_vehicle_model() -> None:
    options = wn.Options(dynamics="roll", guidance="l1", l1_period=12.0)
    assert (str(options.dynamics), str(options.guidance), options.l1_period) == ("roll", "l1", 12.0)
    assert "dynamics='roll'" in repr(options) and "l1_period=12" in repr(options)
    assert str(wn.Options().dynamics) == "dubins" and str(wn.Options().guidance) == "law5"


def test_cli_flies_metres_on_the_roll_model_by_default(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "m"
    assert main(["waypoints", str(METRES), "--quiet", "--out", str(out), "--frames", "4", "--wind", "0,2",
                 "--gusts", "3"]) == 0
    printed = capsys.readouterr().out
    assert "roll vehicle, legs by l1, R = 50, v = 20 (metres, m/s)" in printed
    record = json.loads((out / "metrics.json").read_text())
    settings = record["settings"]
    assert (settings["units"], settings["dynamics"], settings["guidance"]) == ("metres", "roll", "l1")
    assert settings["turn_radius"] == 50.0 and settings["speed"] == 20.0
    for flight in record["flights"]:
        assert flight["all_reached"] and flight["swirls"] == 0
        assert flight["smoothness"]["roll_reversals_per_s"] < 1.0
    assert "bank.png" in record["figures"] and (out / "bank.png").stat().st_size > 10_000
    assert "Bank flown" in (out / "report.md").read_text() and "roll reversals/s" in (out / "report.md").read_text()


def test_cli_route_units_are_checked_before_any_output(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from support.cli import one_line_error

    out = tmp_path / "o"
    one_line_error(["waypoints", str(ROUTE), "--out", str(out)], capsys, 2, "ROUTE", "--paper-units")
    one_line_error(["waypoints", str(METRES), "--paper-units", "--out", str(out)], capsys, 2, "ROUTE",
                   "drop --paper-units")
    one_line_error(["waypoints", str(ROUTE), "--paper-units", "--dynamics", "roll", "--out", str(out)], capsys, 2,
                   "--dynamics = roll")
    assert not out.exists()


# ---------------------------------------------------------------------------------------------
# Routes in (issue 32): the command reads its own export, missions and GeoJSON.

@pytest.mark.parametrize("suffix", [".plan", ".waypoints"])
def test_exported_route_reads_back_within_a_micrometre(tmp_path: Path, suffix: str) -> None:
    route = read_route(METRES)
    origin = vt.Georeference(60.17, 24.94, 12.0)
    flight = wn.fly(route, method="wn", turn_radius=50.0, speed=20.0, waypoint_radius=5.0)
    path = flight.to_mission(origin, 80.0, speed=20.0).save(tmp_path / f"route{suffix}")
    np.testing.assert_allclose(wn.read_route(path), route, atol=1e-6)  # about the mission's home
    np.testing.assert_allclose(wn.read_route(path, origin=(60.17, 24.94, 12.0)), route, atol=1e-6)
    home = wn.route_georeference(path)
    assert home is not None and (home.lat, home.lon) == pytest.approx((60.17, 24.94))
    moved = wn.read_route(path, origin=(60.171, 24.94))  # another origin: the same route, shifted south
    assert np.all(moved[:, 1] < route[:, 1] - 100.0)


def test_cli_flies_its_own_export(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "a"
    assert main(["waypoints", str(METRES), "--method", "wn", "--quiet", "--out", str(out), "--frames", "4",
                 "--origin", "60.17,24.94", "--export", str(tmp_path / "r.waypoints")]) == 0
    again = tmp_path / "b"
    assert main(["waypoints", str(tmp_path / "r.waypoints"), "--method", "wn", "--quiet", "--out", str(again),
                 "--frames", "4", "--export", str(tmp_path / "r2.plan")]) == 0  # placed about its home
    first = json.loads((out / "metrics.json").read_text())["flights"][0]
    second = json.loads((again / "metrics.json").read_text())["flights"][0]
    assert second["path_length"] == pytest.approx(first["path_length"], rel=1e-9)
    np.testing.assert_allclose(wn.read_route(tmp_path / "r2.plan"), read_route(METRES), atol=1e-6)


def test_geojson_routes_need_an_origin(tmp_path: Path) -> None:
    origin = vt.Georeference(48.136, 10.069)
    route = read_route(METRES)
    lat, lon = origin.to_latlon(route[:, 0], route[:, 1])
    line = {"type": "Feature", "geometry": {"type": "LineString", "coordinates": [[x, y] for x, y in zip(lon, lat)]}}
    points = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "geometry": {"type": "Point", "coordinates": [x, y]}} for x, y in zip(lon, lat)]}
    for name, document in (("line.geojson", line), ("points.geojson", points)):
        path = tmp_path / name
        path.write_text(json.dumps(document))
        np.testing.assert_allclose(wn.read_route(path, origin=origin), route, atol=1e-6)
        with pytest.raises(VistrackError, match="origin"):
            wn.read_route(path)
    bad = tmp_path / "bad.geojson"
    bad.write_text(json.dumps({"type": "LineString", "coordinates": [[200.0, 10.0], [0.0, 0.0]]}))
    with pytest.raises(VistrackError, match="longitudes"):
        wn.read_route(bad, origin=origin)



def test_arduplane_switching_never_swirls_on_random_routes_and_winds() -> None:
    """Issue 32: WN switching as ArduPlane does (past the finish line, or inside the turn distance)
    reaches every waypoint without a loop where the paper's WN swirls, on seeded random routes and
    winds of up to 0.5 v from any direction, at acceptance radii down to 0.01 R."""
    rng = np.random.default_rng(32)
    v = wn.DEFAULTS["speed"]
    paper_swirls = 0
    for _ in range(12):
        route = wn.random_route(rng, 6, R)
        w = rng.uniform(0.0, 0.5) * v
        a = rng.uniform(0.0, 2 * math.pi)
        wind = vt.flight.Wind(east=w * math.cos(a), north=w * math.sin(a))
        for fraction in (0.01, 0.1):
            line = wn.fly(route, method="wn_passed_line", waypoint_radius=fraction * R, wind=wind)
            assert line.swirls == 0 and line.all_reached and line.label.startswith("WN-line")
            paper_swirls += wn.fly(route, method="wn", waypoint_radius=fraction * R, wind=wind).swirls
    assert paper_swirls > 0  # the same routes and winds make the paper's WN loop


def test_cli_flies_all_three_methods(tmp_path: Path) -> None:
    out = tmp_path / "all"
    assert main(["waypoints", str(METRES), "--method", "all", "--quiet", "--out", str(out), "--frames", "4"]) == 0
    labels = [f["label"] for f in json.loads((out / "metrics.json").read_text())["flights"]]
    assert labels[0] == "DWN" and "WN R_WP=0.1R" in labels and "WN-line R_WP=0.1R" in labels


def test_per_waypoint_and_per_leg_tables_agree_with_the_flight(calm: list[wn.NavigationFlight]) -> None:
    """Issue 32: the tables a report prints, checked against the trajectory itself."""
    for flight in calm:
        rows, legs = flight.waypoint_table(), flight.leg_table()
        assert len(rows) == len(flight.waypoints) and len(legs) == len(flight.waypoints)
        traj = flight.trajectory
        for row, w in zip(rows, flight.waypoints):
            assert row["miss"] == pytest.approx(np.min(np.hypot(traj[:, 1] - w[0], traj[:, 2] - w[1])), abs=0.02)
            i = int(np.searchsorted(traj[:, 0], row["time"]))
            assert np.hypot(traj[i, 1] - w[0], traj[i, 2] - w[1]) <= row["miss"] + 0.8 * 0.02 + 1e-12
            assert 0.0 <= row["overshoot"] <= flight.overshoot + 1e-12
        assert max(r["overshoot"] for r in rows) == pytest.approx(flight.overshoot, abs=1e-12)
        assert sum(leg["time"] for leg in legs) == pytest.approx(rows[-1]["time"] - traj[0, 0], abs=1e-9)
        assert sum(leg["flown"] for leg in legs) <= flight.path_length + 1e-9
        # Independent of how the table is built: in calm air the ground speed is the airspeed, so
        # each leg's flown distance is v times its time (the discrete flight's chords: 2e-5 shorter).
        for leg in legs:
            assert leg["flown"] == pytest.approx(wn.DEFAULTS["speed"] * leg["time"], rel=1e-3, abs=1e-9)
        route = np.vstack([flight.start[:2], flight.waypoints])
        np.testing.assert_allclose([leg["length"] for leg in legs], np.linalg.norm(np.diff(route, axis=0), axis=1))
        metrics = flight.metrics()
        assert metrics["max_miss_over_R"] == pytest.approx(flight.miss_distances.max() / R)
        assert metrics["miss_at_last_over_R"] == pytest.approx(flight.miss_distances[-1] / R)


def test_cli_writes_the_waypoint_and_leg_tables(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "t"
    assert main(["waypoints", str(ROUTE), "--paper-units", "--method", "wn", "--waypoint-radius", "0.07",
                 "--quiet", "--out", str(out), "--frames", "4"]) == 0
    printed = capsys.readouterr().out
    assert "(the last, at its finish line:" in printed
    report = (out / "report.md").read_text()
    assert "waypoints and legs" in report and "miss at the last (R)" in report
    lines = (out / "waypoints_wn_0.1R.csv").read_text().splitlines()
    assert lines[0] == "waypoint,x,y,miss,miss_over_R,time,overshoot,overshoot_over_R,reached"
    assert len(lines) == 1 + 5 and (out / "legs_wn_0.1R.csv").read_text().startswith("leg,length,time,flown")



def test_wind_aware_legs_steer_the_course_and_miss_less(route: np.ndarray) -> None:
    """Issue 32: with the mean wind known, the law (5) steers the course over the ground: WN at 0.1 R
    misses less in 0.3 v wind from 8 directions; in calm air it is the same flight."""
    v = wn.DEFAULTS["speed"]
    plain, aware = 0.0, 0.0
    for a in np.linspace(0.0, 2 * math.pi, 8, endpoint=False):
        wind = vt.flight.Wind(east=0.3 * v * math.cos(a), north=0.3 * v * math.sin(a))
        plain = max(plain, wn.fly(route, method="wn", waypoint_radius=0.1 * R, wind=wind).miss_distances[:-1].max())
        flight = wn.fly(route, method="wn", waypoint_radius=0.1 * R, wind=wind, wind_aware=True)
        assert flight.all_reached and flight.swirls == 0
        aware = max(aware, flight.miss_distances[:-1].max())
    assert aware < 0.5 * plain and aware < 0.02 * R
    calm = wn.fly(route, method="wn", waypoint_radius=0.1 * R)
    calm_aware = wn.fly(route, method="wn", waypoint_radius=0.1 * R, wind_aware=True)
    np.testing.assert_allclose(calm_aware.trajectory, calm.trajectory, atol=1e-9)
    with pytest.raises(VistrackError, match="wind"):
        wn.fly(route, wind=vt.flight.Wind(east=0.9), wind_aware=True)


def test_navigation_guidance_is_what_navigate_flies(route: np.ndarray) -> None:
    """navigation_guidance (the guidance a 6-DOF aircraft flies, vistrack.waypoint_nav.fdm) flown by
    vistrack.flight.fly gives navigate()'s flight to the bit, for DWN and WN, each leg law, with a
    wind-aware DWN; navigation_time_limit is navigate()'s limit; WN refuses DWN's re-planning."""
    from vistrack._core import waypoint_nav as core

    assert wn.navigation_guidance is core.navigation_guidance and wn.navigation_time_limit is core.navigation_time_limit

    pose, flown = (float(route[0, 0]), float(route[0, 1]), 0.3), route[1:]
    wind = vt.flight.Wind(east=0.1, north=-0.05)
    for kwargs, kind in (({"method": "dwn"}, core.DubinsWaypointGuidance),
                         ({"method": "dwn", "guidance": "l1", "wind_aware": True}, core.DubinsWaypointGuidance),
                         ({"method": "wn", "waypoint_radius": 0.2}, vt.flight.WaypointFollower),
                         ({"method": "wn_passed_line", "guidance": "l1"}, vt.flight.WaypointFollower)):
        options = core.Options(**kwargs)
        guidance = core.navigation_guidance(flown, pose, options, wind)
        assert isinstance(guidance, kind)
        limit = core.navigation_time_limit(flown, pose, options)
        expected = core.navigate(flown, pose, wind=wind, **kwargs)
        assert limit == expected.max_time
        flight = vt.flight.fly(guidance, pose, options.speed, options.turn_radius, wind=wind, dt=options.dt,
                               max_time=limit)
        assert np.array_equal(flight.x, expected.trajectory.x) and np.array_equal(flight.y, expected.trajectory.y)
    length = np.linalg.norm(flown[0] - route[0]) + np.linalg.norm(np.diff(flown, axis=0), axis=1).sum()
    assert core.navigation_time_limit(flown, pose, core.Options()) == pytest.approx(
        3 * (length + 2 * math.pi * 0.7 * len(flown)) / 0.8, rel=1e-12)
    assert core.navigation_time_limit(flown, pose, core.Options(max_time=12.5)) == 12.5
    refuses(lambda: core.navigation_guidance(flown, pose, core.Options(method="wn", replan_interval=5.0)),
            "replan_interval")
    refuses(lambda: core.navigation_guidance(flown[:0], pose, core.Options()), "waypoints")
    refuses(lambda: core.navigation_time_limit(flown, pose, core.Options(speed=0.0)), "speed")
    refuses(lambda: core.navigation_time_limit(np.array([[0.0, math.nan]]), pose, core.Options()), "waypoints[0].y")
