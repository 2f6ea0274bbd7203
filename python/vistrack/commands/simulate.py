"""``vistrack simulate``: the closed loop of section VI around an orbit plan.

Writes trajectory.csv (one sample per line), metrics.json, trajectory.png (Figure 10 style: the
UAV's path over the city with the reference orbits) and errors.png (Figure 11 style: radial
error, heading error and control against time). With ``--map`` the line of sight UAV -> POI is
evaluated at every sample; ``--baseline-radius`` adds the same loop around constant-radius orbits.
"""

from __future__ import annotations

import argparse
import itertools
import json
import math
import time
from pathlib import Path
from typing import Any, Sequence

import numpy as np

from .. import _core

from ..planning import load_environment
from ..plotting import OSM_CREDIT, evenly_spaced_indices, plot_buildings, pyplot


def read_plan(path: str | Path) -> Any:
    try:
        text = Path(path).read_text()
    except OSError as error:
        raise _core.VistrackError(f"--plan = {path}: cannot read the file ({error.strerror})") from None
    return _core.OrbitPlan.from_json(text)


def metrics(result: Any, converge_after: float = 20.0) -> dict[str, Any]:
    """Summary numbers of one closed-loop run (errors after ``converge_after`` seconds)."""
    t = np.asarray(result.t)
    radial = np.asarray(result.radial_error)
    heading = np.asarray(result.heading_error)
    control = np.asarray(result.control)
    late = t >= min(converge_after, t[-1])
    stats = result.statistics
    out: dict[str, Any] = {
        "duration_s": float(t[-1] - t[0]),
        "samples": int(len(t)),
        "rhs_evaluations": int(stats.rhs_evaluations),
        "accepted_steps": int(stats.accepted_steps),
        "rejected_steps": int(stats.rejected_steps),
        "restarts": int(len(result.restart_times) - 1),
        "initial_radial_error_m": float(radial[0]),
        "converge_after_s": float(converge_after),
        "radial_error_after_mean_m": float(np.mean(radial[late])),
        "radial_error_after_max_abs_m": float(np.max(np.abs(radial[late]))),
        "heading_error_after_max_abs_rad": float(np.max(np.abs(heading[late]))),
        "control_max_abs": float(np.max(np.abs(control))),
        "saturated_fraction": float(np.mean(np.asarray(result.control_unsaturated) != control)),
        "orbit_radius_first_m": float(result.orbit_radius[0]),
        "orbit_radius_last_m": float(result.orbit_radius[-1]),
    }
    out["visibility_fraction"] = None if result.visibility_fraction is None else float(result.visibility_fraction)
    return out


def figure_trajectory(runs: Sequence[tuple[str, Any, Any]], env: Any, path: str | Path, title: str = "",
                      orbit_count: int = 8, credit: str | None = OSM_CREDIT) -> None:
    """Figure 10 style: each run's UAV path (label, plan, result) with its orbits and the POI path."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(8, 8))
    label0, plan0, result0 = runs[0]
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
    if env is not None and credit:
        fig.text(0.99, 0.01, credit, ha="right", va="bottom", fontsize=6, color="gray")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def figure_errors(result: Any, path: str | Path, window: float | None = None, title: str = "",
                  max_turn_rate: float | None = None) -> None:
    """Figure 11 style: radial error, heading and its error, and control against time."""
    plt = pyplot()
    t = np.asarray(result.t)
    keep = t <= (t[0] + window) if window else np.ones_like(t, bool)
    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
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
    axes[2].set_xlabel("time (s)")
    for t_restart in np.asarray(result.restart_times)[1:-1]:
        if t_restart <= t[keep][-1]:
            for ax in axes:
                ax.axvline(t_restart, color="0.85", lw=0.6, zorder=0)
    for ax in axes:
        ax.grid(alpha=0.3)
    axes[0].set_title(title or "Errors and control (grey lines: orbit segment boundaries)")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def _x0(text: str) -> np.ndarray:
    try:
        values = [float(v) for v in text.replace(",", " ").split()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"--x0 = {text}: expected X,Y,PSI") from None
    if len(values) != 3:
        raise argparse.ArgumentTypeError(f"--x0 = {text}: expected three numbers X,Y,PSI")
    return np.array(values)


def register(subparsers: argparse._SubParsersAction) -> None:
    p = subparsers.add_parser(
        "simulate",
        help="closed-loop simulation of the UAV around an orbit plan",
        description="The Dubins UAV steered by the guidance law (86) around the plan's time-varying orbit "
        "(section VI). Writes trajectory.csv, metrics.json, trajectory.png and errors.png.",
    )
    uav, control, options = _core.Uav(), _core.Control(), _core.SimulationOptions()
    p.add_argument("--plan", required=True, help="orbit plan JSON (vistrack orbits writes plan.json)")
    p.add_argument("--out", default="simulate_out", help="output folder (created)")
    p.add_argument("--map", help="city for line-of-sight evaluation: .geojson footprints or a mesh")
    p.add_argument("--up", default="y", choices=["y", "z"], help="up axis of a mesh file (default y)")
    p.add_argument("--speed", type=float, default=uav.speed, help="UAV speed v, m/s")
    p.add_argument("--min-turn-radius", type=float, default=uav.min_turn_radius, help="r_min, m")
    p.add_argument("--altitude", type=float, default=uav.altitude, help="h_UAV, m")
    p.add_argument("--beta", type=float, default=control.beta, help="beta of the vector field")
    p.add_argument("--k-psi", type=float, default=control.k_psi, help="heading gain k_psi")
    p.add_argument("--direction", default=control.direction, choices=["ccw", "cw"], help="circulation")
    p.add_argument("--x0", type=_x0, help="start X,Y,PSI (default: on the first orbit east of the POI)")
    p.add_argument("--rtol", type=float, default=options.rtol)
    p.add_argument("--atol", type=float, default=options.atol)
    p.add_argument("--max-step", type=float, default=options.max_step, help="s")
    p.add_argument("--output-step", type=float, default=options.output_step, help="s")
    p.add_argument("--fixed-step", type=float, default=0.0, help="fixed integration step, s (0: adaptive)")
    p.add_argument("--baseline-radius", type=float, action="append", default=[],
                   help="also simulate constant-radius orbits of this radius (repeatable)")
    p.add_argument("--window", type=float, default=None, help="errors.png shows only the first WINDOW s")
    p.add_argument("--converge-after", type=float, default=20.0, help="metrics of errors after this time, s")
    p.add_argument("--title", default="", help="figure title")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    plan = read_plan(args.plan)
    uav = _core.Uav(speed=args.speed, min_turn_radius=args.min_turn_radius, altitude=args.altitude)
    control = _core.Control(beta=args.beta, k_psi=args.k_psi, direction=args.direction)
    options = _core.SimulationOptions(rtol=args.rtol, atol=args.atol, max_step=args.max_step,
                                      output_step=args.output_step)
    env = load_environment(args.map, args.up) if args.map else None
    if args.x0 is None:
        g = np.asarray(plan.centers)[0]
        x0 = np.array([g[0] + plan.radii[0], g[1], math.pi / 2])
    else:
        x0 = args.x0
    scene = _core.VisibilityScene(env) if env is not None else None  # one BVH for every run
    runs = []
    summary: dict[str, Any] = {"plan": str(args.plan), "x0": [float(v) for v in x0],
                               "uav": {"speed": uav.speed, "min_turn_radius": uav.min_turn_radius,
                                       "altitude": uav.altitude},
                               "control": {"beta": control.beta, "k_psi": control.k_psi,
                                           "direction": control.direction},
                               "lemma7_min_gain": _core.lemma7_min_gain(uav.speed, control.beta)}
    plans = [("visibility orbit", plan)] + [
        (f"constant R = {r:g} m", _core.constant_radius_plan(plan.poi, r, uav)) for r in args.baseline_radius]
    for label, p in plans:
        start = time.perf_counter()
        result = _core.simulate(p, uav, x0, control, scene, options, fixed_step=args.fixed_step)
        seconds = time.perf_counter() - start
        m = metrics(result, args.converge_after)
        m["seconds"] = seconds
        summary[label] = m
        runs.append((label, p, result))
    (out / "trajectory.csv").write_text(runs[0][2].to_csv())
    for label, _, result in runs[1:]:
        name = "trajectory_R" + label.split("= ")[1].split(" ")[0] + ".csv"
        (out / name).write_text(result.to_csv())
    (out / "metrics.json").write_text(json.dumps(summary, indent=1))
    figure_trajectory(runs, env, out / "trajectory.png", args.title)
    figure_errors(runs[0][2], out / "errors.png", args.window, args.title, uav.speed / uav.min_turn_radius)
    for label, _, result in runs:
        m = summary[label]
        vis = "" if m["visibility_fraction"] is None else f", visible {100 * m['visibility_fraction']:.1f}%"
        print(f"{label}: {m['samples']} samples, {m['rhs_evaluations']} RHS evaluations in {m['seconds'] * 1e3:.1f} ms; "
              f"|r - R| <= {m['radial_error_after_max_abs_m']:.3g} m after {args.converge_after:g} s{vis}")
    print(f"wrote {out}/trajectory.csv, metrics.json, trajectory.png, errors.png")
    return 0
