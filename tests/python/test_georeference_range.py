"""Georeference.to_latlon's range (issue 29): to_latlon(1e7, 1e7) then to_local did not return the
input, and to_latlon(1e8, 0) answered; within MAX_MAP_OFFSET the round trip holds to 1e-6 m, in
every direction and at any origin latitude, and beyond it the call is refused naming the field."""

from __future__ import annotations

import numpy as np
import pytest

import vistrack as vt
from support.refusal import refuses
from vistrack.georeference import MAX_MAP_OFFSET

pytestmark = pytest.mark.sanitize


@pytest.mark.parametrize("lat", [0.0, 35.2249, 60.0, 89.0, -80.0])
def test_round_trip_within_the_range(lat: float) -> None:
    g = vt.Georeference(lat, -80.8403)
    edge = np.linspace(-MAX_MAP_OFFSET, MAX_MAP_OFFSET, 41)
    east, north = (a.ravel() for a in np.meshgrid(edge, edge))  # the whole square, corners included
    back = np.column_stack(g.to_local(*g.to_latlon(east, north)))
    assert np.max(np.hypot(back[:, 0] - east, back[:, 1] - north)) < 1e-6


def test_beyond_the_range_is_refused_naming_the_field() -> None:
    g = vt.Georeference(35.2249, -80.8403)
    refuses(lambda: g.to_latlon(1e7, 1e7), "east = 10000000.0", "MAX_MAP_OFFSET")
    refuses(lambda: g.to_latlon(1e8, 0.0), "east = 100000000.0")
    refuses(lambda: g.to_latlon(0.0, -2.5e6), "north = -2500000.0")
