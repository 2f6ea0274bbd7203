"""The sweep's ``waypoints`` kind in metres and m/s by default, like ``vistrack waypoints``, with
``units: paper`` for the waypoint paper's dimensionless set (examples/sweep_waypoints.yaml)."""

from __future__ import annotations

import argparse
from typing import Any

import numpy as np
import pytest

import vistrack as vt
from support.paths import REPO
from vistrack import waypoint_nav as wn
from vistrack.commands.waypoint_units import flight_options
from vistrack.io import read_route
from vistrack.sweep import SERIAL, SweepSpec

METRES = REPO / "examples" / "waypoints_metres.csv"
PAPER = REPO / "examples" / "waypoints_paper.csv"


def command_options(**flags: Any) -> dict[str, Any]:
    """What ``vistrack waypoints ROUTE`` flies, from its own flag parsing (commands/waypoint_units.py)."""
    args = argparse.Namespace(paper_units=False, turn_radius=None, speed=None, dynamics=None, route=METRES, gains=None,
                              dt=wn.DEFAULTS["dt"], integration="discrete", guidance=None, l1_period=8.0,
                              wind_aware=False, replan_interval=0.0, aircraft=None)
    for key, value in flags.items():
        setattr(args, key, value)
    return flight_options(args, read_route(METRES))


def test_metres_by_default_fly_what_the_command_flies() -> None:
    """No units given: the route in metres, the default aircraft on the roll model with L1 legs, as
    ``vistrack waypoints`` flies it; wind_aware and replan_interval pass through."""
    base = {"route": str(METRES), "wind": {"east": 2.0, "north": 1.0}}
    spec = SweepSpec.from_dict({"kind": "waypoints", "base": base,
                                "parameters": {"method": ["dwn", "wn_passed_line"], "wind_aware": [False, True]}})
    rows = vt.sweep.run_cases(spec.cases(), SERIAL)
    assert all(row["run_status"] == "ok" for row in rows), [row["run_error"] for row in rows]
    route = read_route(METRES)
    assert [case.data["wind_aware"] for case in spec.cases()] == [False, True, False, True]
    for row, case in zip(rows, spec.cases()):
        options = command_options(wind_aware=case.data["wind_aware"])
        flight = wn.fly(route, method=row["method"], wind=vt.flight.Wind(east=2.0, north=1.0), **options)
        expected = flight.metrics()
        assert (row["max_miss_over_R"], row["duration"]) == (expected["max_miss_over_R"], expected["duration"])
    assert options["dynamics"] == "roll" and options["turn_radius"] == vt.Uav().min_turn_radius


def test_replan_interval_reaches_the_flight() -> None:
    spec = SweepSpec.from_dict({"kind": "waypoints", "base": {"route": str(METRES), "wind": {"east": 4.0}},
                                "parameters": {"replan_interval": [0.0, 1.0]}})
    rows = vt.sweep.run_cases(spec.cases(), SERIAL)
    route = read_route(METRES)
    for row, interval in zip(rows, (0.0, 1.0)):
        options = command_options(replan_interval=interval)
        expected = wn.fly(route, wind=vt.flight.Wind(east=4.0), **options).metrics()
        assert row["max_miss_over_R"] == expected["max_miss_over_R"]
    assert rows[0]["max_miss_over_R"] != rows[1]["max_miss_over_R"]


def test_the_paper_units_example_stays_reproducible() -> None:
    """examples/sweep_waypoints.yaml asks for units: paper: its cases fly the paper's section 3."""
    spec = SweepSpec.load(REPO / "examples" / "sweep_waypoints.yaml")
    cases = spec.cases()
    assert len(cases) == 1000
    for case in (cases[0], cases[7]):
        row = vt.sweep.run_cases([case], SERIAL)[0]
        data = case.data
        route = wn.random_route(np.random.default_rng(data["random_route"]["seed"]), 6, wn.DEFAULTS["turn_radius"])
        gusts = data["wind"]["gusts"]
        wind = vt.flight.Wind(east=data["wind"]["east"], north=data["wind"]["north"],
                              gusts=None if gusts is None else wn.paper_gusts(gusts["seed"]))
        expected = wn.fly(route, method=data["method"], wind=wind).metrics()
        assert (row["max_miss_over_R"], row["duration"]) == (expected["max_miss_over_R"], expected["duration"])


@pytest.mark.parametrize(("base", "message"), [
    ({"route": str(PAPER)}, "set units: paper"),
    ({"route": str(METRES), "units": "paper"}, "drop units: paper"),
    ({"route": str(METRES), "units": "feet"}, "units = 'feet'"),
    ({"route": str(METRES), "guidance": "pid"}, "guidance = 'pid'"),
    ({"route": str(METRES), "replan_interval": -1}, "replan_interval = -1"),
    ({"route": str(METRES), "units": "paper", "uav": {"dynamics": "roll"}}, "uav.dynamics = 'roll'"),
])
def test_bad_units_name_the_key(base: dict[str, Any], message: str) -> None:
    with pytest.raises(vt.VistrackError) as error:
        SweepSpec.from_dict({"kind": "waypoints", "base": base, "parameters": {"method": ["dwn"]}})
    assert message in str(error.value)


def test_units_may_vary_as_a_parameter() -> None:
    """Each case takes its own units' vehicle: the paper's route in paper units, then the same
    numbers read as metres, which the route check refuses naming route."""
    spec = SweepSpec.from_dict({"kind": "waypoints", "base": {"route": str(PAPER), "units": "paper"},
                                "parameters": {"units": ["paper", "metres"]}})
    rows = vt.sweep.run_cases(spec.cases(), SERIAL)
    assert rows[0]["run_status"] == "ok" and rows[0]["max_miss_over_R"] == wn.fly(read_route(PAPER)).metrics()[
        "max_miss_over_R"]
    assert rows[1]["run_status"] == "failed" and "set units: paper" in rows[1]["run_error"]


def test_the_units_rules_the_command_and_the_sweep_share() -> None:
    """vistrack.waypoint_nav.units: each unit system's vehicle, leg law and gains, and the route scale
    check at its edges (a longest leg of exactly 2 R in metres, or 100 R in the paper's units, fits)."""
    from vistrack.waypoint_nav.units import ALTITUDE, leg_gains, leg_guidance, route_scale_error, units_uav

    paper, metres = units_uav(True), units_uav(False)
    assert (paper.speed, paper.min_turn_radius) == (wn.DEFAULTS["speed"], wn.DEFAULTS["turn_radius"])
    assert (metres.speed, metres.min_turn_radius, metres.altitude) == (vt.Uav().speed, vt.Uav().min_turn_radius,
                                                                       ALTITUDE)
    assert leg_gains(True, 0.7) == tuple(wn.DEFAULTS["gains"]) and leg_gains(False, 50.0) == vt.flight.paper_gains(50.0)
    assert (leg_guidance(True), leg_guidance(False)) == ("law5", "l1")
    R = 50.0
    for longest, fits in ((2.0 * R, True), (2.0 * R - 1e-9, False)):
        route = np.array([[0.0, 0.0], [0.5 * R, 0.0], [0.5 * R, longest]])
        assert (route_scale_error(route, R, paper=False) is None) == fits
    for longest, fits in ((100.0 * 0.7, True), (100.0 * 0.7 + 1e-9, False)):
        route = np.array([[0.0, 0.0], [longest, 0.0]])
        assert (route_scale_error(route, 0.7, paper=True) is None) == fits
    assert "under 2 R = 100 m" in str(route_scale_error(np.array([[0.0, 0.0], [60.0, 0.0]]), R, paper=False))
