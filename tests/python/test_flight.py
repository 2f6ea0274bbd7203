"""vt.flight: wind and gusts, the feedback law (5), the waypoint follower, fly() from Python."""

from __future__ import annotations

import math

import numpy as np
import pytest

import vistrack as vt
from support.threads import ticks_during
from vistrack import flight


def test_wind_defaults_and_repr() -> None:
    wind = flight.Wind(east=0.0, north=0.08)
    assert wind.east == 0.0 and wind.north == 0.08 and wind.gusts is None
    gusts = flight.Gusts(seed=3, intensity=0.05, length_scale=10.0)
    wind = flight.Wind(north=0.08, gusts=gusts)
    assert wind.gusts is not None and wind.gusts.seed == 3
    assert "Wind(" in repr(wind)


@pytest.mark.parametrize(
    ("make", "field"),
    [
        (lambda: flight.Wind(east=math.nan), "wind.east"),
        (lambda: flight.Gusts(intensity=-1.0), "wind.gusts.intensity"),
        (lambda: flight.Gusts(length_scale=0.0), "wind.gusts.length_scale"),
        (lambda: flight.WindField(flight.Wind(north=0.8), 0.8, 0.0, 10.0), "wind"),
        (lambda: flight.LineFeedback(0.8, 0.7, 2.0), "dt"),
        (lambda: flight.Gusts.mil_f_8785c(1000.0, 7.7), "altitude"),
    ],
)
def test_bad_input_names_the_field(make, field: str) -> None:
    with pytest.raises(vt.VistrackError, match=field):
        make()


def test_gust_series_is_seeded_and_has_the_intensity() -> None:
    gusts = flight.Gusts(seed=11, intensity=0.05, length_scale=10.0)
    wind = flight.Wind(gusts=gusts)
    times = np.linspace(0.0, 2000.0, 20001)
    a = flight.WindField(wind, 0.8, 0.0, 2000.0).at(times)
    b = flight.WindField(wind, 0.8, 0.0, 2000.0).at(times)
    np.testing.assert_array_equal(a, b)
    # 2000 s / (L / V = 12.5 s) = 160 correlation times: the RMS within ~15 %.
    rms = np.sqrt(np.mean(a**2, axis=0))
    np.testing.assert_allclose(rms, 0.05, rtol=0.2)
    other = flight.WindField(flight.Wind(gusts=flight.Gusts(seed=12, intensity=0.05, length_scale=10.0)),
                             0.8, 0.0, 2000.0).at(times)
    assert np.abs(other - a).max() > 0.01


def test_mil_f_8785c_gusts_in_flight_units() -> None:
    model = flight.dryden_low_altitude(50.0, 7.7)
    assert model.sigma_w == pytest.approx(0.77)
    assert model.length_u == pytest.approx(202.29, abs=0.01)
    g = flight.Gusts.mil_f_8785c(50.0, 7.7, seed=5, length_unit=20.0, speed_unit=20.0)
    assert g.intensity == pytest.approx(model.sigma_u / 20.0)
    assert g.length_scale == pytest.approx(model.length_u / 20.0)
    assert g.seed == 5


def test_line_feedback_terms() -> None:
    law = flight.LineFeedback(0.8, 0.7, 0.02, gains=(0.1, 5.25))
    assert law.max_turn == pytest.approx(0.8 * 0.02 / 0.7)
    t = law.terms((0.0, 0.0, 0.0), (0.0, -5.0), (0.0, 5.0))
    assert t.saturated and t.turn == pytest.approx(law.max_turn)
    assert law.turn_rate((1.0, 0.0, 0.0), (0.0, 0.0), (5.0, 0.0)) == 0.0


def square_follower(radius: float = 0.35, smooth: bool = False) -> flight.WaypointFollower:
    law = flight.LineFeedback(0.8, 0.7, 0.02, smooth_sign=smooth)
    return flight.WaypointFollower(law, np.array([[6.0, 0.0], [6.0, 6.0], [0.0, 6.0], [0.0, 0.0]]), radius)


@pytest.mark.parametrize("integration", ["discrete", "continuous"])
def test_fly_a_square(integration: str) -> None:
    wn = square_follower(smooth=integration == "continuous")
    traj = flight.fly(wn, start=(0.0, 0.0, 0.0), speed=0.8, turn_radius=0.7, dt=0.02, max_time=200.0,
                      integration=integration)
    assert traj.finished
    n = len(traj)
    assert traj.array.shape == (n, 4)
    assert traj.target.shape == (n, 2) and traj.wind.shape == (n, 2)
    assert traj.target_index.dtype == np.int32 or traj.target_index.dtype == np.int64
    np.testing.assert_array_equal(np.unique(traj.target_index), [0, 1, 2, 3])
    assert np.all(np.isfinite(wn.accepted_at))
    assert np.all(np.abs(traj.command) <= 0.8 / 0.7 + 1e-12)
    # The straight legs: ground speed is the airspeed without wind.
    step = np.hypot(np.diff(traj.x), np.diff(traj.y)) / np.diff(traj.t)
    assert np.median(step) == pytest.approx(0.8, rel=1e-3)


def test_wind_drifts_the_flight_and_the_guidance_does_not_know() -> None:
    calm = flight.fly(square_follower(0.7), (0.0, 0.0, 0.0), 0.8, 0.7, max_time=200.0)
    windy = flight.fly(square_follower(0.7), (0.0, 0.0, 0.0), 0.8, 0.7, wind=flight.Wind(north=0.08),
                       max_time=200.0)
    assert windy.finished and calm.finished
    np.testing.assert_allclose(windy.wind, np.tile([0.0, 0.08], (len(windy), 1)))
    assert abs(windy.end_time - calm.end_time) > 0.1


def test_on_step_feeds_waypoints_and_progress_reports() -> None:
    law = flight.LineFeedback(1.0, 1.0, 0.02)
    follower = flight.WaypointFollower(law, np.array([[2.0, 0.0]]), 0.3, finish_at_last=False)
    fed: list[float] = []

    def feed(t: float, state: tuple[float, float, float]) -> None:
        if t >= len(fed) + 1.0 - 1e-9:
            fed.append(t)
            follower.add_waypoint((2.0 + len(fed), 0.0))

    seen: list[tuple[int, int]] = []
    traj = flight.fly(follower, (0.0, 0.0, 0.0), 1.0, 1.0, max_time=10.0, on_step=feed,
                      progress=lambda done, total: seen.append((done, total)))
    assert not traj.finished
    assert len(follower.waypoints) == 11
    assert follower.active >= 5
    assert seen[-1] == (1000, 1000)


def test_fly_releases_the_gil() -> None:
    follower = flight.WaypointFollower(flight.LineFeedback(1.0, 1.0, 0.01), np.array([[2.0, 0.0]]), 0.3,
                                       finish_at_last=False)
    ticks, seconds = ticks_during(lambda: flight.fly(follower, (0.0, 0.0, 0.0), 1.0, 1.0, dt=0.01,
                                                     max_time=20000.0))
    assert seconds > 0.05
    assert ticks >= 5


def test_bad_fly_arguments() -> None:
    with pytest.raises(vt.VistrackError, match="integration"):
        flight.fly(square_follower(), (0.0, 0.0, 0.0), 0.8, 0.7, integration="rk4")
    with pytest.raises(vt.VistrackError, match="wind"):
        flight.fly(square_follower(), (0.0, 0.0, 0.0), 0.8, 0.7, wind=flight.Wind(east=0.9))
    with pytest.raises(vt.VistrackError, match=r"start\.x"):
        flight.fly(square_follower(), (math.nan, 0.0, 0.0), 0.8, 0.7)
    with pytest.raises(vt.VistrackError, match="turn_radius"):
        flight.fly(square_follower(), (0.0, 0.0, 0.0), 0.8, -0.7)
