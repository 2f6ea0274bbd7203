"""vistrack.loiter: the planners' API, coverage against shapely and Monte Carlo, the order search
against brute force, scenario files, errors naming the field, the CLI."""

from __future__ import annotations

import dataclasses
import itertools
import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import vistrack as vt
from support.cli import NO_MEDIA
from support.paths import REPO
from support.refusal import refuses
from vistrack import VistrackError, loiter

EXAMPLES = sorted((REPO / "examples").glob("loiter_*aoi.yaml"))
SQUARE = [(200.0, 200.0), (600.0, 200.0), (600.0, 600.0), (200.0, 600.0)]

pytestmark = pytest.mark.sanitize  # the input-facing surface (scripts/sanitize.sh)


def test_public_api_shape() -> None:
    assert vt.loiter is loiter
    assert loiter.METHODS == ("fly_through", "tlpp", "ldlpp")
    plan = vt.loiter.plan(SQUARE, method="ldlpp", start=(0, 0), end=(0, 0), turn_radius=46.0, speed=12.0,
                          aoi_radius=46.0, turns=1, order="given")
    assert plan.flight_time == pytest.approx(plan.length / 12.0)
    assert plan.transit_time == pytest.approx(plan.flight_time - plan.loiter_time)
    assert 0 < plan.transit_time < plan.flight_time
    kinds = {(s.kind, s.role) for s in plan.segments}
    assert ("arc", "loiter") in kinds and ("line", "transit") in kinds and ("arc", "entry") in kinds
    for s in plan.segments:
        assert s.length > 0
        if s.kind == "arc":
            assert s.direction in ("ccw", "cw") and s.radius == pytest.approx(46.0) and s.center is not None
        else:
            assert s.direction is None and s.radius is None and s.center is None
    rows = plan.sample(1.0)
    assert rows.shape[1] == 3
    assert rows[0, :2] == pytest.approx([0.0, 0.0]) and rows[-1, :2] == pytest.approx([0.0, 0.0], abs=1e-9)
    # Continuous heading, turn rate within v / r.
    assert np.all(np.abs(np.diff(rows[:-1, 2])) <= 12.0 / 46.0 + 1e-9)
    records = loiter.segment_records(plan)
    assert json.loads(json.dumps(records))[0]["kind"] == "line"
    circles = loiter.loiter_circles(plan)
    assert [c["aoi"] for c in circles] == list(plan.order)
    for c in circles:
        assert c["direction"] == "ccw" and c["turns"] >= 1.0
        assert math.dist(c["entry"], c["center"]) == pytest.approx(46.0)
        assert math.dist(c["exit"], c["center"]) == pytest.approx(46.0)


def test_sampling_times_and_end() -> None:
    plan = loiter.plan(SQUARE, "tlpp")
    states = plan.sample_states(0.5)
    assert states.t[0] == 0.0 and states.t[-1] == pytest.approx(plan.flight_time)
    assert np.all(np.diff(states.t) > 0)
    for t, row in zip(states.t[::40], states.poses[::40]):
        assert plan.at_time(float(t)) == pytest.approx(tuple(row))
    without_end = plan.sample_states(1.0, False)
    assert without_end.t[-1] <= plan.flight_time and len(without_end.t) == math.floor(plan.flight_time) + 1


def test_every_aoi_is_circled_at_least_turns_times() -> None:
    for method in loiter.METHODS:
        for turns in (1, 2):
            plan = loiter.plan(SQUARE, method, turns=turns)
            assert np.all(plan.loiter_sweep >= 2 * math.pi * turns - 1e-9)
            # The swept angle about each AOI centre, summed along the sampled loiter, agrees.
            states = plan.sample_states(0.05)
            for i, centre in enumerate(SQUARE):
                on = [k for k, seg in enumerate(states.segment)
                      if plan.segments[seg].role == "loiter" and plan.segments[seg].aoi == i]
                angles = np.unwrap(np.arctan2(states.poses[on, 1] - centre[1], states.poses[on, 0] - centre[0]))
                # Samples fall up to one step inside each end of the loiter.
                assert abs(angles[-1] - angles[0]) >= 2 * math.pi * turns - 2 * 0.05 * 12.0 / 46.0 - 1e-9


def test_best_order_matches_brute_force() -> None:
    rng = np.random.default_rng(4)
    aois = loiter.random_aois(6, rng)
    for method in loiter.METHODS:
        brute = min(loiter.order_length(aois, list(order), method) for order in itertools.permutations(range(6)))
        best = loiter.plan(aois, method, order="best")
        assert best.length == pytest.approx(brute, rel=1e-9)
        assert loiter.plan(aois, method).length >= best.length - 1e-9


def _ellipse_polygon(footprint: loiter.Footprint, n: int = 2048):
    from shapely.geometry import Polygon

    t = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    along = np.array(footprint.along)
    left = np.array([-along[1], along[0]])
    points = (np.array(footprint.center)[None, :] + np.outer(footprint.semi_along * np.cos(t), along)
              + np.outer(footprint.semi_across * np.sin(t), left))
    return Polygon(points)


def test_coverage_fractions_agree_with_shapely() -> None:
    from shapely.geometry import Point

    plan = loiter.plan(SQUARE, "tlpp")
    camera = loiter.Camera()
    cov = loiter.coverage(plan, camera=camera)
    states = plan.sample_states(1.0, False)
    assert cov.fraction.shape == (len(states.t), 4)
    checked = 0
    for k in range(0, len(states.t), 7):
        i = cov.pointed[k]
        if i < 0:
            continue
        footprint = camera.footprint(tuple(states.poses[k]), cov.tilt[k])
        disk = Point(*SQUARE[i]).buffer(46.0, 1024)
        theirs = _ellipse_polygon(footprint).intersection(disk).area / disk.area
        assert cov.fraction[k, i] == pytest.approx(theirs, abs=2e-4)
        checked += 1
    assert checked > 20


def test_coverage_area_against_monte_carlo() -> None:
    rng = np.random.default_rng(8)
    camera = loiter.Camera()
    for _ in range(20):
        pose = (rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-math.pi, math.pi))
        footprint = camera.footprint(pose, rng.uniform(-0.7, 0.7))
        centre = np.array(footprint.center) + rng.uniform(-80, 80, 2)
        exact = footprint.disk_area(tuple(centre), 46.0)
        radius = 46.0 * np.sqrt(rng.uniform(0, 1, 200000))
        angle = rng.uniform(0, 2 * math.pi, 200000)
        points = centre + np.column_stack([radius * np.cos(angle), radius * np.sin(angle)])
        d = points - np.array(footprint.center)
        along = np.array(footprint.along)
        a = d @ along
        s = d @ np.array([-along[1], along[0]])
        p = np.mean((a / footprint.semi_along) ** 2 + (s / footprint.semi_across) ** 2 <= 1.0)
        disk = math.pi * 46.0 ** 2
        assert exact == pytest.approx(p * disk, abs=5 * disk * math.sqrt(max(p * (1 - p), 1e-6) / 200000) + 1e-9)


def test_camera_reproduces_nadir_area_and_explains_the_tilted_one() -> None:
    camera = loiter.Camera()
    assert camera.altitude == 61.0 and camera.fov_deg == 74.0 and camera.max_gimbal_deg == 25.0
    assert camera.footprint((0, 0, 0), 0.0).area == pytest.approx(6638, abs=0.5)
    tilted = camera.footprint((0, 0, 0), math.radians(25))
    assert tilted.area == pytest.approx(10866, abs=1)
    assert math.pi * (2 * tilted.semi_across) ** 2 == pytest.approx(51223, abs=1)


def test_coverage_from_samples_matches_the_plan() -> None:
    plan = loiter.plan(SQUARE, "ldlpp")
    states = plan.sample_states(1.0, False)
    exact = loiter.coverage(plan)
    with_rates = loiter.coverage(np.column_stack([states.poses, states.turn_rate]), SQUARE)
    assert with_rates.time == exact.time and with_rates.area == pytest.approx(exact.area)
    # Turn rates from the headings: nearly the same (they differ at segment joins).
    estimated = loiter.coverage(states.poses, SQUARE)
    assert estimated.time == pytest.approx(exact.time, rel=0.05)


def test_scenario_files_load_and_plan() -> None:
    assert len(EXAMPLES) == 6
    for path in EXAMPLES:
        scenario = loiter.load_scenario(path)
        assert 4 <= len(scenario.aois) <= 9
        assert np.all((scenario.aois >= 0) & (scenario.aois <= 800))
        assert set(scenario.paper) == set(loiter.METHODS)
        for method in loiter.METHODS:
            plan = scenario.plan(method)
            assert plan.flight_time > 0 and scenario.coverage(plan).time > 0


def test_random_scenarios_are_seeded() -> None:
    a = loiter.random_scenario(7, seed=3)
    b = loiter.random_scenario(7, seed=3)
    assert np.array_equal(a.aois, b.aois)
    assert not np.array_equal(a.aois, loiter.random_scenario(7, seed=4).aois)
    d = np.hypot(*(a.aois[:, None, :] - a.aois[None, :, :]).transpose(2, 0, 1))
    assert np.min(d[np.triu_indices(7, 1)]) >= 160.0
    for method in loiter.METHODS:  # every order is flyable
        a.plan(method, "best")


@pytest.mark.parametrize("kwargs, field", [
    ({"aois": np.zeros((0, 2))}, "aois"),
    ({"aoi_radius": 30.0}, "aoi_radius"),
    ({"aois": [(300, 300), (350, 300)]}, "aois[1]"),
    ({"turns": 0}, "turns"),
    ({"speed": 0.0}, "speed"),
    ({"turn_radius": -1.0}, "turn_radius"),
    ({"aois": [(300, float("nan"))]}, "aois[0][1]"),
    ({"method": "spiral"}, "method"),
    ({"order": "random"}, "order"),
    ({"start": (310, 300)}, "start"),
])
def test_bad_input_names_the_field(kwargs: dict, field: str) -> None:
    arguments = {"aois": [(300.0, 300.0), (600.0, 300.0)], **kwargs}
    with pytest.raises(VistrackError, match=field.replace("[", r"\[").replace("]", r"\]")):
        loiter.plan(**arguments)


def test_ldlpp_refuses_lines_too_short_for_its_turns() -> None:
    with pytest.raises(VistrackError, match=r"aois\[1\].*LDLPP needs"):
        loiter.plan([(300, 0), (420, 0), (360, 400)], "ldlpp")
    assert loiter.plan([(300, 0), (420, 0), (360, 400)], "ldlpp", order="best").order in ([0, 2, 1], [1, 2, 0])


def test_computed_limits_are_printed_to_4_significant_digits() -> None:
    """Issue 29: "LDLPP needs 159.3486742963367 m" is now 159.3 m; the user's own values are echoed
    as given (the AOI at 100.123456789), the distance computed from them to 4 digits."""
    message = refuses(lambda: loiter.plan([(0, 0), (100.123456789, 0)], "ldlpp", start=(-500, 0), end=(500, 0),
                                          turn_radius=46.0, aoi_radius=46.0),
                      "aois[1] = (100.123456789, 0): LDLPP needs 159.3 m", "aois[0] before it is 100.1 m away")
    assert "159.34" not in message
    refuses(lambda: loiter.plan([(0, 0), (60.5, 0)], "tlpp", start=(-500, 0), end=(500, 0), turn_radius=46.1,
                                aoi_radius=46.1),
            "the centres are 60.5 m apart, at least 2 R = 92.2 are needed")


def test_scenario_file_errors_name_the_key(tmp_path: Path) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("aois: [[300, 300], [600, 300]]\nspeed: -3\n")
    with pytest.raises(VistrackError, match="speed"):
        loiter.load_scenario(bad)
    bad.write_text("aois: [[300, 300], [600, 300]]\nwind: 3\n")
    with pytest.raises(VistrackError, match="wind"):
        loiter.load_scenario(bad)
    bad.write_text("aois: [[300, 300], [600]]\n")
    with pytest.raises(VistrackError, match=r"aois\[1\]"):
        loiter.load_scenario(bad)
    bad.write_text("aois: [[300, 300]]\ncamera: {altitude: 0}\n")
    with pytest.raises(VistrackError, match=r"camera\.altitude"):
        loiter.load_scenario(bad)
    bad.write_text("aois: [[300, 300]]\ncamera: {levelled: 'no'}\n")
    with pytest.raises(VistrackError, match=r"camera\.levelled = 'no'"):
        loiter.load_scenario(bad)


def test_body_camera_sees_less_of_a_minimum_radius_loiter(tmp_path: Path) -> None:
    """camera.levelled: false puts the gimbal under the banked body: on a loiter at the minimum
    turn radius the belly faces out of the circle, so the AOI is held for far less of the loiter
    than with the paper's levelled camera, which holds it all the time (README's numbers)."""
    scenario = tmp_path / "one.yaml"
    scenario.write_text("aois: [[300, 300]]\ncamera: {levelled: false}\n")
    body = loiter.load_scenario(scenario)
    assert not body.camera.levelled
    plan = body.plan("tlpp")
    on_loiter = np.array([plan.segments[k].role == "loiter" for k in plan.sample_states(body.dt, False).segment])
    held_body = (body.coverage(plan).fraction[:, 0] >= body.threshold)[on_loiter].mean()
    levelled = dataclasses.replace(body, camera=loiter.Camera())
    held_levelled = (levelled.coverage(plan).fraction[:, 0] >= levelled.threshold)[on_loiter].mean()
    assert held_levelled == 1.0
    assert held_body < 0.3


def test_cli_writes_figures_metrics_and_paths(tmp_path: Path) -> None:
    from vistrack.cli import main

    source = EXAMPLES[0].read_bytes()
    assert main(["loiter", str(EXAMPLES[0]), "--order", "best", "--out", str(tmp_path / "one"), "--quiet",
                 *NO_MEDIA]) == 0
    assert EXAMPLES[0].read_bytes() == source  # input untouched
    metrics = json.loads((tmp_path / "one" / "metrics.json").read_text())
    assert [m["method"] for m in metrics["methods"]] == list(loiter.ALL_METHODS)
    assert all(m["best_flight_time_s"] <= m["flight_time_s"] + 1e-9 for m in metrics["methods"])
    for method in loiter.METHODS:
        lines = (tmp_path / "one" / f"path_{method}.csv").read_text().splitlines()
        assert lines[0].startswith("t,x,y,psi") and len(lines) > 100
    assert (tmp_path / "one" / "plans.png").stat().st_size > 10000
    assert main(["loiter", *map(str, EXAMPLES[:2]), "--method", "ldlpp", "tlpp", "--out", str(tmp_path / "two"),
                 "--quiet", *NO_MEDIA]) == 0
    assert "| TLPP |" in (tmp_path / "two" / "table.md").read_text()
    assert (tmp_path / "two" / "fig14_comparison.png").exists()
    assert main(["loiter", "--random", "6", "--seed", "1", "--out", str(tmp_path / "random"), "--quiet"]) == 0
    assert len(json.loads((tmp_path / "random" / "random.json").read_text())["records"]) == 6 * len(loiter.ALL_METHODS)


def test_cli_errors_are_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from vistrack.cli import main

    assert main(["loiter", "--out", str(tmp_path)]) == 2
    assert "scenarios" in capsys.readouterr().err
    assert main(["loiter", str(EXAMPLES[0]), "--wind", "3", "--out", str(tmp_path)]) == 2
    assert "--wind" in capsys.readouterr().err


def test_plans_fly_through_the_flight_layer() -> None:
    plan = loiter.plan(SQUARE, "ldlpp")
    calm = loiter.fly(plan)
    assert calm.finished and calm.end_time == pytest.approx(plan.flight_time, abs=0.5)
    pieces = loiter.path_pieces(plan)
    assert pieces.shape == (len(plan.segments), 5)
    follower = vt.flight.PathFollower(pieces, plan.speed, plan.turn_radius)
    assert follower.length == pytest.approx(plan.length)
    # Without wind the flown path stays on the plan and covers what the plan covers: within 1 m on
    # the Dubins vehicle; the roll model (a scenario's default) enters each arc with its roll lag,
    # within 3 m since the follower's feed-forward anticipates the arcs by tau (10.9 m without).
    scenario = loiter.Scenario(aois=np.array(SQUARE), dynamics="dubins")
    assert loiter.fly_and_score(scenario, plan, (0.0, 0.0), keep_trajectory=False)["max_cross_track_m"] < 1.0
    scenario = loiter.Scenario(aois=np.array(SQUARE))
    assert scenario.uav().dynamics == "roll"
    calm_score = loiter.fly_and_score(scenario, plan, (0.0, 0.0), keep_trajectory=False)
    assert calm_score["max_cross_track_m"] < 3.0
    assert calm_score["smoothness"]["max_roll_rate_deg_s"] <= 70.0 * (1 + 1e-9)
    assert calm_score["smoothness"]["roll_reversals_per_s"] < 1.0
    assert calm_score["loiter_covered_fraction"] == pytest.approx(calm_score["planned_loiter_covered_fraction"])
    assert calm_score["coverage_time_s"] == pytest.approx(calm_score["planned_coverage_time_s"], abs=3.0)
    # In a 5 m/s wind the minimum-radius loiters cannot be held: coverage on the loiters drops.
    windy = loiter.fly_and_score(scenario, plan, (5.0, 0.0), keep_trajectory=False)
    assert windy["finished"]
    assert windy["max_cross_track_m"] > 20.0
    assert windy["loiter_covered_fraction"] < calm_score["loiter_covered_fraction"] - 0.1
    with pytest.raises(VistrackError, match="wind"):
        loiter.fly(plan, (12.0, 0.0))


def test_cli_wind(tmp_path: Path) -> None:
    from vistrack.cli import main

    assert main(["loiter", str(EXAMPLES[0]), "--method", "tlpp", "--wind", "5,0", "--out", str(tmp_path),
                 "--quiet", *NO_MEDIA]) == 0
    metrics = json.loads((tmp_path / "metrics.json").read_text())
    flown = metrics["methods"][0]["wind"][0]
    assert flown["wind"] == [5.0, 0.0] and 0.0 <= flown["loiter_covered_fraction"] <= 1.0
    assert (tmp_path / "wind_tlpp.png").exists()


AOIS = [[200.0, 0.0], [500.0, 0.0], [500.0, 300.0]]


@pytest.mark.parametrize("kwargs, fragment", [
    ({"turn_radius": 1e300, "aoi_radius": 1e300}, "turn_radius = 1e+300"),
    ({"speed": 1e300}, "speed = 1e+300"),
    ({"start": "ab"}, "start = 'ab'"),
    ({"start": (math.nan, 0.0)}, "start[0] = nan"),
])
def test_loiter_plans_refuse_out_of_range_inputs(kwargs: dict[str, Any], fragment: str) -> None:
    refuses(lambda: vt.loiter.plan(AOIS, **kwargs), fragment)


def test_loiter_refuses_far_aois_too_many_and_nan_thresholds() -> None:
    refuses(lambda: vt.loiter.plan([[1e300, 0.0], [400.0, 0.0]]), "aois[0][0] = 1e+300")
    refuses(lambda: vt.loiter.plan(None), "aois = None")  # type: ignore[arg-type]
    many = np.column_stack([np.arange(10001) * 100.0, np.zeros(10001)])
    refuses(lambda: vt.loiter.plan(many, turn_radius=40.0, aoi_radius=40.0), "at most 10000 AOIs")
    plan = vt.loiter.plan(AOIS)
    refuses(lambda: vt.loiter.metrics(plan, threshold=math.nan), "threshold = nan")
    refuses(lambda: vt.loiter.fly(plan, wind=(1e300, 0.0)), "wind.east = 1e+300")


def test_loiter_coverage_refuses_altitudes_and_steps_beyond_the_limits() -> None:
    """An altitude of 1e300 m covered every AOI fully and a dt of 1e300 s gave coverage 0: the
    altitude is a length ([1e-6, 1e7] m), dt a time step ((0, 3600] s)."""
    plan = vt.loiter.plan(AOIS)
    refuses(lambda: vt.loiter.coverage(plan, dt=1e300), "dt = 1e+300", "(0, 3600] s")
    refuses(lambda: vt.loiter.Camera(74.0, 25.0, 1e300, True), "camera.altitude = 1e+300", "[1e-06, 1e+07] m")
    refuses(lambda: vt.loiter.CoverageOptions(dt=7200.0), "dt = 7200", "(0, 3600] s")


# ---------------------------------------------------------------------------------------------
# Beyond the paper: the loiter directions chosen (issue 33).

def _layouts(count: int, seed: int) -> list[loiter.Scenario]:
    return [loiter.random_scenario(3 + k % 6, seed + k) for k in range(count)]


def _mirrored(scenario: loiter.Scenario) -> loiter.Scenario:
    flip = np.array([-1.0, 1.0])
    return loiter.Scenario(aois=np.asarray(scenario.aois) * flip, start=tuple(np.asarray(scenario.start) * flip),
                           end=tuple(np.asarray(scenario.end) * flip))


def _contiguous(plan: loiter.Plan) -> None:
    for a, b in zip(plan.segments, plan.segments[1:]):
        np.testing.assert_allclose(b.start, a.end, atol=1e-7)
        assert b.start_heading == pytest.approx(a.end_heading, abs=1e-9)


@pytest.mark.parametrize("seed", [11, 12])
def test_per_aoi_ldlpp_loiters_the_shorter_way_at_every_aoi(seed: int) -> None:
    for scenario in _layouts(12, 100 * seed):
        printed, chosen = scenario.plan("ldlpp"), scenario.plan("ldlpp_best")
        _contiguous(chosen)
        assert chosen.method == "ldlpp_best" and printed.method == "ldlpp"
        printed_sweep, chosen_sweep = np.asarray(printed.loiter_sweep), np.asarray(chosen.loiter_sweep)
        assert (chosen_sweep <= printed_sweep + 1e-12).all()
        # The transit is the same either way: the plans differ by R times the loiter saved.
        saved = scenario.aoi_radius * float(np.sum(printed_sweep - chosen_sweep))
        assert chosen.length == pytest.approx(printed.length - saved, rel=1e-12, abs=1e-6)
        for k, direction in enumerate(chosen.directions):
            assert (str(direction) == "cw") == (chosen_sweep[k] < printed_sweep[k] - 1e-12)


def test_per_aoi_ldlpp_over_one_aoi_is_the_shorter_of_the_layout_and_its_mirror_image() -> None:
    """An independent oracle: mirroring the layout mirrors the printed plan (its clockwise twin)."""
    rng = np.random.default_rng(5)
    for _ in range(40):
        aoi = rng.uniform(150.0, 700.0, 2)
        start, end = tuple(rng.uniform(-200.0, 0.0, 2)), tuple(rng.uniform(800.0, 1000.0, 2))
        scenario = loiter.Scenario(aois=np.array([aoi]), start=start, end=end)
        mirror = _mirrored(scenario).plan("ldlpp").length
        assert scenario.plan("ldlpp_best").length == pytest.approx(min(scenario.plan("ldlpp").length, mirror),
                                                                   rel=1e-12)


def test_tlpp_with_both_first_directions_keeps_the_shorter() -> None:
    shorter = 0
    for scenario in _layouts(24, 7):
        printed, chosen = scenario.plan("tlpp"), scenario.plan("tlpp_best")
        _contiguous(chosen)
        assert chosen.length <= printed.length * (1 + 1e-12)
        first = chosen.order[0]
        if chosen.directions[first] == printed.directions[first]:
            assert chosen.length == pytest.approx(printed.length, rel=1e-12)
        else:
            assert chosen.length < printed.length
            shorter += 1
        # TLPP's directions alternate along the visiting order.
        flown = [str(chosen.directions[k]) for k in chosen.order]
        assert all(a != b for a, b in zip(flown, flown[1:]))
    assert shorter > 0  # the printed rule does pick the longer plan on some layouts


@pytest.mark.parametrize("order", ["given", "best"])
def test_best_is_never_slower_than_any_method(order: str) -> None:
    for scenario in _layouts(6, 300):
        plans = {m: scenario.plan(m, order) for m in loiter.ALL_METHODS}
        best = scenario.plan("best", order)
        assert best.method in loiter.ALL_METHODS
        assert best.flight_time == min(p.flight_time for p in plans.values())
        assert plans["ldlpp_best"].flight_time <= plans["ldlpp"].flight_time * (1 + 1e-12)
        by_coverage = scenario.plan("best", order, objective="coverage")
        assert scenario.coverage(by_coverage).time == max(scenario.coverage(p).time for p in plans.values())
    with pytest.raises(vt.VistrackError, match="objective"):
        loiter.plan([(300.0, 300.0)], "best", objective="area")


def test_best_plans_a_layout_ldlpp_cannot_fly(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from vistrack.cli import main

    aois = [(300.0, 300.0), (400.0, 300.0)]  # 100 m apart: LDLPP needs 2 D_Entry = 159.3 m
    with pytest.raises(vt.VistrackError, match="LDLPP needs"):
        loiter.plan(aois, "ldlpp")
    best = loiter.plan(aois, "best")
    assert best.method in ("fly_through", "tlpp", "tlpp_best")
    scenario = tmp_path / "close.yaml"
    scenario.write_text("name: close\naois: [[300, 300], [400, 300]]\n")
    assert main(["loiter", str(scenario), "--out", str(tmp_path / "o"), "--quiet", *NO_MEDIA]) == 0
    out = capsys.readouterr().out
    assert "close ldlpp: skipped, cannot fly this layout: " in out and "close tlpp: " in out
    metrics = json.loads((tmp_path / "o" / "metrics.json").read_text())
    assert "ldlpp" not in [m["method"] for m in metrics["methods"]]
    assert main(["loiter", str(scenario), "--method", "ldlpp", "ldlpp_best", "--out", str(tmp_path / "p"),
                 "--quiet", *NO_MEDIA]) == 1
    assert "no method given can fly" in capsys.readouterr().err


def test_report_says_the_units_and_the_papers_numbers_per_scenario(tmp_path: Path) -> None:
    """Issue 33: coverage in covered seconds beside the paper's (its m^2 over the 6,669.56 m^2 it
    counts per covered second), the camera mount in metrics.json, AOIs numbered from 0 everywhere,
    the coverage and gimbal timeline."""
    from vistrack.cli import main
    from vistrack.loiter.study import PAPER_AREA_PER_SECOND

    assert PAPER_AREA_PER_SECOND == pytest.approx(6669.56, abs=0.01)
    four = REPO / "examples" / "loiter_4aoi.yaml"
    assert main(["loiter", str(four), "--out", str(tmp_path / "o"), "--quiet", *NO_MEDIA]) == 0
    metrics = json.loads((tmp_path / "o" / "metrics.json").read_text())
    assert metrics["camera"]["mount"] == "levelled"
    rows = {m["method"]: m for m in metrics["methods"]}
    assert rows["tlpp"]["paper_covered_time_s"] == pytest.approx(131.0, abs=1e-6)  # 873,713 m^2 in Table 1
    # The unit is taken from that one value; the other scenarios' TLPP and LDLPP values are whole
    # multiples of it too (an independent check of the reading of Table 1).
    for n in range(5, 10):
        paper = loiter.load_scenario(REPO / "examples" / f"loiter_{n}aoi.yaml").paper
        for method in ("tlpp", "ldlpp"):
            seconds = paper[method]["coverage_m2"] / PAPER_AREA_PER_SECOND
            assert seconds == pytest.approx(round(seconds), abs=2e-3), (n, method)
    assert rows["ldlpp"]["paper_covered_time_s"] == pytest.approx(140.0, abs=1e-3)  # Table 1 rounds to 1 m^2
    assert "coverage_area_m2s" in rows["ldlpp"] and "coverage_area_m2" not in rows["ldlpp"]
    report = (tmp_path / "o" / "report.md").read_text()
    assert "| paper: covered time (s) |" in report and "| 131.0 |" in report and "10^3 m^2 s" in report
    assert "timeline.png" in report and (tmp_path / "o" / "timeline.png").stat().st_size > 10_000
    assert "numbered from 0" in report
