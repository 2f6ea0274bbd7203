"""Guidance field, steering law and the Dormand-Prince integrator from Python, cross-checked
against scipy (same algorithm: identical step counts) and the paper's theory."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import vistrack as vt
from support.paths import EXAMPLES
from support.refusal import refuses
from vistrack import schema


def test_vector_field_has_constant_speed_and_turns_the_right_way():
    rng = np.random.default_rng(3)
    orbit = vt.OrbitState(center=np.array([10.0, -4.0]), center_velocity=np.array([3.0, -4.0]),
                          radius=80.0, radius_rate=1.5)
    points = orbit.center + rng.uniform(-300, 300, size=(5000, 2))
    for direction, sign in (("ccw", 1), ("cw", -1)):
        gains = vt.GuidanceGains(speed=20.0, beta=0.1, direction=direction)
        u, heading, rate = vt.sample_vector_field(points, orbit, gains)
        assert np.allclose(np.linalg.norm(u, axis=1), 20.0, rtol=1e-12)
        assert np.allclose(heading, np.arctan2(u[:, 1], u[:, 0]))
        assert np.all(np.isfinite(rate))
        rel = points - orbit.center
        cross = rel[:, 0] * u[:, 1] - rel[:, 1] * u[:, 0]
        assert np.all(sign * cross > 0)  # circulation sign of (72)


def test_heading_rate_is_the_derivative_along_the_field():
    orbit = vt.OrbitState(center=np.array([0.0, 0.0]), center_velocity=np.array([-5 / math.sqrt(2)] * 2),
                          radius=10.0, radius_rate=0.0)
    gains = vt.GuidanceGains(speed=10.0, beta=0.1)  # the setting of the paper's Figs. 7-8
    xi = np.array([25.0, 7.0])
    f = vt.vector_field(xi, orbit, gains)
    h = 1e-5

    def shifted(dt):
        return vt.OrbitState(center=orbit.center + orbit.center_velocity * dt,
                             center_velocity=orbit.center_velocity, radius=orbit.radius)

    ahead = vt.vector_field(xi + h * f.u, shifted(h), gains).heading
    behind = vt.vector_field(xi - h * f.u, shifted(-h), gains).heading
    assert f.heading_rate == pytest.approx((ahead - behind) / (2 * h), rel=1e-6)


def test_steering_saturates_and_wraps():
    orbit = vt.OrbitState(radius=100.0)
    gains = vt.GuidanceGains(speed=20.0, max_turn_rate=0.4)
    psi_d = vt.vector_field(np.array([0.0, 150.0]), orbit, gains).heading
    s = vt.steering(np.array([0.0, 150.0, psi_d + 0.05 + 2 * math.pi]), orbit, gains)
    assert s.heading_error == pytest.approx(0.05)
    assert abs(s.command) <= 0.4
    s = vt.steering(np.array([0.0, 150.0, psi_d + 3.0]), orbit, gains)
    assert s.saturated and s.command == -0.4


def test_lemma6_maximum_curvature():
    theta = np.linspace(0, 2 * math.pi, 20001)
    for v, vg, radius in [(20.0, 5.0, 150.0), (3.0, 0.35, 20.0), (10.0, 9.9, 40.0)]:
        orbit = vt.OrbitState(center_velocity=np.array([vg * math.cos(0.4), vg * math.sin(0.4)]), radius=radius)
        kappa = np.array([vt.orbit_signed_curvature(a, orbit, v) for a in theta])
        assert kappa.max() == pytest.approx(vt.lemma6_curvature_bound(radius, v, vg), rel=1e-7)
        assert kappa.max() == pytest.approx((vg + v) ** 2 / (radius * v * v), rel=1e-7)


def test_tuning_matches_figure_9():
    # Section V.D: R = 85.9, dR/dt = 1.30, v = 20, v_g = 5, beta = 0.025; paper: 0.378 rad/s.
    result = vt.tune_turn_rate(85.9, 1.30, 20.0, 5.0, 0.025)
    assert result.max_turn_rate == pytest.approx(0.378, abs=0.003)
    assert result.max_turn_rate < 20.0 / 50.0
    assert result.map.shape == (200, 360)
    assert result.map.max() == result.max_turn_rate
    with pytest.raises(vt.VistrackError, match="radius_rate"):
        vt.tune_turn_rate(85.9, 30.0, 20.0, 5.0, 0.025)
    with pytest.raises(vt.VistrackError, match="direction = 'up'"):
        vt.tune_turn_rate(85.9, 1.0, 20.0, 5.0, 0.025, direction="up")


def test_tune_beta_sweeps_around_beta_within_its_range():
    """Without a sweep, tune_beta searches 30 betas over two decades around beta, clipped to beta's
    range (limits.hpp): around 500 /m the sweep ends at 1000, not 5000."""
    from vistrack.tuning import default_sweep, tune_beta

    wide = tune_beta(85.9, 1.3, 20.0, 5.0, 50.0, 500.0)
    assert max(wide.betas) == pytest.approx(vt._core.limits.MAX_BETA) and min(wide.betas) == pytest.approx(50.0)
    assert np.array_equal(wide.betas, default_sweep(500.0)) and len(wide.sweep_max_turn_rate) == 30


def test_lemma_constants():
    x = np.linspace(0, 20, 2_000_001)
    assert vt.epsilon_max() == pytest.approx(np.max(np.arctan(x) ** 2 / (1 + x * x)), abs=1e-12)
    assert vt.lambda_max() == pytest.approx(np.max(np.arctan(x) / (1 + x * x)), abs=1e-12)
    assert vt.lemma7_min_gain(20.0, 0.025) < 20.0  # the paper's k_psi = 20 satisfies (87)


def test_safe_functions():
    assert vt.sinc(0.0) == 1.0 and vt.one_minus_cos_over_x(0.0) == 0.0
    assert vt.one_minus_cos_over_x(1e-10) == pytest.approx(5e-11, rel=1e-15)
    assert vt.sinc(1e-5) == pytest.approx(1 - 1e-10 / 6, rel=1e-16)


def test_bad_gains_name_the_field():
    with pytest.raises(vt.VistrackError, match=r"gains\.beta"):
        vt.GuidanceGains(beta=0.0)
    with pytest.raises(vt.VistrackError, match="direction = 'sideways'"):
        vt.GuidanceGains(direction="sideways")
    with pytest.raises(TypeError, match="direction: str"):  # the one spelling is the string
        vt.GuidanceGains(direction=2)
    with pytest.raises(vt.VistrackError, match=r"orbit\.radius_rate"):
        orbit = vt.OrbitState(center_velocity=np.array([5.0, 0.0]), radius=10.0, radius_rate=16.0)
        vt.orbit_signed_curvature(0.0, orbit, 20.0)


# --- the integrator against scipy's RK45 (the same method): same steps, same values ---------

def _exp_sin(t, y):
    return y * math.cos(t)


def test_solve_ode_matches_scipy_step_for_step():
    for rtol, atol in [(1e-3, 1e-6), (1e-6, 1e-8), (1e-10, 1e-12)]:
        ours = vt.solve_ode(lambda t, y: _exp_sin(t, y), (0.0, 12.0), np.array([1.0]), rtol=rtol, atol=atol)
        ref = solve_ivp(_exp_sin, (0.0, 12.0), [1.0], method="RK45", rtol=rtol, atol=atol)
        assert ours.statistics.rhs_evaluations == ref.nfev
        np.testing.assert_allclose(ours.t, ref.t, rtol=1e-8)  # same steps up to rounding in h
        np.testing.assert_allclose(ours.y[:, 0], ref.y[0], rtol=1e-7)
        exact = np.exp(np.sin(ours.t))
        assert np.max(np.abs(ours.y[:, 0] - exact)) < 100 * rtol


def test_solve_ode_dense_output_and_events_match_scipy():
    def osc(t, y):
        return np.array([y[1], -y[0]])

    def crossing(t, y):
        return y[0]

    crossing.direction = -1
    t_eval = np.linspace(0, 10, 77)
    ours = vt.solve_ode(osc, (0.0, 10.0), np.array([1.0, 0.0]), rtol=1e-8, atol=1e-10, t_eval=t_eval,
                        events=[crossing])
    ref = solve_ivp(osc, (0.0, 10.0), [1.0, 0.0], rtol=1e-8, atol=1e-10, t_eval=t_eval, events=[crossing])
    np.testing.assert_allclose(ours.y, ref.y.T, atol=1e-12)
    np.testing.assert_allclose(ours.event_t, ref.t_events[0], atol=1e-12)
    np.testing.assert_allclose(ours.event_t, [math.pi / 2, 5 * math.pi / 2], atol=1e-7)

    def stop(t, y):
        return y[0]

    stop.terminal = True
    stopped = vt.solve_ode(osc, (0.0, 10.0), np.array([1.0, 0.0]), rtol=1e-10, atol=1e-12, events=[stop])
    assert stopped.terminated and stopped.t[-1] == pytest.approx(math.pi / 2, abs=1e-9)


def test_solve_ode_fixed_step_order():
    errors = []
    for h in (0.1, 0.05, 0.025):
        sol = vt.solve_ode(_exp_sin, (0.0, 4.0), np.array([1.0]), fixed_step=h, t_eval=[4.0])
        errors.append(abs(sol.y[-1, 0] - math.exp(math.sin(4.0))))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(np.abs(orders - 5.0) < 0.3), orders


def test_solve_ode_bad_input():
    with pytest.raises(vt.VistrackError, match="t_bound"):
        vt.solve_ode(_exp_sin, (1.0, 0.0), np.array([1.0]))
    with pytest.raises(vt.VistrackError, match="y0"):
        vt.solve_ode(_exp_sin, (0.0, 1.0), np.array([math.nan]))
    with pytest.raises(vt.VistrackError, match="size"):
        vt.solve_ode(lambda t, y: np.ones(3), (0.0, 1.0), np.array([1.0]))


@pytest.mark.sanitize
def test_ode_tolerances_out_of_range() -> None:
    """ODE tolerances of 1e-300 reported "ode.rhs = -nan"."""
    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        return -y

    refuses(lambda: vt.solve_ode(rhs, (0.0, 1.0), np.array([1.0]), rtol=1e-300), "rtol = 1e-300")
    refuses(lambda: vt.solve_ode(rhs, (0.0, 1.0), np.array([1.0]), atol=math.nan), "atol = nan")


@pytest.mark.sanitize
def test_gain_and_tolerance_ranges_are_the_same_everywhere() -> None:
    """beta, k_psi, rtol and atol have one range (limits.hpp), whichever entry point takes them."""
    lim = vt._core.limits
    assert (lim.MIN_GAIN, lim.MAX_BETA, lim.MAX_HEADING_GAIN) == (1e-9, 1e3, 1e6)
    assert (lim.MIN_RTOL, lim.MAX_RTOL, lim.MIN_ATOL, lim.MAX_ATOL) == (1e-13, 1.0, 1e-15, 1e6)
    too_big = lim.MAX_ATOL * 10
    refuses(lambda: vt.SimulationOptions(atol=too_big), "simulation.atol", "1e+06")  # the constructor checks
    refuses(lambda: vt.solve_ode(lambda t, y: -y, (0.0, 1.0), np.array([1.0]), atol=too_big), "ode.atol", "1e+06")
    refuses(lambda: vt.Control(beta=lim.MAX_BETA * 2), "control.beta", "1000")
    refuses(lambda: vt.Control(k_psi=0.0), "control.k_psi", "1e-09")
    refuses(lambda: vt.lemma7_min_gain(20.0, lim.MAX_BETA * 2), "beta", "1000")
    for section, key, value in [("control", "beta", 2e3), ("control", "k_psi", 0.0), ("simulation", "rtol", 1e-14),
                                ("simulation", "atol", 1e7), ("planning", "rate_margin", 1.0)]:
        refuses(lambda s=section, k=key, v=value: vt.Scenario.from_dict({s: {k: v}}), f"{section}.{key} = {value:g}:")
    # The follow scenario's baseline controller and the beta sweep of `tune` take the same range.
    import yaml

    from vistrack.follow_scenario import FollowScenario
    from vistrack.tuning import default_sweep, tune_beta

    follow = yaml.safe_load((EXAMPLES / "follow_straight.yaml").read_text())
    follow["baseline"] = {"beta": 5000.0}
    refuses(lambda: FollowScenario.from_mapping(follow, EXAMPLES), "baseline.beta = 5000.0")
    follow["baseline"] = {"k_psi": 0.0}
    refuses(lambda: FollowScenario.from_mapping(follow, EXAMPLES), "baseline.k_psi = 0.0")
    refuses(lambda: tune_beta(85.9, 1.3, 20.0, 5.0, 50.0, 0.025, sweep=[0.01, 5000.0]), "sweep[1] = 5000.0")
    wide = default_sweep(500.0)  # tune_beta's sweep when none is given
    assert max(wide) == pytest.approx(lim.MAX_BETA) and min(wide) == pytest.approx(50.0)
    assert len(default_sweep(0.025)) == 30 and default_sweep(0.025)[0] == pytest.approx(0.0025)
    for check, low, high in [(schema.beta, lim.MIN_GAIN, lim.MAX_BETA),
                             (schema.heading_gain, lim.MIN_GAIN, lim.MAX_HEADING_GAIN),
                             (schema.relative_tolerance, lim.MIN_RTOL, lim.MAX_RTOL),
                             (schema.absolute_tolerance, lim.MIN_ATOL, lim.MAX_ATOL)]:
        assert check("k", low) == low and check("k", high) == high
        for outside in (low / 2, high * 2):
            refuses(lambda c=check, v=outside: c("k", v), f"k = {outside!r}")
