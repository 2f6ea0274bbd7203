"""Scenario files: defaults, validation messages, path resolution."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

import vistrack as vt
from support.refusal import refuses
from vistrack.scenario import Scenario, default_scenario_text


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "s.yaml"
    path.write_text(text)
    return path


def test_defaults_come_from_the_cpp_structs() -> None:
    s = Scenario.from_dict({})
    assert s.uav.speed == vt.Uav().speed
    assert s.planning.cutoff == vt.Planning().cutoff
    assert s.control.direction == "ccw"
    assert s.environment.kind == "demo"
    # --print-defaults writes the demo scenario with every default filled in; it reads back equal.
    again = Scenario.from_dict(yaml.safe_load(default_scenario_text()))
    demo = Scenario.demo()
    demo.name = "scenario"
    assert again.to_dict() == demo.to_dict()
    assert again.uav.altitude == 200.0 and again.poi.route[0] == [-290.0, -210.0]


def test_full_scenario_resolves_relative_paths(tmp_path: Path) -> None:
    path = write(tmp_path, """
name: paper
environment: {mesh: city.obj, up: y}
poi: {path: paths/p.csv, speed: 5}
uav: {speed: 20, min_turn_radius: 50, altitude: 300, start: [0, 100, -3.14159]}
sensor: {d_max: 400}
planning: {spacing: 20, cutoff: 20e6}
control: {beta: 0.025, k_psi: 20, direction: cw}
simulation: {rtol: 1.0e-6}
baselines: [11.2, 35]
""")
    s = Scenario.load(path)
    assert s.environment.kind == "mesh" and s.environment.up == "y"
    assert s.environment.path == tmp_path / "city.obj"
    assert s.poi.path == tmp_path / "paths" / "p.csv"
    assert s.planning.cutoff == 20e6  # "20e6" is a string in YAML 1.1; accepted as a number
    assert s.start == (0.0, 100.0, -3.14159)
    assert s.baselines == [11.2, 35.0]
    assert s.control.direction == "cw"
    assert s.origin is None


def test_origin_georeferences_the_environment(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    s = Scenario.from_dict({"georeference": {"lat": 35.2249, "lon": -80.8403, "alt": 230}})
    assert s.origin == vt.Georeference(35.2249, -80.8403, 230.0)
    assert s.to_dict()["georeference"] == {"lat": 35.2249, "lon": -80.8403, "alt": 230.0}
    assert Scenario.from_dict(s.to_dict()).origin == s.origin
    assert capsys.readouterr().out == ""
    # The spelling before the one schema still loads, with one line naming the new key.
    assert Scenario.from_dict({"origin": [35.2249, -80.8403, 230]}).origin == s.origin
    note = "vistrack: 'origin' is now 'georeference' (still read; see the docs' Scenario files)\n"
    assert capsys.readouterr().out == note
    env = s.environment.load(s.origin)  # the demo city, now on the Earth
    assert env.origin == (35.2249, -80.8403, 230.0)
    assert Scenario.from_dict({}).environment.load().origin is None


@pytest.mark.parametrize(
    "text, message",
    [
        ("uav: {sped: 3}", r"uav.sped = 3: unknown key; allowed keys in uav: aircraft, altitude, dynamics, "
                            r"max_roll_rate_deg_s, min_turn_radius"),
        ("uav: {dynamics: jet}", r"uav.dynamics = 'jet': must be one of roll, dubins"),
        ("colour: red", r"colour = 'red': unknown section"),
        ("uav: {speed: -2}", r"uav.speed = -2: must be a finite number in \[1e-06, 10000\] m/s"),
        ("uav: {speed: .nan}", r"uav.speed = nan: must be a finite number"),
        ("uav: {speed: fast}", r"uav.speed = 'fast': must be a number"),
        ("uav: {speed: 4}\npoi: {speed: 5}", r"uav.speed = 4.0: must exceed poi.speed"),
        ("control: {direction: up}", r"control.direction = 'up': must be \"ccw\" or \"cw\""),
        ("planning: {max_depth: 99}", r"planning.max_depth = 99: must be an integer in \[0, 30\]"),
        ("planning: {resolution_deg: 90}", r"planning.resolution_deg = 90: must be in \[0.1, 30\] degrees"),
        ("planning: {rate_margin: 1}", r"planning.rate_margin = 1: must be in \[0, 1\)"),
        ("planning: {rate_margin: -0.1}", r"planning.rate_margin = -0.1: must be in \[0, 1\)"),
        ("poi: {route: [[0, 0, 1], [5, 5]]}", r"poi.route\[0\] = \[0, 0, 1\]: must be \[x, y\]"),
        ("name: ../../etc", r"name = .*it names the output folder"),
        ("sensor: {altitude_band: [100, 50]}", r"sensor.altitude_band"),
        ("city: {mesh: a.obj, up: x}", r"city.up = 'x': must be \"z\" or \"y\""),
        ("city: {demo: true, mesh: a.obj}", r"city = .*exactly one of"),
        ("environment: {demo: true, mesh: a.obj}", r"city = .*exactly one of"),  # the old spelling, renamed
        ("environment: {demo: true}\ncity: {demo: true}", r"environment = .*renamed to city: give only city"),
        ("georeference: {lat: 95, lon: 0}", r"georeference.lat = 95: must be in \[-90, 90\] degrees"),
        ("georeference: {lon: 0}", r"georeference.lat = None: is required"),
        ("georeference: [35, -80]", r"georeference = \[35, -80\]: must be \{lat, lon, alt\}"),
        ("poi: {waypoints: [[0, 0]]}", r"poi.waypoints = .*at least two"),
        ("uav: {start: [0, 1]}", r"uav.start = \[0, 1\]: must be \[x, y, psi\]"),
        ("baselines: [10, -1]", r"baselines\[1\] = -1: must be >= 1e-06"),
        ("- 1\n- 2", r"scenario = .*must be a mapping"),
        ("origin: [95, 0]", r"origin\[0\] = 95: must be in \[-90, 90\] degrees"),
        ("origin: [35, -80, 1, 2]", r"origin = \[35, -80, 1, 2\]: must be \[lat, lon\] or \[lat, lon, alt\]"),
        ("origin: Charlotte", r"origin = 'Charlotte'"),
    ],
)
def test_schema_errors_name_key_value_and_range(tmp_path: Path, text: str, message: str) -> None:
    with pytest.raises(vt.VistrackError, match=message):
        Scenario.load(write(tmp_path, text))


def test_unreadable_and_invalid_files(tmp_path: Path) -> None:
    with pytest.raises(vt.VistrackError, match="cannot read the file"):
        Scenario.load(tmp_path / "missing.yaml")
    with pytest.raises(vt.VistrackError, match="not valid YAML"):
        Scenario.load(write(tmp_path, "uav: {speed: [1,"))


@pytest.mark.sanitize
def test_scenario_with_a_duplicated_section(tmp_path: Path) -> None:
    """A scenario YAML with a duplicated section kept the last one without a word."""
    from vistrack.scenario import Scenario

    path = tmp_path / "twice.yaml"
    path.write_text("environment: {demo: true}\nplanning: {spacing: 20.0}\nplanning: {spacing: 5.0}\n")
    refuses(lambda: Scenario.load(path), "planning", "twice")
