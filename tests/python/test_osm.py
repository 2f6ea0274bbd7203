"""OpenStreetMap import (vistrack.io.osm): every tag rule on small hand-written .osm files, the
GeoJSON-vs-OSM agreement, and the three real extracts in ../shared/data/osm (skipped when absent)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import osmium
import pytest
import shapely

import vistrack as vt
from support.osm_files import OsmWriter
from support.paths import SHARED_DATA

LAT, LON = 60.17, 24.94
OSM_DATA = SHARED_DATA / "osm"
HELSINKI = OSM_DATA / "Helsinki.osm.pbf"
REAL_FILES = ["Helsinki.osm.pbf", "West-Oakland.osm.bz2", "planet_10.068,48.135_10.071,48.137.osm"]


def read(tmp_path: Path, osm: OsmWriter, **options: object) -> vt.io.OsmCity:
    return vt.io.read_osm(osm.write(tmp_path / "city.osm"), origin=(LAT, LON), **options)


def heights(city: vt.io.OsmCity) -> dict[str, float]:
    """Each imported OSM object's height (the tallest of its footprints)."""
    result: dict[str, float] = {}
    for osm_id, height in zip(city.osm_ids, city.environment.heights):
        result[osm_id] = max(result.get(osm_id, 0.0), float(height))
    return result


def at(k: int) -> tuple[float, float]:
    """The k-th building's corner: buildings 1e-3 degree (55 m) apart, never touching."""
    return LAT, LON + 1e-3 * k


def test_height_tag_units_and_bad_values(tmp_path: Path) -> None:
    osm = OsmWriter()
    ids = {
        "plain": osm.box(*at(0), building="yes", height="12"),
        "metres": osm.box(*at(1), building="yes", height="12.5 m"),
        "feet": osm.box(*at(2), building="yes", height="40 ft"),
        "feet_word": osm.box(*at(3), building="yes", height="40 feet"),
        "feet_inches": osm.box(*at(4), building="yes", height="12'6\""),
        "building_height": osm.box(*at(5), building="yes", building__height="21"),
        "bad": osm.box(*at(6), building="yes", height="tall", building__levels="2"),
        "bad_unit": osm.box(*at(7), building="yes", height="12 furlongs"),
    }
    city = read(tmp_path, osm, default_height=7.0)
    got = heights(city)
    expected = {"plain": 12.0, "metres": 12.5, "feet": 40 * 0.3048, "feet_word": 40 * 0.3048,
                "feet_inches": 12 * 0.3048 + 6 * 0.0254, "building_height": 21.0, "bad": 6.0, "bad_unit": 7.0}
    for name, height in expected.items():
        assert got[f"w{ids[name]}"] == pytest.approx(height), name
    assert city.summary.bad_tags == {"height": 2}
    assert city.summary.height_sources == {"height": 6, "levels": 1, "default": 1}


def test_levels_times_level_height_plus_roof(tmp_path: Path) -> None:
    osm = OsmWriter()
    plain = osm.box(*at(0), building="yes", building__levels="4")
    roof_levels = osm.box(*at(1), building="yes", building__levels="4", roof__levels="1")
    roof_height = osm.box(*at(2), building="yes", building__levels="4", roof__height="5 m")
    untagged = osm.box(*at(3), building="yes")
    city = read(tmp_path, osm, level_height=3.5, roof_height=2.0, default_height=8.0)
    got = heights(city)
    assert got[f"w{plain}"] == pytest.approx(4 * 3.5 + 2.0)
    assert got[f"w{roof_levels}"] == pytest.approx(5 * 3.5)
    assert got[f"w{roof_height}"] == pytest.approx(4 * 3.5 + 5.0)
    assert got[f"w{untagged}"] == pytest.approx(8.0)
    assert city.summary.height_sources == {"levels": 3, "default": 1}
    assert (city.summary.level_height, city.summary.roof_height, city.summary.default_height) == (3.5, 2.0, 8.0)


def test_base_from_min_height_or_min_level(tmp_path: Path) -> None:
    osm = OsmWriter()
    raised = osm.box(*at(0), building__part="yes", height="20", min_height="5")
    level_base = osm.box(*at(1), building__part="yes", building__levels="6", building__min_level="2")
    inverted = osm.box(*at(2), building="yes", height="4", min_height="6")
    ground = osm.box(*at(3), building="yes", height="9")
    untagged_top = osm.box(*at(4), building__part="yes", min_height="18")  # no height: default above the base
    levels_below = osm.box(*at(5), building__part="yes", building__levels="2", building__min_level="3")
    zero = osm.box(*at(6), building="yes", height="7", min_height="0")  # on the ground, not a bad tag
    city = read(tmp_path, osm, default_height=10.0)
    got = heights(city)
    assert got[f"w{raised}"] == 20.0 and got[f"w{level_base}"] == 18.0 and got[f"w{ground}"] == 9.0
    assert got[f"w{untagged_top}"] == 28.0
    assert f"w{inverted}" not in got and f"w{levels_below}" not in got  # tagged tops are from the ground
    assert city.summary.skipped == {"top_not_above_base": 2}
    assert city.summary.raised_base == 3
    bases = dict(zip(city.osm_ids, city.environment.min_heights))
    assert bases == {f"w{raised}": 5.0, f"w{level_base}": 6.0, f"w{ground}": 0.0, f"w{untagged_top}": 18.0,
                     f"w{zero}": 0.0}
    assert city.summary.bad_tags == {}


def test_a_raised_part_leaves_the_space_under_it_open(tmp_path: Path) -> None:
    osm = OsmWriter()
    podium = osm.box(LAT, LON, 2e-4, building__part="yes", height="25")  # a quarter under the bridge
    bridge = osm.box(LAT + 1e-4, LON + 1e-4, 2e-4, building__part="yes", height="30", min_height="18")
    tower = osm.box(LAT + 1.5e-4, LON + 1.5e-4, 5e-5, building__part="yes", height="40")  # through both
    city = read(tmp_path, osm)
    env = city.environment
    # the bridge loses the tower's square; the podium loses the tower's square and the bridge's
    # quarter, where it keeps a piece from the ground to the bridge's base; nothing is dropped
    assert sorted(set(city.osm_ids)) == sorted([f"w{podium}", f"w{bridge}", f"w{tower}"])
    assert city.summary.skipped == {} and city.summary.clipped == 2
    assert sorted(zip(city.osm_ids, env.min_heights, env.heights)) == sorted(
        [(f"w{podium}", 0.0, 25.0), (f"w{podium}", 0.0, 18.0), (f"w{bridge}", 18.0, 30.0), (f"w{tower}", 0.0, 40.0)])
    scene = vt.VisibilityScene(env)
    x0, y0, x1, y1 = shapely.Polygon(env.footprints[city.osm_ids.index(f"w{bridge}")].outer).bounds
    north = y1 - 0.2 * (y1 - y0)  # the bridge's half over open ground
    starts = np.array([[x0 - 20, north, 14.0], [x0 - 20, north, 24.0]])
    ends = np.array([[x1 + 20, north, 14.0], [x1 + 20, north, 24.0]])
    assert scene.line_of_sight(starts, ends).tolist() == [True, False]  # under the bridge, through it
    under, over_podium = (x0 + 1.0, north), (x0 + 1.0, y0 + 1.0)
    assert scene.surface_height(under) == pytest.approx(30.0) == scene.surface_height(over_podium)
    assert not scene.inside_obstacle(np.array([*under, 10.0]))
    assert scene.inside_obstacle(np.array([*over_podium, 10.0]))  # the podium's piece under the bridge
    assert scene.inside_obstacle(np.array([*over_podium, 21.0]))
    # the union of the three solids is kept: with the tower's area T, podium and bridge 16 T each,
    # 16 T x 25 m + 16 T x 12 m - 4 T x 7 m (both, 18 to 25 m) + T x 40 m - T x 30 m (in both)
    volume = sum(f.area * (h - b) for f, h, b in zip(env.footprints, env.heights, env.min_heights))
    tower_area = env.footprints[city.osm_ids.index(f"w{tower}")].area
    assert volume == pytest.approx(574 * tower_area, rel=2e-3)


def test_multipolygon_keeps_its_hole(tmp_path: Path) -> None:
    osm = OsmWriter()
    outer = osm.ring([(LAT, LON), (LAT, LON + 1e-3), (LAT + 5e-4, LON + 1e-3), (LAT + 5e-4, LON)], closed=True)
    inner = osm.ring([(LAT + 2e-4, LON + 4e-4), (LAT + 2e-4, LON + 6e-4), (LAT + 3e-4, LON + 6e-4),
                      (LAT + 3e-4, LON + 4e-4)])
    relation = osm.relation([("way", outer, "outer"), ("way", inner, "inner")], type="multipolygon",
                            building="yes", height="15")
    city = read(tmp_path, osm)
    env = city.environment
    assert city.osm_ids == [f"r{relation}"] and env.num_buildings == 1
    footprint = env.footprints[0]
    assert len(footprint.holes) == 1
    polygon = shapely.Polygon(footprint.outer, footprint.holes)
    assert footprint.area == pytest.approx(polygon.area) and footprint.area < shapely.Polygon(footprint.outer).area
    assert env.heights[0] == 15.0


def test_building_parts_replace_their_outline(tmp_path: Path) -> None:
    osm = OsmWriter()
    outline = osm.ring([(LAT, LON), (LAT, LON + 4e-4), (LAT + 2e-4, LON + 4e-4), (LAT + 2e-4, LON)],
                       building="yes", height="10")
    west = osm.ring([(LAT, LON), (LAT, LON + 2e-4), (LAT + 2e-4, LON + 2e-4), (LAT + 2e-4, LON)],
                    building__part="yes", height="30")
    east = osm.ring([(LAT, LON + 2e-4), (LAT, LON + 4e-4), (LAT + 2e-4, LON + 4e-4), (LAT + 2e-4, LON + 2e-4)],
                    building__part="yes", building__levels="5")
    alone = osm.box(*at(3), building="yes", height="8")
    city = read(tmp_path, osm)
    assert heights(city) == {f"w{west}": 30.0, f"w{east}": 15.0, f"w{alone}": 8.0}
    assert city.environment.num_buildings == 3
    assert city.summary.skipped == {"replaced_by_parts": 1}
    assert f"w{outline}" not in city.osm_ids


def test_broken_geometry_skipped_by_reason(tmp_path: Path) -> None:
    osm = OsmWriter()
    osm.ring([(LAT, LON), (LAT, LON + 1e-4), (LAT + 1e-4, LON + 1e-4)], closed=False, building="yes")
    ids = [osm.node(LAT, LON + 1e-3), osm.node(LAT, LON + 1.1e-3), 999999, osm.node(LAT + 1e-4, LON + 1e-3)]
    osm.way(ids + ids[:1], building="yes")  # node 999999 is not in the file
    osm.ring([(LAT, LON + 2e-3), (LAT, LON + 2.1e-3), (LAT, LON + 2.2e-3)], building="yes")  # on one line
    osm.ring([(LAT, LON + 3e-3), (LAT + 1e-4, LON + 3.1e-3), (LAT, LON + 3.1e-3), (LAT + 1e-4, LON + 3e-3)],
             building="yes")  # a bow tie
    good = osm.box(*at(5), building="yes")
    city = read(tmp_path, osm)
    assert city.osm_ids == [f"w{good}"]
    assert city.summary.skipped == {"unclosed": 1, "missing_node": 1, "zero_area": 1, "self_intersecting": 1}


def test_antimeridian_and_pole_refused(tmp_path: Path) -> None:
    osm = OsmWriter()
    osm.ring([(LAT, 179.9999), (LAT, -179.9999), (LAT + 1e-4, -179.9999), (LAT + 1e-4, 179.9999)], building="yes")
    osm.ring([(89.9999, 0.0), (90.0, 0.0), (89.9999, 1.0)], building="yes")
    good = osm.box(*at(0), building="yes")
    city = read(tmp_path, osm)
    assert city.osm_ids == [f"w{good}"]
    assert city.summary.skipped == {"crosses_antimeridian": 1, "touches_pole": 1}


def test_overlap_resolved_taller_wins(tmp_path: Path) -> None:
    osm = OsmWriter()
    tall = osm.box(LAT, LON, 2e-4, building="yes", height="40")
    low = osm.box(LAT + 1e-4, LON + 1e-4, 2e-4, building="yes", height="10")  # a quarter under the tall one
    osm.box(LAT + 5e-5, LON + 5e-5, 5e-5, building="yes", height="20")  # wholly under it
    city = read(tmp_path, osm)
    env = city.environment
    assert sorted(city.osm_ids) == sorted([f"w{tall}", f"w{low}"])
    assert city.summary.clipped == 1 and city.summary.skipped == {"covered": 1}
    areas = {i: f.area for i, f in zip(city.osm_ids, env.footprints)}
    assert areas[f"w{low}"] == pytest.approx(0.75 * areas[f"w{tall}"], rel=1e-3)


def test_roads_drivable_tunnels_skipped(tmp_path: Path) -> None:
    osm = OsmWriter()
    a, b, c = osm.node(LAT, LON), osm.node(LAT, LON + 1e-3), osm.node(LAT + 1e-3, LON + 1e-3)
    osm.way([a, b], highway="residential", oneway="yes", maxspeed="30")
    osm.way([b, c], highway="primary_link")
    osm.way([a, c], highway="primary", tunnel="yes")
    osm.way([a, c], highway="primary", layer="-1")
    osm.way([a, c], highway="footway")
    osm.box(LAT + 5e-4, LON + 2e-3, building="yes")
    city = read(tmp_path, osm)
    roads = city.environment.roads
    assert len(roads.nodes) == 3 and len(roads.edges) == 2
    assert roads.shortest_route(roads.nearest_node([0.0, 0.0]), roads.nearest_node([55.0, 111.0])) == [0, 1, 2]
    summary = city.summary.roads
    assert summary.ways == 2 and summary.skipped == {"tunnel": 1, "below_ground": 1}
    assert summary.oneway_ways == 1 and summary.maxspeed == {"30": 1}
    assert summary.length_m == pytest.approx(np.linalg.norm(roads.nodes[1] - roads.nodes[0])
                                             + np.linalg.norm(roads.nodes[2] - roads.nodes[1]))


def test_road_through_a_building_left_out(tmp_path: Path) -> None:
    osm = OsmWriter()
    a, b, c = osm.node(LAT, LON - 1e-4), osm.node(LAT + 5e-5, LON + 5e-5), osm.node(LAT, LON + 3e-4)
    osm.way([a, b, c], highway="service")
    osm.box(LAT, LON, building="yes")
    city = read(tmp_path, osm)
    assert city.summary.roads.edges_crossing_buildings == 2 and len(city.environment.roads.edges) == 0


def test_geojson_and_osm_agree_within_a_centimetre(tmp_path: Path) -> None:
    origin = vt.Georeference(LAT, LON)
    shapes = [  # local metres: a box, an L, a courtyard block with a hole
        ([(0, 0), (30, 0), (30, 20), (0, 20)], [], 25.0),
        ([(50, 0), (90, 0), (90, 10), (60, 10), (60, 40), (50, 40)], [], 12.0),
        ([(0, 60), (60, 60), (60, 100), (0, 100)], [[(20, 70), (40, 70), (40, 90), (20, 90)]], 18.0),
        ([(70, 60), (90, 60), (90, 100), (70, 100)], [], 22.0),  # a raised part, min_height 8
    ]
    bases = [0.0, 0.0, 0.0, 8.0]
    features = [{"type": "Feature", "properties": {"height": h, **({"min_height": b} if b else {})},
                 "geometry": {"type": "Polygon", "coordinates": [[*outer, outer[0]], *[[*r, r[0]] for r in holes]]}}
                for (outer, holes, h), b in zip(shapes, bases)]
    geojson = tmp_path / "city.geojson"
    geojson.write_text(json.dumps({"type": "FeatureCollection", "features": features}))
    osm = OsmWriter()
    for (outer, holes, height), base in zip(shapes, bases):
        def way(ring: list[tuple[int, int]], **tags: str) -> int:
            lat, lon = origin.to_latlon(np.array(ring, float)[:, 0], np.array(ring, float)[:, 1])
            return osm.ring(list(zip(lat, lon)), **tags)
        if holes:
            members = [("way", way(outer), "outer")] + [("way", way(h), "inner") for h in holes]
            osm.relation(members, type="multipolygon", building="yes", height=str(height))
        elif base:
            way(outer, building__part="yes", height=str(height), min_height=str(base))
        else:
            way(outer, building="yes", height=str(height))
    from_geojson = vt.Environment.from_geojson(str(geojson), origin=origin)
    from_osm = vt.Environment.from_osm(osm.write(tmp_path / "city.osm"), origin=origin)
    assert from_osm.num_buildings == from_geojson.num_buildings == 4
    assert from_osm.origin == from_geojson.origin
    osm_polygons = [shapely.Polygon(b.outer, b.holes) for b in from_osm.footprints]
    for a, height, base in zip(from_geojson.footprints, from_geojson.heights, from_geojson.min_heights):
        pa = shapely.Polygon(a.outer, a.holes)
        k = int(np.argmin([pa.centroid.distance(pb.centroid) for pb in osm_polygons]))
        assert shapely.hausdorff_distance(pa, osm_polygons[k]) < 0.01
        assert abs(pa.area - osm_polygons[k].area) < 0.01 * pa.length
        assert len(a.holes) == len(from_osm.footprints[k].holes)
        assert from_osm.heights[k] == height and from_osm.min_heights[k] == base
    # the same obstacles: the surface height (roof, hole or ground) agrees on a 1 m grid, away from walls
    scenes = [vt.VisibilityScene(env) for env in (from_geojson, from_osm)]
    walls = shapely.union_all([shapely.Polygon(f.outer, f.holes).boundary for f in from_geojson.footprints])
    grid = [(x + 0.5, y + 0.5) for x in range(-5, 95) for y in range(-5, 105)]
    grid = [p for p in grid if walls.distance(shapely.Point(p)) > 0.02]
    surfaces = np.array([[scene.surface_height(p) for p in grid] for scene in scenes])
    assert set(np.unique(surfaces[0])) == {0.0, 12.0, 18.0, 22.0, 25.0}
    np.testing.assert_allclose(surfaces[0], surfaces[1], atol=1e-5)  # Embree's float32 rays
    # and the open space under the raised part: level lines of sight under it (4 m) and through it
    inside = [p for p in grid if 70 < p[0] < 90 and 60 < p[1] < 100]
    for height, expected in ((4.0, True), (15.0, False)):
        starts = np.array([[100.0, 80.0, height]] * len(inside))
        ends = np.array([[x, y, height] for x, y in inside])
        seen = [scene.line_of_sight(starts, ends) for scene in scenes]
        assert (seen[0] == expected).all() and (seen[1] == expected).all()


def test_errors_name_the_file(tmp_path: Path) -> None:
    with pytest.raises(vt.VistrackError, match=r"osm = .*missing\.osm"):
        vt.io.read_osm(tmp_path / "missing.osm")
    text = tmp_path / "city.txt"
    text.write_text("x")
    with pytest.raises(vt.VistrackError, match="must end in"):
        vt.io.read_osm(text)
    broken = tmp_path / "broken.osm"
    broken.write_text("<osm><node id=")
    with pytest.raises(vt.VistrackError, match=r"broken\.osm"):
        vt.io.read_osm(broken)
    with pytest.raises(vt.VistrackError, match="level_height"):
        vt.io.read_osm(broken, level_height=-1.0)


def _peer_count(path: Path) -> int:
    """pyosmium alone: closed building (or building:part) ways plus building multipolygon relations."""
    class Count(osmium.SimpleHandler):  # type: ignore[misc]
        def __init__(self) -> None:
            super().__init__()
            self.count = 0

        def way(self, way: osmium.osm.Way) -> None:
            if ("building" in way.tags or "building:part" in way.tags) and way.is_closed():
                self.count += 1

        def relation(self, relation: osmium.osm.Relation) -> None:
            tags = relation.tags
            if tags.get("type") == "multipolygon" and ("building" in tags or "building:part" in tags):
                self.count += 1

    counter = Count()
    counter.apply_file(str(path))
    return counter.count


@pytest.mark.parametrize("name", REAL_FILES)
def test_real_extracts_import(name: str) -> None:
    path = OSM_DATA / name
    if not path.exists():
        pytest.skip(f"{path} absent (../shared/data/osm holds the real OSM extracts)")
    city = vt.io.read_osm(path)
    summary = city.summary
    assert city.environment.num_buildings == summary.footprints == len(city.osm_ids) > 0
    assert city.environment.origin == summary.origin
    objects = summary.imported + sum(summary.skipped.values()) - summary.skipped.get("unclosed", 0)
    assert objects == _peer_count(path)


def test_helsinki_counts() -> None:
    if not HELSINKI.exists():
        pytest.skip(f"{HELSINKI} absent (../shared/data/osm holds the real OSM extracts)")
    city = vt.io.read_osm(HELSINKI)
    summary = city.summary
    # the data README counts 433 building ways, 67 relations and 127 building:part ways; pyosmium
    # also finds 12 building:part multipolygons, and 6 ways and 1 relation carry both tags (632):
    # every one is imported or skipped by reason, none unclosed
    assert summary.imported + sum(summary.skipped.values()) == _peer_count(HELSINKI) > 433 + 67
    assert "unclosed" not in summary.skipped
    assert summary.skipped["replaced_by_parts"] > 0 and summary.raised_base > 0
    assert summary.roads.edges > 1000 and summary.roads.skipped["tunnel"] > 0
