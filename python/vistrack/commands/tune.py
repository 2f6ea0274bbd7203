"""``vistrack tune``: choose beta by grid search (section V.D, Figure 9).

For an orbit of radius R changing at dR/dt about a POI of speed v_g, the largest
|dpsi_d/dt + u_lyap| over r >= tau R (all polar angles and heading errors) must stay below the
turn-rate limit v / r_min. Writes tune.json and tune.png (the map at the chosen beta and the
maximum against beta). Defaults are the paper's Figure 9 parameters.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from .. import schema
from ..progress import Progress
from ..report.tune import write_tuning
from ..tracking.tuning import tune_beta
from .output import output_folder
from .types import checked, length, number, speed


def betas(key: str, text: str) -> list[float]:
    """Comma-separated betas, each within beta's range."""
    values = [v for v in text.split(",") if v.strip()]
    if not values:
        raise schema.fail(key, text, "need betas in 1/m like 0.01,0.025,0.05")
    return [schema.beta(key, v) for v in values]


def register(subparsers: argparse._SubParsersAction) -> None:
    p = subparsers.add_parser(
        "tune", help="grid search of the turn rate the guidance needs, to choose beta (Figure 9)",
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    # Figure 9 of the paper (section V.D), not the library's defaults.
    p.add_argument("--radius", type=length("--radius"), default=85.9, help="orbit radius R, m")
    p.add_argument("--radius-rate", type=number("--radius-rate", -1e4, 1e4), default=1.30, help="dR/dt, m/s")
    p.add_argument("--speed", type=speed("--speed"), default=20.0, help="UAV speed v, m/s")
    p.add_argument("--poi-speed", type=number("--poi-speed", 0.0, 1e4), default=5.0, help="POI speed v_g, m/s")
    p.add_argument("--min-turn-radius", type=length("--min-turn-radius"), default=50.0, help="r_min, m")
    p.add_argument("--beta", type=checked("--beta", schema.beta), default=0.025, help="beta for the map, 1/m")
    p.add_argument("--sweep", type=checked("--sweep", betas, numeric=False), default=None,
                   help="betas for the max-vs-beta curve (default: 30 values, log-spaced around --beta)")
    p.add_argument("--tau", type=number("--tau", 0.0, 1.0, low_open=True), default=1.0,
                   help="search r >= tau R (Remark 6), 0 < tau <= 1")
    p.add_argument("--r-max-factor", type=number("--r-max-factor", 0.0, 1e6, low_open=True), default=4.0,
                   help="search r <= factor R")
    p.add_argument("--direction", default="ccw", choices=["ccw", "cw"])
    p.add_argument("--out", default="tune_out", help="output folder (created)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    output_folder(args.out)
    with Progress("beta sweep", unit="beta") as bar:
        tuning = tune_beta(args.radius, args.radius_rate, args.speed, args.poi_speed, args.min_turn_radius,
                           args.beta, args.sweep, tau=args.tau, r_max_factor=args.r_max_factor,
                           direction=args.direction, progress=bar)
    write_tuning(tuning, Path(args.out))
    verdict = "below" if tuning.feasible else "ABOVE"
    print(f"beta = {args.beta:g}: max |dpsi_d/dt + u_lyap| = {tuning.chosen.max_turn_rate:.4f} rad/s, {verdict} "
          f"v / r_min = {tuning.turn_rate_limit:.4f} rad/s (paper, Fig. 9 parameters: 0.378)")
    print(f"wrote {args.out}/tune.json, tune.png")
    return 0
