"""Following as practitioners fly it (issue 31): the camera-aware threshold, the effective
sinusoid per update, the fair baseline, the standoff orbit and strategy auto, imperfect vehicle
reports, camera models and region-of-interest commands."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import ellipe

import vistrack as vt
from support.cli import NO_MEDIA
from support.paths import EXAMPLES
from vistrack import follow

NORTH, EAST, SOUTH, WEST = math.pi / 2, 0.0, -math.pi / 2, math.pi
UAV = vt.Uav(speed=21.0, min_turn_radius=50.0, altitude=200.0)


def _slope(sigma: float) -> float:
    """a with (2/pi) E(-a^2) = sigma (eq. 10) by scipy, independent of ours."""
    return brentq(lambda a: 2.0 / math.pi * ellipe(-a * a) - sigma, 0.0, math.pi * sigma, xtol=1e-14)


def test_auto_threshold_puts_the_amplitude_at_the_camera_reach() -> None:
    camera = follow.DownwardCamera()
    p = follow.FollowParameters()
    assert p.threshold == "auto"
    choice = follow.camera_threshold(p, UAV, camera)
    reach = 200.0 * math.tan(camera.fov / 2 + camera.max_gimbal)  # 376 m
    assert choice.reach == pytest.approx(reach, rel=1e-12)
    rho = p.turn_margin * UAV.min_turn_radius
    # a(h + band/2)^2 rho = w, with a from scipy's ellipe
    assert _slope(choice.threshold + p.hysteresis / 2) ** 2 * rho == pytest.approx(reach, rel=1e-6)
    # the paper's h = 3 is beyond the footprint: 1406 m against 376 m
    paper = follow.camera_threshold(follow.FollowParameters(threshold=3.0), UAV, camera)
    assert paper.beyond_reach and paper.amplitude == pytest.approx(_slope(3.25) ** 2 * rho, rel=1e-6)


def test_auto_run_keeps_every_sinusoid_within_reach_and_reports_it(tmp_path: Path) -> None:
    # A vehicle whose speed ratio sweeps 1.3 .. 3.5: the sinusoid flies below the band, loiter above.
    legs = [follow.VehicleLeg(EAST, 21.0 / 1.3, 100.0, 21.0 / 3.5), follow.VehicleLeg(EAST, 6.0, 100.0)]
    vehicle = follow.GroundVehicle.from_legs(legs)
    result = follow.simulate(vehicle, UAV)
    choice = result.run.threshold
    m = result.metrics
    assert m["threshold"]["automatic"] and m["threshold"]["h"] == pytest.approx(choice.threshold)
    amplitudes = [k.amplitude for k in result.ticks if k.mode == "sinusoid"]
    assert amplitudes and max(amplitudes) <= choice.reach * (1 + 1e-9)
    assert m["sinusoid"]["amplitude_m"][2] == pytest.approx(max(amplitudes))
    assert follow.threshold_warning(result) is None
    # With the paper's h the run warns with the numbers.
    paper = follow.simulate(vehicle, UAV, follow.FollowParameters(threshold=3.0))
    warning = follow.threshold_warning(paper)
    assert warning is not None and "follow.threshold = 3" in warning and "376 m" in warning


def test_period_reported_as_flown() -> None:
    """T = 10 and 60 s fly the same curvature-limited sinusoid (the floor), and the reported T is the
    flown one, D / v_g, not the key."""
    vehicle = follow.GroundVehicle.from_legs([follow.VehicleLeg(SOUTH, 10.0, 120.0)])
    runs = [follow.simulate(vehicle, UAV, follow.FollowParameters(threshold=3.0, period=T)) for T in (10.0, 60.0)]
    for r in runs:
        shape = follow.sinusoid_shape(2.1, 21.0, 30.0, 62.5)
        assert shape.curvature_limited
        periods = {round(k.period, 6) for k in r.ticks if k.mode == "sinusoid"}
        assert periods == {round(shape.period_distance / 10.0, 6)}
    assert np.array_equal(runs[0].state, runs[1].state)


def test_cli_writes_updates_csv_and_threshold(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from vistrack.cli import main

    out = tmp_path / "straight"
    assert main(["follow", str(EXAMPLES / "follow_straight.yaml"), "--out", str(out), "--no-city", "--threshold", "3",
                 *NO_MEDIA]) == 0
    printed = capsys.readouterr().out
    assert "warning: follow.threshold = 3" in printed and "0 switches" in printed
    metrics = json.loads((out / "metrics.json").read_text())
    assert metrics["threshold"]["h"] == 3.0 and metrics["warnings"]
    header, *rows = (out / "updates.csv").read_text().splitlines()
    assert header.split(",")[:6] == ["t", "mode", "speed_ratio", "period_s", "period_distance_m", "amplitude_m"]
    assert len(rows) == 400
    sigma, period, distance, amplitude = (float(v) for v in rows[10].split(",")[2:6])
    assert distance / period == pytest.approx(10.0) and sigma == pytest.approx(2.1)
    assert amplitude == pytest.approx(follow.sinusoid_amplitude(sigma, distance))
    assert "Threshold h = 3" in (out / "report.md").read_text()


def test_cli_strategy_overrides_the_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from vistrack.cli import main

    out = tmp_path / "standoff"
    assert main(["follow", str(EXAMPLES / "follow_straight.yaml"), "--out", str(out), "--no-city",
                 "--strategy", "standoff", *NO_MEDIA]) == 0
    metrics = json.loads((out / "metrics.json").read_text())
    # The file says nothing of the strategy (paper: loiter all 400 s); standoff flies every second.
    assert metrics["time_in_mode_s"]["standoff"] == pytest.approx(400.0)
    assert metrics["time_in_mode_s"]["loiter"] == 0.0
    assert main(["follow", str(EXAMPLES / "follow_straight.yaml"), "--strategy", "sideways"]) == 2
    assert "invalid choice: 'sideways'" in capsys.readouterr().err


def test_parameters_copy_every_field_and_stay_independent() -> None:
    import copy

    p = follow.FollowParameters(period=20.0, threshold=3.0, hysteresis=0.3, strategy="auto", strategy_margin=0.1,
                                standoff_radius=120.0, offset_distance=50.0, offset_angle=0.5, update_period=2.0,
                                loiter_radius=90.0, wind_compensation=False)
    fields = [name for name in dir(p) if not name.startswith("_") and not callable(getattr(p, name))]
    assert len(fields) >= 15
    for q in (copy.copy(p), copy.deepcopy(p)):
        assert {name: getattr(q, name) for name in fields} == {name: getattr(p, name) for name in fields}
        q.wind_compensation = True
        q.standoff_radius = 1.0
        assert p.wind_compensation is False and p.standoff_radius == 120.0


def test_one_switch_is_singular() -> None:
    from vistrack.commands.follow import _count

    assert _count(1, "switch") == "1 switch" and _count(0, "switch") == "0 switches"


def _wiggly_between_updates(vehicle: follow.GroundVehicle, end: float) -> follow.GroundVehicle:
    """The vehicle's 1 Hz samples, with a 2 m sideways detour in the second half of every second:
    the same position and velocity at every update time, a different vehicle in between."""
    t, xy = [], []
    for k in range(int(end)):
        p0, p1 = vehicle.position(k), vehicle.position(k + 1)
        side = np.array([-(p1 - p0)[1], (p1 - p0)[0]]) / max(np.linalg.norm(p1 - p0), 1e-9)
        for f, lateral in ((0.0, 0.0), (0.5, 0.0), (0.75, 2.0)):
            t.append(k + f)
            xy.append(p0 + f * (p1 - p0) + lateral * side)
    t.append(end)
    xy.append(vehicle.position(end))
    return follow.GroundVehicle(np.array(t), np.array(xy))


def test_fair_baseline_knows_the_vehicle_once_a_second() -> None:
    legs = [follow.VehicleLeg(NORTH, 8.0, 60.0), follow.VehicleLeg(EAST, 8.0, 60.0)]
    smooth = follow.GroundVehicle.from_legs(legs)
    wiggly = _wiggly_between_updates(smooth, 120.0)
    a = follow.baseline(smooth, UAV, 150.0)
    b = follow.baseline(wiggly, UAV, 150.0)
    # the same flight (to rounding: the reports' velocity is the segment's), though the vehicles differ
    assert np.abs(a.state - b.state).max() < 1e-6
    assert np.abs(a.vehicle - b.vehicle).max() > 1.0
    # ... and the planner likewise
    assert np.abs(follow.simulate(smooth, UAV).state - follow.simulate(wiggly, UAV).state).max() < 1e-6


def test_fair_baseline_follows_the_offset_schedule() -> None:
    from vistrack.follow_scenario import FollowScenario

    study = FollowScenario.load(EXAMPLES / "follow_stop.yaml").run(city=False)
    base = study.baseline
    assert base is not None
    late = base.t > 400.0  # the offset is 400 m ahead of the standing vehicle from 330 s
    centre = base.state[late, :2].mean(axis=0)
    assert np.linalg.norm(centre - (base.vehicle[-1] + [0.0, 400.0])) < 40.0


def test_reports_with_noise_latency_and_dropouts() -> None:
    vehicle = follow.GroundVehicle.from_legs([follow.VehicleLeg(SOUTH, 10.0, 200.0), follow.VehicleLeg(EAST, 10.0,
                                                                                                      200.0)])
    perfect = follow.simulate(vehicle, UAV)
    assert perfect.metrics["lost_s"] == 0.0 and perfect.metrics["lost_episodes"] == 0
    reports = follow.VehicleReportOptions(position_noise=5.0, velocity_noise=0.5, latency=2.0, dropout=0.6,
                                          timeout=3.0, seed=7)
    first = follow.simulate(vehicle, UAV, reports=reports)
    again = follow.simulate(vehicle, UAV, reports=reports)
    assert np.array_equal(first.state, again.state)  # seeded
    other = follow.simulate(vehicle, UAV, reports=follow.VehicleReportOptions(
        position_noise=5.0, velocity_noise=0.5, latency=2.0, dropout=0.6, timeout=3.0, seed=8))
    assert not np.array_equal(first.state, other.state)
    m = first.metrics
    assert m["lost_s"] > 0.0 and m["lost_episodes"] > 0 and m["reacquire_s"]["max"] >= m["reacquire_s"]["mean"] >= 0
    lost = [k for k in first.ticks if k.lost]
    assert lost and all(np.allclose(k.offset_vector, 0.0) and k.mode == "loiter" for k in lost)
    # the baseline gets the same reports
    base = follow.baseline(vehicle, UAV, reports=reports)
    assert base.metrics["lost_s"] == pytest.approx(m["lost_s"])


@pytest.mark.parametrize(("key", "value"), [("position_noise", -1.0), ("velocity_noise", -0.5), ("latency", -2.0),
                                            ("dropout", 1.0), ("timeout", 0.0)])
def test_bad_reports_name_the_field(key: str, value: float) -> None:
    with pytest.raises(vt.VistrackError, match=rf"^reports\.{key} = "):
        follow.VehicleReportOptions(**{key: value})


def test_standoff_orbits_the_offset_point_at_the_lemma_6_radius() -> None:
    vehicle = follow.GroundVehicle.from_legs([follow.VehicleLeg(NORTH, 6.0, 300.0)])
    p = follow.FollowParameters(strategy="standoff")
    result = follow.simulate(vehicle, UAV, p)
    m = result.metrics
    assert m["time_in_mode_s"]["standoff"] == pytest.approx(300.0)
    radius = follow.FollowPlanner(p, UAV).orbit_radius(6.0)
    assert radius == pytest.approx(62.5 * (1 + 6.0 / 21.0) ** 2)
    late = result.t > 100.0  # converged: the distance from the offset point is the radius
    distance = np.linalg.norm(result.state[late, :2] - result.offset_point[late], axis=1)
    assert np.abs(distance - radius).max() < 0.1 * radius


def test_strategy_auto_picks_the_pattern_it_predicts_best() -> None:
    planner = follow.FollowPlanner(follow.FollowParameters(strategy="auto"), UAV)
    tick = planner.update(0.0, follow.FollowObservation(vehicle_position=np.zeros(2),
                                                        vehicle_velocity=np.array([0.0, -10.0]),
                                                        vehicle_heading=SOUTH))
    assert tick.mode in ("sinusoid", "loiter", "standoff") and 0.0 <= tick.predicted_camera <= 1.0
    # each single pattern's tick for the same observation, scored by the same prediction: auto's choice is
    # within its switching margin of the best of them
    others = []
    for strategy in ("paper", "standoff"):
        single = follow.FollowPlanner(follow.FollowParameters(strategy=strategy), UAV)
        other = single.update(0.0, follow.FollowObservation(vehicle_position=np.zeros(2),
                                                            vehicle_velocity=np.array([0.0, -10.0]),
                                                            vehicle_heading=SOUTH))
        others.append(planner.predicted_camera(other))
    margin = follow.FollowParameters(strategy="auto").strategy_margin
    assert tick.predicted_camera >= max(others) - margin - 1e-9
    # a standing vehicle: never the sinusoid (its amplitude would be unbounded)
    vehicle = follow.GroundVehicle.from_legs([follow.VehicleLeg(NORTH, 8.0, 100.0),
                                              follow.VehicleLeg(NORTH, 0.0, 100.0)])
    result = follow.simulate(vehicle, UAV, follow.FollowParameters(strategy="auto"))
    assert all(k.mode != "sinusoid" for k in result.ticks if k.t > 100.0)
    # the prediction: a sinusoid far beyond the camera's reach is seen less than a tight standoff orbit
    paper = follow.FollowPlanner(follow.FollowParameters(threshold=8.0), UAV)
    wide = paper.update(0.0, follow.FollowObservation(vehicle_position=np.zeros(2),
                                                      vehicle_velocity=np.array([0.0, -21.0 / 6.0])))
    assert wide.mode == "sinusoid" and wide.amplitude > 1000.0
    assert paper.predicted_camera(wide) < 0.5


def test_bad_strategy_names_the_field() -> None:
    with pytest.raises(vt.VistrackError, match=r"^follow\.strategy = 'best'"):
        follow.FollowParameters(strategy="best")


@pytest.mark.parametrize("mount", ["roll", "pan_tilt", "fixed"])
def test_camera_mounts_reach_and_footprint(mount: str) -> None:
    camera = follow.DownwardCamera(mount=mount)
    gimbal = 0.0 if mount == "fixed" else camera.max_gimbal
    reach = follow.camera_reach(camera, 200.0)
    assert reach == pytest.approx(200.0 * math.tan(camera.fov / 2 + gimbal))
    # level, a vehicle abeam just inside and just outside the reach
    assert follow.camera_sees(camera, [0.0, 0.0, 200.0], 0.0, 0.0, [0.0, 0.99 * reach, 0.0])
    assert not follow.camera_sees(camera, [0.0, 0.0, 200.0], 0.0, 0.0, [0.0, 1.01 * reach, 0.0])
    # the drawn footprint contains the point the metric sees
    ring = follow.camera_footprint(camera, (0.0, 0.0, 200.0), 0.0, 0.2, (30.0, 250.0))
    from shapely.geometry import Point, Polygon
    inside = Polygon(ring).contains(Point(30.0, 250.0))
    assert inside == follow.camera_sees(camera, [0.0, 0.0, 200.0], 0.0, 0.2, [30.0, 250.0, 0.0])


def test_pan_tilt_sees_ahead_where_the_roll_gimbal_cannot() -> None:
    ahead = [300.0, 0.0, 0.0]  # 56 degrees ahead of the nadir, level flight east
    assert follow.camera_sees(follow.DownwardCamera(mount="pan_tilt"), [0.0, 0.0, 200.0], 0.0, 0.0, ahead)
    assert not follow.camera_sees(follow.DownwardCamera(mount="roll"), [0.0, 0.0, 200.0], 0.0, 0.0, ahead)
    # the auto threshold follows the camera: a fixed camera asks for a smaller h
    fixed = follow.camera_threshold(follow.FollowParameters(), UAV, follow.DownwardCamera(mount="fixed"))
    roll = follow.camera_threshold(follow.FollowParameters(), UAV, follow.DownwardCamera())
    assert fixed.threshold < roll.threshold
    with pytest.raises(vt.VistrackError, match=r"^camera\.mount = 'tripod'"):
        follow.DownwardCamera(mount="tripod")


def test_a_camera_to_the_horizon_writes_valid_json(tmp_path: Path) -> None:
    from vistrack.cli import main

    scenario = tmp_path / "wide.yaml"
    scenario.write_text("vehicle: {legs: [{heading: east, speed: 5, duration: 30}]}\n"
                        "camera: {mount: pan_tilt, max_gimbal_deg: 60}\nbaseline: false\n")
    assert main(["follow", str(scenario), "--out", str(tmp_path / "o"), "--no-city", "--quiet", *NO_MEDIA]) == 0
    text = (tmp_path / "o" / "metrics.json").read_text()
    assert "Infinity" not in text and json.loads(text)["threshold"]["camera_reach_m"] is None
