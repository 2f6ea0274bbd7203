"""Autopilot missions: files read by pymavlink's MAVWPLoader (the reference QGC WPL 110 reader),
files it writes read by us, .plan files field by field against QGroundControl's format, round
trips, the loiter geometry and orbit plans as timed loiters."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import vistrack as vt
from vistrack import mission as vm
from vistrack.mission import Command, Frame, Georeference, MissionBuilder

CHARLOTTE = Georeference(35.2249, -80.8403, 230.0)


def sample_mission(altitude_mode: str = "relative") -> vm.Mission:
    b = MissionBuilder(CHARLOTTE, 120.0, speed=18.0, altitude_mode=altitude_mode, home=(10.0, -5.0))
    b.waypoints([[0.0, 0.0], [250.0, 40.0]])
    b.waypoint((400.0, 100.0), 150.0, hold=2.0, acceptance_radius=15.0)
    b.loiter((600.0, 100.0), 60.0, direction="ccw", turns=2, entry=(600.0, 40.0), exit=(660.0, 100.0))
    b.loiter((800.0, 300.0), 45.0, direction="cw", seconds=30.0)
    b.loiter((900.0, 0.0), 50.0, direction="cw")
    return b.return_to_launch().build()


def test_commands_and_frames_are_mavlinks() -> None:
    mavutil = pytest.importorskip("pymavlink.mavutil")
    for command in Command:
        assert getattr(mavutil.mavlink, f"MAV_CMD_{command.name}") == command.value
    assert mavutil.mavlink.MAV_FRAME_GLOBAL == Frame.GLOBAL
    assert mavutil.mavlink.MAV_FRAME_MISSION == Frame.MISSION
    assert mavutil.mavlink.MAV_FRAME_GLOBAL_RELATIVE_ALT == Frame.GLOBAL_RELATIVE_ALT
    assert mavutil.mavlink.MAV_AUTOPILOT_ARDUPILOTMEGA == vm.FIRMWARE_TYPES["ardupilot"]
    assert mavutil.mavlink.MAV_AUTOPILOT_PX4 == vm.FIRMWARE_TYPES["px4"]
    assert mavutil.mavlink.MAV_TYPE_FIXED_WING == vm.VEHICLE_FIXED_WING


def test_builder_items() -> None:
    m = sample_mission()
    names = [item.name for item in m.items]
    assert names == ["DO_CHANGE_SPEED", "NAV_WAYPOINT", "NAV_WAYPOINT", "NAV_WAYPOINT",
                     "NAV_WAYPOINT", "NAV_LOITER_TURNS", "NAV_WAYPOINT", "NAV_WAYPOINT", "NAV_WAYPOINT",
                     "NAV_LOITER_TIME", "NAV_LOITER_UNLIM", "NAV_RETURN_TO_LAUNCH"]
    speed, turns, timed, unlimited = m.items[0], m.items[5], m.items[9], m.items[10]
    assert speed.params == (0.0, 18.0, -1.0, 0.0) and speed.frame == Frame.MISSION and m.cruise_speed == 18.0
    assert turns.params == (2.0, 0.0, -60.0, 1.0)  # ccw: negative radius; exit location given
    assert timed.params == (30.0, 0.0, 45.0, 0.0)  # cw: positive radius
    assert unlimited.params == (0.0, 0.0, 50.0, 0.0)
    assert m.items[3].params == (2.0, 15.0, 0.0, 0.0) and m.items[3].alt == 150.0
    assert all(item.alt == 120.0 for item in m.items[1:3])
    # The loiter's centre, entry and arc to the exit lie where they should in local metres.
    local = np.column_stack(CHARLOTTE.to_local([i.lat for i in m.items[4:9]], [i.lon for i in m.items[4:9]]))
    np.testing.assert_allclose(local[0], [600.0, 40.0], atol=1e-6)   # entry
    np.testing.assert_allclose(local[1], [600.0, 100.0], atol=1e-6)  # centre
    np.testing.assert_allclose(local[-1], [660.0, 100.0], atol=1e-6)  # exit
    assert np.allclose(np.hypot(*(local[2:] - [600.0, 100.0]).T), 60.0)  # arc waypoints on the circle
    lat, lon, alt = m.home
    np.testing.assert_allclose(CHARLOTTE.to_local(lat, lon), (10.0, -5.0), atol=1e-6)
    assert alt == 230.0 and m.altitude_mode == "relative"
    amsl = sample_mission("amsl")
    assert amsl.items[1].alt == 350.0 and amsl.items[1].frame == Frame.GLOBAL and amsl.altitude_mode == "amsl"


def test_waypoints_text_is_tab_separated_full_precision(tmp_path) -> None:
    m = sample_mission()
    path = m.save(tmp_path / "route.waypoints")
    lines = path.read_text().splitlines()
    assert lines[0] == "QGC WPL 110"
    rows = [line.split("\t") for line in lines[1:]]
    assert len(rows) == len(m) + 1 and all(len(row) == 12 for row in rows)
    assert " " not in "".join(lines[1:])
    home = rows[0]
    assert home[:4] == ["0", "1", "0", "16"] and home[11] == "1"
    assert [float(v) for v in home[8:11]] == list(m.home)
    for seq, (row, item) in enumerate(zip(rows[1:], m.items), start=1):
        assert int(row[0]) == seq and row[1] == "0" and int(row[2]) == item.frame and int(row[3]) == item.command
        assert float(row[8]) == item.lat and float(row[9]) == item.lon  # exact: no 6-decimal rounding
    assert any(len(row[8].split(".")[1]) > 6 for row in rows[1:] if row[8] != "0.0")


def test_mavwploader_reads_every_file_we_write(tmp_path) -> None:
    mavwp = pytest.importorskip("pymavlink.mavwp")
    for mode in ("relative", "amsl"):
        m = sample_mission(mode)
        for suffix in (".waypoints", ".txt"):
            path = m.save(tmp_path / f"route-{mode}{suffix}")
            loader = mavwp.MAVWPLoader()
            assert loader.load(str(path)) == len(m) + 1
            home = loader.wp(0)
            assert (home.x, home.y, home.z) == m.home and home.current == 1
            for i, item in enumerate(m.items, start=1):
                w = loader.wp(i)
                assert (w.seq, w.command, w.frame, w.current, w.autocontinue) == (i, item.command, item.frame, 0, 1)
                assert (w.param1, w.param2, w.param3, w.param4) == item.params
                assert abs(w.x - item.lat) < 1e-7 and abs(w.y - item.lon) < 1e-7 and w.z == item.alt


def test_we_read_what_mavwploader_saves(tmp_path) -> None:
    mavwp, mavutil = pytest.importorskip("pymavlink.mavwp"), pytest.importorskip("pymavlink.mavutil")
    m = sample_mission()
    loader = mavwp.MAVWPLoader()
    rows = [(0, 1, 0, 16, (0.0, 0.0, 0.0, 0.0), *m.home, 1)]
    rows += [(i, 0, it.frame, it.command, it.params, it.lat, it.lon, it.alt, 1) for i, it in enumerate(m.items, 1)]
    for seq, current, frame, command, params, x, y, z, autocontinue in rows:
        args = [0, 0, seq, frame, command, current, autocontinue, *params, x, y, z]
        if mavutil.mavlink20():
            args.append(0)
        loader.add(mavutil.mavlink.MAVLink_mission_item_message(*args))
    path = tmp_path / "saved_by_pymavlink.waypoints"
    loader.save(str(path))
    read = vm.load(path)
    assert len(read) == len(m)
    assert read.home == pytest.approx(m.home, abs=1e-6)  # MAVWPLoader writes %f: 6 decimals
    for ours, theirs in zip(m.items, read.items):
        assert (theirs.command, theirs.frame, theirs.autocontinue) == (ours.command, ours.frame, True)
        assert theirs.params == pytest.approx(ours.params, abs=1e-6)
        assert (theirs.lat, theirs.lon, theirs.alt) == pytest.approx((ours.lat, ours.lon, ours.alt), abs=1e-6)
    assert read.cruise_speed == 18.0  # from the DO_CHANGE_SPEED item
    # Comment lines and spaces (MAVWPLoader accepts both) read too.
    text = path.read_text().splitlines()
    (tmp_path / "commented.txt").write_text("\n".join([text[0], "# home", text[1].replace("\t", " "), *text[2:]]))
    assert len(vm.load(tmp_path / "commented.txt")) == len(m)


def test_plan_file_field_by_field(tmp_path) -> None:
    m = sample_mission()
    path = m.save(tmp_path / "route.plan")
    plan = json.loads(path.read_text())
    assert set(plan) == {"fileType", "geoFence", "groundStation", "mission", "rallyPoints", "version"}
    assert plan["fileType"] == "Plan" and plan["version"] == 1 and plan["groundStation"] == "vistrack"
    assert plan["geoFence"] == {"circles": [], "polygons": [], "version": 2}
    assert plan["rallyPoints"] == {"points": [], "version": 2}
    mission = plan["mission"]
    assert set(mission) == {"cruiseSpeed", "firmwareType", "globalPlanAltitudeMode", "hoverSpeed", "items",
                            "plannedHomePosition", "vehicleType", "version"}
    assert (mission["version"], mission["firmwareType"], mission["vehicleType"]) == (2, 3, 1)
    assert (mission["cruiseSpeed"], mission["hoverSpeed"], mission["globalPlanAltitudeMode"]) == (18.0, 5.0, 1)
    assert mission["plannedHomePosition"] == list(m.home)
    assert len(mission["items"]) == len(m)
    for seq, (entry, item) in enumerate(zip(mission["items"], m.items), start=1):
        assert entry["type"] == "SimpleItem" and entry["doJumpId"] == seq and entry["autoContinue"] is True
        assert entry["command"] == item.command and entry["frame"] == item.frame
        assert entry["params"] == [*item.params, item.lat, item.lon, item.alt]
        if item.has_coordinate:  # what QGroundControl writes for items that specify an altitude
            assert entry["Altitude"] == item.alt and entry["AltitudeMode"] == 1
            assert "AMSLAltAboveTerrain" in entry and entry["AMSLAltAboveTerrain"] is None
        else:
            assert not {"Altitude", "AltitudeMode", "AMSLAltAboveTerrain"} & set(entry)
    amsl = json.loads(sample_mission("amsl").save(tmp_path / "amsl.plan").read_text())["mission"]
    assert amsl["globalPlanAltitudeMode"] == 2 and amsl["items"][1]["AltitudeMode"] == 2
    assert amsl["items"][1]["frame"] == 0 and amsl["items"][1]["Altitude"] == 350.0


def test_plan_and_waypoints_round_trip(tmp_path) -> None:
    m = sample_mission()
    for suffix in (".plan", ".waypoints"):
        read = vm.load(m.save(tmp_path / f"route{suffix}"))
        assert read.items == m.items and read.home == m.home and read.cruise_speed == m.cruise_speed
    px4 = vm.Mission(m.items, m.home, cruise_speed=12.0, hover_speed=3.0, firmware="px4")
    again = vm.load(px4.save(tmp_path / "px4.plan"))
    assert (again.firmware, again.cruise_speed, again.hover_speed) == ("px4", 12.0, 3.0)
    # A file as QGroundControl writes it (yaw NaN saved as null) reads too.
    plan = json.loads((tmp_path / "route.plan").read_text())
    plan["mission"]["items"][1]["params"][3] = None
    (tmp_path / "qgc.plan").write_text(json.dumps(plan))
    assert vm.load(tmp_path / "qgc.plan").items[1].params[3] == 0.0


def test_mission_errors_name_the_field(tmp_path) -> None:
    m = sample_mission()
    with pytest.raises(vt.VistrackError, match=r"items = \[\]: a mission needs at least one item"):
        vm.Mission([], m.home)
    with pytest.raises(vt.VistrackError, match=r"path = .*route\.kml.*unknown mission format.*\.plan"):
        m.save(tmp_path / "route.kml")
    with pytest.raises(vt.VistrackError, match=r"altitude_mode = 'agl': must be 'relative' or 'amsl'"):
        MissionBuilder(CHARLOTTE, 100.0, altitude_mode="agl")
    with pytest.raises(vt.VistrackError, match=r"direction = 'left'"):
        MissionBuilder(CHARLOTTE, 100.0).loiter((0, 0), 50.0, direction="left")
    with pytest.raises(vt.VistrackError, match=r"radius = -5"):
        MissionBuilder(CHARLOTTE, 100.0).loiter((0, 0), -5.0)
    with pytest.raises(vt.VistrackError, match=r"firmware = 'inav'"):
        vm.Mission(m.items, m.home, firmware="inav")
    with pytest.raises(vt.VistrackError, match=r"home\[0\] = 100"):
        vm.Mission(m.items, (100.0, 0.0, 0.0))
    odd = vm.Mission([vm.MissionItem(16, 10, lat=35.0, lon=-80.0, alt=5.0)], m.home)  # terrain frame
    with pytest.raises(vt.VistrackError, match=r"items\[0\]\.frame = 10: unknown altitude mode"):
        odd.save(tmp_path / "odd.plan")
    plan = json.loads(m.save(tmp_path / "route.plan").read_text())
    plan["mission"]["items"][1]["AltitudeMode"] = 4
    (tmp_path / "bad.plan").write_text(json.dumps(plan))
    with pytest.raises(vt.VistrackError, match=r"items\[1\]\.AltitudeMode = 4"):
        vm.load(tmp_path / "bad.plan")
    plan["mission"]["items"][1]["AltitudeMode"] = 1
    del plan["mission"]["items"][2]["frame"]
    (tmp_path / "bad.plan").write_text(json.dumps(plan))
    with pytest.raises(vt.VistrackError, match=r"items\[2\]\.frame = None: must be an integer"):
        vm.load(tmp_path / "bad.plan")
    with pytest.raises(vt.VistrackError, match=r"line 1 = 'QGC WPL 100'"):
        (tmp_path / "old.waypoints").write_text("QGC WPL 100\n")
        vm.load(tmp_path / "old.waypoints")
    (tmp_path / "short.waypoints").write_text("QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t35\t-80\t0\n")
    with pytest.raises(vt.VistrackError, match=r"line 2 = .*12 tab-separated fields, found 11"):
        vm.load(tmp_path / "short.waypoints")
    (tmp_path / "home.waypoints").write_text("QGC WPL 110\n0\t1\t0\t16\t0\t0\t0\t0\t35\t-80\t0\t1\n")
    with pytest.raises(vt.VistrackError, match=r"items = \[\]: the file holds only the home position"):
        vm.load(tmp_path / "home.waypoints")
    with pytest.raises(vt.VistrackError, match=r"path = .*\.geojson.*load reads"):
        vm.load(tmp_path / "route.geojson")
    with pytest.raises(vt.VistrackError, match=r"cannot read"):
        vm.load(tmp_path / "absent.plan")


@pytest.mark.parametrize("direction", ["ccw", "cw"])
def test_tangent_entry_and_exit(direction: str) -> None:
    rng = np.random.default_rng(7)
    sign = 1 if direction == "ccw" else -1
    for _ in range(200):
        center, radius = rng.uniform(-100, 100, 2), rng.uniform(5, 60)
        start = center + rng.uniform(1.05, 10) * radius * np.array([math.cos(a := rng.uniform(0, 6.3)), math.sin(a)])
        entry = vm.tangent_entry(start, center, radius, direction)
        r, v = entry - center, entry - start
        assert np.hypot(*r) == pytest.approx(radius)
        assert abs(np.dot(r, v)) < 1e-8 * radius * np.hypot(*v)  # tangent
        assert sign * (r[0] * v[1] - r[1] * v[0]) > 0                # travelling in `direction`
        exit_ = vm.tangent_exit(center, radius, direction, start)
        r, v = exit_ - center, start - exit_
        assert abs(np.dot(r, v)) < 1e-8 * radius * np.hypot(*v) and sign * (r[0] * v[1] - r[1] * v[0]) > 0
    # Inside the circle: the nearest point on it.
    np.testing.assert_allclose(vm.tangent_entry((3.0, 0.0), (0.0, 0.0), 10.0), (10.0, 0.0))


def test_path_of_lines_and_arcs() -> None:
    """How a planner of lines and arcs (LDLPP: entry turn, loiter, exit turn) writes its route."""
    b = MissionBuilder(CHARLOTTE, 100.0)
    b.waypoint((0.0, -100.0))                                                  # a line ends at the turn
    b.arc((-30.0, -100.0), 30.0, (0.0, -100.0), (-30.0, -70.0), direction="ccw")  # entry turn, 90 degrees
    b.loiter((-30.0, -20.0), 50.0, direction="cw", turns=1, entry=(-30.0, -70.0), exit=(20.0, -20.0),
             fly_to_entry=False)
    m = b.build()
    names = [i.name for i in m.items]
    assert names == ["NAV_WAYPOINT"] * 4 + ["NAV_LOITER_TURNS"] + ["NAV_WAYPOINT"] * 9  # 270 deg in 30-deg steps
    local = np.column_stack(CHARLOTTE.to_local([i.lat for i in m.items], [i.lon for i in m.items]))
    np.testing.assert_allclose(local[3], (-30.0, -70.0), atol=1e-6)  # the turn ends at the entry, once
    np.testing.assert_allclose(local[4], (-30.0, -20.0), atol=1e-6)
    np.testing.assert_allclose(local[-1], (20.0, -20.0), atol=1e-6)
    assert m.items[4].params == (1.0, 0.0, 50.0, 1.0)  # clockwise: positive radius
    # Clockwise from the bottom of the circle (-90 deg) to its east side (0 deg): 270 degrees.
    assert np.allclose(np.hypot(*(local[5:] - (-30.0, -20.0)).T), 50.0)
    assert local[5][0] < -30.0  # went west first: clockwise from the bottom


def test_arc_points_follow_the_direction() -> None:
    ccw = vm.arc_points((0, 0), 10.0, (10, 0), (0, 10), "ccw", 30.0)
    assert len(ccw) == 4 and np.allclose(ccw[-1], (0, 10))  # 90 degrees in 3 steps
    cw = vm.arc_points((0, 0), 10.0, (10, 0), (0, 10), "cw", 30.0)
    assert len(cw) == 10 and np.all(cw[1:4, 1] < 0)  # 270 degrees the other way
    assert len(vm.arc_points((0, 0), 10.0, (10, 0), (10, 0))) == 1


def test_orbit_plan_as_timed_loiters(tmp_path) -> None:
    poi = vt.PoiPath(np.array([[0.0, 0.0], [100.0, 0.0], [100.0, 60.0]]), 5.0)
    uav = vt.Uav(speed=20.0, min_turn_radius=30.0, altitude=120.0)
    plan = vt.constant_radius_plan(poi, 80.0, uav)
    with pytest.raises(vt.VistrackError, match=r"altitude = None: give the flight altitude"):
        plan.to_mission(CHARLOTTE)
    m = plan.to_mission(CHARLOTTE, 120.0, direction="cw", speed=20.0)
    loiters = [i for i in m.items if i.command == Command.NAV_LOITER_TIME]
    assert m.items[0].command == Command.DO_CHANGE_SPEED and m.items[1].command == Command.NAV_WAYPOINT
    assert m.items[-1].command == Command.NAV_LOITER_UNLIM and m.items[-1].params[2] == 80.0
    assert all(i.params[2] == 80.0 for i in loiters)  # clockwise: positive radius
    assert all(float(i.params[0]).is_integer() for i in loiters)  # ArduPilot counts whole seconds
    assert sum(i.params[0] for i in loiters) == pytest.approx(round(poi.duration), abs=0.5)
    # Centres at the POI's position in the middle of each segment.
    times = np.asarray(plan.times)
    boundaries = np.round(times - times[0])
    kept = np.diff(boundaries) > 0
    middles = 0.5 * (times[:-1] + times[1:])[kept]
    expected = np.array([poi.position(t)[:2] for t in middles])
    local = np.column_stack(CHARLOTTE.to_local([i.lat for i in loiters], [i.lon for i in loiters]))
    np.testing.assert_allclose(local, expected, atol=1e-6)
    # The first waypoint joins the first orbit on a tangent from home.
    entry = np.array(CHARLOTTE.to_local(m.items[1].lat, m.items[1].lon))
    assert np.hypot(*(entry - expected[0])) == pytest.approx(80.0)
    px4 = plan.to_mission(CHARLOTTE, 120.0, firmware="px4", end="rtl")
    durations = [i.params[0] for i in px4.items if i.command == Command.NAV_LOITER_TIME]
    assert sum(durations) == pytest.approx(poi.duration) and px4.items[-1].command == Command.NAV_RETURN_TO_LAUNCH
    assert all(i.params[2] == -80.0 for i in px4.items if i.command == Command.NAV_LOITER_TIME)  # ccw default
    with pytest.raises(vt.VistrackError, match=r"end = 'land'"):
        plan.to_mission(CHARLOTTE, 120.0, end="land")
    assert len(vm.load(m.save(tmp_path / "orbits.waypoints"))) == len(m)


def test_mission_geojson(tmp_path) -> None:
    m = sample_mission()
    data = json.loads(m.save(tmp_path / "route.geojson").read_text())
    kinds = [f["properties"]["kind"] for f in data["features"]]
    assert kinds[:2] == ["home", "route"] and kinds.count("mission_item") == sum(i.has_coordinate for i in m.items)
    route = data["features"][1]["geometry"]
    assert route["type"] == "LineString" and route["coordinates"][0] == [m.home[1], m.home[0]]  # lon, lat
    assert route["coordinates"][1] == [m.items[1].lon, m.items[1].lat]


def test_old_addresses_answer_every_moved_name() -> None:
    """vistrack.io and vistrack.mission still answer the names that moved into the products, as the
    very objects of their new homes."""
    import importlib

    import vistrack.io
    import vistrack.mission

    for package in (vistrack.io, vistrack.mission):
        moved = package.__getattr__.moved  # type: ignore[attr-defined]
        assert moved, package.__name__
        for name, home in moved.items():
            assert getattr(package, name) is getattr(importlib.import_module(home), name), (package.__name__, name)


def test_attached_to_mission_takes_the_converters_parameters() -> None:
    """The to_mission methods attached in Python restate their converters' signatures (for the
    stubs); they must not drift apart."""
    import inspect

    from vistrack.loiter.to_mission import loiter_plan_mission
    from vistrack.tracking.to_mission import orbit_plan_mission

    def parameters(function: object) -> list[tuple[str, object, object]]:
        return [(p.name, p.kind, p.default) for p in list(inspect.signature(function).parameters.values())[1:]]

    assert parameters(vt.OrbitPlan.to_mission) == parameters(orbit_plan_mission)
    assert parameters(vt.loiter.Plan.to_mission) == parameters(loiter_plan_mission)
