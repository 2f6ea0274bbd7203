"""Orbit planning figures (section IV): Figure 4 (the XOR metric along the path), Figure 5 (orbits
inside their visibility polygons) and R(t) against its rate limits."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Mapping, Optional, Union

import numpy as np

from .._core import Discretization, Environment, VisibilityOrbitPlan
from .city import plot_buildings
from .common import OSM_CREDIT, add_credit, evenly_spaced_indices, pyplot, save_figure


def figure_metric(results: Mapping[str, Union[Discretization, VisibilityOrbitPlan]], cutoff: float,
                  path: str | Path, title: str = "", credit: Optional[str] = OSM_CREDIT) -> Path:
    """Figure 4: the XOR metric (56) between neighbouring VVs against distance along the path."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for label, d in results.items():
        s = np.asarray(d.arc_lengths)
        if len(s) < 2:
            continue
        mid = 0.5 * (s[1:] + s[:-1])
        style = {"lw": 2.2, "color": "purple"} if label == "adaptive" else {"lw": 1.2}
        ax.plot(mid, np.asarray(d.metric), marker=".", ms=3, label=f"{label} ({len(s)} VVs)", **style)
    ax.axhline(cutoff, color="k", ls="--", lw=1, label=f"cutoff {cutoff:.3g} m$^3$")
    ax.set_xlabel("distance along the POI path (m)")
    ax.set_ylabel("XOR volume between neighbouring VVs (m$^3$)")
    ax.set_title(title or "VV difference metric (eq. 56) along the path")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    add_credit(fig, credit)
    fig.tight_layout()
    return save_figure(fig, path, dpi=130)


def figure_orbits(plan: VisibilityOrbitPlan, env: Optional[Environment], path: str | Path, count: int = 4,
                  credit: Optional[str] = OSM_CREDIT) -> Path:
    """Figure 5: orbit circles inside their VPs at h_UAV, over the building footprints."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 7.5))
    centres = np.asarray(plan.centers)
    picked = evenly_spaced_indices(len(plan.times), count)
    colors = plt.cm.plasma(np.linspace(0.0, 0.85, len(picked)))
    reach = max([max(plan.max_radii) if len(plan.max_radii) else 0.0, plan.sensor.d_max * 0.3])
    lo = centres.min(axis=0) - reach - 20
    hi = centres.max(axis=0) + reach + 20
    if env is not None:
        plot_buildings(ax, env, cmap="Blues", edgecolor="none")
    way = np.asarray(plan.poi.waypoints)
    ax.plot(way[:, 0], way[:, 1], color="gray", lw=1, label="POI path")
    theta = np.linspace(0, 2 * math.pi, 200)
    for color, k in zip(colors, picked):
        for poly in plan.polygons[k]:
            ring = np.vstack([poly.outer, poly.outer[:1]])
            ax.plot(ring[:, 0], ring[:, 1], color=color, ls="--", lw=1)
            for hole in poly.holes:
                h = np.vstack([hole, hole[:1]])
                ax.plot(h[:, 0], h[:, 1], color=color, ls=":", lw=0.8)
        c = centres[k]
        r = plan.radii[k]
        ax.plot(c[0] + r * np.cos(theta), c[1] + r * np.sin(theta), color=color, lw=2,
                label=f"t = {plan.times[k]:.1f} s, R = {r:.1f} m")
        ax.plot(c[0], c[1], "x", color=color, ms=9, mew=2)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    status = "feasible" if plan.feasible else "INFEASIBLE"
    ax.set_title(f"Orbits inside their VPs at h_UAV = {plan.uav.altitude:g} m ({status})")
    ax.legend(fontsize=8, loc="upper right")
    add_credit(fig, credit)
    fig.tight_layout()
    return save_figure(fig, path, dpi=130)


def figure_radius(plan: VisibilityOrbitPlan, path: str | Path) -> Path:
    """R(t) the guidance follows against MaxRadius (at the samples, and along the path for the
    smooth locus), Algorithm 1's piecewise-linear R(t) and Lemma 6's threshold; dR/dt against
    Lemma 5's bound; d2R/dt2 of the smooth locus."""
    plt = pyplot()
    t = np.asarray(plan.times)
    smooth = plan.planning.locus == "smooth"
    rate_limit = plan.uav.speed - plan.poi.speed
    dense = np.linspace(t[0], t[-1], 2000) if len(t) > 1 else t
    fig, axes = plt.subplots(3 if smooth else 2, 1, figsize=(8, 8 if smooth else 6), sharex=True,
                             gridspec_kw={"height_ratios": [2, 1, 1] if smooth else [2, 1]})
    ax, bx = axes[0], axes[1]
    if smooth and len(plan.check.times):
        c = plan.check
        ax.plot(c.times, c.max_radii, "-", lw=0.8, color="tab:gray", label="MaxRadius along the path (locus check)")
        breaks = np.asarray(c.ceiling.breaks)
        nan = np.full(len(breaks) - 1, np.nan)
        x = np.column_stack([breaks[:-1], breaks[1:], nan]).ravel()
        y = np.column_stack([c.ceiling.starts, c.ceiling.ends, nan]).ravel()
        ax.plot(x, y, color="tab:orange", lw=0.8,
                label=f"ceiling: lower bound of MaxRadius - {plan.planning.tracking_margin:g} m")
    ax.plot(t, plan.max_radii, "o", ms=3, color="tab:gray", label="MaxRadius at the samples")
    if smooth:
        ax.plot(t, plan.orbits.radii, "--", lw=1, color="tab:green", label="Algorithm 1 (the paper's locus)")
    ax.plot(dense, plan.radius_at(dense), "-", lw=2, color="tab:blue",
            label="R(t) followed (smooth locus)" if smooth else "R(t) after Algorithm 1")
    ax.axhline(plan.min_feasible_radius, color="tab:red", ls="--",
               label=f"r_min (1 + v_g/v)$^2$ = {plan.min_feasible_radius:.1f} m (Lemma 6)")
    for k in plan.failing_samples:
        ax.plot(t[k], plan.radii[k], "rx", ms=8, mew=2)
    ax.set_ylabel("orbit radius (m)")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    if len(t) > 1:
        if smooth:
            rates = np.asarray(plan.orbits.radius_rates)
            bx.step(np.r_[t[:-1], t[-1]], np.r_[rates, rates[-1]], where="post", color="tab:green", lw=0.8,
                    label="dR/dt of Algorithm 1")
        bx.plot(dense, plan.radius_rate_at(dense), color="tab:blue", label="dR/dt followed")
        bx.axhline(rate_limit, color="tab:red", ls="--", label=f"±(v − v_g) = ±{rate_limit:g} m/s (Lemma 5)")
        bx.axhline(-rate_limit, color="tab:red", ls="--")
        bx.legend(fontsize=7)
    bx.set_ylabel("dR/dt (m/s)")
    bx.grid(alpha=0.3)
    if smooth:
        cx = axes[2]
        cx.plot(dense, plan.reference.acceleration_at(dense), color="tab:blue", lw=1)
        cx.set_ylabel("d$^2$R/dt$^2$ (m/s$^2$)")
        cx.grid(alpha=0.3)
    axes[-1].set_xlabel("time (s)")
    fig.suptitle(f"R(t): {plan.radii[0]:.1f} m → {plan.radii[-1]:.1f} m over {t[-1]:.2f} s "
                 f"({plan.planning.locus} locus)")
    fig.tight_layout()
    return save_figure(fig, path, dpi=130)
