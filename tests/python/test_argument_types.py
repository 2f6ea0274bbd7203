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


@pytest.mark.parametrize("seed", [-1, 2**64, 1e300, 2e19, "7", True])
def test_gust_seeds_out_of_range_name_the_seed(seed: Any) -> None:
    """Issue 29: a negative seed, 2**64 and 1e300 raised pybind's TypeError naming no field; the
    binding now takes any integer and range-checks it (the same for the attribute and mil_f_8785c)."""
    refuses(lambda: vt.flight.Gusts(seed=seed), "seed = ", "must be an integer in [0, 18446744073709551615]")
    gusts = vt.flight.Gusts(seed=np.uint64(2**64 - 1))
    assert gusts.seed == 2**64 - 1

    def assign() -> None:
        gusts.seed = seed

    refuses(assign, "seed = ")
    refuses(lambda: vt.flight.Gusts.mil_f_8785c(100.0, 7.7, seed=seed), "seed = ")


def test_loiter_turns_and_sinusoid_ratios_out_of_range_name_the_field() -> None:
    """Issue 29: ``turns=2**40`` was a pybind TypeError and ``sinusoid_amplitude(1e300, 300.0)``
    Boost's ValueError text; both are VistrackErrors naming the field."""
    aois = np.array([[300.0, 0.0]])
    refuses(lambda: vt.loiter.plan(aois, "tlpp", turns=2**40), "turns = 1099511627776", "must be an integer")
    refuses(lambda: vt.loiter.plan(aois, "tlpp", turns=1001), "turns = 1001", "at most 1000")
    refuses(lambda: vt.loiter.plan(aois, "tlpp", turns=2.5), "turns = 2.5")
    assert vt.loiter.plan(aois, "tlpp", turns=np.int64(2)).turns == 2
    refuses(lambda: vt.loiter.Parameters(turns=2**40), "turns = ")
    refuses(lambda: vt.follow.sinusoid_amplitude(1e300, 300.0), "speed_ratio = 1e+300", "at most 1e+10")
    assert np.isfinite(vt.follow.sinusoid_amplitude(1e10, 300.0))
