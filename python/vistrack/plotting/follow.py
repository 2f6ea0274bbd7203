"""Figures of ground-vehicle following: the paths from above (the paper's Figures 5-9), the
scores over time, the planner beside the vector-field baseline, the city runs with line of
sight, and the speed ratio against the amplitude (the paper's Figure 2)."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional, Sequence

import numpy as np

from .._core import Environment
from ..follow import MODES, FollowResult, speed_ratio
from .city import plot_buildings
from .common import OSM_CREDIT, add_credit, plot_bank, pyplot, save_figure

MODE_COLORS = {"sinusoid": "tab:blue", "loiter": "tab:orange", "straight": "tab:red", "standoff": "tab:purple"}


def _segments_by(mask: np.ndarray) -> list[slice]:
    """The runs of consecutive True in mask, as slices (each extended by one sample so that the
    pieces join)."""
    edges = np.flatnonzero(np.diff(np.concatenate([[0], mask.astype(int), [0]])))
    return [slice(a, min(b + 1, len(mask))) for a, b in zip(edges[::2], edges[1::2])]


def plot_run(ax: Any, result: FollowResult, *, desired: bool = True, waypoints: bool = False,
             label: str = "UAV") -> None:
    """The vehicle's track, the UAV's path coloured by mode, and the planned path (dashed)."""
    ax.plot(result.vehicle[:, 0], result.vehicle[:, 1], color="tab:green", lw=3.0, alpha=0.7, label="vehicle",
            zorder=2)
    if desired:
        ax.plot(result.desired[:, 0], result.desired[:, 1], "--", color="0.45", lw=0.8, label="planned", zorder=3)
    if waypoints and len(result.waypoints):
        ax.plot(result.waypoints[:, 0], result.waypoints[:, 1], ".", color="0.3", ms=2.0, label="waypoints (1 Hz)",
                zorder=4)
    mode = result.mode
    for name in MODES:
        pieces = _segments_by(mode == name)
        for k, piece in enumerate(pieces):
            ax.plot(result.state[piece, 0], result.state[piece, 1], color=MODE_COLORS[name], lw=1.3, zorder=5,
                    label=f"{label}: {name}" if k == 0 else None)
    ax.plot(*result.vehicle[0], "o", color="tab:green", ms=6, zorder=6)
    ax.plot(*result.state[0, :2], "s", color="k", ms=5, zorder=6, label="start")
    ax.set_aspect("equal")
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    ax.grid(True, alpha=0.3)


def figure_paths(result: FollowResult, path: str | Path, title: str = "") -> Path:
    """The paper's view (Figures 5-9): vehicle, UAV path coloured by mode, planned path, waypoints."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(8.0, 8.0), constrained_layout=True)
    plot_run(ax, result, waypoints=True)
    m = result.metrics
    ax.set_title(f"{title}\ncamera sees the vehicle {100 * m['camera_fraction']:.1f} % of the time, "
                 f"tracking error {m['mean_tracking_error_m']:.1f} m mean", fontsize=10)
    ax.legend(loc="best", fontsize=7)
    return save_figure(fig, path)


def figure_scores(result: FollowResult, threshold: float, hysteresis: float, path: str | Path, title: str = "") -> Path:
    """Over time: speed ratio with the threshold's band, mode, tracking error and lag, and when the
    camera (and the line of sight) sees the vehicle, and the bank flown (the camera's tilt)."""
    plt = pyplot()
    fig, axes = plt.subplots(5, 1, figsize=(9.0, 11.0), sharex=True, constrained_layout=True)
    ticks = result.ticks
    t_ticks = np.array([k.t for k in ticks])
    sigma = np.array([min(k.speed_ratio, 1e6) for k in ticks])
    ax = axes[0]
    ax.plot(t_ticks, sigma, ".-", ms=2, lw=0.8, label="speed ratio sigma (per update)")
    ax.axhspan(threshold - hysteresis / 2, threshold + hysteresis / 2, color="tab:orange", alpha=0.2,
               label=f"hysteresis band about h = {threshold:g}")
    ax.axhline(1.0, color="tab:red", lw=0.8, ls=":", label="sigma = 1")
    ax.set_ylim(0.0, max(threshold * 2.0, 4.0))
    ax.set_ylabel("sigma")
    ax.legend(fontsize=7, loc="upper right")
    ax = axes[1]
    codes = np.array([MODES.index(m) for m in result.mode])
    ax.step(result.t, codes, where="post", color="k", lw=1.0)
    ax.set_yticks(range(len(MODES)), MODES)
    ax.set_ylabel("mode")
    ax = axes[2]
    ax.plot(result.t, np.asarray(result.run.tracking_error), lw=0.8, label="distance from the planned path")
    ax.plot(result.t, np.asarray(result.run.along_track_lag), lw=0.8, label="along-track lag")
    ax.set_ylabel("m")
    ax.legend(fontsize=7, loc="upper right")
    ax = axes[3]
    ax.fill_between(result.t, 0, result.in_view.astype(float), step="post", alpha=0.5, label="in the camera")
    if result.line_of_sight is not None:
        ax.fill_between(result.t, 0, -result.line_of_sight.astype(float), step="post", alpha=0.5, color="tab:purple",
                        label="line of sight (below)")
    ax.set_yticks([])
    ax.legend(fontsize=7, loc="upper right")
    plot_bank(axes[4], result.t, result.run.bank)
    axes[4].set_xlabel("t (s)")
    axes[0].set_title(title, fontsize=10)
    return save_figure(fig, path)


def figure_compare(runs: Sequence[tuple[str, FollowResult]], path: str | Path, title: str = "",
                   env: Optional[Environment] = None) -> Path:
    """Several runs side by side (the planner, the baseline, with and without compensation), over
    the city's buildings when given, each titled with its camera (and line-of-sight) fraction."""
    plt = pyplot()
    fig, axes = plt.subplots(1, len(runs), figsize=(6.5 * len(runs), 6.8), constrained_layout=True, squeeze=False)
    for ax, (name, result) in zip(axes[0], runs):
        if env is not None:
            plot_buildings(ax, env, cmap="Greys", vmax=env.max_height * 1.1)
        plot_run(ax, result, desired=result.strategy == "sinusoid")
        m = result.metrics
        text = f"{name}\ncamera {100 * m['camera_fraction']:.1f} %"
        if "line_of_sight_fraction" in m:
            text += (f", line of sight {100 * m['line_of_sight_fraction']:.1f} %, both "
                     f"{100 * m['camera_and_line_of_sight_fraction']:.1f} %")
        ax.set_title(text, fontsize=9)
        if env is not None:
            span = np.vstack([result.state[:, :2], result.vehicle])
            lo, hi = span.min(axis=0) - 50.0, span.max(axis=0) + 50.0
            ax.set_xlim(lo[0], hi[0])
            ax.set_ylim(lo[1], hi[1])
        ax.legend(fontsize=6, loc="best")
    fig.suptitle(title, fontsize=11)
    if env is not None:
        add_credit(fig, OSM_CREDIT)
    return save_figure(fig, path)


def figure_speed_ratio(path: str | Path, distances: Sequence[float] = (100.0, 500.0, 2000.0)) -> Path:
    """The paper's Figure 2: sigma against A / D from eq. (9), for several D (they overlap)."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.0, 4.2), constrained_layout=True)
    ratio = np.linspace(0.0, 1.5, 301)
    for d in distances:
        ax.plot(ratio, speed_ratio(ratio * d, d), lw=1.5, label=f"D = {d:g} m")
    ax.set_xlabel("A / D")
    ax.set_ylabel("sigma = v_p / v_g")
    ax.set_title("Speed ratio against amplitude (eqs. 9-10, Fig. 2)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    return save_figure(fig, path)
