"""``vistrack tune``: choose beta by grid search (section V.D, Figure 9).

For an orbit of radius R changing at dR/dt about a POI of speed v_g, the largest
|dpsi_d/dt + u_lyap| over r >= tau R (all polar angles and heading errors) must stay below the
turn-rate limit v / r_min. Writes tune.json and tune.png (the map at the chosen beta and the
maximum against beta).
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np

from .. import _core
from ..plotting import pyplot
from . import positive_numbers


def register(subparsers: argparse._SubParsersAction) -> None:
    p = subparsers.add_parser(
        "tune",
        help="grid search of the turn rate the guidance needs, to choose beta (Figure 9)",
        description="Largest |dpsi_d/dt + u_lyap| over r >= tau R for the given orbit and speeds; "
        "compare with v / r_min. Defaults are the paper's Figure 9 parameters.",
    )
    p.add_argument("--radius", type=float, default=85.9, help="orbit radius R, m")
    p.add_argument("--radius-rate", type=float, default=1.30, help="dR/dt, m/s")
    p.add_argument("--speed", type=float, default=20.0, help="UAV speed v, m/s")
    p.add_argument("--poi-speed", type=float, default=5.0, help="POI speed v_g, m/s")
    p.add_argument("--min-turn-radius", type=float, default=50.0, help="r_min, m")
    p.add_argument("--beta", type=float, default=0.025, help="beta for the map")
    p.add_argument("--sweep", type=positive_numbers("--sweep", "0.01,0.025,0.05"), default=None,
                   help="betas for the max-vs-beta curve (default: 30 values, log-spaced around --beta)")
    p.add_argument("--tau", type=float, default=1.0, help="search r >= tau R (Remark 6), 0 < tau <= 1")
    p.add_argument("--r-max-factor", type=float, default=4.0, help="search r <= factor R")
    p.add_argument("--direction", default="ccw", choices=["ccw", "cw"])
    p.add_argument("--out", default="tune_out", help="output folder (created)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    limit = args.speed / args.min_turn_radius if args.min_turn_radius > 0 else math.inf
    if not (args.min_turn_radius > 0):
        raise _core.VistrackError(f"--min-turn-radius = {args.min_turn_radius}: must be greater than 0")

    def search(beta: float):
        return _core.tune_turn_rate(args.radius, args.radius_rate, args.speed, args.poi_speed, beta,
                                    direction=args.direction, tau=args.tau, r_max_factor=args.r_max_factor)

    chosen = search(args.beta)
    betas = args.sweep or list(np.geomspace(args.beta / 10, args.beta * 10, 30))
    from tqdm import tqdm

    sweep = [search(b).max_turn_rate for b in tqdm(betas, desc="beta sweep", leave=False)]
    feasible = [b for b, m in zip(betas, sweep) if m < limit]
    summary = {
        "radius": args.radius, "radius_rate": args.radius_rate, "speed": args.speed,
        "poi_speed": args.poi_speed, "tau": args.tau, "beta": args.beta,
        "max_turn_rate": chosen.max_turn_rate, "turn_rate_limit": limit,
        "feasible": chosen.max_turn_rate < limit,
        "at": {"r": chosen.at_r, "theta_from_poi_motion": chosen.at_theta,
               "heading_error": chosen.at_heading_error},
        "sweep": {"beta": [float(b) for b in betas], "max_turn_rate": sweep},
        "largest_feasible_beta_in_sweep": max(feasible) if feasible else None,
        "lemma7_min_gain": _core.lemma7_min_gain(args.speed, args.beta),
    }
    (out / "tune.json").write_text(json.dumps(summary, indent=1))

    plt = pyplot()

    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(12, 5.2))
    radii, angles = np.asarray(chosen.radii), np.asarray(chosen.angles)
    a = np.append(angles, angles[0] + 2 * math.pi)
    value = np.concatenate([chosen.map, chosen.map[:, :1]], axis=1)
    rr, aa = np.meshgrid(radii, a, indexing="ij")
    mesh = ax0.pcolormesh(rr * np.cos(aa), rr * np.sin(aa), value, shading="gouraud", cmap="magma")
    fig.colorbar(mesh, ax=ax0, label="max over heading error of |dpsi_d/dt + u_lyap| (rad/s)")
    t = np.linspace(0, 2 * math.pi, 200)
    ax0.plot(args.radius * np.cos(t), args.radius * np.sin(t), "c--", lw=1, label="orbit R")
    ax0.annotate("", xy=(0.6 * args.radius, 0), xytext=(0, 0), arrowprops=dict(arrowstyle="->", color="w"))
    ax0.plot(chosen.at_r * math.cos(chosen.at_theta), chosen.at_r * math.sin(chosen.at_theta), "wx", ms=9,
             label=f"max {chosen.max_turn_rate:.3f} rad/s")
    ax0.set_aspect("equal")
    ax0.set_xlabel("x relative to the POI (m), POI moving along +x")
    ax0.set_ylabel("y (m)")
    ax0.set_title(f"beta = {args.beta:g}, R = {args.radius:g} m, dR/dt = {args.radius_rate:g} m/s,\n"
                  f"v = {args.speed:g} m/s, v_g = {args.poi_speed:g} m/s, r >= {args.tau:g} R", fontsize=10)
    ax0.legend(fontsize=8, loc="upper right")
    ax1.loglog(betas, sweep, "o-", ms=3, label="max |dpsi_d/dt + u_lyap| over r >= tau R")
    ax1.axhline(limit, color="r", ls="--", label=f"v / r_min = {limit:.3g} rad/s")
    ax1.axvline(args.beta, color="0.5", ls=":", label=f"beta = {args.beta:g}")
    ax1.set_xlabel("beta")
    ax1.set_ylabel("rad/s")
    ax1.set_title("Turn rate needed against beta")
    ax1.grid(alpha=0.3, which="both")
    ax1.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "tune.png", dpi=130)
    plt.close(fig)
    verdict = "below" if chosen.max_turn_rate < limit else "ABOVE"
    print(f"beta = {args.beta:g}: max |dpsi_d/dt + u_lyap| = {chosen.max_turn_rate:.4f} rad/s, {verdict} "
          f"v / r_min = {limit:.4f} rad/s (paper, Fig. 9 parameters: 0.378)")
    print(f"wrote {out}/tune.json, tune.png")
    return 0
