"""Defaults come from the bound C++ structs only: the Python defaults of the loiter, waypoint and
follow planners (functions, scenario classes, scenario files, sweep bases) equal the bound
structs', and with the structs' defaults changed (subclasses swapped in before the package is
imported, in a child process) every one of them follows: no default is restated in Python."""

from __future__ import annotations

import dataclasses
import inspect
import json
import subprocess
import sys
import textwrap
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import vistrack as vt
from support.paths import REPO
from vistrack.follow.scenario import FollowScenario
from vistrack.sweep import SweepSpec
from vistrack.sweep.waypoint_nav import _flight_inputs as flight_inputs

LEGS = {"vehicle": {"legs": [{"heading": "east", "speed": 5, "duration": 10}]}}


def defaults(function: Any, *names: str) -> dict[str, Any]:
    signature = inspect.signature(function).parameters
    return {name: signature[name].default for name in names}


def loiter_defaults() -> dict[str, Any]:
    """Every loiter default Python states, by where it is stated."""
    loiter = vt.loiter
    scenario = {f.name: f.default for f in dataclasses.fields(loiter.Scenario)}
    return {
        "plan": defaults(loiter.plan, "turn_radius", "speed", "aoi_radius", "turns"),
        "plan_in_order": defaults(loiter.plan_in_order, "turn_radius", "speed", "aoi_radius", "turns"),
        "coverage": defaults(loiter.coverage, "threshold", "dt"),
        "metrics": defaults(loiter.metrics, "threshold", "dt"),
        "coverage_by_role": defaults(loiter.coverage_by_role, "threshold", "dt"),
        "flown_samples": defaults(loiter.flown_samples, "dt"),
        "loiter_coverage_fraction": defaults(loiter.loiter_coverage_fraction, "threshold"),
        "write_loiter_samples_csv": defaults(vt.loiter.files.write_loiter_samples_csv, "threshold"),
        "Scenario": {k: scenario[k] for k in ("turn_radius", "speed", "aoi_radius", "turns", "threshold", "dt")},
    }


def test_loiter_defaults_are_the_bound_structs() -> None:
    p, c = vt.loiter.Parameters(), vt.loiter.CoverageOptions()
    plan = {"turn_radius": p.turn_radius, "speed": p.speed, "aoi_radius": p.aoi_radius, "turns": p.turns}
    stated = loiter_defaults()
    assert stated["plan"] == stated["plan_in_order"] == plan
    for name in ("coverage", "metrics", "coverage_by_role"):
        assert stated[name] == {"threshold": c.threshold, "dt": c.dt}, name
    assert stated["flown_samples"] == {"dt": c.dt}
    assert stated["loiter_coverage_fraction"] == stated["write_loiter_samples_csv"] == {"threshold": c.threshold}
    assert stated["Scenario"] == {**plan, "threshold": c.threshold, "dt": c.dt}
    # What the binding's own defaults give, and the paper's section 4.1.
    aois = [(300.0, 200.0), (600.0, 500.0)]
    assert vt.loiter.plan(aois).length == vt._core.loiter.plan(np.array(aois)).length
    assert (p.turn_radius, p.speed, p.aoi_radius, p.turns, c.threshold, c.dt) == (46.0, 12.0, 46.0, 1, 0.75, 1.0)


def test_bound_parameter_structs_validate_and_print() -> None:
    p = vt.loiter.Parameters(turn_radius=40.0, aoi_radius=50.5)
    assert repr(p) == "loiter.Parameters(turn_radius=40, speed=12, aoi_radius=50.5, turns=1)"
    assert repr(vt.loiter.CoverageOptions(threshold=0.1 + 0.2)) == \
        "loiter.CoverageOptions(threshold=0.30000000000000004, dt=1, gravity=9.80665)"
    p.aoi_radius = 30.0
    with pytest.raises(vt.VistrackError, match=r"^aoi_radius = 30: must be at least turn_radius = 40"):
        p.validate()
    with pytest.raises(vt.VistrackError, match=r"^turns = 0: must be at least 1"):
        vt.loiter.Parameters(turns=0)
    with pytest.raises(vt.VistrackError, match=r"^threshold = 1.5: must be in \(0, 1\]"):
        vt.loiter.CoverageOptions(threshold=1.5)
    o = vt.waypoint_nav.Options(method="wn", waypoint_radius=0.35)
    assert repr(o) == ("waypoint_nav.Options(method='wn', turn_radius=0.7, speed=0.8, dt=0.02, gains=(0.1, 5.25), "
                       "waypoint_radius=0.35, weights=(1, 1), integration='discrete', dynamics='dubins', "
                       "guidance='law5')")
    o.method = "dwn"
    with pytest.raises(vt.VistrackError, match=r"^waypoint_radius = 0.35: DWN has no waypoint radius"):
        o.validate()
    with pytest.raises(vt.VistrackError, match=r"^gains.h = -1"):
        vt.waypoint_nav.Options(gains=(0.1, -1.0))


def test_waypoint_defaults_are_the_bound_struct() -> None:
    o, wn = vt.waypoint_nav.Options(), vt.waypoint_nav
    fields = {"method": o.method, "turn_radius": o.turn_radius, "speed": o.speed, "dt": o.dt, "gains": o.gains,
              "weights": o.weights, "integration": o.integration}
    assert defaults(wn.fly, *fields) == fields
    assert wn.DEFAULTS == fields  # kept for its readers, built from the struct
    assert (o.turn_radius, o.speed, o.dt, o.gains) == (0.7, 0.8, 0.02, (0.1, 5.25))  # the paper's section 3
    sweep = SweepSpec.from_dict({"kind": "waypoints", "base": {"waypoints": [[0, 0], [5, 0]], "units": "paper"},
                                 "parameters": {"method": ["wn"]}}).base  # a sweep in the paper's units
    flown = flight_inputs(sweep, REPO, seed=0)[1]  # what a case flies: the units' defaults filled in
    assert (flown["speed"], flown["turn_radius"]) == (o.speed, o.turn_radius)
    assert (flown["dt"], flown["gains"], flown["weights"]) == (o.dt, o.gains, o.weights)


def test_follow_defaults_are_the_bound_structs(tmp_path: Path) -> None:
    uav, flight, parameters = vt.follow.default_uav(), vt.follow.FollowFlight(), vt.follow.FollowParameters()
    assert (uav.speed, uav.min_turn_radius, uav.altitude) == (21.0, 50.0, 200.0)  # the follow examples' UAV
    path = tmp_path / "bare.yaml"
    path.write_text(json.dumps(LEGS))
    scenario = FollowScenario.load(path)
    assert repr(scenario.uav) == repr(FollowScenario(vehicle=scenario.vehicle).uav)
    uav.dynamics = "roll"  # scenarios fly the roll model unless they say (scenario_blocks.DEFAULT_DYNAMICS)
    assert repr(scenario.uav) == repr(uav)
    assert (scenario.flight.integration, scenario.flight.dt, scenario.flight.max_time) == \
        (flight.integration, flight.dt, flight.max_time)
    assert (scenario.parameters.offset_distance, scenario.parameters.offset_angle) == \
        (parameters.offset_distance, parameters.offset_angle)
    assert vt.follow.default_uav() is not vt.follow.default_uav()  # a new one each time: changing it changes no default


CHANGED = '''
import sys
sys.path.insert(0, {tests!r})
from support.build_tree import use_build_tree
use_build_tree()
import vistrack
core = sys.modules["vistrack._core"]
for name in [m for m in sys.modules if m.startswith("vistrack") and not m.startswith("vistrack._core")]:
    del sys.modules[name]  # the package is imported again below, over the changed structs


def changed(cls, **values):
    class Changed(cls):
        def __init__(self, **given):
            super().__init__(**{{**values, **given}})
    return Changed


core.loiter.Parameters = changed(core.loiter.Parameters, turn_radius=40.0, speed=15.0, aoi_radius=50.0, turns=2)
core.loiter.CoverageOptions = changed(core.loiter.CoverageOptions, threshold=0.5, dt=2.0)
core.waypoint_nav.Options = changed(core.waypoint_nav.Options, turn_radius=0.6, speed=0.9, dt=0.01,
                                    gains=(0.2, 5.0), weights=(1.5, 1.0), integration="continuous", method="wn")
core.follow.default_uav = lambda: core.Uav(speed=25.0, min_turn_radius=60.0, altitude=250.0)
core.follow.FollowFlight = changed(core.follow.FollowFlight, dt=0.05, max_time=99.0)
'''


def test_changed_struct_defaults_are_seen_everywhere(tmp_path: Path) -> None:
    """With every bound default changed, each Python default follows (a restated literal would not)."""
    follow_file = tmp_path / "follow.yaml"
    follow_file.write_text(json.dumps(LEGS))
    loiter_file = tmp_path / "loiter.yaml"
    loiter_file.write_text(json.dumps({"aois": [[300, 200], [600, 500]]}))
    check = CHANGED.format(tests=str(REPO / "tests" / "python")) + textwrap.dedent(f'''
        import json, dataclasses, inspect
        import vistrack as vt
        from test_bound_defaults import loiter_defaults, defaults
        from vistrack.follow.scenario import FollowScenario
        from vistrack.sweep import SweepSpec
        stated = loiter_defaults()
        scenario = vt.loiter.load_scenario({str(loiter_file)!r})
        stated["file"] = {{k: getattr(scenario, k) for k in ("turn_radius", "speed", "aoi_radius", "turns",
                                                            "threshold", "dt")}}
        loiter_base = SweepSpec.from_dict({{"kind": "loiter", "base": {{"aois": [[300, 200], [600, 500]]}},
                                           "parameters": {{"method": ["tlpp"]}}}}).base
        stated["sweep"] = {{"uav": loiter_base["uav"], "aoi_radius": loiter_base["aoi_radius"],
                           "turns": loiter_base["turns"], "threshold": loiter_base["threshold"],
                           "dt": loiter_base["dt"]}}
        o = vt.waypoint_nav.fly
        stated["fly"] = defaults(o, "method", "turn_radius", "speed", "dt", "gains", "weights", "integration")
        stated["DEFAULTS"] = vt.waypoint_nav.DEFAULTS
        from vistrack.sweep.waypoint_nav import _flight_inputs
        base = SweepSpec.from_dict({{"kind": "waypoints", "base": {{"waypoints": [[0, 0], [5, 0]], "units": "paper"}},
                                    "parameters": {{"method": ["wn"]}}}}).base
        flown = _flight_inputs(base, __import__("pathlib").Path("."), 0)[1]
        stated["waypoint_sweep"] = {{k: flown[k] for k in ("turn_radius", "speed", "dt", "gains", "weights",
                                                          "integration", "method")}}
        follow = FollowScenario.load({str(follow_file)!r})
        stated["follow"] = [follow.uav.speed, follow.uav.min_turn_radius, follow.uav.altitude, follow.flight.dt,
                            follow.flight.max_time]
        uav = FollowScenario(vehicle=follow.vehicle).uav
        stated["follow_class"] = [uav.speed, uav.min_turn_radius, uav.altitude]
        print(json.dumps(stated))
    ''')
    result = subprocess.run([sys.executable, "-c", check], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    stated = json.loads(result.stdout.splitlines()[-1])
    plan = {"turn_radius": 40.0, "speed": 15.0, "aoi_radius": 50.0, "turns": 2}
    cover = {"threshold": 0.5, "dt": 2.0}
    assert stated["plan"] == stated["plan_in_order"] == plan
    for name in ("coverage", "metrics", "coverage_by_role"):
        assert stated[name] == cover, name
    assert stated["flown_samples"] == {"dt": 2.0}
    assert stated["loiter_coverage_fraction"] == stated["write_loiter_samples_csv"] == {"threshold": 0.5}
    assert stated["Scenario"] == stated["file"] == {**plan, **cover}
    assert stated["sweep"] == {"uav": {"speed": 15.0, "min_turn_radius": 40.0, "altitude": 61.0},
                               "aoi_radius": 50.0, "turns": 2, **cover}
    options = {"method": "wn", "turn_radius": 0.6, "speed": 0.9, "dt": 0.01, "gains": [0.2, 5.0],
               "weights": [1.5, 1.0], "integration": "continuous"}
    assert stated["fly"] == stated["DEFAULTS"] == options
    assert stated["waypoint_sweep"] == options
    assert stated["follow"] == [25.0, 60.0, 250.0, 0.05, 99.0]
    assert stated["follow_class"] == [25.0, 60.0, 250.0]
