"""Following a ground vehicle (vt.follow): the amplitude against scipy's elliptic integral, the
generated path's length, the hysteresis, the offset geometry, wind compensation, the baseline
against vt.simulate, bad input, the CLI and the city runs."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.cli import NO_MEDIA
from support.paths import EXAMPLES
from support.refusal import refuses
from support.threads import ticks_during
from support.vehicles import east_truck
from vistrack import follow
from vistrack.follow_scenario import FollowScenario

NORTH, EAST, SOUTH, WEST = math.pi / 2, 0.0, -math.pi / 2, math.pi
UAV = vt.Uav(speed=21.0, min_turn_radius=50.0, altitude=200.0)

pytestmark = pytest.mark.sanitize  # the input-facing surface (scripts/sanitize.sh)


def _amplitude_by_scipy(sigma: float, distance: float) -> float:
    """brentq on sigma = (2/pi) E(-A'^2) with scipy's ellipe (the parameter convention), independent
    of our elliptic integrals and of our solver."""
    from scipy.optimize import brentq
    from scipy.special import ellipe

    slope = brentq(lambda a: 2.0 / math.pi * ellipe(-a * a) - sigma, 0.0, math.pi * sigma, xtol=1e-300, rtol=1e-15,
                   maxiter=500)
    return slope * distance / (2.0 * math.pi)


@pytest.mark.parametrize("sigma", np.geomspace(1.001, 10.0, 25))
def test_amplitude_matches_scipy_ellipe(sigma: float) -> None:
    pytest.importorskip("scipy")
    for distance in (1.0, 300.0, 5000.0):
        ours = follow.sinusoid_amplitude(sigma, distance)
        assert ours == pytest.approx(_amplitude_by_scipy(sigma, distance), rel=1e-12)
        assert follow.speed_ratio(ours, distance) == pytest.approx(sigma, rel=1e-14)


def test_amplitude_on_arrays_and_at_one() -> None:
    sigmas = np.array([1.0, 1.5, 2.0, 3.0])
    amplitudes = follow.sinusoid_amplitude(sigmas, 400.0)
    assert amplitudes.shape == (4,)
    assert amplitudes[0] == 0.0
    assert np.all(np.diff(amplitudes) > 0)
    with pytest.raises(vt.VistrackError, match=r"speed_ratio = 0\.9"):
        follow.sinusoid_amplitude(0.9, 400.0)


def test_one_generated_period_is_sigma_d_long() -> None:
    # The planner's desired path over one period, on the ground, sampled finely.
    planner = follow.FollowPlanner(follow.FollowParameters(period=60.0, threshold=3.0), UAV)
    velocity = np.array([0.0, -9.0])
    tick = planner.update(0.0, follow.FollowObservation(vehicle_position=np.zeros(2), vehicle_velocity=velocity,
                                                        vehicle_heading=SOUTH))
    assert tick.mode == "sinusoid" and not tick.capturing
    taus = np.linspace(0.0, tick.period, 20001)
    points = np.array([velocity * tau + planner.relative_position(tick, tau) for tau in taus])
    length = np.linalg.norm(np.diff(points, axis=0), axis=1).sum()
    assert length == pytest.approx(tick.speed_ratio * tick.period_distance, rel=1e-6)
    # ... and it is y = A sin(2 pi x / D) about the vehicle's track (x south, y east).
    along, across = -points[:, 1], points[:, 0]
    assert np.allclose(across, tick.amplitude * np.sin(2 * np.pi * along / tick.period_distance), atol=1e-6)


def _switches(speeds: list[float], leg: float = 5.0) -> tuple[int, list[str]]:
    vehicle = follow.GroundVehicle.from_legs([follow.VehicleLeg(EAST, v, leg) for v in speeds])
    result = follow.simulate(vehicle, UAV, follow.FollowParameters(threshold=3.0, hysteresis=0.6))
    return result.metrics["mode_switches"], [t.mode for t in result.ticks]


def test_speed_oscillating_inside_the_band_does_not_switch() -> None:
    # sigma = 21 / v between 2.8 and 3.2: inside the band (2.7, 3.3) about h = 3.
    switches, modes = _switches([21.0 / 2.8, 21.0 / 3.2] * 12)
    assert switches == 0
    assert set(modes) == {"sinusoid"}


def test_one_crossing_of_the_band_switches_once() -> None:
    # A vehicle slowing from sigma 2 to sigma 4 through the band with +-0.25 noise on sigma.
    sigmas = [2.0 + 0.1 * k + (0.25 if k % 2 else -0.25) for k in range(20)] + [4.0 + (0.25 if k % 2 else -0.25)
                                                                              for k in range(8)]
    switches, modes = _switches([21.0 / s for s in sigmas])
    assert switches == 1
    assert modes[0] == "sinusoid" and modes[-1] == "loiter"


@pytest.mark.parametrize("reference", ["north", "heading"])
def test_offset_point_in_both_references(reference: str) -> None:
    # 100 m at 90 degrees: north on the map, or to the left of the vehicle.
    vehicle = follow.GroundVehicle.from_legs([follow.VehicleLeg(EAST, 8.0, 40.0), follow.VehicleLeg(NORTH, 8.0, 40.0)])
    parameters = follow.FollowParameters(offset_distance=100.0, offset_angle=math.pi / 2, offset_reference=reference)
    result = follow.simulate(vehicle, UAV, parameters)
    t = result.t
    offset = result.offset_point - result.vehicle
    east_leg, north_leg = (t > 1) & (t < 39), (t > 41) & (t < 79)
    assert np.allclose(offset[east_leg], [0.0, 100.0], atol=1e-9)
    expected = [0.0, 100.0] if reference == "north" else [-100.0, 0.0]
    assert np.allclose(offset[north_leg], expected, atol=1e-9)
    for tick in result.ticks:  # the planner's offset point at every update
        heading = vehicle.heading(tick.t)
        angle = math.pi / 2 + (heading if reference == "heading" else 0.0)
        assert np.allclose(tick.offset_point, vehicle.position(tick.t) + 100.0 * np.array([math.cos(angle),
                                                                                           math.sin(angle)]))


def test_compensation_lowers_the_tracking_error_and_centres_the_path() -> None:
    scenario = FollowScenario.load(EXAMPLES / "follow_wind.yaml")
    scenario.parameters.threshold = 3.0  # the paper's Figs. 6-7
    on = scenario.run(compensation=True, city=False).follow.metrics
    off = scenario.run(compensation=False, city=False).follow.metrics
    assert on["mean_tracking_error_m"] < 0.5 * off["mean_tracking_error_m"]
    assert np.hypot(*on["centre_offset_m"]) < 0.5 * np.hypot(*off["centre_offset_m"])


def test_waypoints_at_one_hertz_and_desired_path_followed() -> None:
    vehicle = follow.GroundVehicle.from_legs([follow.VehicleLeg(SOUTH, 10.0, 200.0)])
    result = follow.simulate(vehicle, UAV, follow.FollowParameters(threshold=3.0))
    assert np.allclose(np.diff(result.waypoint_times), 1.0)
    assert result.waypoints.shape == (len(result.ticks), 2)
    m = result.metrics
    assert m["mean_tracking_error_m"] < 0.5 and m["max_tracking_error_m"] < 5.0
    assert m["time_in_mode_s"]["sinusoid"] == pytest.approx(200.0)
    assert 0.0 < m["camera_fraction"] < 1.0


def test_a_faster_vehicle_is_chased_straight_with_a_growing_lag() -> None:
    vehicle = follow.GroundVehicle.from_legs([follow.VehicleLeg(EAST, 25.0, 120.0)])
    result = follow.simulate(vehicle, UAV)
    m = result.metrics
    assert m["time_in_mode_s"]["straight"] == pytest.approx(120.0)
    lag = np.asarray(result.run.along_track_lag)
    assert np.all(np.isfinite(lag)) and np.all(np.isfinite(result.state))
    assert m["final_along_track_lag_m"] == pytest.approx((25.0 - 21.0) * 120.0, rel=0.05)


def test_baseline_agrees_with_the_tracking_pipeline() -> None:
    # The vector-field follower flown by the flight layer (Dormand-Prince) against vt.simulate on a
    # PoiPath with a constant-radius plan: the same closed loop by two independent integrations.
    vehicle = follow.GroundVehicle.from_legs([follow.VehicleLeg(SOUTH, 10.0, 150.0)])
    radius = follow.baseline_radius(vehicle, UAV)
    result = follow.baseline(vehicle, UAV, radius, flight=follow.FollowFlight(integration="continuous", dt=0.1))
    poi = vt.PoiPath(np.array([[0.0, 0.0, 0.0], [0.0, -1500.0, 0.0]]), 10.0)
    plan = vt.constant_radius_plan(poi, radius, UAV)
    reference = vt.simulate(plan, UAV, tuple(result.state[0]), vt.Control(),
                            options=vt.SimulationOptions(output_step=0.1, rtol=1e-10, atol=1e-12))
    n = min(len(reference.t), len(result.t))
    assert np.allclose(reference.t[:n], result.t[:n])
    assert np.abs(reference.state[:n, :2] - result.state[:n, :2]).max() < 1e-5
    assert result.metrics["max_tracking_error_m"] < 0.1


@pytest.mark.parametrize(("call", "field"), [
    (lambda: vt.Uav(speed=0.0), "uav.speed"),
    (lambda: follow.FollowParameters(period=0.0), "follow.period"),
    (lambda: follow.FollowParameters(threshold=3.0, hysteresis=3.5), "follow.hysteresis"),
    (lambda: follow.GroundVehicle(np.array([0.0, 2.0, 1.0]), np.zeros((3, 2))), "track.t[2]"),
    (lambda: follow.GroundVehicle(np.array([0.0, 1.0, 2.0]), np.array([[0, 0], [np.nan, 0], [1, 1]])), "track.x[1]"),
    (lambda: follow.simulate(follow.GroundVehicle.from_legs([follow.VehicleLeg(0.0, 5.0, 10.0)]), UAV,
                             wind=(0.0, 21.0)), "wind"),
    (lambda: follow.FollowParameters(loiter_pattern="square"), "follow.loiter_pattern"),
    (lambda: follow.FollowParameters(offset_reference="up"), "follow.offset_reference"),
])
def test_bad_input_names_the_field(call, field: str) -> None:
    with pytest.raises(vt.VistrackError, match="^" + re.escape(field) + " = "):
        call()


def test_old_follow_spellings(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Before the one schema: city.map still loads (a mesh, Y up by default) with one line naming
    its new key; city.altitude, which was no rename, is refused; gusts: false means no gusts."""
    legs = "vehicle: {legs: [{heading: east, speed: 5, duration: 10}]}\n"
    path = tmp_path / "old.yaml"
    path.write_text(legs + "city: {map: city.obj, road: road.csv}\nwind: {north: 3, gusts: false}\n")
    scenario = FollowScenario.load(path)
    assert scenario.city is not None and scenario.city.kind == "mesh" and scenario.city.up == "y"
    assert scenario.city.path == tmp_path / "city.obj" and scenario.city.road == tmp_path / "road.csv"
    assert scenario.wind.gusts is None and scenario.wind.north == 3.0
    assert capsys.readouterr().out.startswith("vistrack: 'city.map' is now 'city.mesh' (still read;")
    path.write_text(legs + "city: {map: city.geojson, road: road.csv}\n")
    city = FollowScenario.load(path).city
    assert city is not None and city.kind == "geojson"
    path.write_text(legs + "city: {map: city.obj, road: road.csv, altitude: 300}\n")
    refuses(lambda: FollowScenario.load(path), "city.altitude = 300", "the flight altitude is uav.altitude")
    path.write_text(legs + "city: {mesh: city.obj}\n")
    refuses(lambda: FollowScenario.load(path), "city = ", "road: a CSV path")


def test_scenario_errors_name_the_key(tmp_path: Path) -> None:
    def load(text: str) -> FollowScenario:
        path = tmp_path / "s.yaml"
        path.write_text(text)
        return FollowScenario.load(path)

    with pytest.raises(vt.VistrackError, match=r"^vehicle\.legs\[0\]\.heading = 'up'"):
        load("vehicle: {legs: [{heading: up, speed: 5, duration: 10}]}")
    with pytest.raises(vt.VistrackError, match=r"^speed = "):
        load("speed: 3\nvehicle: {legs: [{heading: east, speed: 5, duration: 10}]}")
    # The wind's speed against the airspeed is the flight's one check (WindField), made when it flies.
    too_windy = load("uav: {speed: 20}\nwind: {north: 25}\nvehicle: {legs: [{heading: east, speed: 5, duration: 10}]}")
    with pytest.raises(vt.VistrackError, match=r"^wind = "):
        too_windy.run(city=False)
    # Angles are limited to |a| <= 1e9 rad (5.73e10 degrees); 1e300 degrees was accepted.
    with pytest.raises(vt.VistrackError,
                       match=r"^vehicle\.legs\[0\]\.heading_deg = '1e300': must be <= 5\.72958e\+10 and >= -5\.7"):
        load("vehicle: {legs: [{heading_deg: 1e300, speed: 5, duration: 10}]}")
    # A period of 1e300 s flew a straight line 1 km off with tracking error 0: (0, 3600] s.
    with pytest.raises(vt.VistrackError, match=r"^follow\.period = 1e\+300: must be a finite number in \(0, 3600\] s$"):
        load("follow: {period: 1e300}\nvehicle: {legs: [{heading: east, speed: 5, duration: 10}]}").run(city=False)
    with pytest.raises(vt.VistrackError, match=r"^follow\.hysteresis = 4"):
        load("follow: {threshold: 3, hysteresis: 4}\nvehicle: {legs: [{heading: east, speed: 5, duration: 10}]}")
    for bad in ("-1", "1", "fast", "0"):
        with pytest.raises(vt.VistrackError, match=rf"^follow\.threshold = '?{bad}'?: must be \"auto\" or a number"):
            load(f"follow: {{threshold: {bad}}}\nvehicle: {{legs: [{{heading: east, speed: 5, duration: 10}}]}}")
    track = tmp_path / "track.csv"
    track.write_text("t,x,y\n0,0,0\n2,10,0\n1,20,0\n")
    with pytest.raises(vt.VistrackError, match=r"^track\.t\[2\] = 1"):
        load(f"vehicle: {{track: {track}}}")


def test_track_file_drives_the_vehicle(tmp_path: Path) -> None:
    track = tmp_path / "track.csv"
    track.write_text("t,x,y\n0,0,0\n10,100,0\n20,100,0\n30,100,-100\n")
    from vistrack.io import read_vehicle_track

    t, xy = read_vehicle_track(track)
    vehicle = follow.GroundVehicle(t, xy)
    assert vehicle.position(25.0) == pytest.approx([100.0, -50.0])
    assert vehicle.heading(15.0) == pytest.approx(0.0)  # standing: the last heading
    assert track.read_text().startswith("t,x,y")  # not modified


def test_follow_releases_the_gil() -> None:
    vehicle = follow.GroundVehicle.from_legs([follow.VehicleLeg(SOUTH, 10.0, 1500.0)])
    ticks, seconds = ticks_during(lambda: follow.simulate(vehicle, UAV))
    assert seconds > 0.05 and ticks >= 3


def test_cli_writes_figures_trajectory_and_metrics(tmp_path: Path) -> None:
    from vistrack.cli import main

    out = tmp_path / "stop"
    assert main(["follow", str(EXAMPLES / "follow_stop.yaml"), "--out", str(out), "--no-city", "--quiet",
                 "--threshold", "3", *NO_MEDIA]) == 0
    metrics = json.loads((out / "metrics.json").read_text())
    for key in ("mean_tracking_error_m", "max_tracking_error_m", "along_track_lag_m", "mode_switches",
                "time_in_mode_s", "camera_fraction"):
        assert key in metrics
    assert set(metrics["time_in_mode_s"]) >= {"sinusoid", "loiter"}
    assert metrics["mode_switches"] == 1  # the stop switches to loiter once, no chattering
    assert metrics["time_in_mode_s"]["loiter"] == pytest.approx(300.0, abs=2.0)
    assert metrics["wind_compensation"] is True
    for name in ("follow_paths.png", "follow_scores.png", "follow_compare.png", "trajectory.csv",
                 "baseline_trajectory.csv"):
        assert (out / name).is_file()
    header, *rows = (out / "trajectory.csv").read_text().splitlines()
    assert header.split(",")[:4] == ["t", "x", "y", "psi"] and "mode" in header.split(",")
    assert len(rows) == 500 * 50 + 1
    # The loiter ends 400 m ahead of the standing vehicle (the offset moved after the stop).
    last = [float(v) for v in rows[-1].split(",")[8:10]]
    assert last[1] == pytest.approx(1600.0 + 400.0)
    assert main(["follow", str(EXAMPLES / "follow_wind.yaml"), "--out", str(tmp_path / "w"), "--no-city", "--quiet",
                 "--no-compensation", *NO_MEDIA]) == 0
    assert json.loads((tmp_path / "w" / "metrics.json").read_text())["wind_compensation"] is False


def test_cli_error_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from vistrack.cli import main

    bad = tmp_path / "bad.yaml"
    bad.write_text("follow: {period: -3}\nvehicle: {legs: [{heading: east, speed: 5, duration: 10}]}\n")
    assert main(["follow", str(bad), "--out", str(tmp_path / "o")]) == 1  # input refused: a failure
    assert "follow.period = -3" in capsys.readouterr().err


def test_city_runs_report_line_of_sight(charlotte: Path) -> None:
    scenario = FollowScenario.load(EXAMPLES / "follow_straight_city.yaml")
    scenario.flight = follow.FollowFlight(max_time=120.0)
    study = scenario.run(city=True)
    assert study.city_follow is not None and study.city_baseline is not None
    for result in (study.city_follow, study.city_baseline):
        m = result.metrics
        assert 0.0 <= m["camera_and_line_of_sight_fraction"] <= min(m["camera_fraction"], m["line_of_sight_fraction"])
        assert result.line_of_sight is not None and result.line_of_sight.shape == result.t.shape
    # The same segments through the Environment's own per-call BVH, at every 50th sample.
    env, result = study.environment, study.city_follow
    scene = vt.VisibilityScene(env)
    k = np.arange(0, len(result.t), 50)
    uav = np.column_stack([result.state[k, :2], np.full(len(k), scene.ground_level + 300.0)])
    ground = scene.poi_on_surface(np.column_stack([result.vehicle[k], np.full(len(k), 0.5)]))
    assert np.array_equal(env.line_of_sight(uav, ground), result.line_of_sight[k])
    assert not result.line_of_sight.all()  # the buildings hide the vehicle some of the time


def test_follow_refuses_out_of_range_inputs_and_wrong_shapes() -> None:
    F = vt.follow
    uav = vt.Uav(speed=20.0, min_turn_radius=40.0, altitude=100.0)
    truck = east_truck()
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
