"""One-way streets: the road network's directed edges (RoadNetwork.oneway), the OSM importer's
oneway / junction=roundabout rules on small hand-written .osm files, and routes that respect them."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import vistrack as vt
from support.osm_files import OsmWriter
from support.refusal import refuses
from vistrack.io.osm_tags import oneway

LAT, LON = 60.17, 24.94
SQUARE = np.array([[0.0, 0.0], [100.0, 0.0], [100.0, 100.0], [0.0, 100.0]])


@pytest.mark.parametrize("tags, direction", [
    ({"oneway": "yes"}, 1), ({"oneway": "true"}, 1), ({"oneway": "1"}, 1), ({"oneway": "-1"}, -1),
    ({"oneway": "no"}, 0), ({}, 0), ({"oneway": "reversible"}, 0), ({"junction": "roundabout"}, 1),
    ({"junction": "circular"}, 1), ({"junction": "roundabout", "oneway": "no"}, 0),
    ({"highway": "motorway"}, 1), ({"highway": "motorway", "oneway": "no"}, 0), ({"highway": "primary"}, 0),
])
def test_oneway_tags(tags: dict[str, str], direction: int) -> None:
    assert oneway(tags) == direction


def test_directed_edges_route_the_long_way_round() -> None:
    # a square block 0-1-2-3 driven counter-clockwise only, and a two-way diagonal spur 0-4
    nodes = np.vstack([SQUARE, [[-50.0, -50.0]]])
    edges = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [0, 4]])
    roads = vt.RoadNetwork(nodes, edges, oneway=[True, True, True, True, False])
    assert roads.oneway.tolist() == [True, True, True, True, False]
    assert list(roads.shortest_route(0, 3)) == [0, 1, 2, 3]  # 300 m: the 100 m edge 3-0 is one-way
    assert list(roads.shortest_route(3, 0)) == [3, 0]
    assert list(roads.shortest_route(4, 1)) == [4, 0, 1]
    two_way = vt.RoadNetwork(nodes, edges)
    assert two_way.oneway.tolist() == [False] * 5 and list(two_way.shortest_route(0, 3)) == [0, 3]
    refuses(lambda: vt.RoadNetwork(nodes, edges, oneway=[True]), "oneway = 1 flags", "one flag per edge (5)")
    refuses(lambda: vt.PoiPath.from_nodes(roads, [0, 3], 5.0), "nodes[1] = 3", "one-way the other way")
    assert vt.PoiPath.from_nodes(roads, [3, 0], 5.0).length == pytest.approx(100.0)


def test_a_route_only_against_one_way_streets_is_an_error() -> None:
    roads = vt.RoadNetwork(SQUARE[:2], np.array([[0, 1]]), oneway=[True])
    assert list(roads.shortest_route(0, 1)) == [0, 1]
    message = refuses(lambda: roads.shortest_route(1, 0), "to = 0", "respects one-way streets")
    assert "\n" not in message
    refuses(lambda: vt.RoadNetwork(SQUARE, np.array([[0, 1]]), oneway=[True]).shortest_route(0, 2),
            "no road route from node 0")  # no road at all: the plain message
    block = [(vt.Polygon(SQUARE + np.array([200.0, 0.0])), 10.0)]
    env = vt.Environment.from_buildings(block, roads)
    assert env.roads.oneway.tolist() == [True]
    two_way = vt.RoadNetwork(SQUARE[:2], np.array([[0, 1]]))
    assert env.fingerprint != vt.Environment.from_buildings(block, two_way).fingerprint


def _one_way_city(tmp_path: Path) -> Path:
    """A street west to east (one-way east), a street back east to west one block north (oneway=-1
    drawn west to east, so driven east to west), joined at both ends by two-way streets, a one-way
    roundabout east of them and a building far away."""
    osm = OsmWriter()
    sw, se = osm.node(LAT, LON), osm.node(LAT, LON + 2e-3)
    nw, ne = osm.node(LAT + 1e-3, LON), osm.node(LAT + 1e-3, LON + 2e-3)
    osm.way([sw, se], highway="residential", oneway="yes")
    osm.way([nw, ne], highway="residential", oneway="-1")
    osm.way([se, ne], highway="residential")
    osm.way([sw, nw], highway="residential", oneway="no")
    # a roundabout east of se, drawn counter-clockwise as the way is driven (right-hand traffic)
    r = [osm.node(LAT, LON + 3e-3), osm.node(LAT + 2e-4, LON + 3.2e-3), osm.node(LAT, LON + 3.4e-3),
         osm.node(LAT - 2e-4, LON + 3.2e-3)]
    osm.way([*r, r[0]][::-1], highway="tertiary", junction="roundabout")
    osm.way([se, r[0]], highway="tertiary")
    osm.box(LAT + 5e-3, LON + 5e-3, building="yes", height="10")
    return osm.write(tmp_path / "oneway.osm")


def test_osm_one_way_streets_are_respected(tmp_path: Path) -> None:
    city = vt.io.read_osm(_one_way_city(tmp_path), origin=(LAT, LON))
    env = city.environment
    assert city.summary.roads.oneway_ways == 3 and city.summary.roads.oneway_edges == 6
    east = vt.PoiPath.from_route(env, (LON, LAT), (LON + 2e-3, LAT), 5.0)  # along the one-way street
    back = vt.PoiPath.from_route(env, (LON + 2e-3, LAT), (LON, LAT), 5.0)  # round the block
    block = vt.Georeference(LAT, LON).to_local(LAT + 1e-3, LON + 2e-3)
    assert east.length == pytest.approx(block[0], rel=1e-3)
    assert back.length == pytest.approx(block[0] + 2 * block[1], rel=1e-3)  # north, west, south
    # the north street is driven east to west only (oneway=-1): from nw to ne goes round the block
    north = vt.PoiPath.from_route(env, (LON, LAT + 1e-3), (LON + 2e-3, LAT + 1e-3), 5.0)
    assert north.length == pytest.approx(block[0] + 2 * block[1], rel=1e-3)
    # the roundabout is driven west, south, east, north: from its south node back to its west
    # node the long way (three quarters), the other way one quarter
    west, south = (LON + 3e-3, LAT), (LON + 3.2e-3, LAT - 2e-4)
    assert len(vt.PoiPath.from_route(env, west, south, 5.0).waypoints) == 2
    assert len(vt.PoiPath.from_route(env, south, west, 5.0).waypoints) == 4  # south, east, north, west


def test_a_route_blocked_by_one_way_streets_is_one_line(tmp_path: Path) -> None:
    osm = OsmWriter()
    a, b, c = osm.node(LAT, LON), osm.node(LAT, LON + 1e-3), osm.node(LAT, LON + 2e-3)
    osm.way([a, b], highway="residential", oneway="yes")
    osm.way([c, b], highway="residential", oneway="yes")  # both drive into b: a dead end
    osm.box(LAT + 5e-3, LON, building="yes", height="10")
    env = vt.Environment.from_osm(osm.write(tmp_path / "dead_end.osm"), origin=(LAT, LON))
    assert vt.PoiPath.from_route(env, (LON, LAT), (LON + 1e-3, LAT), 5.0).length > 0
    message = refuses(lambda: vt.PoiPath.from_route(env, (LON, LAT), (LON + 2e-3, LAT), 5.0),
                      "route: no road route from = [", "that respects one-way streets")
    assert "\n" not in message
