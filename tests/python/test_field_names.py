"""Messages name the field the user gave, at the check that should catch it first (issue 29): a
follow leg's duration, not the track it makes; the tracking sensor's d_max, not a vertex of a VV's
slice; a loiter file's uav.altitude, not the camera's."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.cli import one_line_error
from support.paths import EXAMPLES
from support.refusal import refuses
from vistrack import follow

pytestmark = pytest.mark.sanitize


def test_a_leg_too_long_names_its_duration(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # legs: [{duration: 1e9}] reported track.y[1] (the track the legs make).
    message = refuses(lambda: follow.GroundVehicle.from_legs([follow.VehicleLeg(math.pi / 2, 3.0, 1e9)]),
                      "legs[0].duration = 1e+09", "beyond the coordinate limit")
    assert "track" not in message
    second = [follow.VehicleLeg(0.0, 3.0, 10.0), follow.VehicleLeg(0.0, 10.0, 1e6, 20.0)]
    refuses(lambda: follow.GroundVehicle.from_legs(second), "legs[1].duration = 1e+06")
    scenario = tmp_path / "legs.yaml"
    scenario.write_text("vehicle:\n  legs: [{heading: north, speed: 3, duration: 1e9}]\n")
    err = one_line_error(["follow", str(scenario), "--out", str(tmp_path / "out")], capsys, 1,
                         "legs[0].duration = 1e+09")
    assert "track." not in err


def test_a_sensor_reaching_past_the_coordinates_names_d_max() -> None:
    # sensor.d_max: 1e7 reported polygons[0].outer[1136] (a vertex of a slice), after the VVs.
    env = vt.Environment.demo()
    poi = vt.PoiPath(np.array([[-290.0, -210.0], [95.0, -210.0]]), 5.0)
    message = refuses(lambda: vt.plan_orbits(env, poi, vt.Uav(), vt.Sensor(d_max=1e7), vt.Planning()),
                      "sensor.d_max = 1e+07", "beyond the coordinate limit")
    assert "polygons" not in message


def test_loiter_uav_altitude_is_named_as_given(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    scenario = tmp_path / "alt.yaml"
    scenario.write_text((EXAMPLES / "loiter_5aoi.yaml").read_text().replace("altitude: 61.0", "altitude: 2.0e7"))
    err = one_line_error(["loiter", str(scenario), "--out", str(tmp_path / "out")], capsys, 1,
                         "uav.altitude = 2e+07")
    assert "camera.altitude" not in err
