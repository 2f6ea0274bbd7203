"""Missions of the loiter planners and of follow runs: every item on the planned path to 1 cm after
the trip through latitude and longitude, the loiter circles as NAV_LOITER_TURNS with the radius
signed by the direction and the whole turns plus the exit arc equal to the planned sweep, files read
back by pymavlink's MAVWPLoader and by our loader, and the CLI."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.paths import REPO
from vistrack import mission as vm
from vistrack.cli import main
from vistrack.mission import Command, Frame, Georeference

CHARLOTTE = Georeference(35.2249, -80.8403, 230.0)
CM = 0.01


def local(item: vm.MissionItem, ref: Georeference = CHARLOTTE) -> np.ndarray:
    return np.array(ref.to_local(item.lat, item.lon), dtype=float)


def distance_to_segment(point: np.ndarray, s: vt.loiter.Segment) -> float:
    """Exact distance from a point to a line or arc of the plan (an oracle independent of the
    mission code: the arc's angular extent from its start, direction and sweep)."""
    a, b = np.asarray(s.start), np.asarray(s.end)
    if s.kind == "line":
        d = b - a
        t = 0.0 if not d.any() else float(np.clip(np.dot(point - a, d) / np.dot(d, d), 0.0, 1.0))
        return float(np.hypot(*(point - a - t * d)))
    c = np.asarray(s.center)
    sign = 1.0 if s.direction == "ccw" else -1.0
    a0 = math.atan2(*(a - c)[::-1])
    angle = math.atan2(*(point - c)[::-1])
    if s.sweep >= 2 * math.pi - 1e-12 or (sign * (angle - a0)) % (2 * math.pi) <= s.sweep + 1e-12:
        return abs(float(np.hypot(*(point - c))) - s.radius)
    return min(float(np.hypot(*(point - a))), float(np.hypot(*(point - b))))


def distance_to_plan(point: np.ndarray, plan: vt.loiter.Plan) -> float:
    return min(distance_to_segment(point, s) for s in plan.segments)


def check_plan_file(path: Path, mission: vm.Mission) -> None:
    """The .plan checks of test_mission.py: QGroundControl's structure, field by field."""
    plan = json.loads(path.read_text())
    assert set(plan) == {"fileType", "geoFence", "groundStation", "mission", "rallyPoints", "version"}
    assert (plan["fileType"], plan["version"], plan["groundStation"]) == ("Plan", 1, "vistrack")
    assert plan["geoFence"] == {"circles": [], "polygons": [], "version": 2}
    assert plan["rallyPoints"] == {"points": [], "version": 2}
    m = plan["mission"]
    assert (m["version"], m["firmwareType"], m["vehicleType"], m["globalPlanAltitudeMode"]) == (2, 3, 1, 1)
    assert m["plannedHomePosition"] == list(mission.home) and len(m["items"]) == len(mission)
    for seq, (entry, item) in enumerate(zip(m["items"], mission.items), start=1):
        assert entry["type"] == "SimpleItem" and entry["doJumpId"] == seq and entry["autoContinue"] is True
        assert (entry["command"], entry["frame"]) == (item.command, item.frame)
        assert entry["params"] == [*item.params, item.lat, item.lon, item.alt]
        if item.has_coordinate:
            assert entry["Altitude"] == item.alt and entry["AltitudeMode"] == 1 and entry["AMSLAltAboveTerrain"] is None
    assert vm.load(path).items == mission.items


def check_mavwploader(path: Path, mission: vm.Mission) -> None:
    mavwp = pytest.importorskip("pymavlink.mavwp")
    loader = mavwp.MAVWPLoader()
    assert loader.load(str(path)) == len(mission) + 1
    for i, item in enumerate(mission.items, start=1):
        w = loader.wp(i)
        assert (w.command, w.frame, (w.param1, w.param2, w.param3, w.param4)) == (item.command, item.frame, item.params)
        assert abs(w.x - item.lat) < 1e-7 and abs(w.y - item.lon) < 1e-7 and w.z == item.alt


@pytest.mark.parametrize("method", vt.loiter.METHODS)
@pytest.mark.parametrize("turns", [1, 2])
def test_loiter_mission_flies_the_planned_path(method: str, turns: int, tmp_path: Path) -> None:
    scenario = vt.loiter.random_scenario(5, 11, turns=turns)
    plan = scenario.plan(method)
    mission = plan.to_mission(CHARLOTTE, 61.0)
    items = mission.items
    assert items[0].command == Command.DO_CHANGE_SPEED and items[0].params[1] == plan.speed == mission.cruise_speed
    located = [i for i in items if i.has_coordinate]
    assert all(i.alt == 61.0 and i.frame == Frame.GLOBAL_RELATIVE_ALT for i in located)
    np.testing.assert_allclose(CHARLOTTE.to_local(*mission.home[:2]), plan.start, atol=CM)
    # Every waypoint lies on the planned path (1 cm after the round trip through lat/lon); the first
    # is the start, the last the end.
    waypoints = [i for i in items if i.command == Command.NAV_WAYPOINT]
    for item in waypoints:
        assert distance_to_plan(local(item), plan) < CM
    np.testing.assert_allclose(local(waypoints[0]), plan.start, atol=CM)
    np.testing.assert_allclose(local(waypoints[-1]), plan.end, atol=CM)
    # One NAV_LOITER_TURNS per AOI, in the visiting order, at its centre, radius signed by the
    # direction (MAVLink: positive clockwise), started where the plan joins the circle.
    loiters = [k for k, i in enumerate(items) if i.command == Command.NAV_LOITER_TURNS]
    assert len(loiters) == len(plan.aois)
    circles = vt.loiter.loiter_circles(plan)
    for k, circle in zip(loiters, circles):
        item = items[k]
        np.testing.assert_allclose(local(item), circle["center"], atol=CM)
        assert item.params[2] == (-1.0 if circle["direction"] == "ccw" else 1.0) * plan.aoi_radius
        assert item.params[3] == 1.0 and item.params[1] == 0.0  # leave from the exit point, no heading wait
        np.testing.assert_allclose(local(items[k - 1]), circle["entry"], atol=CM)  # joins on the circle
        # Whole turns on the circle, then waypoints along it to the exit: together the planned sweep.
        whole = item.params[0]
        assert whole == int(whole) >= turns
        arc = []
        for later in items[k + 1:]:
            p = local(later)
            if later.command != Command.NAV_WAYPOINT or abs(np.hypot(*(p - circle["center"])) - plan.aoi_radius) > CM:
                break
            arc.append(p)
        sign = 1.0 if circle["direction"] == "ccw" else -1.0
        angles = [math.atan2(*(np.asarray(q) - circle["center"])[::-1]) for q in [circle["entry"], *arc]]
        flown = sum((sign * (b - a)) % (2 * math.pi) for a, b in zip(angles, angles[1:]))
        assert 2 * math.pi * whole + flown == pytest.approx(circle["sweep"], abs=1e-6)
        if arc:
            np.testing.assert_allclose(arc[-1], circle["exit"], atol=CM)
    # The files: QGroundControl's structure, pymavlink's reader, our reader.
    check_plan_file(mission.save(tmp_path / "route.plan"), mission)
    check_mavwploader(mission.save(tmp_path / "route.waypoints"), mission)
    assert vm.load(tmp_path / "route.waypoints").items == items


def test_loiter_mission_options() -> None:
    plan = vt.loiter.plan([(300.0, 200.0), (600.0, 500.0)], method="ldlpp")
    mission = plan.to_mission((35.0, -80.0), 80.0, speed=14.0, return_to_launch=True)
    assert mission.items[0].params[1] == 14.0 and mission.items[-1].command == Command.NAV_RETURN_TO_LAUNCH
    # The waypoints along a 46 m turn every 30 degrees are 23.8 m apart: accepted within 11 m.
    arc = [i for i in mission.items if i.command == Command.NAV_WAYPOINT and i.params[1] > 0]
    assert arc and {i.params[1] for i in arc} == {11.0}
    coarse = plan.to_mission((35.0, -80.0), 80.0, max_step_deg=60.0, acceptance_radius=0.0)
    assert len(coarse) < len(mission) and all(i.params[1] == 0.0 for i in coarse.items if i.command == 16)
    with pytest.raises(vt.VistrackError, match=r"altitude = nan"):
        plan.to_mission((35.0, -80.0), math.nan)
    with pytest.raises(vt.VistrackError, match=r"origin\[0\] = 95|georeference\[0\] = 95"):
        plan.to_mission((95.0, -80.0), 80.0)


def small_follow() -> vt.follow.FollowResult:
    car = vt.follow.GroundVehicle.from_legs([vt.follow.VehicleLeg(-math.pi / 2, 10.0, 80.0),
                                             vt.follow.VehicleLeg(0.0, 0.0, 40.0)])
    return vt.follow.simulate(car, vt.Uav(speed=21.0, min_turn_radius=50.0, altitude=200.0))


def test_follow_mission_keeps_the_route_within_the_tolerance(tmp_path: Path) -> None:
    from shapely.geometry import LineString, Point

    result = small_follow()
    generated = result.waypoints
    everything = result.to_mission(CHARLOTTE, 200.0, speed=21.0, tolerance=0.0)
    assert everything.items[0].command == Command.DO_CHANGE_SPEED and everything.items[0].params[1] == 21.0
    points = np.array([local(i) for i in everything.items[1:] if i.command == Command.NAV_WAYPOINT])
    np.testing.assert_allclose(points, generated, atol=CM)  # every 1 Hz waypoint, in order
    # Before each waypoint, the gimbal's region of interest: the vehicle predicted there, on the ground.
    rois = everything.items[1::2]
    assert all(i.command == Command.DO_SET_ROI_LOCATION and i.alt == 0.0 for i in rois)
    assert all(i.command == Command.NAV_WAYPOINT for i in everything.items[2::2])
    np.testing.assert_allclose(np.array([local(i) for i in rois]), result.roi, atol=CM)
    car = vt.follow.GroundVehicle.from_legs([vt.follow.VehicleLeg(-math.pi / 2, 10.0, 80.0),
                                             vt.follow.VehicleLeg(0.0, 0.0, 40.0)])
    np.testing.assert_allclose(result.roi[:70], [car.position(t + 1.0) for t in result.waypoint_times[:70]],
                               atol=1e-6)  # a constant velocity: the prediction is exact
    assert all(i.command == Command.NAV_WAYPOINT for i in result.to_mission(CHARLOTTE, 200.0, roi=False).items)
    np.testing.assert_allclose(CHARLOTTE.to_local(*everything.home[:2]), result.state[0, :2], atol=CM)
    mission = result.to_mission(CHARLOTTE, 200.0, tolerance=1.0)
    kept = np.array([local(i) for i in mission.items if i.command == Command.NAV_WAYPOINT])
    assert 2 <= len(kept) < len(generated)
    # Kept points are generated ones (in order, first and last included); every generated
    # waypoint lies within 1 m of the kept route (shapely's distance, not the simplifier).
    index = [int(np.argmin(np.hypot(*(generated - p).T))) for p in kept]
    assert np.all(np.diff(index) > 0) and index[0] == 0 and index[-1] == len(generated) - 1
    assert max(np.hypot(*(generated[index] - kept).T)) < CM
    route = LineString(kept)
    assert max(route.distance(Point(p)) for p in generated) <= 1.0 + CM
    check_mavwploader(mission.save(tmp_path / "follow.waypoints"), mission)
    check_plan_file(mission.save(tmp_path / "follow.plan"), mission)
    with pytest.raises(vt.VistrackError, match="tolerance = -1"):
        result.to_mission(CHARLOTTE, 200.0, tolerance=-1.0)


def test_cli_loiter_export_as_the_issue_shows(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """`vistrack loiter --random 1 --seed 3 --method ldlpp --export route.plan --out DIR` and the
    same with route.waypoints; pymavlink counts the items."""
    mavwp = pytest.importorskip("pymavlink.mavwp")
    for name in ("route.plan", "route.waypoints"):
        assert main(["loiter", "--random", "1", "--seed", "3", "--method", "ldlpp", "--export", str(tmp_path / name),
                     "--out", str(tmp_path / "DIR"), "--quiet"]) == 0
    printed = capsys.readouterr().out
    assert "no --origin given; local (0, 0) placed at 35.2249,-80.8403" in printed
    assert "wrote " + str(tmp_path / "route.plan") in printed
    mission = vm.load(tmp_path / "route.plan")
    assert mavwp.MAVWPLoader().load(str(tmp_path / "route.waypoints")) == len(mission) + 1
    scenario = next(vt.loiter_study.random_scenarios(1, 3))
    assert mission.items == scenario.plan("ldlpp").to_mission(Georeference(35.2249, -80.8403), 61.0).items
    # Several methods: one file per method; --origin and --altitude are used.
    assert main(["loiter", "--random", "1", "--seed", "3", "--method", "tlpp", "ldlpp", "--order", "best",
                 "--export", str(tmp_path / "r.waypoints"), "--origin", "40.0,-83.0,250", "--altitude", "90",
                 "--out", str(tmp_path / "D2"), "--quiet"]) == 0
    tlpp = vm.load(tmp_path / "r_tlpp.waypoints")
    assert tlpp.home[2] == 250.0 and (tmp_path / "r_ldlpp.waypoints").is_file()
    assert all(i.alt == 90.0 for i in tlpp.items if i.has_coordinate)
    ref = Georeference(40.0, -83.0, 250.0)
    best = scenario.plan("tlpp", "best")
    assert tlpp.items == best.to_mission(ref, 90.0).items
    # A scenario file's origin places the mission (no note).
    scenario_file = tmp_path / "four.yaml"
    scenario_file.write_text("origin: [40.5, -83.5, 200]\n" + (REPO / "examples" / "loiter_4aoi.yaml").read_text())
    capsys.readouterr()
    assert main(["loiter", str(scenario_file), "--method", "tlpp", "--export", str(tmp_path / "f.plan"),
                 "--out", str(tmp_path / "D5"), "--quiet"]) == 0
    assert "no --origin" not in capsys.readouterr().out
    assert vm.load(tmp_path / "f.plan").home == pytest.approx((40.5, -83.5, 200.0), abs=1e-9)
    # Errors are one line naming the option.
    capsys.readouterr()
    assert main(["loiter", "--random", "2", "--export", str(tmp_path / "x.plan"), "--out", str(tmp_path / "D3"),
                 "--quiet"]) == 2
    assert "--export = " in capsys.readouterr().err and not (tmp_path / "x.plan").exists()
    assert main(["loiter", "--random", "1", "--export", str(tmp_path / "x.kml"), "--out", str(tmp_path / "D4"),
                 "--quiet"]) == 2
    assert "--export = " in capsys.readouterr().err


def test_cli_follow_export(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    scenario = tmp_path / "short.yaml"
    scenario.write_text("origin: [35.0, -80.0]\nuav: {speed: 21.0, min_turn_radius: 50.0, altitude: 200.0}\n"
                        "vehicle: {legs: [{heading: south, speed: 10.0, duration: 80.0}]}\n"
                        "follow: {threshold: 3}\nbaseline: false\n")  # the paper's sinusoid starts at the origin
    out = tmp_path / "out"
    assert main(["follow", str(scenario), "--out", str(out), "--quiet", "--export", str(tmp_path / "f.plan"),
                 "--export", str(tmp_path / "f.geojson"), "--origin", "35.2249,-80.8403"]) == 0
    assert capsys.readouterr().out.count("mission items") == 2  # --origin wins over the file's
    mission = vm.load(tmp_path / "f.plan")
    assert mission.items[0].params[1] == 21.0 and all(i.alt == 200.0 for i in mission.items
                                                      if i.command == Command.NAV_WAYPOINT)
    study = vt.follow_scenario.FollowScenario.load(scenario).run(city=False)
    assert mission.items == study.follow.to_mission(Georeference(35.2249, -80.8403), 200.0, speed=21.0).items
    features = json.loads((tmp_path / "f.geojson").read_text())["features"]
    assert {f["properties"]["kind"] for f in features} >= {"home", "route"}
    assert main(["follow", str(scenario), "--out", str(out), "--quiet", "--export", str(tmp_path / "g.txt")]) == 0
    assert vm.load(tmp_path / "g.txt").home == pytest.approx((35.0, -80.0, 0.0), abs=1e-9)
