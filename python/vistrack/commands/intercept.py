"""``vistrack intercept``: optimal interception of a target moving on a circle.

Solves the problem of Manyam et al. (Algorithm 1) from flags or a YAML file and writes the
Figure 7 pair as PNG (travel times of pursuer and target against the arrival angle; the
interception path on the plane) and the numbers as JSON. Defaults are the paper's test
scenario: pursuer at the origin heading 0, target circle centred at (-4, 3), target starting at
alpha_i = pi, speeds 1 and 1.2 m/s; the paper takes rho equal to the circle radius (1 here).
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path
from typing import Any

import numpy as np

from .. import VistrackError
from .. import dubins
from ..plotting import pyplot

DEFAULTS: dict[str, Any] = {
    "pursuer": [0.0, 0.0, 0.0],
    "rho": 1.0,
    "pursuer_speed": 1.0,
    "center": [-4.0, 3.0],
    "radius": 1.0,
    "target_angle0": math.pi,
    "target_speed": 1.2,
    "direction": "cw",
    "angle_tolerance": 1e-12,
}


def register(subparsers: argparse._SubParsersAction) -> None:
    parser = subparsers.add_parser(
        "intercept",
        help="optimal Dubins interception of a target moving on a circle (Figure 7)",
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--config", type=Path, help="YAML file with any of the keys below (flags override it)")
    parser.add_argument("--pursuer", type=float, nargs=3, metavar=("X", "Y", "PSI"), help="pursuer x y psi (m, m, rad)")
    parser.add_argument("--rho", type=float, help="pursuer minimum turn radius (m)")
    parser.add_argument("--pursuer-speed", dest="pursuer_speed", type=float, help="v_p (m/s)")
    parser.add_argument("--center", type=float, nargs=2, metavar=("CX", "CY"), help="target circle centre (m)")
    parser.add_argument("--radius", type=float, help="target circle radius (m)")
    parser.add_argument("--target-angle", dest="target_angle0", type=float, help="alpha_i, initial target angle (rad)")
    parser.add_argument("--target-speed", dest="target_speed", type=float, help="v_t (m/s)")
    parser.add_argument("--direction", choices=["cw", "ccw"], help="target travel direction on the circle")
    parser.add_argument("--tolerance", dest="angle_tolerance", type=float, help="bisection tolerance on the angle (rad)")
    parser.add_argument("--out", type=Path, default=Path("intercept_out"), help="output folder (default intercept_out)")
    parser.set_defaults(func=run)


def load_problem(args: argparse.Namespace) -> dict[str, Any]:
    """Defaults, then the YAML file, then explicit flags."""
    problem = dict(DEFAULTS)
    if args.config is not None:
        import yaml

        with open(args.config, encoding="utf-8") as handle:
            loaded = yaml.safe_load(handle) or {}
        if not isinstance(loaded, dict):
            raise VistrackError(f"config = {args.config}: expected a mapping of keys to values")
        unknown = sorted(set(loaded) - set(DEFAULTS))
        if unknown:
            raise VistrackError(f"config = {args.config}: unknown keys {unknown} (known: {sorted(DEFAULTS)})")
        problem.update(loaded)
    for key in DEFAULTS:
        value = getattr(args, key, None)
        if value is not None:
            problem[key] = value
    for key in ("pursuer", "center"):
        expected = 3 if key == "pursuer" else 2
        value = problem[key]
        if not isinstance(value, (list, tuple)) or len(value) != expected:
            raise VistrackError(f"{key} = {value!r}: expected {expected} numbers")
        problem[key] = [float(v) for v in value]
    for key in ("rho", "pursuer_speed", "radius", "target_angle0", "target_speed", "angle_tolerance"):
        try:
            problem[key] = float(problem[key])
        except (TypeError, ValueError):
            raise VistrackError(f"{key} = {problem[key]!r}: expected a number") from None
    problem["direction"] = str(problem["direction"])
    return problem


def solve(problem: dict[str, Any]) -> dubins.InterceptResult:
    return dubins.intercept_circle(
        problem["pursuer"],
        problem["rho"],
        problem["pursuer_speed"],
        problem["center"],
        problem["radius"],
        problem["target_angle0"],
        problem["target_speed"],
        problem["direction"],
        angle_tolerance=problem["angle_tolerance"],
    )


def result_record(problem: dict[str, Any], result: dubins.InterceptResult) -> dict[str, Any]:
    sign = -1.0 if problem["direction"] == "cw" else 1.0
    cx, cy = problem["center"]
    r = problem["radius"]
    # Where the target really is at the interception time (independent of the path's goal).
    target_angle = problem["target_angle0"] + sign * problem["target_speed"] * result.time / r
    path = result.path
    return {
        "problem": problem,
        "interception": {
            "angle": result.angle,
            "angle_mod_2pi": result.angle % (2.0 * math.pi),
            "swept_angle": result.swept_angle,
            "time": result.time,
            "pursuer_time": path.length / problem["pursuer_speed"],
            "residual": result.residual,
            "point": list(path.goal),
            "target_position_at_time": [cx + r * math.cos(target_angle), cy + r * math.sin(target_angle)],
        },
        "path": {
            "word": path.word,
            "segment_types": list(path.segment_types),
            "segment_lengths": list(path.segment_lengths),
            "length": path.length,
        },
        "four_rho_condition": result.four_rho_condition,
        "optimality": "guaranteed (Proposition 1)" if result.four_rho_condition else "feasible, not guaranteed optimal",
        "period": result.period,
        "alpha_min": result.alpha_min,
        "bracket_windows": result.bracket_windows,
        "bisection_steps": result.bisection_steps,
    }


def plot(problem: dict[str, Any], result: dubins.InterceptResult, out: Path) -> list[Path]:
    plt = pyplot()

    # (a) travel times against the target's angular position, a little past the interception.
    swept = np.linspace(0.0, max(result.swept_angle * 1.25, result.swept_angle + math.pi / 2), 1500)
    angles, t_pursuer, t_target = dubins.intercept_travel_times(
        problem["pursuer"], problem["rho"], problem["pursuer_speed"], problem["center"], problem["radius"],
        problem["target_angle0"], problem["target_speed"], problem["direction"], swept,
    )
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.plot(angles, t_pursuer, label=r"pursuer $T_p(\alpha) = D(\alpha)/v_p$")
    ax.plot(angles, t_target, label=r"target $T_t(\alpha)$")
    ax.plot([result.angle], [result.time], "ko", label=rf"$\alpha^*$ = {result.angle:.4f} rad, T = {result.time:.4f} s")
    ax.set_xlabel(r"angular position on the target circle $\alpha$ (rad)")
    ax.set_ylabel("travel time (s)")
    ax.set_title("Travel times of the target and the pursuer (Fig. 7a)")
    if problem["direction"] == "cw":
        ax.invert_xaxis()  # the target moves towards decreasing alpha
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    times_png = out / "fig7a_travel_times.png"
    fig.savefig(times_png, dpi=130)
    plt.close(fig)

    # (b) the interception path on the plane.
    path = result.path
    samples = path.sample(max(path.length / 400.0, 1e-6))
    cx, cy = problem["center"]
    r = problem["radius"]
    sign = -1.0 if problem["direction"] == "cw" else 1.0
    circle = np.linspace(0.0, 2.0 * math.pi, 400)
    travelled = problem["target_angle0"] + sign * np.linspace(0.0, result.swept_angle, 400)
    fig, ax = plt.subplots(figsize=(6.0, 6.0))
    ax.plot(cx + r * np.cos(circle), cy + r * np.sin(circle), color="0.6", lw=1, label="target circle")
    ax.plot(cx + r * np.cos(travelled), cy + r * np.sin(travelled), color="tab:orange", lw=2.5,
            label=f"target travel ({result.swept_angle / (2.0 * math.pi):.2f} laps)")
    ax.plot(samples[:, 0], samples[:, 1], color="tab:blue", lw=2, label=f"pursuer path ({path.word}, {path.length:.3f} m)")
    x0, y0, psi0 = problem["pursuer"]
    ax.annotate("", xy=(x0 + 0.6 * math.cos(psi0), y0 + 0.6 * math.sin(psi0)), xytext=(x0, y0),
                arrowprops={"arrowstyle": "->", "color": "tab:blue", "lw": 1.5})
    ax.plot([x0], [y0], "s", color="tab:blue", label="pursuer start")
    a0 = problem["target_angle0"]
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
    path_png = out / "fig7b_path.png"
    fig.savefig(path_png, dpi=130)
    plt.close(fig)
    return [times_png, path_png]


def run(args: argparse.Namespace) -> int:
    problem = load_problem(args)
    result = solve(problem)
    out: Path = args.out
    out.mkdir(parents=True, exist_ok=True)
    record = result_record(problem, result)
    figures = plot(problem, result, out)
    record["figures"] = [f.name for f in figures]
    (out / "intercept.json").write_text(json.dumps(record, indent=2) + "\n", encoding="utf-8")
    i = record["interception"]
    print(
        f"alpha* = {i['angle']:.6f} rad, T = {i['time']:.6f} s, path {record['path']['word']} "
        f"{record['path']['length']:.6f} m, 4-rho condition: {record['four_rho_condition']} -> {out}"
    )
    return 0
