"""A vehicle faster than the UAV is a valid follow run (issue 29): the planner chases it in its
straight mode with a note, and the baseline, which no constant orbit can fly (Lemma 5), is
reported ``feasible: false`` with the reason instead of refusing the command or the sweep case."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from support.cli import NO_MEDIA
from support.refusal import refuses
from vistrack import follow
from vistrack.cli import main
from vistrack.follow_scenario import FollowScenario
from vistrack.sweep import SERIAL, SweepSpec, run_cases

pytestmark = pytest.mark.sanitize

UAV = {"speed": 21.0, "min_turn_radius": 50.0, "altitude": 200.0}


def _scenario(speed: float) -> dict[str, Any]:
    return {"uav": dict(UAV), "vehicle": {"legs": [{"heading": "east", "speed": speed, "duration": 60.0}]}}


def test_the_baseline_alone_still_refuses_a_faster_vehicle() -> None:
    vehicle = follow.GroundVehicle.from_legs([follow.VehicleLeg(0.0, 25.0, 60.0)])
    uav = FollowScenario.from_mapping(_scenario(25.0), Path(".")).uav
    refuses(lambda: follow.baseline(vehicle, uav), "uav.speed = 21", "top speed 25", "(Lemma 5)")
    assert "top speed 25" in (follow.baseline_infeasibility(vehicle, uav) or "")
    slow = follow.GroundVehicle.from_legs([follow.VehicleLeg(0.0, 20.0, 60.0)])
    assert follow.baseline_infeasibility(slow, uav) is None


def test_scenario_run_reports_the_baseline_infeasible_and_notes_the_chase() -> None:
    study = FollowScenario.from_mapping(_scenario(25.0), Path(".")).run(city=False)
    record = study.metrics()
    assert study.baseline is None
    assert record["baseline"]["feasible"] is False
    assert "top speed 25" in record["baseline"]["reason"] and "camera_fraction" not in record["baseline"]
    assert record["time_in_mode_s"]["straight"] == pytest.approx(60.0)
    assert "straight mode for 60 s" in record["note"]
    slower = FollowScenario.from_mapping(_scenario(10.0), Path(".")).run(city=False).metrics()
    assert slower["baseline"]["feasible"] is True and "camera_fraction" in slower["baseline"]
    assert "note" not in slower


def test_cli_follow_of_a_faster_vehicle_succeeds(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    file = tmp_path / "fast.yaml"
    file.write_text(json.dumps(_scenario(25.0)))
    out = tmp_path / "out"
    assert main(["follow", str(file), "--out", str(out), "--quiet", *NO_MEDIA]) == 0
    printed = capsys.readouterr().out
    assert "baseline not flown" in printed and "note: straight mode" in printed
    metrics = json.loads((out / "metrics.json").read_text())
    assert metrics["baseline"] == {"feasible": False, "reason": metrics["baseline"]["reason"]}
    assert "Baseline not flown" in (out / "report.md").read_text()
    assert not (out / "baseline_trajectory.csv").exists()


def test_follow_sweep_over_a_vehicle_faster_than_the_uav() -> None:
    # examples/sweep_follow.yaml at 1.25x the truck's speeds failed every case this way.
    spec = SweepSpec.from_dict({"kind": "follow", "base": _scenario(10.0),
                                "parameters": {"vehicle.speed_scale": [1.0, 2.5]}})
    slow, fast = run_cases(spec.cases(), SERIAL)
    assert slow["run_status"] == fast["run_status"] == "ok", (slow.get("run_error"), fast.get("run_error"))
    assert slow["baseline.feasible"] is True and slow["baseline.camera_fraction"] > 0.0
    assert fast["baseline.feasible"] is False and "top speed 25" in fast["baseline.reason"]
    assert "baseline.camera_fraction" not in fast
    assert fast["time_in_mode_s.straight"] == pytest.approx(60.0) and "straight mode" in fast["note"]
