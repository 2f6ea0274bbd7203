"""Buildings with a base (min_height): a raised part is a solid from its base to its top, the
space under it open for lines of sight; validation names the field."""

from __future__ import annotations

import json

import numpy as np
import pytest

import vistrack as vt
from support.refusal import refuses


def _square(x0: float, y0: float, size: float) -> vt.Polygon:
    return vt.Polygon(np.array([[x0, y0], [x0 + size, y0], [x0 + size, y0 + size], [x0, y0 + size]]))


def _bridge() -> vt.Environment:
    """A 20 m square part from 18 m to 30 m over the ground, beside a tower on the ground."""
    return vt.Environment.from_buildings([(_square(0, 0, 20), 30.0, 7, 18.0), (_square(40, 0, 10), 25.0)])


def test_a_raised_part_is_a_solid_from_its_base_to_its_top() -> None:
    env = _bridge()
    assert np.allclose(env.min_heights, [18.0, 0.0]) and np.allclose(env.heights, [30.0, 25.0])
    assert env.ground_level == 0.0 and np.allclose(env.bounds, [[0, 0, 0], [50, 20, 30]])
    v = env.vertices[env.faces]
    volume = float(np.einsum("ij,ij->i", v[:, 0], np.cross(v[:, 1], v[:, 2])).sum() / 6.0)
    assert volume == pytest.approx(400 * 12 + 100 * 25)
    assert env.vertices[:, 2].min() == 0.0 and sorted(set(env.vertices[:, 2].tolist())) == [0.0, 18.0, 25.0, 30.0]


def test_a_ray_under_a_raised_part_passes_and_one_through_it_is_blocked() -> None:
    scene = vt.visibility_scene(_bridge())
    starts = np.array([[-30.0, 5.0, 5.0], [-30.0, 10.0, 24.0], [-30.0, 10.0, 10.0], [-30.0, 10.0, 5.0]])
    ends = np.array([[60.0, 5.0, 5.0], [25.0, 10.0, 24.0], [25.0, 10.0, 10.0], [25.0, 10.0, 5.0]])
    # Under the part (5 m, 10 m) the first ray still meets the tower on the ground at x = 40.
    assert scene.line_of_sight(starts, ends).tolist() == [False, False, True, True]
    assert scene.inside_obstacle(np.array([10.0, 10.0, 24.0]))
    assert not scene.inside_obstacle(np.array([10.0, 10.0, 10.0]))
    # A ray down onto the ground under the part from its side passes; one from above is blocked.
    down = scene.line_of_sight(np.array([[-10.0, 10.0, 12.0], [10.0, 10.0, 60.0]]), np.array([[10.0, 10.0, 0.5]] * 2))
    assert down.tolist() == [True, False]


def test_stacked_parts_may_share_a_footprint_but_not_a_volume() -> None:
    stacked = vt.Environment.from_buildings([(_square(0, 0, 20), 18.0), (_square(0, 0, 20), 30.0, 1, 18.0)])
    assert stacked.num_buildings == 2
    refuses(lambda: vt.Environment.from_buildings([(_square(0, 0, 20), 20.0), (_square(5, 5, 20), 30.0, 1, 18.0)]),
            "buildings[0] (id 0) and buildings[1] (id 1) overlap")
    # A part inside its outline is accepted only when its heights lie within the outline's.
    inner = vt.Environment.from_buildings([(_square(0, 0, 20), 30.0), (_square(5, 5, 5), 25.0, 1, 10.0)])
    assert inner.num_buildings == 2
    refuses(lambda: vt.Environment.from_buildings([(_square(0, 0, 20), 30.0, 0, 10.0), (_square(5, 5, 5), 25.0)]),
            "overlap")


@pytest.mark.parametrize("base, fragments", [
    (-1.0, ("buildings[0].min_height = -1", ">= 0")),
    (float("nan"), ("buildings[0].min_height = nan",)),
    (30.0, ("buildings[0].min_height = 30", "below the top", "buildings[0].height = 30")),
    (31.0, ("buildings[0].min_height = 31", "below the top")),
])
def test_a_bad_base_names_the_field(base: float, fragments: tuple[str, ...]) -> None:
    refuses(lambda: vt.Environment.from_buildings([(_square(0, 0, 20), 30.0, 0, base)]), *fragments)


def _collection(path, features) -> str:
    path.write_text(json.dumps({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": properties, "geometry": {"type": "Polygon", "coordinates": [ring]}}
        for ring, properties in features]}))
    return str(path)


SQUARE = [[0, 0], [20, 0], [20, 20], [0, 20], [0, 0]]


def test_geojson_min_height(tmp_path) -> None:
    env = vt.Environment.from_geojson(_collection(tmp_path / "ok.geojson", [
        (SQUARE, {"height": 30, "min_height": 18}), (SQUARE, {"height": "18 m"}),
        ([[30, 0], [40, 0], [40, 10], [30, 0]], {"height": 9, "min_height": "3"})]))
    assert np.allclose(env.min_heights, [18, 0, 3]) and np.allclose(env.heights, [30, 18, 9])
    assert env.fingerprint != vt.Environment.from_geojson(_collection(tmp_path / "flat.geojson", [
        (SQUARE, {"height": 30}), ([[30, 0], [40, 0], [40, 10], [30, 0]], {"height": 9})])).fingerprint
    refuses(lambda: vt.Environment.from_geojson(_collection(tmp_path / "bad.geojson", [
        (SQUARE, {"height": 10, "min_height": 12})])), "features[0].properties.min_height = 12", "below the top")
    refuses(lambda: vt.Environment.from_geojson(_collection(tmp_path / "text.geojson", [
        (SQUARE, {"height": 10, "min_height": "high"})])), "features[0].properties.min_height")
