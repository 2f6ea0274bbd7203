"""Figure 7 of the target-intercept paper: travel times against the arrival angle, and the
interception path."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from .._core.dubins import InterceptResult
from ..intercept import InterceptProblem
from .common import pyplot, save_figure


def figure_intercept(problem: InterceptProblem, result: InterceptResult, out: Path) -> list[Path]:
    """Figure 7 of the intercept paper: (a) the travel times of target and pursuer against the
    arrival angle, (b) the interception path on the plane. Returns the two PNG paths."""
    plt = pyplot()

    # (a) travel times against the target's angular position, a little past the interception.
    swept = np.linspace(0.0, max(result.swept_angle * 1.25, result.swept_angle + math.pi / 2), 1500)
    angles, t_pursuer, t_target = problem.travel_times(swept)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.plot(angles, t_pursuer, label=r"pursuer $T_p(\alpha) = D(\alpha)/v_p$")
    ax.plot(angles, t_target, label=r"target $T_t(\alpha)$")
    ax.plot([result.angle], [result.time], "ko", label=rf"$\alpha^*$ = {result.angle:.4f} rad, T = {result.time:.4f} s")
    ax.set_xlabel(r"angular position on the target circle $\alpha$ (rad)")
    ax.set_ylabel("travel time (s)")
    ax.set_title("Travel times of the target and the pursuer (Fig. 7a)")
    if problem.direction == "cw":
        ax.invert_xaxis()  # the target moves towards decreasing alpha
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    times_png = save_figure(fig, out / "fig7a_travel_times.png", dpi=130)

    # (b) the interception path on the plane.
    path = result.path
    samples = path.sample(max(path.length / 400.0, 1e-6))
    cx, cy = problem.center
    r = problem.radius
    sign = -1.0 if problem.direction == "cw" else 1.0
    circle = np.linspace(0.0, 2.0 * math.pi, 400)
    travelled = problem.target_angle0 + sign * np.linspace(0.0, result.swept_angle, 400)
    fig, ax = plt.subplots(figsize=(6.0, 6.0))
    ax.plot(cx + r * np.cos(circle), cy + r * np.sin(circle), color="0.6", lw=1, label="target circle")
    ax.plot(cx + r * np.cos(travelled), cy + r * np.sin(travelled), color="tab:orange", lw=2.5,
            label=f"target travel ({result.swept_angle / (2.0 * math.pi):.2f} laps)")
    ax.plot(samples[:, 0], samples[:, 1], color="tab:blue", lw=2,
            label=f"pursuer path ({path.word}, {path.length:.3f} m)")
    x0, y0, psi0 = problem.pursuer
    ax.annotate("", xy=(x0 + 0.6 * math.cos(psi0), y0 + 0.6 * math.sin(psi0)), xytext=(x0, y0),
                arrowprops={"arrowstyle": "->", "color": "tab:blue", "lw": 1.5})
    ax.plot([x0], [y0], "s", color="tab:blue", label="pursuer start")
    a0 = problem.target_angle0
    ax.plot([cx + r * math.cos(a0)], [cy + r * math.sin(a0)], "o", color="tab:orange", label="target start")
    gx, gy, _ = path.goal
    ax.plot([gx], [gy], "k*", ms=12, label="interception")
    ax.set_aspect("equal")
    ax.grid(True, alpha=0.3)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title("Path of the pursuer intercepting the target (Fig. 7b)")
    ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    path_png = save_figure(fig, out / "fig7b_path.png", dpi=130)
    return [times_png, path_png]
