"""The vehicle model switch (Uav.dynamics): the Dubins model's flights bit-identical to those before
the roll model existed, the roll model's bank within its limits in every planner's flight, the
smoothness measures, the scenario key and the command-line flag."""

from __future__ import annotations

import hashlib
import json
import math
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.cli import NO_MEDIA
from vistrack import follow
from vistrack.scenario_blocks import uav_block

ROLL = vt.Uav(speed=21.0, min_turn_radius=50.0, altitude=200.0, dynamics="roll")
DUBINS = vt.Uav(speed=21.0, min_turn_radius=50.0, altitude=200.0, dynamics="dubins")


def _digest(trajectory: vt.flight.FlightTrajectory, samples: int | None = None) -> str:
    h = hashlib.sha256()
    for a in (trajectory.t, trajectory.x, trajectory.y, trajectory.psi, trajectory.command):
        h.update(np.ascontiguousarray(np.asarray(a, dtype=np.float64)[:samples]).tobytes())
    return h.hexdigest()[:16]


# sha256 prefixes of these flights computed by the build before the roll model (b6fed75), with
# the same inputs: the Dubins model must fly them bit for bit as it did. Since the waypoint
# flights end past the last waypoint's finish line (issue 32) they fly on after where they used to
# stop: the old discrete flights are exactly their first 1320 (DWN) and 1214 (WN) samples, and the
# whole flights are pinned as re-computed then (the continuous ones used to stop on an event
# located inside a step, so no prefix of theirs is the old flight).
BEFORE_THE_ROLL_MODEL = {
    "dwn-discrete": "0c4887db5a097d19", "wn-discrete": "df04b30b1bf5683b", "fly-discrete": "5a405b99ff8afd53",
    "fly-continuous": "c03d266055d8fc70",
}
OLD_LENGTHS = {"dwn-discrete": 1320, "wn-discrete": 1214}
SINCE_THE_FINISH_LINE = {
    "dwn-discrete": "0967e875c7c51d75", "wn-discrete": "6b10949ff24b06d8", "fly-discrete": "5a405b99ff8afd53",
    "dwn-continuous": "6f39a2f0e6319bb1", "wn-continuous": "91a0591f508872b4", "fly-continuous": "c03d266055d8fc70",
}


def _flights() -> dict[str, vt.flight.FlightTrajectory]:
    route = np.array([[5.0, 0.0], [8.0, 4.0], [3.0, 6.0], [0.0, 2.0]])
    gusts = vt.flight.Gusts(seed=7, intensity=0.05, length_scale=3.0)
    out = {}
    for integration in ("discrete", "continuous"):
        for method in ("dwn", "wn"):
            flown = vt.waypoint_nav.fly(route, start=(0.0, 0.0, 0.0), method=method,
                                        wind=vt.flight.Wind(0.03, 0.08, gusts), integration=integration)
            out[f"{method}-{integration}"] = flown.flight
        law = vt.flight.LineFeedback(speed=20.0, turn_radius=50.0, dt=0.02, smooth_sign=integration == "continuous")
        wn = vt.flight.WaypointFollower(law, [[400, 0], [400, 400], [0, 400]], waypoint_radius=50.0)
        out[f"fly-{integration}"] = vt.flight.fly(wn, start=(0, 0, 0), speed=20.0, turn_radius=50.0,
                                                  wind=vt.flight.Wind(3.0, -2.0), dt=0.02, integration=integration,
                                                  max_time=400.0)
    return out


def test_dubins_flights_are_bit_identical_to_before_the_roll_model() -> None:
    flights = _flights()
    assert {name: _digest(t) for name, t in flights.items()} == SINCE_THE_FINISH_LINE
    assert {name: _digest(flights[name], OLD_LENGTHS.get(name)) for name in BEFORE_THE_ROLL_MODEL} == \
        BEFORE_THE_ROLL_MODEL


def test_roll_model_bank_stays_within_its_limits_under_law_5() -> None:
    law = vt.flight.LineFeedback(speed=20.0, turn_radius=50.0, dt=0.02)
    uav = vt.Uav(speed=20.0, min_turn_radius=50.0, dynamics="roll")
    model = vt.flight.RollModel(uav)
    wn = vt.flight.WaypointFollower(law, [[400, 0], [400, 400], [0, 400]], waypoint_radius=50.0)
    flown = vt.flight.fly(wn, start=(0, 0, 0), speed=20.0, turn_radius=50.0, wind=vt.flight.Wind(3.0, -2.0),
                          max_time=400.0, uav=uav)
    bank = np.asarray(flown.bank)
    assert np.max(np.abs(bank)) <= model.max_bank * (1 + 1e-12)
    assert np.max(np.abs(np.diff(bank))) / 0.02 <= model.max_roll_rate * (1 + 1e-9)
    # The turn rate flown is the bank's: g tan(phi) / v, one step behind the bank it reached.
    assert np.allclose(np.asarray(flown.command)[:-1], 9.80665 * np.tan(bank[1:]) / 20.0, rtol=0, atol=1e-12)
    smooth = flown.smoothness()
    assert smooth.max_roll_rate_deg_s <= 70.0 * (1 + 1e-9)
    dubins = vt.flight.fly(vt.flight.WaypointFollower(law, [[400, 0], [400, 400], [0, 400]], waypoint_radius=50.0),
                           start=(0, 0, 0), speed=20.0, turn_radius=50.0, wind=vt.flight.Wind(3.0, -2.0),
                           max_time=400.0)
    assert dubins.smoothness().max_roll_rate_deg_s > 10 * smooth.max_roll_rate_deg_s


def test_smoothness_of_a_sine_by_hand() -> None:
    t = np.linspace(0.0, 20.0, 20001)
    bank = np.radians(5.0) * np.sin(2 * math.pi * 0.25 * t)  # 4 s period: extrema every 2 s
    s = vt.flight.flight_smoothness(t, bank)
    assert s.roll_reversals == 10  # rising from 0, it turns at every extremum: 1, 3, ..., 19 s
    assert s.max_roll_rate_deg_s == pytest.approx(5.0 * 2 * math.pi * 0.25, rel=1e-5)
    assert set(s.as_dict()) == {"bank_rms_deg", "roll_reversals_per_s", "roll_reversals", "max_roll_rate_deg_s"}
    with pytest.raises(vt.VistrackError, match=r"bank = 1: must have as many samples as t \(2\)"):
        vt.flight.flight_smoothness([0.0, 1.0], [0.0])


def test_uav_dynamics_is_checked_by_name() -> None:
    assert vt.Uav(dynamics="ROLL").dynamics == "roll"
    with pytest.raises(vt.VistrackError, match=r"uav.dynamics = 'jet': must be one of 'dubins', 'roll'"):
        vt.Uav(dynamics="jet")
    with pytest.raises(vt.VistrackError, match=r"uav.roll_time_constant = 0:"):
        vt.Uav(roll_time_constant=0.0)
    assert "dynamics='roll'" in repr(ROLL) and "roll_time_constant=0.5" in repr(ROLL)


def test_scenario_files_fly_the_roll_model_unless_they_say_dubins() -> None:
    assert uav_block({}, vt.Uav()).uav.dynamics == "roll"
    block = uav_block({"uav": {"dynamics": "dubins", "roll_time_constant": 0.3}}, vt.Uav())
    assert block.uav.dynamics == "dubins" and block.uav.roll_time_constant == 0.3
    with pytest.raises(vt.VistrackError, match=r"uav.max_roll_rate_deg_s = -1: must be a finite number in"):
        uav_block({"uav": {"max_roll_rate_deg_s": -1}}, vt.Uav())
    assert vt.Scenario().uav.dynamics == "roll"
    assert vt.Scenario().to_dict()["uav"]["dynamics"] == "roll"


def _parked(seconds: float = 240.0) -> follow.GroundVehicle:
    return follow.GroundVehicle.from_legs([follow.VehicleLeg(0.0, 0.0, seconds)], (0.0, 0.0))


def test_circling_a_parked_vehicle_keeps_it_in_the_camera_with_the_roll_model() -> None:
    """Issue 28: the Dubins model's bank chatters between its limits about a parked vehicle; the roll
    model flies the same plan smoothly and keeps the vehicle in view at least 95 % of the time. (Since
    issue 31 the loiter circle is flown as a path, which keeps even the chattering Dubins model's
    camera on the parked vehicle; the chatter itself remains.)"""
    roll = follow.simulate(_parked(), ROLL, flight=follow.FollowFlight(guidance="l1"))
    dubins = follow.simulate(_parked(), DUBINS)  # the paper's: each 1 s leg by the law (5)
    assert vt.flight.flight_smoothness(dubins.run.t, dubins.run.bank).roll_reversals_per_s > 5.0
    assert roll.metrics["camera_fraction"] >= 0.95
    s = vt.flight.flight_smoothness(roll.run.t, roll.run.bank)
    assert s.roll_reversals_per_s <= 1.0
    assert s.max_roll_rate_deg_s <= 70.0 * (1 + 1e-9)


def test_tracking_closed_loop_flies_the_roll_model_in_rk45() -> None:
    poi = vt.PoiPath(np.array([[0.0, 0.0, 0.0], [600.0, 0.0, 0.0]]), 5.0)
    out = {}
    for uav in (ROLL, DUBINS):
        plan = vt.constant_radius_plan(poi, 150.0, uav)
        res = vt.simulate(plan, uav, np.array([150.0, 0.0, math.pi / 2]), vt.Control())
        assert np.asarray(res.state).shape[1] == 3
        out[str(uav.dynamics)] = res
    roll, dubins = out["roll"], out["dubins"]
    model = vt.flight.RollModel(ROLL)
    assert np.max(np.abs(roll.bank)) <= model.max_bank * (1 + 1e-9)
    assert roll.bank[0] == 0.0  # starts level
    # Both settle on the orbit; the roll model lags the Dubins vehicle a little.
    late = np.asarray(roll.t) > 60
    assert np.max(np.abs(np.asarray(roll.radial_error)[late])) < 2.0
    assert np.max(np.abs(np.asarray(dubins.radial_error)[late])) < 2.0
    assert np.allclose(dubins.bank, np.arctan(21.0 * np.asarray(dubins.control) / 9.80665))
    assert np.allclose(roll.turn_rate, 9.80665 * np.tan(roll.bank) / 21.0)


def test_dynamics_flag_overrides_the_scenario(tmp_path: Path) -> None:
    from vistrack.cli import main

    scenario = Path(__file__).resolve().parents[2] / "examples" / "follow_stop.yaml"
    for model in ("dubins", "roll"):
        out = tmp_path / model
        assert main(["follow", str(scenario), "--out", str(out), "--no-city", "--quiet", "--dynamics", model,
                     *NO_MEDIA]) == 0
        metrics = json.loads((out / "metrics.json").read_text())
        assert metrics["uav"]["dynamics"] == model
        rate = metrics["smoothness"]["max_roll_rate_deg_s"]
        # The Dubins vehicle's bank jumps where the command does; the roll model's never passes its limit.
        assert rate > 500.0 if model == "dubins" else rate <= 70.0 * (1 + 1e-9)


def test_curve_l1_from_python() -> None:
    l1 = vt.flight.CurveL1(20.0, np.array([[0.0, 0.0], [100.0, 0.0]]), period=8.0)
    assert l1.distance == pytest.approx(0.75 * 8.0 * 20.0 / math.pi)
    ref = l1.reference_point(np.array([50.0, -10.0]))
    assert ref[1] == pytest.approx(0.0) and ref[0] == pytest.approx(50.0 + math.sqrt(l1.distance ** 2 - 100.0))
    l1.set_path(np.array([[3.0, 4.0]]))
    assert np.allclose(l1.reference_point(np.zeros(2)), [3.0, 4.0])
    with pytest.raises(vt.VistrackError, match=r"path\[0\]\.x = nan"):
        l1.set_path(np.array([[math.nan, 0.0]]))


def test_follow_flies_the_planned_curve_with_l1() -> None:
    """flight.guidance l1 flies the planner's path (renewed each update) instead of 1 s legs: on the
    straight run the UAV stays within metres of the planned sinusoid and its bank is smooth."""
    car = follow.GroundVehicle.from_legs([follow.VehicleLeg(-math.pi / 2, 10.0, 300.0)], (0.0, 0.0))
    sinusoid = follow.FollowParameters(period=30.0)
    sinusoid.threshold = 3.0  # the paper's h: a sinusoid all the way (auto loiters at 10 m/s)
    curve = follow.simulate(car, ROLL, sinusoid, flight=follow.FollowFlight(guidance="l1"))
    legs = follow.simulate(car, ROLL, sinusoid, flight=follow.FollowFlight(guidance="law5"))
    assert curve.metrics["time_in_mode_s"]["sinusoid"] == 300.0
    assert curve.metrics["mean_tracking_error_m"] < 2.0
    assert curve.metrics["smoothness"]["roll_reversals_per_s"] < 0.1
    assert legs.metrics["smoothness"]["roll_reversals_per_s"] > 1.0


def test_planned_path_starts_at_the_desired_position_and_passes_the_waypoint() -> None:
    """planned_path(tick, ...) is the curve the waypoint is sampled from: at tau = 0 the desired
    position, at tau = update_period the tick's waypoint."""
    planner = follow.FollowPlanner(follow.FollowParameters(period=30.0), ROLL)
    tick = planner.update(0.0, follow.FollowObservation(vehicle_position=np.zeros(2),
                                                        vehicle_velocity=np.array([0.0, -10.0]),
                                                        vehicle_heading=-math.pi / 2, uav_position=np.zeros(2),
                                                        uav_heading=-math.pi / 2))
    path = planner.planned_path(tick, 1.0, 0.25)
    assert path.shape == (5, 2)
    assert np.allclose(path[-1], tick.waypoint, atol=1e-9)
    assert np.allclose(path[0], tick.offset_point + planner.relative_position(tick, 0.0), atol=1e-9)
    assert np.allclose(tick.offset_velocity, [0.0, -10.0])


def test_sweeps_take_the_vehicle_model(tmp_path: Path) -> None:
    import csv

    import yaml

    from vistrack.cli import main

    base = {"uav": {"speed": 21.0, "min_turn_radius": 50.0, "altitude": 200.0},
            "vehicle": {"legs": [{"heading": "north", "speed": 10.0, "duration": 30.0}]}}
    sweep = tmp_path / "follow.yaml"
    sweep.write_text(yaml.safe_dump({"kind": "follow", "base": base, "parameters": {"follow.period": [30.0]}}))
    for model in ("dubins", "roll"):
        out = tmp_path / model
        assert main(["sweep", str(sweep), "--out", str(out), "--workers", "1", "--no-figures", "--quiet",
                     "--dynamics", model]) == 0
        with open(out / "results.csv", newline="") as f:
            rows = list(csv.DictReader(f))
        assert [row["uav.dynamics"] for row in rows] == [model]
    # Waypoint sweeps in the paper's dimensionless units fly the Dubins vehicle: roll is refused, naming the key.
    with pytest.raises(vt.VistrackError, match=r"base: uav.dynamics = 'roll': the waypoint paper's dimensionless"):
        vt.sweep.SweepSpec.from_dict({"kind": "waypoints", "base": {"waypoints": [[0, 0], [5, 0]], "units": "paper",
                                                                    "uav": {"dynamics": "roll"}},
                                      "parameters": {"method": ["wn"]}})
