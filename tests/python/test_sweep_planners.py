"""The sweep kinds of the loiter and follow planners: rows equal running each case directly through
the planners' public API, serially and on a LocalCluster, bad bases name the key, and the declared
metric names match what a run returns."""

from __future__ import annotations

import fnmatch
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import vistrack as vt
from support.paths import EXAMPLES
from support.sweeps import assert_same_sweep, renamed_note, without_run_columns
from vistrack.follow_scenario import FollowScenario
from vistrack.scenario_blocks import uav_dict
from vistrack.sweep import SERIAL, SweepSpec
from vistrack.sweep.kinds import flatten

# --- loiter ---------------------------------------------------------------------------------------------


def loiter_alone(count: int, seed: int, method: str, wind: tuple[float, float]) -> dict[str, Any]:
    """A loiter case by hand: the scenario, plan, coverage and flight of vt.loiter."""
    scenario = vt.loiter.random_scenario(count, seed)
    plan = vt.loiter.plan(scenario.aois, method)
    coverage = vt.loiter.coverage(plan, scenario.aois, vt.loiter.Camera(), speed=12.0, aoi_radius=46.0)
    metrics = {k: v for k, v in flatten(vt.loiter.metrics(plan, coverage)).items() if not isinstance(v, list)}
    metrics.update({"aois": count, "coverage_per_aoi_s": coverage.time / count,
                    "min_coverage_per_aoi_s": float(min(coverage.time_per_aoi))})
    if wind != (0.0, 0.0):
        flown = vt.loiter.fly_and_score(scenario, plan, wind, planned=coverage)
        metrics.update({f"flown.{k}": v for k, v in flatten(flown).items() if not isinstance(v, (list, np.ndarray))
                        and not k.startswith(("planned_flight", "planned_coverage", "_"))})
    return metrics


LOITER_SWEEP = {"kind": "loiter", "base": {"random": {"count": 4, "seed": 0}},
                "parameters": {"random.seed": [1, 2], "method": ["fly_through", "tlpp", "ldlpp"],
                               "wind": [{"east": 0.0, "north": 0.0}, {"east": 0.0, "north": 5.0}]}}


def test_loiter_sweep_equals_each_case_alone(tmp_path: Path) -> None:
    spec = SweepSpec.from_dict(LOITER_SWEEP)
    result = vt.sweep.run(spec, SERIAL, out=tmp_path, figures=False)
    assert [row["run_status"] for row in result.rows] == ["ok"] * 12, result.failed
    for case, row in zip(spec.cases(), result.rows):
        p = case.parameters
        wind = (p["wind"]["east"], p["wind"]["north"])
        expected = loiter_alone(4, p["random.seed"], p["method"], wind)
        assert {k: row[k] for k in expected} == expected
        assert ("flown.coverage_time_s" in row and row["flown.coverage_time_s"] is not None) == (wind != (0.0, 0.0))
    # The three methods of a seed plan the same AOIs: LDLPP has the shortest transit (the paper's claim).
    calm = [row for row in result.rows if row.get("flown.flight_time_s") is None]
    for seed in (1, 2):
        mine = {row["method"]: row for row in calm if row["random.seed"] == seed}
        assert mine["ldlpp"]["transit_time_s"] < min(mine["tlpp"]["transit_time_s"],
                                                     mine["fly_through"]["transit_time_s"])


def test_loiter_sweep_on_a_local_cluster_equals_serial(tmp_path: Path) -> None:
    spec = SweepSpec.from_dict({**LOITER_SWEEP, "parameters": {**LOITER_SWEEP["parameters"], "wind": [{}]}})
    cluster = vt.sweep.run(spec, scheduler=None, n_workers=2, out=tmp_path / "c", figures=False)
    serial = vt.sweep.run_cases(spec.cases(), SERIAL)
    assert without_run_columns(cluster.rows) == without_run_columns(serial)
    assert all(row["run_status"] == "ok" for row in cluster.rows)


def test_loiter_scenario_file_base_and_a_failing_case(tmp_path: Path) -> None:
    spec = SweepSpec.from_dict({"kind": "loiter", "base": {"scenario": str(EXAMPLES / "loiter_6aoi.yaml")},
                                "parameters": {"turns": [1, 0, 2], "order": ["given"]}})
    assert len(spec.base["aois"]) == 6 and "scenario" not in spec.base
    rows = vt.sweep.run(spec, SERIAL, out=tmp_path, figures=False).rows
    assert [row["run_status"] for row in rows] == ["ok", "failed", "ok"]
    assert "turns = 0" in rows[1]["run_error"]
    scenario = vt.loiter.load_scenario(EXAMPLES / "loiter_6aoi.yaml")
    assert rows[0]["flight_time_s"] == scenario.plan("ldlpp").flight_time
    assert rows[0]["flight_time_min"] == pytest.approx(9.03, abs=0.005)  # the file's Table 1 match
    assert rows[2]["loiter_time_s"] > rows[0]["loiter_time_s"] + 6 * 2 * math.pi * 46.0 / 12.0 - 1e-6


# --- follow ---------------------------------------------------------------------------------------------

FOLLOW_BASE: dict[str, Any] = {
    "uav": {"speed": 21.0, "min_turn_radius": 50.0, "altitude": 200.0},
    "vehicle": {"legs": [{"heading": "north", "speed": 10.0, "duration": 60.0},
                         {"heading": "east", "speed": 4.0, "end_speed": 8.0, "duration": 40.0}]},
    "follow": {"period": 30.0},
    "wind": {"east": 0.0, "north": 5.0},
}


def follow_alone(period: float, scale: float, compensation: bool) -> dict[str, Any]:
    legs = [vt.follow.VehicleLeg(math.pi / 2, 10.0 * scale, 60.0), vt.follow.VehicleLeg(0.0, 4.0 * scale, 40.0,
                                                                                       8.0 * scale)]
    vehicle = vt.follow.GroundVehicle.from_legs(legs)
    # What a scenario file flies unless it says otherwise: the roll model, L1 legs.
    uav = vt.Uav(speed=21.0, min_turn_radius=50.0, altitude=200.0, dynamics="roll")
    parameters = vt.follow.FollowParameters(period=period, wind_compensation=compensation)
    run = vt.follow.simulate(vehicle, uav, parameters, wind=(0.0, 5.0), flight=vt.follow.FollowFlight(guidance="l1"))
    base = vt.follow.baseline(vehicle, uav, parameters=parameters, wind=(0.0, 5.0))
    out = {k: v for k, v in flatten(run.metrics).items()
           if k not in ("strategy", "centre_offset_m") and not k.startswith("sinusoid")}  # per run, not swept
    out.update({f"baseline.{k}": v for k, v in flatten(base.metrics).items()
                if k not in ("strategy", "centre_offset_m")})
    out["centre_offset_east_m"], out["centre_offset_north_m"] = run.metrics["centre_offset_m"]
    out["baseline.centre_offset_east_m"], out["baseline.centre_offset_north_m"] = base.metrics["centre_offset_m"]
    out["updates"], out["wind_compensation"] = len(run.ticks), compensation
    out.update({f"uav.{k}": v for k, v in uav_dict(uav).items()})
    return out


def test_follow_sweep_equals_each_case_alone(tmp_path: Path) -> None:
    spec = SweepSpec.from_dict({"kind": "follow", "base": FOLLOW_BASE, "parameters": {
        "follow.period": [20.0, 30.0], "vehicle.speed_scale": [1.0, 1.5], "follow.compensation": [True, False]}})
    result = vt.sweep.run(spec, SERIAL, out=tmp_path, figures=False)
    assert all(row["run_status"] == "ok" for row in result.rows), result.failed
    for case, row in zip(spec.cases(), result.rows):
        p = case.parameters
        expected = follow_alone(p["follow.period"], p["vehicle.speed_scale"], p["follow.compensation"])
        assert {k: row[k] for k in expected if k != "baseline.radius_m"} == {
            k: v for k, v in expected.items() if k != "baseline.radius_m"}
        assert row["baseline.radius_m"] > 0
    # The parameters matter: compensation lowers the mean tracking error in this wind.
    by = {(r["follow.period"], r["vehicle.speed_scale"], r["follow.compensation"]): r for r in result.rows}
    assert by[(30.0, 1.0, True)]["mean_tracking_error_m"] < by[(30.0, 1.0, False)]["mean_tracking_error_m"]


def test_follow_sweep_of_an_example_file_equals_the_scenario_run(tmp_path: Path) -> None:
    spec = SweepSpec.from_dict({"kind": "follow", "base": str(EXAMPLES / "follow_wind.yaml"),
                                "parameters": {"follow.compensation": [False], "baseline": [False]}})
    assert "city" not in spec.base
    (row,) = vt.sweep.run_cases(spec.cases(), SERIAL)
    scenario = FollowScenario.load(EXAMPLES / "follow_wind.yaml")
    scenario.baseline_control = None
    study = scenario.run(compensation=False, city=False)
    assert row["mean_tracking_error_m"] == study.follow.metrics["mean_tracking_error_m"]
    assert row["camera_fraction"] == study.follow.metrics["camera_fraction"] and "baseline.camera_fraction" not in row


@pytest.mark.parametrize(("kind", "base", "message"), [
    ("loiter", {"aois": [[300, 300]], "random": {"count": 3}}, "give exactly one of scenario"),
    ("loiter", {"aois": [[300, 300]], "method": "zigzag"}, "method = 'zigzag'"),
    ("loiter", {"aois": [[300, 300]], "colour": 1}, "colour = 1: unknown key"),
    ("loiter", {"aois": [[300, 300]], "aoi_radius": 30.0}, "aoi_radius"),
    ("loiter", {"aois": [[300, 300]], "camera": {"altitude": -3}}, "camera.altitude = -3"),
    ("loiter", {"random": {"count": 0}}, "random.count = 0"),
    ("loiter", {"scenario": "missing.yaml"}, "scenario = "),
    ("follow", {"vehicle": {"legs": []}}, "vehicle.legs = []"),
    ("follow", {**FOLLOW_BASE, "uav": {"speed": -1.0}}, "uav.speed = -1: must be a finite number"),
    ("follow", {**FOLLOW_BASE, "vehicle": {**FOLLOW_BASE["vehicle"], "speed_scale": -1}}, "vehicle.speed_scale = -1"),
    ("follow", {**FOLLOW_BASE, "colour": 1}, "colour = 1: unknown key"),
])
def test_bad_bases_name_the_key(kind: str, base: dict[str, Any], message: str) -> None:
    with pytest.raises(vt.VistrackError) as error:
        parameter = "dt" if kind == "loiter" else "wind.east"
        SweepSpec.from_dict({"kind": kind, "base": base, "parameters": {parameter: [1]}})
    assert message in str(error.value) and str(error.value).startswith("base: ")


def test_old_loiter_sweep_spellings(capsys: pytest.CaptureFixture[str]) -> None:
    """Before the one schema the loiter base spelled the vehicle at the top level, the camera's
    height and mount in camera, the wind by speed and direction: still read, one line on stdout
    each, into the cases the new spelling gives."""
    aois = [[300.0, 200.0], [600.0, 500.0]]
    old = {"kind": "loiter", "base": {"aois": aois, "turn_radius": 45.0, "speed": 13.0,
                                      "camera": {"altitude": 80.0, "levelled": False},
                                      "wind": {"speed": 4.0, "direction_deg": 0.0}},
           "parameters": {"speed": [12.0, 13.0], "camera.levelled": [True, False], "camera.altitude": [70.0],
                          "wind": [{"speed": 0.0}, {"speed": 4.0, "direction_deg": 0.0}]}}
    spec = SweepSpec.from_dict(old)
    assert set(capsys.readouterr().out.splitlines()) == {
        renamed_note("turn_radius", "uav.min_turn_radius"), renamed_note("speed", "uav.speed"),
        renamed_note("camera.altitude", "uav.altitude"), renamed_note("camera.levelled", "camera.mount"),
        renamed_note("wind.speed, wind.direction_deg", "wind.east, wind.north")}
    new = {"kind": "loiter", "base": {"aois": aois, "uav": {"min_turn_radius": 45.0, "speed": 13.0, "altitude": 80.0},
                                      "camera": {"mount": "roll"}, "wind": {"east": 4.0, "north": 0.0}},
           "parameters": {"uav.speed": [12.0, 13.0], "camera.mount": ["levelled", "roll"], "uav.altitude": [70.0],
                          "wind": [{"east": 0.0, "north": 0.0}, {"east": 4.0, "north": 0.0}]}}
    again = SweepSpec.from_dict(new)
    assert capsys.readouterr().out == ""
    rows = assert_same_sweep(spec, again)
    # The body-mounted camera sees less than the levelled one, at the same plan.
    by = {(row["uav.speed"], row["camera.mount"], row["wind"]["east"]): row for row in rows}
    assert by[(13.0, "roll", 0.0)]["coverage_time_s"] < by[(13.0, "levelled", 0.0)]["coverage_time_s"]
    with pytest.raises(vt.VistrackError, match=r"parameters\.camera = .*camera\.altitude is now uav\.altitude"):
        SweepSpec.from_dict({"kind": "loiter", "base": {"aois": aois}, "parameters": {"camera": [{"altitude": 70}]}})


def test_loiter_base_blocks_take_the_file_key_by_key() -> None:
    """Keys given beside a scenario file win one by one, inside a block too."""
    spec = SweepSpec.from_dict({"kind": "loiter", "base": {"scenario": str(EXAMPLES / "loiter_6aoi.yaml"),
                                                           "uav": {"speed": 15.0}},
                                "parameters": {"method": ["tlpp"]}})
    assert spec.base["uav"] == {"speed": 15.0, "min_turn_radius": 46.0, "altitude": 61.0, "dynamics": "roll",
                                "roll_time_constant": 0.5, "max_roll_rate_deg_s": 70.0}


def test_parameters_are_keys_of_the_kind() -> None:
    with pytest.raises(vt.VistrackError, match=r"parameters\.follow\.perod .*did you mean follow\.period"):
        SweepSpec.from_dict({"kind": "follow", "base": FOLLOW_BASE, "parameters": {"follow.perod": [20]}})
    with pytest.raises(vt.VistrackError, match=r"parameters\.methd .*did you mean method"):
        SweepSpec.from_dict({"kind": "loiter", "base": {"random": {}}, "parameters": {"methd": ["tlpp"]}})
    # Without a layout seed, every case draws its own layout from its own seed: reproducibly.
    own = SweepSpec.from_dict({"kind": "loiter", "seed": 4, "base": {"random": {"count": 4}},
                               "parameters": {"method": ["ldlpp", "ldlpp"]}})
    first = vt.sweep.run_cases(own.cases(), SERIAL)
    assert first[0]["length_m"] != first[1]["length_m"]
    assert first[1]["length_m"] == vt.loiter.random_scenario(4, own.cases()[1].seed).plan("ldlpp").length
    # Setting one source of AOIs replaces the other.
    spec = SweepSpec.from_dict({"kind": "loiter", "base": {"random": {"count": 4}}, "parameters": {
        "aois": [[[300, 300], [600, 600]]], "wind.speed": [5.0]}})
    data = spec.cases()[0].data
    assert "random" not in data and data["wind"] == {"speed": 5.0}


@pytest.mark.parametrize("kind", ["loiter", "follow"])
def test_declared_metric_names_match_a_run(kind: str) -> None:
    if kind == "loiter":
        spec = SweepSpec.from_dict({**LOITER_SWEEP, "parameters": {"wind": [{}, {"east": 3.0}]}})
    else:
        # 3x: a vehicle faster than the UAV, even in the 5 m/s tail wind (the planner's note, the
        # baseline's reason).
        spec = SweepSpec.from_dict({"kind": "follow", "base": FOLLOW_BASE,
                                    "parameters": {"vehicle.speed_scale": [1.0, 3.0]}})
    rows = vt.sweep.run_cases(spec.cases(), SERIAL)
    produced = {k for row in rows for k, v in row.items() if v is not None and not k.startswith("run_")}
    produced -= {"case", *spec.parameters}
    declared = vt.sweep.get_kind(kind).metric_names
    assert all(any(fnmatch.fnmatchcase(m, d) for d in declared) for m in produced), produced
    assert all(any(fnmatch.fnmatchcase(m, d) for m in produced) for d in declared), declared
