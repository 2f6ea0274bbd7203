"""Choosing beta (section V.D, Figure 9): for an orbit of radius R changing at dR/dt about a POI
of speed v_g, the largest |dpsi_d/dt + u_lyap| over r >= tau R (all polar angles and heading
errors) must stay below the turn-rate limit v / r_min."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Optional, Sequence

import numpy as np

from .. import schema
from .._core import TuningResult, VistrackError, lemma7_min_gain, tune_turn_rate
from .._core import limits as _limits

__all__ = ["BetaTuning", "default_sweep", "tune_beta"]


@dataclass
class BetaTuning:
    """The turn rate the guidance needs at ``beta``, and its maximum over a sweep of betas."""

    radius: float
    radius_rate: float
    speed: float
    poi_speed: float
    min_turn_radius: float
    beta: float
    tau: float
    chosen: TuningResult
    betas: list[float] = field(default_factory=list)
    sweep_max_turn_rate: list[float] = field(default_factory=list)

    @property
    def turn_rate_limit(self) -> float:
        """v / r_min, rad/s."""
        return self.speed / self.min_turn_radius

    @property
    def feasible(self) -> bool:
        return self.chosen.max_turn_rate < self.turn_rate_limit

    def summary(self) -> dict[str, Any]:
        """The numbers of tune.json."""
        chosen, limit = self.chosen, self.turn_rate_limit
        feasible = [b for b, m in zip(self.betas, self.sweep_max_turn_rate) if m < limit]
        return {
            "radius": self.radius, "radius_rate": self.radius_rate, "speed": self.speed,
            "poi_speed": self.poi_speed, "tau": self.tau, "beta": self.beta,
            "max_turn_rate": chosen.max_turn_rate, "turn_rate_limit": limit, "feasible": self.feasible,
            "at": {"r": chosen.at_r, "theta_from_poi_motion": chosen.at_theta,
                   "heading_error": chosen.at_heading_error},
            "sweep": {"beta": list(self.betas), "max_turn_rate": list(self.sweep_max_turn_rate)},
            "largest_feasible_beta_in_sweep": max(feasible) if feasible else None,
            "lemma7_min_gain": lemma7_min_gain(self.speed, self.beta),
        }


def default_sweep(beta: float, count: int = 30) -> np.ndarray:
    """``count`` betas log-spaced over two decades around ``beta``, clipped to beta's range
    [1e-9, 1e3] 1/m (tune_beta's sweep when none is given)."""
    beta = schema.beta("beta", beta)
    return np.geomspace(max(beta / 10, _limits.MIN_GAIN), min(beta * 10, _limits.MAX_BETA), count)


def tune_beta(radius: float, radius_rate: float, speed: float, poi_speed: float, min_turn_radius: float,
              beta: float, sweep: Optional[Sequence[float]] = None, *, tau: float = 1.0,
              r_max_factor: float = 4.0, direction: str = "ccw",
              progress: Callable[[int, int], None] | None = None) -> BetaTuning:
    """The grid search of Figure 9 at ``beta`` and over ``sweep`` (default: 30 betas log-spaced over
    two decades around ``beta``, within beta's range [1e-9, 1e3] 1/m). ``progress(done, total)``
    is called after each beta. Every beta is checked before the first search."""
    if not (min_turn_radius > 0 and np.isfinite(min_turn_radius)):
        raise VistrackError(f"min_turn_radius = {min_turn_radius}: must be a finite number > 0")
    beta = schema.beta("beta", beta)
    if sweep is None:
        betas = default_sweep(beta)
    else:
        betas = np.asarray([schema.beta(f"sweep[{k}]", b) for k, b in enumerate(sweep)], dtype=float)

    def search(b: float) -> TuningResult:
        return tune_turn_rate(radius, radius_rate, speed, poi_speed, b, direction=direction, tau=tau,
                              r_max_factor=r_max_factor)

    tuning = BetaTuning(radius, radius_rate, speed, poi_speed, min_turn_radius, beta, tau, search(beta))
    tuning.betas = [float(b) for b in betas]
    for k, b in enumerate(tuning.betas):
        tuning.sweep_max_turn_rate.append(search(b).max_turn_rate)
        if progress is not None:
            progress(k + 1, len(tuning.betas))
    return tuning
