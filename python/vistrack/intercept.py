"""Optimal interception of a target moving on a circle (Manyam et al., Algorithm 1) as a problem
read from a YAML file and flags, solved by the Dubins core, and recorded as plain data.

The defaults are the paper's test scenario: pursuer at the origin heading 0, target circle
centred at (-4, 3) of radius 1, target starting at alpha_i = pi, speeds 1 and 1.2 m/s; the paper
takes rho equal to the circle radius.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, fields
from pathlib import Path
from typing import Any, Mapping, Optional

import numpy as np

from . import dubins
from .io.documents import read_yaml_mapping
from .schema import fail, number, reject_unknown

__all__ = ["InterceptProblem"]


@dataclass
class InterceptProblem:
    """One interception problem: the pursuer (x, y, psi, turn radius rho, speed) and the target
    on a circle (centre, radius, initial angle, speed, direction "cw" or "ccw")."""

    pursuer: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rho: float = 1.0
    pursuer_speed: float = 1.0
    center: tuple[float, float] = (-4.0, 3.0)
    radius: float = 1.0
    target_angle0: float = math.pi
    target_speed: float = 1.2
    direction: str = "cw"
    angle_tolerance: float = 1e-12

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any], where: str = "config") -> "InterceptProblem":
        """Defaults updated by ``data``; unknown keys and bad values name the key."""
        names = [f.name for f in fields(cls)]
        reject_unknown(data, names, f"{where}.")
        problem = cls()
        for key, value in data.items():
            if value is None:
                continue
            if key in ("pursuer", "center"):
                size = 3 if key == "pursuer" else 2
                if not isinstance(value, (list, tuple)) or len(value) != size:
                    raise fail(key, value, f"expected {size} numbers")
                setattr(problem, key, tuple(number(f"{key}[{i}]", v) for i, v in enumerate(value)))
            elif key == "direction":
                if value not in ("cw", "ccw"):
                    raise fail(key, value, 'must be "cw" or "ccw"')
                problem.direction = value
            else:
                setattr(problem, key, number(key, value))
        return problem

    @classmethod
    def load(cls, config: Optional[str | Path], overrides: Mapping[str, Any]) -> "InterceptProblem":
        """Defaults, then the YAML file ``config`` (when given), then the non-None ``overrides``."""
        data = read_yaml_mapping(config, "--config") if config is not None else {}
        data.update({k: v for k, v in overrides.items() if v is not None})
        return cls.from_mapping(data)

    def solve(self) -> dubins.InterceptResult:
        return dubins.intercept_circle(self.pursuer, self.rho, self.pursuer_speed, self.center, self.radius,
                                       self.target_angle0, self.target_speed, self.direction,
                                       angle_tolerance=self.angle_tolerance)

    def travel_times(self, swept: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(angles, pursuer times, target times) over the target's swept angles."""
        return dubins.intercept_travel_times(self.pursuer, self.rho, self.pursuer_speed, self.center, self.radius,
                                             self.target_angle0, self.target_speed, self.direction,
                                             [float(a) for a in swept])

    def record(self, result: dubins.InterceptResult) -> dict[str, Any]:
        """The problem, the interception and its path as plain data (intercept.json)."""
        sign = -1.0 if self.direction == "cw" else 1.0
        cx, cy = self.center
        # Where the target really is at the interception time (independent of the path's goal).
        target_angle = self.target_angle0 + sign * self.target_speed * result.time / self.radius
        path = result.path
        problem = asdict(self)
        problem["pursuer"], problem["center"] = list(self.pursuer), list(self.center)
        return {
            "problem": problem,
            "interception": {
                "angle": result.angle,
                "angle_mod_2pi": result.angle % (2.0 * math.pi),
                "swept_angle": result.swept_angle,
                "time": result.time,
                "pursuer_time": path.length / self.pursuer_speed,
                "residual": result.residual,
                "point": list(path.goal),
                "target_position_at_time": [cx + self.radius * math.cos(target_angle),
                                            cy + self.radius * math.sin(target_angle)],
            },
            "path": {"word": path.word, "segment_types": list(path.segment_types),
                     "segment_lengths": list(path.segment_lengths), "length": path.length},
            "four_rho_condition": result.four_rho_condition,
            "optimality": ("guaranteed (Proposition 1)" if result.four_rho_condition
                           else "feasible, not guaranteed optimal"),
            "period": result.period,
            "alpha_min": result.alpha_min,
            "bracket_windows": result.bracket_windows,
            "bisection_steps": result.bisection_steps,
        }
