"""``vistrack city`` and the scenario key ``city: {osm: FILE, ...}`` on a small hand-written OSM file."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.cli import cli, one_line_error
from support.osm_files import OsmWriter
from support.paths import REPO, SHARED_DATA
from support.refusal import refuses
from vistrack.scenario_blocks import city_block

LAT, LON = 60.17, 24.94


def small_city(tmp_path: Path) -> Path:
    osm = OsmWriter()
    osm.box(LAT, LON, building="yes", height="20")
    osm.box(LAT, LON + 1e-3, building="yes", building__levels="3")
    osm.box(LAT + 1e-3, LON, building="yes")
    osm.box(LAT + 1e-3, LON + 1e-3, building="yes", height="high")
    a, b, c = osm.node(LAT - 1e-4, LON), osm.node(LAT - 1e-4, LON + 2e-3), osm.node(LAT + 2e-3, LON + 2e-3)
    osm.way([a, b, c], highway="tertiary")
    return osm.write(tmp_path / "small.osm")


def test_city_command_writes_geojson_mesh_and_summary(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = small_city(tmp_path)
    out = tmp_path / "out"
    status, err = cli(["city", str(path), "--out", str(out), "--default-height", "6"], capsys)
    assert status == 0, err
    summary = json.loads((out / "summary.json").read_text())
    assert summary["imported"] == 4 and summary["footprints"] == 4 and summary["skipped"] == {}
    assert summary["height_sources"] == {"height": 1, "levels": 1, "default": 2}
    assert summary["bad_tags"] == {"height": 1} and summary["default_height"] == 6.0
    assert summary["roads"]["edges"] == 2 and summary["tallest"]["height"] == 20.0
    city = vt.io.read_osm(path, default_height=6.0)
    collection = json.loads((out / "city.geojson").read_text())
    lon, lat = np.array([p for f in collection["features"] for p in f["geometry"]["coordinates"][0]]).T
    assert np.all(np.abs(lon - LON) < 0.01) and np.all(np.abs(lat - LAT) < 0.01)  # RFC 7946: [lon, lat]
    again = vt.Environment.from_geojson(out / "city.geojson", origin=city.georeference)
    np.testing.assert_array_equal(np.sort(again.heights), np.sort(city.environment.heights))
    np.testing.assert_allclose(sorted(f.area for f in again.footprints),
                               sorted(f.area for f in city.environment.footprints), rtol=1e-9)
    obj = (out / "city.obj").read_text().splitlines()
    assert sum(line.startswith("v ") for line in obj) == len(city.environment.vertices)
    assert sum(line.startswith("f ") for line in obj) == len(city.environment.faces)


def test_city_command_errors_are_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    one_line_error(["city", str(tmp_path / "none.osm"), "--out", str(tmp_path / "o")], capsys, 1, "FILE = ")
    one_line_error(["city", str(small_city(tmp_path)), "--level-height", "-2"], capsys, 2, "--level-height")


def test_scenario_city_osm(tmp_path: Path) -> None:
    small_city(tmp_path)
    spec = city_block({"city": {"osm": "small.osm", "level_height": 4.0, "default_height": 7.0}}, tmp_path)
    assert spec is not None and spec.kind == "osm" and spec.options == {"level_height": 4.0, "default_height": 7.0}
    env = spec.load(vt.Georeference(LAT, LON))
    assert env.num_buildings == 4 and sorted(env.heights) == [7.0, 7.0, 12.0, 20.0]
    assert env.origin == (LAT, LON, 0.0) and len(env.roads.edges) == 2
    with pytest.raises(vt.VistrackError, match=r"city\.level_height"):
        city_block({"city": {"geojson": "a.geojson", "level_height": 3.0}}, tmp_path)
    with pytest.raises(vt.VistrackError, match=r"city\.default_height"):
        city_block({"city": {"osm": "small.osm", "default_height": "tall"}}, tmp_path)
    with pytest.raises(vt.VistrackError, match=r"city\.osm"):
        city_block({"city": {"osm": "missing.osm"}}, tmp_path).load()  # type: ignore[union-attr]


def two_streets(tmp_path: Path) -> Path:
    """Two streets no road joins: west (lon LON) and east (lon LON + 2e-3), both north-south."""
    osm = OsmWriter()
    for lon in (LON, LON + 2e-3):
        nodes = [osm.node(LAT + k * 5e-4, lon) for k in range(3)]
        osm.way(nodes, highway="residential")
    osm.box(LAT, LON + 1e-3, building="yes")
    return osm.write(tmp_path / "streets.osm")


def test_route_between_lon_lat_points(tmp_path: Path) -> None:
    env = vt.Environment.from_osm(two_streets(tmp_path), origin=(LAT, LON))
    path = vt.PoiPath.from_route(env, (LON + 1e-5, LAT - 1e-5), (LON - 1e-5, LAT + 1e-3), 5.0)
    north = vt.Georeference(LAT, LON).to_local(LAT + 1e-3, LON)[1]
    assert path.length == pytest.approx(north) and path.speed == 5.0
    np.testing.assert_allclose(path.waypoints[0, :2], [0.0, 0.0], atol=1e-6)
    local = vt.PoiPath.from_route(env, (2.0, -1.0), (0.5, north), 5.0, crs="local")
    np.testing.assert_allclose(local.waypoints, path.waypoints)
    with pytest.raises(vt.VistrackError, match="no road connects") as error:
        vt.PoiPath.from_route(env, (LON, LAT), (LON + 2e-3, LAT), 5.0)
    assert "\n" not in str(error.value)
    with pytest.raises(vt.VistrackError, match="no georeference"):
        vt.PoiPath.from_route(vt.Environment.demo(), (LON, LAT), (LON, LAT + 1e-3), 5.0)
    with pytest.raises(vt.VistrackError, match=r"route\.crs"):
        vt.PoiPath.from_route(env, (0, 0), (1, 1), 5.0, crs="utm")


def test_scenario_poi_route_from_to(tmp_path: Path) -> None:
    two_streets(tmp_path)
    data = {"georeference": {"lat": LAT, "lon": LON}, "city": {"osm": "streets.osm"},
            "poi": {"route": {"from": [LON, LAT], "to": [LON, LAT + 1e-3]}, "speed": 4.0}}
    scenario = vt.Scenario.from_dict(data, tmp_path)
    env = scenario.environment.load(scenario.origin)
    path = scenario.poi.build(env)
    assert path.speed == 4.0 and len(path.waypoints) == 3
    assert scenario.to_dict()["poi"]["route"] == {"crs": "lonlat", "from": [LON, LAT], "to": [LON, LAT + 1e-3]}
    with pytest.raises(vt.VistrackError, match=r"poi\.route\.to"):
        vt.Scenario.from_dict({**data, "poi": {"route": {"from": [LON, LAT], "to": [LON]}}}, tmp_path)
    with pytest.raises(vt.VistrackError, match=r"poi\.route: no road connects"):
        vt.Scenario.from_dict({**data, "poi": {"route": {"from": [LON, LAT], "to": [LON + 2e-3, LAT]}}},
                              tmp_path).poi.build(env)
    # the spelling: the speed inside the route
    inside = vt.Scenario.from_dict({**data, "poi": {"route": {"from": [LON, LAT], "to": [LON, LAT + 1e-3],
                                                              "speed": 7.5}}}, tmp_path)
    assert inside.poi.speed == 7.5 and inside.poi.build(env).speed == 7.5
    assert inside.to_dict()["poi"]["speed"] == 7.5 and "speed" not in inside.to_dict()["poi"]["route"]
    assert vt.Scenario.from_dict(inside.to_dict(), tmp_path).poi.speed == 7.5
    refuses(lambda: vt.Scenario.from_dict({**data, "poi": {"route": {"from": [LON, LAT], "to": [LON, LAT + 1e-3],
                                                                     "speed": 7.5}, "speed": 4.0}}, tmp_path),
            "poi.route.speed = 7.5", "give the speed once")
    refuses(lambda: vt.Scenario.from_dict({**data, "poi": {"route": {"from": [LON, LAT], "to": [LON, LAT + 1e-3],
                                                                     "speed": -1}}}, tmp_path),
            "poi.route.speed = -1")


def test_follow_scenario_drives_a_road_route_on_an_osm_city(tmp_path: Path) -> None:
    two_streets(tmp_path)
    (tmp_path / "follow.yaml").write_text(f"""
uav: {{speed: 21.0, min_turn_radius: 50.0, altitude: 120.0}}
vehicle:
  start: [0.0, 0.0]
  legs:
    - {{heading: north, speed: 5.0, duration: 20.0}}
  route: {{from: [{LON}, {LAT}], to: [{LON}, {LAT + 1e-3}]}}
georeference: {{lat: {LAT}, lon: {LON}}}
city:
  osm: streets.osm
""")
    scenario = vt.follow.FollowScenario.load(tmp_path / "follow.yaml")
    assert scenario.city_available()
    env = scenario.city.load(scenario.origin)  # type: ignore[union-attr]
    vehicle = scenario.city_vehicle(env)
    start = np.asarray(vehicle.position(0.0))[:2]
    end = np.asarray(vehicle.position(20.0))[:2]
    np.testing.assert_allclose(start, [0.0, 0.0], atol=1e-6)
    assert end[1] == pytest.approx(100.0, abs=1e-6) and abs(end[0]) < 0.5  # 5 m/s north along the west street
    bad = (tmp_path / "follow.yaml").read_text().replace(f"to: [{LON}, {LAT + 1e-3}]", f"to: [{LON + 2e-3}, {LAT}]")
    (tmp_path / "bad.yaml").write_text(bad)
    with pytest.raises(vt.VistrackError, match=r"vehicle\.route: no road connects"):
        vt.follow.FollowScenario.load(tmp_path / "bad.yaml").city_vehicle()
    text = (tmp_path / "follow.yaml").read_text()
    route_line = f"  route: {{from: [{LON}, {LAT}], to: [{LON}, {LAT + 1e-3}]}}\n"
    # the first slice's city.road: {from, to} (never released) is refused, pointing to vehicle.route
    (tmp_path / "old.yaml").write_text(text.replace(route_line, "") + route_line.replace("route", "road"))
    refuses(lambda: vt.follow.FollowScenario.load(tmp_path / "old.yaml"), "city.road = ", "vehicle.route")
    (tmp_path / "no_city.yaml").write_text(text.split("georeference")[0])
    refuses(lambda: vt.follow.FollowScenario.load(tmp_path / "no_city.yaml"), "vehicle.route = ", "needs a city")
    track = text.replace("  start: [0.0, 0.0]\n", "  track: track.csv\n").split("  legs:")[0] + route_line
    (tmp_path / "track.yaml").write_text(track)
    refuses(lambda: vt.follow.FollowScenario.load(tmp_path / "track.yaml"), "vehicle.route = ", "needs legs")
    (tmp_path / "two.yaml").write_text(text + "  road: road.csv\n")
    refuses(lambda: vt.follow.FollowScenario.load(tmp_path / "two.yaml"), "city = ", "one road")


def test_helsinki_examples_build_their_routes() -> None:
    if not (SHARED_DATA / "osm" / "Helsinki.osm.pbf").exists():
        pytest.skip(f"{SHARED_DATA / 'osm'} absent (../shared/data/osm holds the real OSM extracts)")
    scenario = vt.Scenario.load(REPO / "examples" / "helsinki_osm.yaml")
    env = scenario.environment.load(scenario.origin)
    poi = scenario.poi.build(env)
    # 1,322 m respecting one-way streets (937 m when they were driven both ways)
    assert env.num_buildings > 500 and 1200.0 < poi.length < 1450.0
    follow = vt.follow.FollowScenario.load(REPO / "examples" / "follow_helsinki_osm.yaml")
    vehicle = follow.city_vehicle(env)
    np.testing.assert_allclose(vehicle.position(0.0), poi.waypoints[0, :2], atol=1e-6)  # the same route start


def test_city_command_writes_raised_bases(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    osm = OsmWriter()
    osm.box(LAT, LON, building__part="yes", height="30", min_height="18")
    osm.box(LAT, LON + 1e-3, building="yes", height="12")
    out = tmp_path / "out"
    status, err = cli(["city", str(osm.write(tmp_path / "raised.osm")), "--out", str(out)], capsys)
    assert status == 0, err
    assert json.loads((out / "summary.json").read_text())["raised_base"] == 1
    collection = json.loads((out / "city.geojson").read_text())
    assert sorted(f["properties"].get("min_height", 0.0) for f in collection["features"]) == [0.0, 18.0]
    city = vt.io.read_osm(out.parent / "raised.osm")
    assert "  1 footprints with a base above the ground (open underneath)" in city.summary.lines()
    again = vt.Environment.from_geojson(out / "city.geojson", origin=city.georeference)
    assert sorted(zip(again.min_heights, again.heights)) == [(0.0, 12.0), (18.0, 30.0)]
    lines = (out / "city.obj").read_text().splitlines()
    z = sorted({float(line.split()[3]) for line in lines if line.startswith("v ")})
    assert z == [0.0, 12.0, 18.0, 30.0]  # the raised part's floor at 18 m, nothing of it below
