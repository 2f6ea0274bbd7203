"""Monte Carlo beyond the paper: random routes and winds, with and without gusts."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Optional, Sequence

import numpy as np

from .._core import VistrackError
from ..flight import Wind
from .navigation import PAPER_GUST_MODEL, PAPER_RADII, Options, paper_flights, paper_gusts

__all__ = ["MonteCarlo", "monte_carlo", "random_route"]


def random_route(rng: np.random.Generator, count: int, turn_radius: float, legs: tuple[float, float] = (4.0, 10.0),
                 max_turn: float = math.pi / 2) -> np.ndarray:
    """``count`` waypoints from the origin: legs uniform in ``legs`` (units of R), each turn
    uniform in [-max_turn, max_turn], first heading uniform."""
    heading = rng.uniform(-math.pi, math.pi)
    points = [np.zeros(2)]
    for k in range(count - 1):
        if k > 0:
            heading += rng.uniform(-max_turn, max_turn)
        length = rng.uniform(*legs) * turn_radius
        points.append(points[-1] + length * np.array([math.cos(heading), math.sin(heading)]))
    return np.array(points)


@dataclass
class MonteCarlo:
    """Per-flight rows and the per-method summary of :func:`monte_carlo`."""

    rows: list[dict[str, Any]]
    settings: dict[str, Any]

    def methods(self) -> list[str]:
        return list(dict.fromkeys(r["label"] for r in self.rows))

    def summary(self) -> list[dict[str, Any]]:
        """Per (gusts, method): miss distance over R (median, 90th percentile, max, over every
        waypoint of every flight), swirl rate (flights with at least one), share of flights
        reaching every waypoint, path length over the route's length, overshoot over R (median)."""
        out = []
        for gusts in (False, True):
            for label in self.methods():
                rows = [r for r in self.rows if r["gusts"] == gusts and r["label"] == label]
                if not rows:
                    continue
                miss = np.concatenate([r["miss_over_R"] for r in rows])
                out.append({
                    "gusts": gusts, "label": label, "flights": len(rows),
                    "miss_median": float(np.median(miss)), "miss_p90": float(np.percentile(miss, 90)),
                    "miss_max": float(miss.max()),
                    "swirl_rate": float(np.mean([r["swirls"] > 0 for r in rows])),
                    "all_reached_rate": float(np.mean([r["all_reached"] for r in rows])),
                    "path_ratio_mean": float(np.mean([r["path_ratio"] for r in rows])),
                    "overshoot_median": float(np.median([r["overshoot_over_R"] for r in rows])),
                })
        return out


def monte_carlo(runs: int = 200, seed: int = 0, waypoints: int = 6, wind_fraction: tuple[float, float] = (0.0, 0.2),
                radii: Sequence[float] = PAPER_RADII, legs: tuple[float, float] = (4.0, 10.0),
                gust_model: Optional[dict[str, float]] = None, progress: Optional[Callable[[int, int], None]] = None,
                **options: Any) -> MonteCarlo:
    """Random routes (``waypoints`` points, legs in ``legs`` x R, turns <= 90 deg) and winds
    (speed uniform in ``wind_fraction`` of the airspeed, direction uniform), each flown by DWN and
    by WN at every radius (units of R), without and with gusts. Seeded: run k draws from
    ``numpy.random.default_rng([seed, k])``. Gusts: :func:`paper_gusts` (``gust_model`` overrides
    keys of ``PAPER_GUST_MODEL``)."""
    if runs < 1:
        raise VistrackError(f"runs = {runs}: must be at least 1")
    if not 0.0 <= wind_fraction[0] <= wind_fraction[1] < 1.0:
        raise VistrackError(f"wind_fraction = {tuple(wind_fraction)}: need 0 <= low <= high < 1 (fractions of v)")
    model = {**PAPER_GUST_MODEL, **(gust_model or {})}
    defaults = Options()
    R = float(options.get("turn_radius", defaults.turn_radius))
    v = float(options.get("speed", defaults.speed))
    rows: list[dict[str, Any]] = []
    total = runs * 2
    for k in range(runs):
        rng = np.random.default_rng([seed, k])
        route = random_route(rng, waypoints, R, legs)
        speed = rng.uniform(*wind_fraction) * v
        direction = rng.uniform(0.0, 2.0 * math.pi)
        gust_seed = int(rng.integers(0, 2**63 - 1))
        route_length = float(np.sum(np.linalg.norm(np.diff(route, axis=0), axis=1)))
        for with_gusts in (False, True):
            gusts = paper_gusts(gust_seed, model) if with_gusts else None
            wind = Wind(east=speed * math.cos(direction), north=speed * math.sin(direction), gusts=gusts)
            for flight in paper_flights(route, wind=wind, radii=radii, **options):
                rows.append({
                    "run": k, "gusts": with_gusts, "wind_speed": speed, "wind_direction": direction,
                    "label": flight.label, "method": flight.method,
                    "miss_over_R": flight.miss_distances / R, "swirls": flight.swirls,
                    "all_reached": flight.all_reached, "path_ratio": flight.path_length / route_length,
                    "overshoot_over_R": flight.overshoot / R, "duration": flight.duration,
                })
            if progress is not None:
                progress(2 * k + 1 + int(with_gusts), total)
    settings = {"runs": runs, "seed": seed, "waypoints": waypoints, "wind_fraction": list(wind_fraction),
                "radii": list(radii), "legs": list(legs), "gust_model": model,
                "turn_radius": R, "speed": v}
    return MonteCarlo(rows=rows, settings=settings)
