"""``vistrack intercept``: flags and YAML in, Figure 7 PNGs and JSON out, clear errors."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from vistrack import dubins
from vistrack.cli import main


def test_default_paper_scenario(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "run"
    assert main(["intercept", "--out", str(out)]) == 0
    record = json.loads((out / "intercept.json").read_text())
    for name in record["figures"]:
        png = out / name
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10_000
    problem = record["problem"]
    assert problem["center"] == [-4.0, 3.0] and problem["target_speed"] == 1.2
    i = record["interception"]
    # The JSON agrees with a direct solve and the target sits at the interception point.
    direct = dubins.intercept_circle((0, 0, 0), 1.0, 1.0, (-4, 3), 1.0, math.pi, 1.2, "cw")
    assert i["time"] == pytest.approx(direct.time, abs=1e-12)
    assert i["point"][:2] == pytest.approx(i["target_position_at_time"], abs=1e-9)
    assert i["pursuer_time"] == pytest.approx(i["time"], abs=1e-9)
    # |p - C| - r = 5 - 1 = 4 = 4 rho: the strict 4 rho condition does not hold here.
    assert record["four_rho_condition"] is False
    assert record["optimality"].startswith("feasible")
    assert "alpha*" in capsys.readouterr().out


def test_yaml_file_and_flag_override(tmp_path: Path) -> None:
    config = tmp_path / "case.yaml"
    config.write_text(
        "pursuer: [2.0, -1.0, 2.0]\nrho: 0.5\npursuer_speed: 2.0\ncenter: [10.0, 4.0]\n"
        "radius: 3.0\ntarget_angle0: 0.3\ntarget_speed: 1.0\ndirection: ccw\n"
    )
    before = config.read_text()
    out = tmp_path / "yaml"
    assert main(["intercept", "--config", str(config), "--direction", "cw", "--out", str(out)]) == 0
    assert config.read_text() == before  # input untouched
    record = json.loads((out / "intercept.json").read_text())
    assert record["problem"]["direction"] == "cw"  # the flag wins
    assert record["problem"]["rho"] == 0.5
    assert record["four_rho_condition"] is True
    direct = dubins.intercept_circle((2, -1, 2), 0.5, 2.0, (10, 4), 3.0, 0.3, 1.0, "cw")
    assert record["interception"]["angle"] == pytest.approx(direct.angle, abs=1e-12)


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--rho", "-1"], "rho = -1"),
        (["--pursuer-speed", "0"], "--pursuer-speed = 0"),
        (["--radius", "nan"], "radius"),
    ],
)
def test_bad_flags_exit_2_naming_the_field(tmp_path: Path, capsys, argv: list[str], message: str) -> None:
    assert main(["intercept", "--out", str(tmp_path / "x"), *argv]) == 2
    assert message in capsys.readouterr().err


def test_bad_yaml(tmp_path: Path, capsys) -> None:
    config = tmp_path / "bad.yaml"
    config.write_text("rho: 1.0\nspeed_of_light: 3\n")
    assert main(["intercept", "--config", str(config), "--out", str(tmp_path / "x")]) == 1  # a failure, not usage
    assert "speed_of_light" in capsys.readouterr().err
    assert main(["intercept", "--config", str(tmp_path / "missing.yaml"), "--out", str(tmp_path / "x")]) == 1
