"""Orbit plan basics: max inscribed radius, constant-radius plans and the JSON round trip."""

from __future__ import annotations

import numpy as np
import pytest

import vistrack as vt
from support.cities import square


def test_max_inscribed_radius_analytic() -> None:
    poly = vt.Polygon(square(0.0, 0.0, 10.0), [square(5.0, 0.0, 1.0)])
    # Nearest boundary from the origin is the hole's left edge at x = 4.
    assert vt.max_inscribed_radius([poly], np.array([0.0, 0.0])) == pytest.approx(4.0)
    assert vt.max_inscribed_radius([poly], np.array([0.0, 8.0])) == pytest.approx(2.0)
    assert vt.max_inscribed_radius([poly], np.array([5.0, 0.0])) == 0.0  # inside the hole
    assert vt.max_inscribed_radius([poly], np.array([20.0, 0.0])) == 0.0
    # Brute force: the radius is the largest r with every sampled circle point inside.
    rng = np.random.default_rng(3)
    for _ in range(50):
        c = rng.uniform(-9.5, 9.5, size=2)
        r = vt.max_inscribed_radius([poly], c)
        if r == 0.0:
            continue
        theta = np.linspace(0, 2 * np.pi, 720, endpoint=False)
        inside = [poly.contains(c + 0.999 * r * np.array([np.cos(t), np.sin(t)])) for t in theta]
        assert all(inside)
        outside = [poly.contains(c + 1.01 * r * np.array([np.cos(t), np.sin(t)])) for t in theta]
        assert not all(outside)


def test_constant_radius_plan_and_json_round_trip() -> None:
    poi = vt.PoiPath(np.array([[0.0, 0.0], [100.0, 0.0], [100.0, 50.0]]), speed=5.0)
    plan = vt.constant_radius_plan(poi, 60.0, vt.Uav(speed=20.0, min_turn_radius=50.0))
    assert plan.radius(7.0) == 60.0 and plan.radius_rate(7.0) == 0.0
    # Lemma 6: 60 m < r_min (1 + v_g/v)^2 = 78.125 m, so this constant orbit is not flyable; the
    # message prints the computed limit to 4 significant digits (issue 29), the given radius as given.
    assert not plan.feasible and "radius 60 m < r_min (1 + v_g/v)^2 = 78.12 m" in plan.infeasibility
    assert vt.constant_radius_plan(poi, 80.0, vt.Uav(speed=20.0, min_turn_radius=50.0)).feasible
    again = vt.OrbitPlan.from_json(plan.to_json())
    assert again.times == plan.times and again.radii == plan.radii
    assert np.allclose(again.centers, plan.centers)
    with pytest.raises(vt.VistrackError, match=r"uav\.speed"):
        vt.constant_radius_plan(poi, 60.0, vt.Uav(speed=4.0))
    with pytest.raises(vt.VistrackError, match="radius"):
        vt.constant_radius_plan(poi, -1.0, vt.Uav())
    with pytest.raises(vt.VistrackError, match="orbit plan JSON"):
        vt.OrbitPlan.from_json("{")


def test_visibility_plan_json_derives_rates_and_validates_parameters() -> None:
    import json

    env = vt.Environment.demo()
    poi = vt.PoiPath(np.array([[-290.0, -210.0], [95.0, -210.0]]), speed=5.0)
    uav = vt.Uav(speed=20.0, min_turn_radius=15.0, altitude=200.0)
    plan = vt.plan_orbits(env, poi, uav, vt.Sensor(d_max=300.0), vt.Planning(resolution_deg=3.0, cutoff=1e12))
    data = json.loads(plan.to_json())
    data["radius_rates"] = [123.0] * len(data["radius_rates"])  # tampered: must not be trusted
    again = vt.VisibilityOrbitPlan.from_json(json.dumps(data))
    # radius_rates are Algorithm 1's (the paper's piecewise-linear locus); the smooth reference
    # R(t) the plan follows has its own rates at its knots (plan.reference.rates).
    expected = np.diff(plan.orbits.radii) / np.diff(plan.times)
    assert np.allclose(again.radius_rates, expected) and np.allclose(plan.radius_rates, expected)
    np.testing.assert_array_equal(again.reference.rates, plan.reference.rates)
    data["uav"]["speed"] = -3.0
    with pytest.raises(vt.VistrackError, match=r"uav\.speed = -3"):
        vt.VisibilityOrbitPlan.from_json(json.dumps(data))


def test_rate_margin_tightens_algorithm_1_and_survives_json() -> None:
    env = vt.Environment.demo()
    poi = vt.PoiPath(np.array([[-290.0, -210.0], [95.0, -210.0]]), speed=5.0)
    uav = vt.Uav(speed=20.0, min_turn_radius=15.0, altitude=200.0)
    sensor = vt.Sensor(d_max=300.0)
    # Algorithm 1's rate passes, on the paper's locus (the smooth one solves an LP to 1 cm under the
    # same rate bound, so its radii need not be ordered to 1e-9).
    paper = vt.plan_orbits(env, poi, uav, sensor,
                           vt.Planning(resolution_deg=3.0, spacing=10.0, cutoff=1e12, locus="paper"))
    tight = vt.plan_orbits(env, poi, uav, sensor, vt.Planning(resolution_deg=3.0, spacing=10.0, cutoff=1e12,
                                                              rate_margin=0.5, locus="paper"))
    assert np.max(np.abs(paper.radius_rates)) == pytest.approx(15.0)  # the city makes it reach v - v_g
    assert np.max(np.abs(tight.radius_rates)) <= 7.5 * (1 + 1e-12)
    assert np.all(np.asarray(tight.radii) <= np.asarray(paper.radii) + 1e-9)
    # The smooth locus keeps the same margin on its dR/dt everywhere (linear between its knots).
    smooth = vt.plan_orbits(env, poi, uav, sensor,
                            vt.Planning(resolution_deg=3.0, spacing=10.0, cutoff=1e12, rate_margin=0.5))
    assert smooth.reference.smooth and np.max(np.abs(smooth.reference.rates)) <= 7.5 * (1 + 1e-9)
    again = vt.VisibilityOrbitPlan.from_json(tight.to_json())
    assert again.planning.rate_margin == 0.5
    with pytest.raises(vt.VistrackError, match=r"planning\.rate_margin = 1"):
        vt.Planning(rate_margin=1.0)
