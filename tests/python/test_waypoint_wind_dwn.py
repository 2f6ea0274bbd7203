"""Issue 32's remainder: DWN with turning points planned in the air mass (wind-aware DWN), the
paper's option of re-planning more often (section 2.1), and flights ending on the last waypoint's
finish line."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

import vistrack as vt
from support.paths import REPO
from vistrack import VistrackError
from vistrack import waypoint_nav as wn

R = wn.DEFAULTS["turn_radius"]
V = wn.DEFAULTS["speed"]
ROUTE = wn.read_route(REPO / "examples" / "waypoints_paper.csv")


def wind_at(ratio: float, angle: float) -> vt.flight.Wind:
    return vt.flight.Wind(east=ratio * V * math.cos(angle), north=ratio * V * math.sin(angle))


def test_air_mass_turning_point_is_the_horizon_of_the_moving_waypoints() -> None:
    """Oracle: the returned path, moved back into the air frame, is turning_point's optimum for the
    waypoints displaced by -w tau, tau the times its own arc lengths give (the fixed point), and
    calm air gives turning_point itself."""
    rng = np.random.default_rng(7)
    for _ in range(20):
        pose = (0.0, 0.0, rng.uniform(-math.pi, math.pi))
        w_next = rng.uniform(3.0, 6.0) * R * np.array([1.0, rng.uniform(-0.5, 0.5)])
        w_after = w_next + rng.uniform(4.0, 8.0) * R * np.array([math.cos(a := rng.uniform(-1.5, 1.5)), math.sin(a)])
        wind = tuple(rng.uniform(-0.3, 0.3, 2) * V)
        ground = wn.air_mass_turning_point(pose, w_next, w_after, R, V, wind)
        w = np.asarray(wind)
        to_next = (ground.first_arc + ground.first_straight + ground.arc_to_waypoint) / V
        to_after = to_next + (ground.arc_from_waypoint + ground.last_straight) / V
        air = wn.turning_point(pose, w_next - w * to_next, w_after - w * to_after, R)
        assert air.length == pytest.approx(ground.length, abs=1e-9)
        at_point = (air.first_arc + air.first_straight) / V
        np.testing.assert_allclose(np.asarray(ground.point), np.asarray(air.point) + w * at_point, atol=1e-9)
        calm = wn.air_mass_turning_point(pose, w_next, w_after, R, V, (0.0, 0.0))
        still = wn.turning_point(pose, w_next, w_after, R)
        np.testing.assert_array_equal(np.asarray(calm.point), np.asarray(still.point))
    with pytest.raises(VistrackError, match="wind"):
        wn.air_mass_turning_point((0.0, 0.0, 0.0), (4.0, 0.0), (8.0, 2.0), R, V, (V, 0.0))


def test_air_mass_planning_is_exact_in_continuous_flight() -> None:
    """Flown continuously (no step to overshoot a switch by), the air-mass plan passes every
    waypoint of the example route in 0.3 v wind from 8 directions within 1e-3 R: the plan, not the
    law, decides where the path goes."""
    for a in np.linspace(0.0, 2 * math.pi, 8, endpoint=False):
        f = wn.fly(ROUTE, wind=wind_at(0.3, a), wind_aware=True, integration="continuous")
        assert f.all_reached and f.miss_distances.max() < 1e-3 * R


def test_wind_aware_dwn_meets_the_issues_bounds_on_random_routes_and_winds() -> None:
    """Issue 32's done-when: wind-aware DWN's largest miss (every waypoint, the last one included,
    measured where the flight ends on its line) is at most 0.02 R at w = 0.1 v and 0.05 R at 0.3 v,
    on seeded random routes and wind directions this seed was not tuned on; DWN planned in still
    air misses several times more on the same flights."""
    rng = np.random.default_rng(20261205)
    for ratio, bound in ((0.1, 0.02), (0.3, 0.05)):
        aware, still = 0.0, 0.0
        for _ in range(10):
            route = wn.random_route(rng, 6, R)
            wind = wind_at(ratio, rng.uniform(0.0, 2 * math.pi))
            f = wn.fly(route, wind=wind, wind_aware=True)
            assert f.all_reached and f.swirls == 0
            aware = max(aware, float(f.miss_distances.max()) / R)
            still = max(still, float(wn.fly(route, wind=wind).miss_distances.max()) / R)
        assert aware <= bound < still


@pytest.mark.parametrize("aware,guidance,replan,integration",
                         list(itertools.product((False, True), ("law5", "l1"), (0.0, 0.5), ("discrete", "continuous"))))
def test_dwn_never_swirls_in_any_mode(aware: bool, guidance: str, replan: float, integration: str) -> None:
    """DWN in every mode (wind-aware or not, law (5) or L1 legs, re-planning or not, discrete or
    continuous) reaches every waypoint without a loop in 0.3 v wind from 6 directions."""
    for a in np.linspace(0.0, 2 * math.pi, 6, endpoint=False):
        f = wn.fly(ROUTE, wind=wind_at(0.3, a), wind_aware=aware, guidance=guidance, replan_interval=replan,
                   integration=integration)
        assert f.swirls == 0 and f.all_reached


def last_turning_points(flight: wn.NavigationFlight) -> np.ndarray:
    return np.array([r.path.point for r in flight.turning_point_records if not r.direct])


@pytest.mark.parametrize("interval", [wn.DEFAULTS["dt"], 0.5])
def test_replanning_in_calm_air_changes_nothing(interval: float) -> None:
    """Section 2.1's option, invariance: without wind the vehicle flies the planned path, and a
    path's tail is the best path from any of its points (Bellman), so re-planning every step or
    every 0.5 s gives the same turning points and misses (to the law's step: 2e-3 R); the records
    show it did re-plan (each planned after the switch that first planned it)."""
    still = wn.fly(ROUTE)
    again = wn.fly(ROUTE, replan_interval=interval)
    np.testing.assert_allclose(last_turning_points(again), last_turning_points(still), atol=2e-3 * R)
    np.testing.assert_allclose(again.miss_distances, still.miss_distances, atol=2e-3 * R)
    later = [a.t > s.t for a, s in zip(again.turning_point_records, still.turning_point_records) if not s.direct]
    assert later and all(later)


def test_replanning_in_wind_misses_no_more() -> None:
    """With wind (unknown, or known and with gusts the plan does not know) re-planning every step
    or every 0.5 s misses no more than the paper's planning on seeded random routes and winds."""
    rng = np.random.default_rng(99)
    flights = []
    for k in range(8):
        route = wn.random_route(rng, 6, R)
        gusts = wn.paper_gusts(k) if k % 2 else None
        a = rng.uniform(0.0, 2 * math.pi)
        ratio = rng.uniform(0.1, 0.3)
        flights.append((route, vt.flight.Wind(east=ratio * V * math.cos(a), north=ratio * V * math.sin(a),
                                              gusts=gusts)))
    for aware in (False, True):
        worst = {}
        for interval in (0.0, wn.DEFAULTS["dt"], 0.5):
            misses = [wn.fly(route, wind=wind, wind_aware=aware, replan_interval=interval).miss_distances.max()
                      for route, wind in flights]
            worst[interval] = max(misses)
        assert worst[wn.DEFAULTS["dt"]] <= worst[0.0] + 1e-3 * R and worst[0.5] <= worst[0.0] + 1e-3 * R


def test_replan_interval_is_checked() -> None:
    with pytest.raises(VistrackError, match="replan_interval"):
        wn.fly(ROUTE, replan_interval=-1.0)
    with pytest.raises(VistrackError, match="replan_interval"):
        wn.fly(ROUTE, method="wn", replan_interval=0.5)


@pytest.mark.parametrize("method,radius", [("dwn", None), ("wn", 1.0), ("wn", 0.1), ("wn_passed_line", 0.5)])
def test_every_flight_ends_on_the_last_waypoints_finish_line(method: str, radius: float | None) -> None:
    """The flight ends at the first state past the line through the last waypoint perpendicular to
    the last leg (WN no longer stops on entering R_WP there), and the last miss is the distance where
    the path crosses that line: for WN at R_WP = R now a pursuit's miss, not about R."""
    f = wn.fly(ROUTE, method=method, waypoint_radius=None if radius is None else radius * R,
               wind=wind_at(0.1, 0.5 * math.pi))
    assert f.finished and f.all_reached
    w, leg = ROUTE[-1], ROUTE[-1] - ROUTE[-2]
    along = (f.trajectory[:, 1:3] - w) @ leg / np.linalg.norm(leg)
    assert along[-1] >= 0.0 > along[-2]
    a, b = along[-2], along[-1]
    crossing = f.trajectory[-2, 1:3] + (-a / (b - a)) * (f.trajectory[-1, 1:3] - f.trajectory[-2, 1:3])
    assert f.miss_distances[-1] == pytest.approx(float(np.linalg.norm(crossing - w)), abs=1e-12)
    assert f.miss_distances[-1] < 0.05 * R
    assert f.metrics()["max_miss_over_R"] == pytest.approx(f.miss_distances.max() / R)


def test_the_bound_guidance_plans_in_the_air_mass_as_fly_does() -> None:
    """DubinsWaypointGuidance.set_wind flown by vt.flight.fly is the flight fly(wind_aware=True)
    makes up to the direct flight to the last waypoint (which fly() gives a wind-aware law)."""
    wind = wind_at(0.2, 1.0)
    expected = wn.fly(ROUTE, wind=wind, wind_aware=True, replan_interval=0.5)
    guidance = wn.DubinsWaypointGuidance(vt.flight.LineFeedback(V, R, wn.DEFAULTS["dt"]), ROUTE[1:], R)
    guidance.set_wind((wind.east, wind.north), V)
    guidance.replan_interval = 0.5
    flight = vt.flight.fly(guidance, expected.start, V, R, wind=wind, max_time=float(expected.flight.t[-1]) + 10.0)
    direct = expected.turning_point_records[-1].t
    n = int(np.searchsorted(expected.trajectory[:, 0], direct)) + 1
    assert n > 100
    np.testing.assert_allclose(np.column_stack([flight.t, flight.x, flight.y])[:n], expected.trajectory[:n, :3],
                               atol=1e-12)
    np.testing.assert_allclose(guidance.turning_points[:-1], expected.turning_points[:-1], atol=1e-12)
