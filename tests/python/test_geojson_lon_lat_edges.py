"""Longitude/latitude GeoJSON buildings that the local projection would misread (issue 29): one
crossing the antimeridian was read as local metres (a 20 m building became a 360 m x 0.0002 m
sliver), one touching a pole projects onto a singular plane. Each is refused naming the feature;
a building beside the antimeridian, on one side, still loads."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import vistrack as vt
from support.refusal import refuses

pytestmark = pytest.mark.sanitize

D = 0.0002  # degrees: about 20 m of longitude at the equator


def _file(tmp_path: Path, *rings: list[list[float]]) -> Path:
    features = [{"type": "Feature", "properties": {"height": 20.0},
                 "geometry": {"type": "Polygon", "coordinates": [ring]}} for ring in rings]
    path = tmp_path / "city.geojson"
    path.write_text(json.dumps({"type": "FeatureCollection", "features": features}))
    return path


def _square(lon: float, lat: float, size: float = D) -> list[list[float]]:
    return [[lon, lat], [lon + size, lat], [lon + size, lat + size], [lon, lat + size], [lon, lat]]


def test_a_building_across_the_antimeridian_is_refused(tmp_path: Path) -> None:
    ring = [[179.9999, 10.0], [-179.9999, 10.0], [-179.9999, 10.0002], [179.9999, 10.0002], [179.9999, 10.0]]
    message = refuses(lambda: vt.Environment.from_geojson(str(_file(tmp_path, ring))), "features[0]",
                      "crosses the antimeridian")
    assert "\n" not in message


def test_buildings_on_both_sides_of_the_antimeridian_are_refused(tmp_path: Path) -> None:
    path = _file(tmp_path, _square(179.999, 10.0), _square(-179.9995, 10.0))
    refuses(lambda: vt.Environment.from_geojson(str(path)), "both sides of 180 degrees")


def test_a_building_touching_a_pole_is_refused(tmp_path: Path) -> None:
    ring = [[0.0, 89.9998], [0.0002, 89.9998], [0.0002, 90.0], [0.0, 90.0], [0.0, 89.9998]]
    refuses(lambda: vt.Environment.from_geojson(str(_file(tmp_path, ring))), "features[0]", "touches a pole")


def test_a_building_beside_the_antimeridian_loads_in_metres(tmp_path: Path) -> None:
    env = vt.Environment.from_geojson(str(_file(tmp_path, _square(179.9996, 10.0))))
    assert env.origin is not None and abs(env.origin[1] - 179.9997) < 1e-6
    (footprint,) = env.footprints
    xs = [p[0] for p in footprint.outer]
    assert 15.0 < max(xs) - min(xs) < 30.0  # about 22 m of longitude at 10 degrees north
