"""Reference closed loop in numpy + scipy.integrate.solve_ivp (RK45), independent of vistrack's C++.

The right-hand side is the Dubins vehicle (1) steered by (86) with the vector field (74), the
desired heading rate (85) and the Lyapunov term, written directly from the paper's equations
(with g_dot, not g, in the Lyapunov term; see Lemma 7). Segments where dR/dt or the POI velocity
jump are integrated one after the other, as vistrack does. Used by bench/simulate_bench.py and
as a test oracle by tests/python/test_simulate.py.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp


@dataclass
class Segment:
    start: float
    center: np.ndarray  # g at start
    center_velocity: np.ndarray  # g_dot
    radius: float  # R at start
    radius_rate: float  # dR/dt


def path_node_times(waypoints: np.ndarray, speed: float) -> np.ndarray:
    steps = np.linalg.norm(np.diff(waypoints[:, :2], axis=0), axis=1)
    return np.concatenate([[0.0], np.cumsum(steps) / speed])


def poi_position(waypoints: np.ndarray, node_times: np.ndarray, t: float) -> np.ndarray:
    t = min(max(t, 0.0), node_times[-1])
    i = min(int(np.searchsorted(node_times, t, side="right")) - 1, len(node_times) - 2)
    s = (t - node_times[i]) / (node_times[i + 1] - node_times[i])
    return (1 - s) * waypoints[i, :2] + s * waypoints[i + 1, :2]


def poi_velocity(waypoints: np.ndarray, node_times: np.ndarray, speed: float, t: float) -> np.ndarray:
    i = min(max(int(np.searchsorted(node_times, t, side="right")) - 1, 0), len(node_times) - 2)
    d = waypoints[i + 1, :2] - waypoints[i, :2]
    return speed * d / np.linalg.norm(d)


def plan_segments(times, radii, waypoints, speed) -> tuple[list[Segment], list[float]]:
    """Segments between plan samples and path nodes, and the boundary times."""
    times = np.asarray(times, float)
    radii = np.asarray(radii, float)
    nodes = path_node_times(waypoints, speed)
    t0, t1 = times[0], min(times[-1], nodes[-1])
    cuts = sorted(set([t0, t1] + [t for t in list(times) + list(nodes) if t0 < t < t1]))
    merged = [cuts[0]]
    for t in cuts[1:]:
        if t - merged[-1] > 1e-9 * max(1.0, t1 - t0):
            merged.append(t)
    merged[-1] = t1
    segments = []
    for a in merged[:-1]:
        k = min(int(np.searchsorted(times, a, side="right")) - 1, len(times) - 2)
        rate = (radii[k + 1] - radii[k]) / (times[k + 1] - times[k])
        radius = radii[k] + rate * (a - times[k])
        segments.append(Segment(a, poi_position(waypoints, nodes, a), poi_velocity(waypoints, nodes, speed, a),
                                radius, rate))
    return segments, merged


def make_rhs(segment: Segment, v: float, beta: float, k_psi: float, direction: int, max_turn_rate: float):
    gdot = segment.center_velocity
    vg = float(np.linalg.norm(gdot))
    rdot = segment.radius_rate
    margin = max(0.0, v - vg - abs(rdot))

    def rhs(t: float, q: np.ndarray) -> np.ndarray:
        dt = t - segment.start
        g = segment.center + gdot * dt
        radius = segment.radius + rdot * dt
        d = q[:2] - g
        r = np.hypot(d[0], d[1])
        e_r = d / r
        e_t = np.array([-e_r[1], e_r[0]])
        rt = r - radius
        at = np.arctan(beta * rt)
        phi = margin * 2.0 / np.pi * at  # (70)
        u_r = -phi + rdot + gdot @ e_r  # (74)
        u_t = direction * np.sqrt(max(0.0, v * v - u_r * u_r))
        u = u_r * e_r + u_t * e_t
        psi_d = np.arctan2(u[1], u[0])  # (77)
        phi_dot = -(4.0 / np.pi**2) * at * beta * margin**2 / (1.0 + (beta * rt) ** 2)  # (83)
        theta_dot = (u_t - gdot @ e_t) / r  # (84)
        psi_d_dot = (phi_dot + r * theta_dot**2) / u_t  # (85)
        e = (q[2] - psi_d + np.pi) % (2 * np.pi) - np.pi  # short way round
        if e == -np.pi:
            e = np.pi
        k = beta * 2.0 / np.pi * at / (1.0 + (beta * rt) ** 2)
        if e == 0.0:
            lyap = k * u_t
        else:
            lyap = k * ((gdot @ e_r + rdot) * (1 - np.cos(e)) / e + u_t * np.sin(e) / e)  # (86)
        u_psi = np.clip(-k_psi * e + psi_d_dot + lyap, -max_turn_rate, max_turn_rate)
        return np.array([v * np.cos(q[2]), v * np.sin(q[2]), u_psi])

    return rhs


def simulate_reference(times, radii, waypoints, poi_speed, x0, *, speed, min_turn_radius, beta, k_psi,
                       direction="ccw", rtol=1e-6, atol=1e-8, max_step=1.0, output_step=0.1):
    """The closed loop by solve_ivp(RK45) per segment. Returns (t, states (n, 3), rhs evaluations)."""
    waypoints = np.asarray(waypoints, float)
    segments, cuts = plan_segments(times, radii, waypoints, poi_speed)
    sign = 1 if direction == "ccw" else -1
    t0, t1 = cuts[0], cuts[-1]
    count = math.floor((t1 - t0) / output_step + 1e-9)
    outputs = [t0 + k * output_step for k in range(count + 1)]
    if t1 - outputs[-1] > 1e-9 * output_step:
        outputs.append(t1)
    else:
        outputs[-1] = t1
    outputs = np.array(outputs)
    y = np.asarray(x0, float)
    ts, ys, nfev = [], [], 0
    for segment, a, b in zip(segments, cuts[:-1], cuts[1:]):
        rhs = make_rhs(segment, speed, beta, k_psi, sign, speed / min_turn_radius)
        inside = outputs[(outputs >= a) & (outputs <= b)]
        if ts:
            inside = inside[inside > a]
        t_eval = inside if len(inside) and inside[-1] == b else np.append(inside, b)
        sol = solve_ivp(rhs, (a, b), y, method="RK45", rtol=rtol, atol=atol, max_step=max_step, t_eval=t_eval)
        if not sol.success:
            raise RuntimeError(sol.message)
        nfev += sol.nfev
        keep = len(inside)
        ts.extend(sol.t[:keep])
        ys.extend(sol.y.T[:keep])
        y = sol.y[:, -1]
    return np.array(ts), np.array(ys), nfev
