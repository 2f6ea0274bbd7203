"""Figures of the loiter planners: a plan over its AOIs (the paper's Figures 6, 9, 12), the
scenarios (Figure 13), coverage and transit time per method (Figure 14), distributions over
random scenarios, and plans flown in wind."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ..loiter.planning import METHOD_NAMES
from .common import pyplot, save_figure

ROLE_COLORS = {"transit": "tab:blue", "entry": "tab:orange", "loiter": "tab:green", "exit": "tab:red"}
METHOD_COLORS = {"fly_through": "tab:red", "tlpp": "tab:blue", "ldlpp": "tab:green", "tlpp_best": "tab:cyan",
                 "ldlpp_best": "tab:olive", "best": "tab:purple"}


MAX_ARC_POINTS = 721  # an arc is drawn with at most this many points (every half degree of a full turn)
ARROW_SPACING = 150.0  # m between the arrows that show the direction of travel
MAX_ARROWS_PER_SEGMENT = 20


def _drawn_length(segment: Any) -> float:
    """How much of a segment a drawing needs: an arc of several turns retraces its first one."""
    if segment.kind == "arc" and segment.sweep > 2.0 * math.pi:
        return 2.0 * math.pi * float(segment.radius)
    return float(segment.length)


def _segment_points(segment: Any, step: float = 2.0) -> np.ndarray:
    """Points along a segment for drawing: a line's two ends; an arc every ``step`` m, at most
    MAX_ARC_POINTS, over at most one turn (the cost is bounded by the picture, not by the length
    or the number of turns)."""
    if segment.kind == "line":
        return np.array([segment.at(0.0)[:2], segment.at(segment.length)[:2]])
    length = _drawn_length(segment)
    count = min(max(2, math.ceil(length / step) + 1), MAX_ARC_POINTS)
    return np.array([segment.at(s)[:2] for s in np.linspace(0.0, length, count)])


def plan_outline(plan: Any) -> np.ndarray:
    """(n, 2) points along the whole plan for drawing, segment by segment (:func:`_segment_points`:
    bounded by the picture, however many turns a loiter makes)."""
    return np.vstack([_segment_points(segment) for segment in plan.segments])


def _arrows(segments: Sequence[Any]) -> np.ndarray:
    """(n, 3) x, y, psi of the direction arrows: every ARROW_SPACING m along each segment's drawn
    length, at most MAX_ARROWS_PER_SEGMENT per segment."""
    poses = []
    for segment in segments:
        length = _drawn_length(segment)
        count = min(int(length // ARROW_SPACING), MAX_ARROWS_PER_SEGMENT)
        poses += [segment.at(s) for s in (np.arange(count) + 0.5) * (length / max(count, 1))]
    return np.array(poses, dtype=float).reshape(-1, 3)


def draw_plan(ax: Any, plan: Any, coverage: Any = None, title: str | None = None, legend: bool = True) -> None:
    """A plan on its AOIs: the AOI disks, the path coloured by role, start/end, visiting order. AOIs are
    labelled by their index (as in tables, metrics.json and errors) and their place in the order."""
    aois = np.asarray(plan.aois)
    circle = np.linspace(0.0, 2.0 * math.pi, 200)
    for i, (x, y) in enumerate(aois):
        ax.fill(x + plan.aoi_radius * np.cos(circle), y + plan.aoi_radius * np.sin(circle), color="0.85", zorder=0)
        rank = list(plan.order).index(i) + 1
        label = f"AOI {i}\nvisit {rank}"
        if coverage is not None:
            label += f"\n{coverage.time_per_aoi[i]:.0f} s"
        ax.text(x, y, label, ha="center", va="center", fontsize=7, zorder=5)
    seen: set[str] = set()
    for segment in plan.segments:
        points = _segment_points(segment)
        role = segment.role
        ax.plot(points[:, 0], points[:, 1], color=ROLE_COLORS[role], lw=1.3,
                label=role if role not in seen else None, zorder=3)
        seen.add(role)
    # Arrows every ~150 m show the direction of travel (one artist, however many).
    arrows = _arrows(plan.segments)
    if len(arrows):
        ax.quiver(arrows[:, 0], arrows[:, 1], np.cos(arrows[:, 2]), np.sin(arrows[:, 2]), color="0.25",
                  angles="xy", pivot="tail", width=0.004, headwidth=4, headlength=5, zorder=4)
    ax.plot(*plan.start, "ks", ms=6, label="start", zorder=6)
    if tuple(plan.end) != tuple(plan.start):
        ax.plot(*plan.end, "k^", ms=6, label="end", zorder=6)
    ax.set_aspect("equal")
    ax.grid(True, alpha=0.3)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    if title:
        ax.set_title(title, fontsize=9)
    if legend:
        ax.legend(loc="best", fontsize=7)


def methods_figure(plans: Mapping[str, Any], coverages: Mapping[str, Any], path: Path, name: str = "") -> Path:
    """The three planners on one scenario side by side (the paper's Figures 6, 9 and 12)."""
    plt = pyplot()
    fig, axes = plt.subplots(1, len(plans), figsize=(5.2 * len(plans), 5.4), constrained_layout=True, squeeze=False)
    for ax, (method, plan) in zip(axes[0], plans.items()):
        cov = coverages.get(method)
        title = (f"{METHOD_NAMES.get(method, method)}: {plan.flight_time / 60:.2f} min, transit "
                 f"{plan.transit_time:.0f} s" + (f", covered {cov.time:.0f} s" if cov is not None else ""))
        draw_plan(ax, plan, cov, title, legend=ax is axes[0][0])
    if name:
        fig.suptitle(name, fontsize=10)
    return save_figure(fig, path)


def scenarios_figure(plans: Sequence[Any], names: Sequence[str], path: Path) -> Path:
    """The scenarios' layouts with one plan each (the paper's Figure 13)."""
    plt = pyplot()
    columns = 3
    rows = math.ceil(len(plans) / columns)
    fig, axes = plt.subplots(rows, columns, figsize=(4.4 * columns, 4.4 * rows), constrained_layout=True,
                             squeeze=False)
    for k, ax in enumerate(axes.flat):
        if k >= len(plans):
            ax.axis("off")
            continue
        draw_plan(ax, plans[k], None, names[k], legend=False)
        ax.set_xlim(-60, 860)
        ax.set_ylim(-60, 860)
    return save_figure(fig, path)


def comparison_figure(rows: Sequence[Mapping[str, Any]], path: Path) -> Path:
    """Coverage and transit time per method and scenario, ours beside the paper's (Figure 14).

    ``rows``: one per (scenario, method) with keys scenario, aois, method, coverage_area_m2s,
    transit_time_s, flight_time_min and optionally paper_coverage_m2, paper_flight_time_min."""
    plt = pyplot()
    scenarios = sorted({(r["aois"], r["scenario"]) for r in rows})
    methods = [m for m in METHOD_NAMES if any(r["method"] == m for r in rows)]
    fig, axes = plt.subplots(3, 1, figsize=(9.0, 10.0), constrained_layout=True)
    width = 0.8 / len(methods)
    x = np.arange(len(scenarios))
    panels = [("coverage_time_s", "paper_covered_time_s", 1.0, "AOI covered time (s; the paper's m^2 / 6,669.56)"),
              ("flight_time_min", "paper_flight_time_min", 1.0, "flight time (min)"),
              ("transit_time_s", None, 1.0, "transit time (s)")]
    for ax, (key, paper_key, scale, label) in zip(axes, panels):
        for j, method in enumerate(methods):
            values, paper = [], []
            for _, name in scenarios:
                row = next(r for r in rows if r["scenario"] == name and r["method"] == method)
                values.append(row[key] * scale)
                theirs = row.get(paper_key) if paper_key else None
                paper.append(float(theirs) * scale if theirs is not None else np.nan)
            offset = (j - (len(methods) - 1) / 2) * width
            ax.bar(x + offset, values, width, color=METHOD_COLORS[method], label=f"{METHOD_NAMES[method]} (ours)")
            if not np.all(np.isnan(paper)):
                ax.plot(x + offset, paper, "k_", ms=14, mew=2, label="paper" if j == 0 else None)
        ax.set_xticks(x, [f"{n} AOIs" for n, _ in scenarios])
        ax.set_ylabel(label)
        ax.grid(True, axis="y", alpha=0.3)
    axes[0].legend(fontsize=7, ncol=2)
    axes[0].set_title("Coverage and time per method (black bars: the paper's Table 1)", fontsize=10)
    return save_figure(fig, path)


def distribution_figure(records: Sequence[Mapping[str, Any]], path: Path) -> Path:
    """Distributions over random scenarios, per method: flight time, transit time and coverage
    time per AOI, each against the number of AOIs."""
    plt = pyplot()
    methods = [m for m in METHOD_NAMES if any(r["method"] == m for r in records)]
    counts = sorted({int(r["aois"]) for r in records})
    panels = [("flight_time_s", 1 / 60.0, "flight time (min)"), ("transit_time_s", 1.0, "transit time (s)"),
              ("coverage_time_s", None, "covered time per AOI (s)")]
    fig, axes = plt.subplots(1, 3, figsize=(15.0, 4.6), constrained_layout=True)
    width = 0.8 / len(methods)
    for ax, (key, scale, label) in zip(axes, panels):
        for j, method in enumerate(methods):
            data = []
            for n in counts:
                values = [float(r[key]) * (scale if scale else 1.0 / n)
                          for r in records if r["method"] == method and int(r["aois"]) == n]
                data.append(values)
            positions = np.arange(len(counts)) + (j - (len(methods) - 1) / 2) * width
            parts = ax.boxplot(data, positions=positions, widths=width * 0.9, patch_artist=True,
                               showfliers=False, manage_ticks=False)
            for box in parts["boxes"]:
                box.set_facecolor(METHOD_COLORS[method])
                box.set_alpha(0.6)
            ax.plot([], [], color=METHOD_COLORS[method], lw=6, alpha=0.6, label=METHOD_NAMES[method])
        ax.set_xticks(np.arange(len(counts)), [str(n) for n in counts])
        ax.set_xlabel("AOIs")
        ax.set_ylabel(label)
        ax.grid(True, axis="y", alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle(f"{len(records) // max(1, len(methods))} random scenarios (boxes: quartiles, whiskers: 1.5 IQR)",
                 fontsize=10)
    return save_figure(fig, path)


def timeline_figure(runs: Sequence[Any], threshold: float, dt: float, path: Path, name: str = "") -> Path:
    """Coverage and gimbal over time, one row of panels per method: which AOI is covered at each
    step (AOI index against time, a mark where at least ``threshold`` of it is in the footprint),
    and the gimbal and bank angles (degrees, positive left)."""
    plt = pyplot()
    fig, axes = plt.subplots(len(runs), 2, figsize=(12.0, 2.2 * len(runs) + 0.6), squeeze=False,
                             constrained_layout=True)
    for (ax_cov, ax_angle), run in zip(axes, runs):
        cov = run.coverage
        fraction = np.asarray(cov.fraction)
        t = np.arange(fraction.shape[0]) * dt
        color = METHOD_COLORS.get(run.method, "0.3")
        for aoi in range(fraction.shape[1]):
            covered = fraction[:, aoi] >= threshold
            ax_cov.plot(t[covered], np.full(int(covered.sum()), aoi), "|", color=color, ms=8)
        ax_cov.set_yticks(range(fraction.shape[1]))
        ax_cov.set_ylabel("AOI covered")
        ax_cov.set_title(f"{METHOD_NAMES.get(run.method, run.method)}: {cov.time:.0f} s covered", fontsize=9)
        ax_angle.plot(t, np.degrees(np.asarray(cov.gimbal)), color=color, lw=1, label="gimbal")
        ax_angle.plot(t, np.degrees(np.asarray(cov.bank)), color="0.5", lw=0.8, ls="--", label="bank")
        ax_angle.set_ylabel("angle (deg)")
        ax_angle.legend(fontsize=7, loc="upper right")
        for ax in (ax_cov, ax_angle):
            ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("t (s)")
    axes[-1, 1].set_xlabel("t (s)")
    if name:
        fig.suptitle(f"{name}: coverage and gimbal over time")
    return save_figure(fig, path, dpi=110)


def wind_figure(plan: Any, flights: Sequence[tuple[str, np.ndarray]], path: Path, title: str = "") -> Path:
    """A plan and the paths flown along it in wind (each flight: label and (n, >= 3) x, y, ... rows)."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.0, 7.0), constrained_layout=True)
    draw_plan(ax, plan, None, title, legend=False)
    styles = [("tab:purple", "-"), ("k", "--"), ("tab:brown", "-."), ("tab:olive", ":")]
    for k, (label, rows) in enumerate(flights):
        color, style = styles[k % len(styles)]
        ax.plot(rows[:, 0], rows[:, 1], color=color, ls=style, lw=0.9, alpha=0.9, label=label)
    ax.legend(fontsize=7, loc="best")
    return save_figure(fig, path)
