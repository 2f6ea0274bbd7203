"""Closed-loop figures (section VI): Figure 10 (the UAV's path with its reference orbits) and
Figure 11 (radial error, heading error and control against time)."""

from __future__ import annotations

import itertools
import math
from pathlib import Path
from typing import Optional, Sequence, Union

import numpy as np

from .._core import Environment, OrbitPlan, SimulationResult, VisibilityOrbitPlan
from .city import plot_buildings
from .common import OSM_CREDIT, add_credit, evenly_spaced_indices, plot_bank, pyplot, save_figure

Run = tuple[str, Union[OrbitPlan, VisibilityOrbitPlan], SimulationResult]  # (label, plan, result)


def figure_trajectory(runs: Sequence[Run], env: Optional[Environment], path: str | Path, title: str = "",
                      orbit_count: int = 8, credit: Optional[str] = OSM_CREDIT) -> Path:
    """Figure 10 style: each run's UAV path (label, plan, result) with its orbits and the POI path."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(8, 8))
    _label0, plan0, result0 = runs[0]
    everything = np.vstack([np.asarray(r.state)[:, :2] for _, _, r in runs] + [np.asarray(result0.poi)[:, :2]])
    lo = everything.min(axis=0) - 30
    hi = everything.max(axis=0) + 30
    if env is not None:
        plot_buildings(ax, env, cmap="Greys", edgecolor="none")
    poi = np.asarray(result0.poi)
    ax.plot(poi[:, 0], poi[:, 1], color="0.3", ls="--", lw=1.2, label="POI path")
    theta = np.linspace(0, 2 * math.pi, 181)
    times = np.asarray(plan0.times)
    picked = evenly_spaced_indices(len(times), orbit_count)
    centers = np.asarray(plan0.centers)
    polygons = getattr(plan0, "polygons", None)  # visibility polygons when the plan carries them
    for n, k in enumerate(picked):
        c, r = centers[k], plan0.radii[k]
        ax.plot(c[0] + r * np.cos(theta), c[1] + r * np.sin(theta), color="k", ls="--", lw=0.9,
                label="reference orbits" if n == 0 else None)
        if polygons is not None:
            for poly in polygons[k]:
                ring = np.vstack([poly.outer, poly.outer[:1]])
                ax.plot(ring[:, 0], ring[:, 1], color="green", ls="--", lw=0.8,
                        label="visibility polygons" if (n == 0 and poly is polygons[k][0]) else None)
    colors = ["red", "tab:blue", "tab:orange", "tab:purple", "tab:brown"]
    for (label, _, result), color in zip(runs, itertools.cycle(colors)):
        s = np.asarray(result.state)
        text = label
        if result.visibility_fraction is not None:
            text += f" (visible {100 * result.visibility_fraction:.1f}%)"
        ax.plot(s[:, 0], s[:, 1], color=color, lw=1.4, label=text)
        ax.plot(s[0, 0], s[0, 1], "o", color=color, ms=6)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    ax.set_title(title or "UAV tracking the POI")
    ax.legend(fontsize=8, loc="best")
    add_credit(fig, credit if env is not None else None)
    fig.tight_layout()
    return save_figure(fig, path, dpi=130)


def figure_errors(result: SimulationResult, path: str | Path, window: Optional[float] = None, title: str = "",
                  max_turn_rate: Optional[float] = None) -> Path:
    """Figure 11 style: radial error, heading and its error, control and the bank flown against time."""
    plt = pyplot()
    t = np.asarray(result.t)
    keep = t <= (t[0] + window) if window else np.ones_like(t, bool)
    fig, axes = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    axes[0].plot(t[keep], np.asarray(result.radial_error)[keep], color="tab:blue")
    axes[0].set_ylabel("radial error r - R (m)")
    psi = (np.asarray(result.state)[:, 2] + math.pi) % (2 * math.pi) - math.pi
    desired = np.asarray(result.desired_heading, float).copy()
    # Break the lines where an angle wraps from pi to -pi instead of drawing a vertical stroke.
    psi[1:][np.abs(np.diff(psi)) > math.pi] = np.nan
    desired[1:][np.abs(np.diff(desired)) > math.pi] = np.nan
    axes[1].plot(t[keep], psi[keep], color="0.5", lw=1, label="heading psi")
    axes[1].plot(t[keep], desired[keep], color="k", ls="--", lw=1, label="desired psi_d")
    axes[1].plot(t[keep], np.asarray(result.heading_error)[keep], color="tab:red", lw=1.2, label="error psi - psi_d")
    axes[1].set_ylabel("heading (rad)")
    axes[1].legend(fontsize=8, loc="upper right")
    axes[2].plot(t[keep], np.asarray(result.control)[keep], color="tab:green", label="u_psi applied")
    if max_turn_rate:
        for sign in (1, -1):
            axes[2].axhline(sign * max_turn_rate, color="0.4", ls=":", lw=1)
    axes[2].set_ylabel("control u_psi (rad/s)")
    plot_bank(axes[3], t[keep], np.asarray(result.bank)[keep])
    axes[3].set_xlabel("time (s)")
    for t_restart in np.asarray(result.restart_times)[1:-1]:
        if t_restart <= t[keep][-1]:
            for ax in axes:
                ax.axvline(t_restart, color="0.85", lw=0.6, zorder=0)
    for ax in axes:
        ax.grid(alpha=0.3)
    axes[0].set_title(title or "Errors and control (grey lines: orbit segment boundaries)")
    fig.tight_layout()
    return save_figure(fig, path, dpi=130)
