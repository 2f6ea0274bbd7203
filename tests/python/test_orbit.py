"""Algorithm 1, Lemma 5/6 bounds, and plan_orbits on Charlotte (the paper's two examples)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import vistrack as vt


def test_circular_orbits_matches_the_lower_envelope_closed_form():
    rng = np.random.default_rng(5)
    for _ in range(30):
        n = int(rng.integers(2, 25))
        t = np.cumsum(np.r_[0.0, rng.uniform(0.1, 3.0, n - 1)])
        m = rng.uniform(0.0, 300.0, n)
        v, vg = 20.0, float(rng.uniform(1.0, 10.0))
        out = vt.circular_orbits(list(t), list(m), vt.Uav(speed=v, min_turn_radius=10.0), vg)
        envelope = np.min(m[None, :] + (v - vg) * np.abs(t[:, None] - t[None, :]), axis=1)
        np.testing.assert_allclose(out.radii, envelope, rtol=1e-12, atol=1e-9)
        assert np.all(np.abs(out.radius_rates) <= (v - vg) * (1 + 1e-12))


def test_printed_typos_would_fail():
    uav = vt.Uav(speed=20.0, min_turn_radius=50.0)
    # Line 5 of the listing would give R_1 = (v - v_g) dt = 15 m; from the neighbour it is 115 m.
    assert vt.circular_orbits([0.0, 1.0], [100.0, 300.0], uav, 5.0).radii[1] == pytest.approx(115.0)
    # Line 11 would give R_0 = (v_g - v) dt = -15 m.
    assert vt.circular_orbits([0.0, 1.0], [300.0, 100.0], uav, 5.0).radii[0] == pytest.approx(115.0)
    # Line 15 reversed: R = 100 m >= 50 * 1.25^2 = 78.1 m is feasible, R = 60 m is not.
    assert vt.circular_orbits([0.0, 10.0], [100.0, 100.0], uav, 5.0).feasible
    bad = vt.circular_orbits([0.0, 10.0, 20.0], [100.0, 60.0, 100.0], uav, 5.0)
    assert not bad.feasible and list(bad.failing_samples) == [1]
    assert "sample 1" in bad.infeasibility and "Lemma 6" in bad.infeasibility


def test_lemma6_bound_is_the_maximum_of_31():
    v, vg, R = 20.0, 7.0, 90.0
    a = np.linspace(-math.pi, math.pi, 361)
    rates = np.linspace(-(v - vg), v - vg, 101)[1:-1]
    best = max(vt.orbit_curvature(R, c, x, v, vg) for x in a for c in rates)
    assert best == pytest.approx(vt.max_orbit_curvature(R, v, vg), rel=1e-9)
    assert vt.min_feasible_radius(vt.Uav(speed=v, min_turn_radius=50.0), vg) == pytest.approx(50 * (1 + vg / v) ** 2)


def test_bad_input_names_the_field():
    with pytest.raises(vt.VistrackError, match="uav.speed"):
        vt.circular_orbits([0.0, 1.0], [10.0, 10.0], vt.Uav(speed=5.0), 5.0)
    with pytest.raises(vt.VistrackError, match="max_radii"):
        vt.circular_orbits([0.0, 1.0], [10.0, float("nan")], vt.Uav(), 5.0)
    with pytest.raises(vt.VistrackError, match="times"):
        vt.circular_orbits([0.0, 0.0], [10.0, 10.0], vt.Uav(), 5.0)
