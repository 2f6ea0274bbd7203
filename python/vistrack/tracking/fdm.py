"""The tracking closed loop flown on a 6-DOF JSBSim aircraft (``vistrack.fdm``).

The guidance is the same as the kinematic closed loop's: the orbit of the plan at t
(``orbit_state`` on the segment of ``segment_boundaries``), the vector field (74) and the steering
law (86) (``steering``), with the gains ``GuidanceGains.from_parameters`` gives the roll model (its
heading gain capped at half the roll loop's bandwidth: the autopilot's roll loop is the inner loop
here too). It runs at the aircraft's guidance rate; the autopilot and JSBSim fly the rest. The POI
is in view when the segment from the aircraft (at its flown altitude) to the POI lifted onto the
surface is unobstructed, at every guidance sample.
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass
from typing import Any, Optional, Union

import numpy as np

from .._core import (
    Control,
    GuidanceGains,
    OrbitPlan,
    Uav,
    VisibilityOrbitPlan,
    VisibilityScene,
    orbit_state,
    segment_boundaries,
    steering,
)
from ..fdm import FdmTrajectory, fly
from ..flight import Wind, flight_smoothness
from ..scenario_blocks import with_dynamics

AnyPlan = Union[OrbitPlan, VisibilityOrbitPlan]

__all__ = ["TrackingFdm", "TrackingGuidance", "fly_tracking", "tracking_fdm_metrics"]


class TrackingGuidance:
    """Vector field (74) and steering law (86) around the plan's orbit at t: a ``vistrack.fdm`` Guidance."""

    def __init__(self, plan: AnyPlan, uav: Uav, control: Control):
        self.plan = plan
        self.gains = GuidanceGains.from_parameters(with_dynamics(uav, "roll"), control)
        self.boundaries = list(segment_boundaries(plan))
        self.done = False
        self.radial_error: list[float] = []

    def turn_rate(self, t: float, x: float, y: float, psi: float) -> float:
        b = self.boundaries
        i = min(max(bisect.bisect_right(b, t) - 1, 0), len(b) - 2)
        s = steering(np.array([x, y, psi]), orbit_state(self.plan, b[i], t), self.gains)
        self.radial_error.append(s.field.radial_error)
        return float(s.command)

    def advance(self, t: float, x: float, y: float, psi: float) -> None:
        pass


@dataclass
class TrackingFdm:
    """A 6-DOF tracking flight: the trajectory, the radial error and line of sight at its samples."""

    trajectory: FdmTrajectory
    radial_error: np.ndarray
    visible: np.ndarray
    poi: np.ndarray  # (n, 3) POI on the surface

    @property
    def visibility_fraction(self) -> float:
        return float(np.mean(self.visible))


def fly_tracking(plan: AnyPlan, x0: np.ndarray, uav: Uav, control: Control, scene: Optional[VisibilityScene],
                 aircraft: str, wind: Optional[Wind] = None) -> TrackingFdm:
    """Fly the plan from ``x0`` = (x, y, psi) on ``aircraft`` at the UAV's speed and altitude; the plan's
    turn radius (``uav.min_turn_radius``) and speed are checked against the aircraft's envelope."""
    guidance = TrackingGuidance(plan, uav, control)
    t0, t1 = guidance.boundaries[0], guidance.boundaries[-1]
    traj = fly(guidance, (float(x0[0]), float(x0[1]), float(x0[2])), speed=uav.speed, altitude=uav.altitude,
               duration=t1 - t0, turn_radius=uav.min_turn_radius, aircraft=aircraft, wind=wind, t0=t0)
    poi = np.array([plan.poi.position(float(t)) for t in traj.t])
    visible = np.ones(len(traj.t), dtype=bool)
    if scene is not None:
        poi = np.asarray(scene.poi_on_surface(poi))
        uav_points = np.column_stack([traj.x, traj.y, traj.altitude])
        visible = np.asarray(scene.line_of_sight(uav_points, poi), dtype=bool)
    radial = np.asarray(guidance.radial_error[:len(traj.t)])
    return TrackingFdm(traj, radial, visible, poi)


def tracking_fdm_metrics(run: TrackingFdm, converge_after: float) -> dict[str, Any]:
    """metrics.json's ``fdm`` block of a tracking run: its ``simulation`` mirrors the kinematic one's keys
    that a 6-DOF flight has, beside the aircraft and the altitude and airspeed errors."""
    traj = run.trajectory
    t = traj.t
    late = t >= min(t[0] + converge_after, t[-1])
    return {
        "aircraft": traj.aircraft,
        "altitude_error_max_m": traj.altitude_error_max,
        "airspeed_error_max_m_s": traj.airspeed_error_max,
        "trim": {"alpha_rad": traj.trim.alpha, "elevator": traj.trim.elevator, "throttle": traj.trim.throttle},
        "seconds": traj.seconds,
        "real_time_factor": float((t[-1] - t[0]) / traj.seconds) if traj.seconds > 0 else None,
        "simulation": {
            "duration_s": float(t[-1] - t[0]),
            "samples": len(t),
            "initial_radial_error_m": float(run.radial_error[0]),
            "converge_after_s": float(converge_after),
            "radial_error_after_mean_m": float(np.mean(run.radial_error[late])),
            "radial_error_after_max_abs_m": float(np.max(np.abs(run.radial_error[late]))),
            "visibility_fraction": run.visibility_fraction,
            "smoothness": flight_smoothness(t, traj.bank).as_dict(),
        },
    }
