"""Figures of the Dubins waypoint navigation comparison: Figures 11/12 (DWN against WN at three
waypoint radii), Figure 10 (theta against the arc weight) and the Monte Carlo distributions."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Optional, Sequence

import numpy as np

from .._core.flight import Wind
from .._core.waypoint_nav import HorizonPath
from ..waypoint_nav import MonteCarlo, NavigationFlight
from .common import plot_bank, pyplot, save_figure

DWN_STYLE = {"color": "tab:blue", "lw": 1.6, "ls": "-"}
WN_STYLE = {"color": "tab:orange", "lw": 1.4, "ls": "--"}


def _arc(center: np.ndarray, radius: float, start: float, sweep: float) -> np.ndarray:
    angles = start + np.linspace(0.0, sweep, max(2, int(abs(sweep) / 0.05) + 2))
    return center + radius * np.column_stack([np.cos(angles), np.sin(angles)])


def horizon_polyline(pose: Sequence[float], path: HorizonPath, turn_radius: float,
                     w_after: Sequence[float]) -> np.ndarray:
    """Points along a horizon path: first arc, straight to T_n, arc through W_n, straight on."""
    first, second = (1 if part == "ccw" else -1 for part in path.case.split("-"))
    x, y, psi = pose
    R = turn_radius
    c1 = np.array([x - first * R * math.sin(psi), y + first * R * math.cos(psi)])
    a0 = math.atan2(y - c1[1], x - c1[0])
    c2 = np.asarray(path.circle_center)
    t0 = math.atan2(path.point[1] - c2[1], path.point[0] - c2[0])
    parts = [
        _arc(c1, R, a0, first * path.first_arc / R),
        np.array([path.line_start, path.point]),
        _arc(c2, R, t0, second * (path.arc_to_waypoint + path.arc_from_waypoint) / R),
        np.array([path.exit_point, w_after]),
    ]
    return np.vstack(parts)


def _wind_text(wind: Optional[Wind]) -> str:
    if wind is None or (wind.east == 0.0 and wind.north == 0.0 and wind.gusts is None):
        return "no wind"
    text = f"wind ({wind.east:g}, {wind.north:g})"
    return text + (f" + Dryden gusts (seed {wind.gusts.seed})" if wind.gusts is not None else "")


def _wind_arrow(ax: Any, wind: Optional[Wind]) -> None:
    """An arrow in the upper left corner pointing where the mean wind blows to (none in calm air)."""
    if wind is None or (wind.east == 0.0 and wind.north == 0.0):
        return
    speed = math.hypot(wind.east, wind.north)
    ax.annotate("", xy=(0.08 + 0.07 * wind.east / speed, 0.9 + 0.07 * wind.north / speed), xytext=(0.08, 0.9),
                xycoords="axes fraction", arrowprops={"arrowstyle": "->", "color": "tab:gray", "lw": 1.5})
    ax.text(0.08, 0.8, "wind", transform=ax.transAxes, fontsize=7, color="tab:gray", ha="center")


def figure_paths(flights: Sequence[NavigationFlight], path: Path, title: str = "",
                 wind: Optional[Wind] = None) -> Path:
    """Figures 11/12: one panel per WN flight (its R_WP), WN dashed, DWN solid in every panel;
    waypoints with their R_WP circles, DWN turning points as crosses."""
    plt = pyplot()
    dwn = next((f for f in flights if f.method == "dwn"), None)
    wns: list[Optional[NavigationFlight]] = [f for f in flights if f.method != "dwn"] or [None]
    fig, axes = plt.subplots(1, len(wns), figsize=(4.6 * len(wns), 4.8), squeeze=False, constrained_layout=True)
    for ax, wn in zip(axes[0], wns):
        ref = dwn if dwn is not None else wn
        assert ref is not None
        route = np.vstack([ref.start[:2], ref.waypoints])
        ax.plot(route[:, 0], route[:, 1], color="0.7", lw=0.8, ls=":", label="legs")
        ax.plot(ref.waypoints[:, 0], ref.waypoints[:, 1], "ko", ms=4, label="waypoints")
        ax.plot([ref.start[0]], [ref.start[1]], "ks", ms=5)
        if wn is not None and wn.waypoint_radius is not None:
            traj = wn.trajectory
            ax.plot(traj[:, 1], traj[:, 2], label=f"WN ({wn.swirls} swirls)" if wn.swirls else "WN", **WN_STYLE)
            for w in wn.waypoints:
                ax.add_patch(plt.Circle(w, wn.waypoint_radius, fill=False, color="tab:orange", lw=0.6, alpha=0.6))
            ax.set_title(wn.label)
        if dwn is not None:
            traj = dwn.trajectory
            ax.plot(traj[:, 1], traj[:, 2], label="DWN", **DWN_STYLE)
            tps = dwn.turning_points[:-1]
            ax.plot(tps[:, 0], tps[:, 1], "x", color="tab:blue", ms=5, label="turning points")
        ax.set_aspect("equal")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=7)
        _wind_arrow(ax, wind)
    fig.suptitle(f"{title} ({_wind_text(wind)})" if title else _wind_text(wind))
    return save_figure(fig, path, dpi=130)


def figure_bank(flights: Sequence[NavigationFlight], path: Path) -> Path:
    """The bank flown against time, one panel per flight, with its smoothness in the legend."""
    plt = pyplot()
    fig, axes = plt.subplots(len(flights), 1, figsize=(8.0, 1.9 * len(flights) + 0.6), sharex=True, squeeze=False,
                             constrained_layout=True)
    for ax, flight in zip(axes[:, 0], flights):
        plot_bank(ax, flight.flight.t, flight.flight.bank, label=flight.label)
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("t (s)")
    return save_figure(fig, path, dpi=110)


def figure_waypoint_zoom(flights: Sequence[NavigationFlight], path: Path, window: float = 0.6) -> Path:
    """One small panel per waypoint: every flight within ``window`` R of it, with each WN flight's
    R_WP circle, so misses of a few hundredths of R can be seen."""
    plt = pyplot()
    ref = flights[0]
    R = ref.turn_radius
    points = np.asarray(ref.waypoints, dtype=float)
    columns = min(len(points), 4)
    rows = math.ceil(len(points) / columns)
    fig, axes = plt.subplots(rows, columns, figsize=(2.6 * columns, 2.6 * rows), squeeze=False,
                             constrained_layout=True)
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, ax in enumerate(axes.flat):
        if k >= len(points):
            ax.set_visible(False)
            continue
        w = points[k]
        for j, flight in enumerate(flights):
            traj = flight.trajectory
            ax.plot(traj[:, 1], traj[:, 2], lw=1, color=colors[j % len(colors)], label=flight.label if k == 0 else None)
            if flight.waypoint_radius:
                ax.add_patch(plt.Circle(w, flight.waypoint_radius, fill=False, lw=0.5, color=colors[j % len(colors)]))
        ax.plot([w[0]], [w[1]], "ko", ms=3)
        ax.set_xlim(w[0] - window * R, w[0] + window * R)
        ax.set_ylim(w[1] - window * R, w[1] + window * R)
        ax.set_aspect("equal")
        ax.set_title(f"waypoint {k}", fontsize=8)
        ax.tick_params(labelsize=6)
    fig.legend(loc="lower right", fontsize=6)
    return save_figure(fig, path, dpi=110)


def figure_theta_weight(data: dict[str, Any], path: Path) -> Path:
    """Figure 10: theta of the turning circle against w_a (w_s = 1), and the paths at the ends."""
    plt = pyplot()
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(10.0, 4.2), constrained_layout=True)
    weights, thetas = data["arc_weights"], np.degrees(np.unwrap(data["thetas"]))
    ax.plot(weights, thetas, "o-")
    ax.set_xlabel("arc weight w_a (w_s = 1)")
    ax.set_ylabel("theta (deg)")
    ax.set_title(f"theta moves {data['theta_range_deg']:.2f} deg over w_a in [{weights[0]:g}, {weights[-1]:g}]")
    ax.grid(True, alpha=0.3)
    for index, style in ((0, "-"), (-1, "--")):
        point = data["points"][index]
        line = horizon_polyline(data["pose"], point, 1.0, data["w_after"])
        ax2.plot(line[:, 0], line[:, 1], ls=style, label=f"w_a = {weights[index]:g} ({point.case})")
        ax2.plot([point.point[0]], [point.point[1]], "x", color="k")
    marks = np.array([data["pose"][:2], data["w_next"], data["w_after"]])
    ax2.plot(marks[:, 0], marks[:, 1], "ko")
    ax2.set_aspect("equal")
    ax2.grid(True, alpha=0.3)
    ax2.legend(fontsize=8)
    ax2.set_title("A = B = 4, alpha = -45 deg, beta = 30 deg (R = 1)")
    return save_figure(fig, path, dpi=130)


def figure_monte_carlo(mc: MonteCarlo, path: Path) -> Path:
    """Per method, without (blue) and with (red) gusts: miss distances (box plots over every
    waypoint of every flight), overshoot, path length over the route's length, swirl rate."""
    plt = pyplot()
    labels = mc.methods()
    fig, axes = plt.subplots(1, 4, figsize=(17.0, 4.4), constrained_layout=True)
    positions = np.arange(len(labels))

    def boxes(ax: Any, data: list[Any], offset: float, color: str) -> None:
        box = ax.boxplot(data, positions=positions + offset, widths=0.3, patch_artist=True, showfliers=False)
        for patch in box["boxes"]:
            patch.set_facecolor(color)
            patch.set_alpha(0.5)

    most_swirls = 0.0
    for offset, gusts, color in ((-0.18, False, "tab:blue"), (0.18, True, "tab:red")):
        rows = [[r for r in mc.rows if r["label"] == label and r["gusts"] == gusts] for label in labels]
        boxes(axes[0], [np.concatenate([r["miss_over_R"] for r in group]) for group in rows], offset, color)
        boxes(axes[1], [[r["overshoot_over_R"] for r in group] for group in rows], offset, color)
        boxes(axes[2], [[r["path_ratio"] for r in group] for group in rows], offset, color)
        swirl = [float(np.mean([r["swirls"] > 0 for r in group])) for group in rows]
        most_swirls = max(most_swirls, *swirl)
        axes[3].bar(positions + offset, swirl, width=0.35, color=color, alpha=0.7,
                    label="with gusts" if gusts else "without gusts")
    if most_swirls == 0.0:
        axes[3].set_ylim(0.0, 1.0)
        axes[3].text(0.5, 0.5, f"no swirl in {len(mc.rows)} flights", ha="center", transform=axes[3].transAxes)
    names = ("miss distance / R", "overshoot / R", "path length / route length", "swirl rate (share of flights)")
    for ax, name in zip(axes, names):
        ax.set_xticks(positions)
        ax.set_xticklabels(labels, rotation=15, fontsize=8)
        ax.set_ylabel(name)
        ax.grid(True, alpha=0.3)
    axes[3].legend(fontsize=8)
    s = mc.settings
    fig.suptitle(f"{s['runs']} random routes ({s['waypoints']} waypoints, legs {s['legs'][0]:g}-{s['legs'][1]:g} R, "
                 f"turns <= 90 deg), wind {100 * s['wind_fraction'][0]:g}-{100 * s['wind_fraction'][1]:g} % of v "
                 "in any direction; blue: no gusts, red: Dryden gusts (MIL-F-8785C, light)")
    return save_figure(fig, path, dpi=130)
