"""The planners flown on the 6-DOF aircraft (vistrack.fdm): the scenario key and the CLI flag, the
tracking paper's Example 1 on Charlotte (issue 34's done-when: POI in view >= 99 %, altitude within
10 m, airspeed within 2 m/s), and refusals before flying."""

from __future__ import annotations

from pathlib import Path

import pytest

import vistrack as vt
from vistrack.scenario import Scenario
from vistrack.tracking.pipeline import compute

REPO = Path(__file__).resolve().parents[2]


def test_the_scenario_key_selects_the_aircraft_and_keeps_the_kinematic_model() -> None:
    data = Scenario.demo().to_dict()
    data["uav"].update({"dynamics": "jsbsim", "aircraft": "c172p"})
    scenario = Scenario.from_dict(data)
    assert scenario.aircraft == "c172p"
    assert str(scenario.uav.dynamics) == "roll"  # the kinematic flight beside it
    again = Scenario.from_dict(scenario.to_dict())
    assert again.aircraft == "c172p"
    data["uav"]["dynamics"] = "jsbsim"
    del data["uav"]["aircraft"]
    assert Scenario.from_dict(data).aircraft == "aerosonde"
    data["uav"]["aircraft"] = "zeppelin"
    with pytest.raises(vt.VistrackError, match=r"uav.aircraft = .*zeppelin.*must be one of aerosonde, c172p"):
        Scenario.from_dict(data)
    data["uav"]["dynamics"] = "roll"
    data["uav"]["aircraft"] = "c172p"
    with pytest.raises(vt.VistrackError, match=r"uav.aircraft = .*c172p.*needs uav.dynamics: jsbsim"):
        Scenario.from_dict(data)


def test_a_plan_outside_the_envelope_is_refused_before_flying() -> None:
    """The demo's vehicle turns at r_min 15 m at 20 m/s: a 70-degree bank, past the Aerosonde's 45."""
    scenario = Scenario.demo()
    scenario.aircraft = "aerosonde"
    with pytest.raises(vt.VistrackError, match=r"uav.min_turn_radius = 15 m is below aerosonde's tightest turn at "
                                               r"20 m/s: 40.8 m \(bank limit 45 deg\)"):
        compute(scenario, metric_spacings=())


def test_the_cli_refuses_an_aircraft_without_jsbsim(capsys: pytest.CaptureFixture[str]) -> None:
    from vistrack.cli import main

    code = main(["run", str(REPO / "examples" / "charlotte_paper_slow.yaml"), "--aircraft", "c172p"])
    assert code != 0
    assert "--aircraft c172p needs --dynamics jsbsim" in capsys.readouterr().err


def test_charlotte_paper_slow_on_the_6dof_uav_keeps_the_poi_in_view(charlotte: Path) -> None:
    scenario = Scenario.load(REPO / "examples" / "charlotte_paper_slow.yaml")
    scenario.aircraft = "aerosonde"
    result = compute(scenario, metric_spacings=())
    kinematic, six = result.metrics["simulation"], result.metrics["fdm"]
    assert kinematic["visibility_fraction"] == 1.0
    assert six["aircraft"] == "aerosonde"
    assert six["simulation"]["visibility_fraction"] >= 0.99
    assert six["altitude_error_max_m"] < 10.0
    assert six["airspeed_error_max_m_s"] < 2.0
    assert six["simulation"]["duration_s"] == pytest.approx(kinematic["duration_s"], abs=0.1)
    # the 6-DOF flight follows the same orbit: after the capture it stays near R(t) as the kinematic one does
    assert six["simulation"]["radial_error_after_max_abs_m"] < 20.0
