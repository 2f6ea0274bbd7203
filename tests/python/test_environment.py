"""Environment and POI path through the Python bindings."""

from __future__ import annotations

import numpy as np
import pytest

import vistrack as vt


def test_poi_path_constant_speed() -> None:
    poi = vt.PoiPath(np.array([[0.0, 0.0], [30.0, 40.0], [30.0, 0.0]]), speed=5.0)
    assert poi.length == pytest.approx(90.0)
    assert poi.duration == pytest.approx(18.0)
    assert np.allclose(poi.node_times, [0.0, 10.0, 18.0])
    assert np.allclose(poi.position(5.0), [15.0, 20.0, 0.0])
    assert np.allclose(poi.velocity(12.0), [0.0, -5.0])
    assert poi.heading(12.0) == pytest.approx(-np.pi / 2)


@pytest.mark.parametrize(
    "waypoints, speed, field",
    [
        ([[0.0, 0.0], [0.0, 0.0]], 1.0, "waypoints"),
        ([[0.0, 0.0], [1.0, 0.0]], 0.0, "speed"),
        ([[0.0, 0.0], [1.0, 0.0]], float("nan"), "speed"),
        ([[0.0, float("nan")], [1.0, 0.0]], 1.0, "waypoints[0][1]"),
    ],
)
def test_poi_path_rejects_bad_input(waypoints, speed, field) -> None:
    with pytest.raises(vt.VistrackError, match=field.replace("[", r"\[").replace("]", r"\]")):
        vt.PoiPath(np.array(waypoints), speed)
