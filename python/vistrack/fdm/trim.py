"""Trim in straight and level flight at a given airspeed and altitude.

``newton`` (the project's aircraft, whose thrust is not a JSBSim engine): Newton's method on the
angle of attack, elevator and throttle until the model's udot, wdot and qdot vanish with the
flight-path angle held at zero, each evaluation one ``run_ic`` of JSBSim itself (finite-difference
Jacobian). ``jsbsim``: JSBSim's own trim (``simulation/do_simple_trim`` = 1, full trim).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._core import VistrackError
from .model import JsbsimModel


@dataclass(frozen=True)
class Trim:
    """The trimmed condition: commands (normalised) and attitude."""

    elevator: float
    throttle: float
    alpha: float  # rad
    theta: float  # rad
    residual: float  # largest |udot|, |wdot| (ft/s^2) or |qdot| (rad/s^2) left


def _evaluate(model: JsbsimModel, airspeed: float, u: np.ndarray) -> np.ndarray:
    model.set_initial(airspeed, alpha=float(u[0]))
    model.set_controls(0.0, float(u[1]), 0.0, float(u[2]))
    model.run_ic()
    return np.array(model.accelerations())


def _newton(model: JsbsimModel, airspeed: float) -> Trim:
    u = np.array([0.1, 0.0, 0.5])  # alpha (rad), elevator, throttle
    steps = np.array([1e-4, 1e-4, 1e-4])
    residual = _evaluate(model, airspeed, u)
    for _ in range(30):
        if np.max(np.abs(residual)) < 1e-6:
            break
        jac = np.empty((3, 3))
        for k in range(3):
            du = u.copy()
            du[k] += steps[k]
            jac[:, k] = (_evaluate(model, airspeed, du) - residual) / steps[k]
        try:
            delta = np.linalg.solve(jac, -residual)
        except np.linalg.LinAlgError:
            break
        delta *= min(1.0, 0.2 / max(abs(delta[0]), 1e-12))  # at most 0.2 rad of alpha per step
        u = u + delta
        residual = _evaluate(model, airspeed, u)
    worst = float(np.max(np.abs(residual)))
    in_range = -1.0 <= u[1] <= 1.0 and 0.0 <= u[2] <= 1.0
    if worst > 1e-3 or not in_range:
        raise VistrackError(f"trim of {model.aircraft.name!r} at {airspeed:g} m/s failed: residual {worst:.3g}, "
                            f"elevator {u[1]:.3f}, throttle {u[2]:.3f} (controls saturate: outside the envelope)")
    theta = model.fdm["attitude/theta-rad"]
    return Trim(elevator=float(u[1]), throttle=float(u[2]), alpha=float(u[0]), theta=theta, residual=worst)


def _jsbsim_trim(model: JsbsimModel, airspeed: float) -> Trim:
    f = model.fdm
    model.set_initial(airspeed, alpha=0.05)
    f["propulsion/set-running"] = -1  # every engine running
    model.run_ic()
    try:
        f["simulation/do_simple_trim"] = 1
    except Exception as exc:  # JSBSim raises its own TrimFailureError
        raise VistrackError(f"trim of {model.aircraft.name!r} at {airspeed:g} m/s failed: {exc}") from exc
    elevator, throttle, _ = model.controls()
    worst = float(np.max(np.abs(model.accelerations())))
    return Trim(elevator=elevator, throttle=throttle, alpha=f["aero/alpha-rad"], theta=f["attitude/theta-rad"],
                residual=worst)


def trim(model: JsbsimModel, airspeed: float) -> Trim:
    """Trim ``model`` in level flight at ``airspeed`` (m/s) at its start altitude and heading; the model
    is left at that condition with the trim's commands. VistrackError when no trim exists."""
    method = model.aircraft.trim
    if method == "newton":
        return _newton(model, airspeed)
    if method == "jsbsim":
        return _jsbsim_trim(model, airspeed)
    raise VistrackError(f"aircraft {model.aircraft.name!r}: trim = {method!r}, expected 'newton' or 'jsbsim'")
