"""Arguments of the wrong Python type or kind, whichever entry point takes them: the refusal names
the parameter (a VistrackError, or pybind11's TypeError listing the signature)."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import vistrack as vt
from support.refusal import refuses
from support.vehicles import east_truck
from vistrack import VistrackError

pytestmark = pytest.mark.sanitize


@pytest.mark.parametrize("bad", [None, "abc", (1.0, 2.0), np.array([object(), 1, 2], dtype=object)])
def test_wrong_python_types_name_the_parameter(bad: Any) -> None:
    """None, a string, a 2-tuple where 3 are needed, an object array read as clearly as wrong values."""
    with pytest.raises((VistrackError, TypeError)) as raised:
        vt.dubins.shortest_path(bad, (10.0, 5.0, 1.0), 2.0)
    message = str(raised.value)
    assert "q0" in message or "incompatible function arguments" in message, message


def test_python_values_of_the_wrong_kind_name_the_parameter() -> None:
    """Found in review: follow's radius and offset keys, and numpy thresholds (which are valid)."""
    truck = east_truck()
    uav = vt.Uav(speed=20.0, min_turn_radius=40.0, altitude=100.0)
    refuses(lambda: vt.follow.baseline(truck, uav, "abc"), "baseline.radius = 'abc'")
    refuses(lambda: vt.follow.simulate(truck, uav, offset_schedule=[(0.0, 1.0)]), "offset_schedule[0]")
    plan = vt.loiter.plan(np.array([[300.0, 0.0]]), "tlpp")
    assert vt.loiter.coverage(plan, np.array([[300.0, 0.0]]), threshold=np.float32(0.75)).time > 0.0
    poi = vt.PoiPath(np.array([[0.0, 0.0], [1e6, 0.0]]), 5.0)
    refuses(lambda: vt.visibility.check_count(poi, 1.0, 100), "max_volumes = 100", "raise max_volumes")
