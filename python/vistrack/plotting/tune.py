"""Controller tuning figure (section V.D, Figure 9): the turn rate the guidance needs around an
orbit at the chosen beta, and its maximum against beta."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..tracking.tuning import BetaTuning
from .common import pyplot, save_figure


def figure_tuning(tuning: BetaTuning, path: str | Path) -> Path:
    """Left: max over heading errors of |dpsi_d/dt + u_lyap| around the orbit at tuning.beta (polar
    map about the POI, moving along +x). Right: its maximum against beta, with v / r_min."""
    chosen, limit = tuning.chosen, tuning.turn_rate_limit
    betas, sweep = tuning.betas, tuning.sweep_max_turn_rate
    plt = pyplot()

    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(12, 5.2))
    radii, angles = np.asarray(chosen.radii), np.asarray(chosen.angles)
    a = np.append(angles, angles[0] + 2 * math.pi)
    value = np.concatenate([chosen.map, chosen.map[:, :1]], axis=1)
    rr, aa = np.meshgrid(radii, a, indexing="ij")
    mesh = ax0.pcolormesh(rr * np.cos(aa), rr * np.sin(aa), value, shading="gouraud", cmap="magma")
    fig.colorbar(mesh, ax=ax0, label="max over heading error of |dpsi_d/dt + u_lyap| (rad/s)")
    t = np.linspace(0, 2 * math.pi, 200)
    ax0.plot(tuning.radius * np.cos(t), tuning.radius * np.sin(t), "c--", lw=1, label="orbit R")
    ax0.annotate("", xy=(0.6 * tuning.radius, 0), xytext=(0, 0), arrowprops={"arrowstyle": "->", "color": "w"})
    ax0.plot(chosen.at_r * math.cos(chosen.at_theta), chosen.at_r * math.sin(chosen.at_theta), "wx", ms=9,
             label=f"max {chosen.max_turn_rate:.3f} rad/s")
    ax0.set_aspect("equal")
    ax0.set_xlabel("x relative to the POI (m), POI moving along +x")
    ax0.set_ylabel("y (m)")
    ax0.set_title(f"beta = {tuning.beta:g}, R = {tuning.radius:g} m, dR/dt = {tuning.radius_rate:g} m/s,\n"
                  f"v = {tuning.speed:g} m/s, v_g = {tuning.poi_speed:g} m/s, r >= {tuning.tau:g} R", fontsize=10)
    ax0.legend(fontsize=8, loc="upper right")
    ax1.loglog(betas, sweep, "o-", ms=3, label="max |dpsi_d/dt + u_lyap| over r >= tau R")
    ax1.axhline(limit, color="r", ls="--", label=f"v / r_min = {limit:.3g} rad/s")
    ax1.axvline(tuning.beta, color="0.5", ls=":", label=f"beta = {tuning.beta:g}")
    ax1.set_xlabel("beta")
    ax1.set_ylabel("rad/s")
    ax1.set_title("Turn rate needed against beta")
    ax1.grid(alpha=0.3, which="both")
    ax1.legend(fontsize=8)
    fig.tight_layout()
    return save_figure(fig, path, dpi=130)
