"""``vistrack intercept``: optimal interception of a target moving on a circle.

Solves the problem of Manyam et al. (Algorithm 1) from flags or a YAML file and writes the
Figure 7 pair as PNG (travel times of pursuer and target against the arrival angle; the
interception path on the plane) and the numbers as JSON. Defaults are the paper's test
scenario: pursuer at the origin heading 0, target circle centred at (-4, 3), target starting at
alpha_i = pi, speeds 1 and 1.2 m/s; the paper takes rho equal to the circle radius (1 here).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from ..intercept import InterceptProblem
from ..report.intercept import write_intercept
from .output import output_folder
from .types import coordinate, length, number, speed


def register(subparsers: argparse._SubParsersAction) -> None:
    parser = subparsers.add_parser(
        "intercept", help="optimal Dubins interception of a target moving on a circle (Figure 7)",
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--config", type=Path, help="YAML file with any of the keys below (flags override it)")
    parser.add_argument("--pursuer", type=number("--pursuer", -1e7, 1e7), nargs=3, metavar=("X", "Y", "PSI"),
                        help="pursuer x y psi (m, m, rad)")
    parser.add_argument("--rho", type=length("--rho"), help="pursuer minimum turn radius (m)")
    parser.add_argument("--pursuer-speed", dest="pursuer_speed", type=speed("--pursuer-speed"), help="v_p (m/s)")
    parser.add_argument("--center", type=coordinate("--center"), nargs=2, metavar=("CX", "CY"),
                        help="target circle centre (m)")
    parser.add_argument("--radius", type=length("--radius"), help="target circle radius (m)")
    parser.add_argument("--target-angle", dest="target_angle0", type=number("--target-angle", -1e9, 1e9),
                        help="alpha_i, initial target angle (rad)")
    parser.add_argument("--target-speed", dest="target_speed", type=speed("--target-speed"), help="v_t (m/s)")
    parser.add_argument("--direction", choices=["cw", "ccw"], help="target travel direction on the circle")
    parser.add_argument("--tolerance", dest="angle_tolerance", type=number("--tolerance", 1e-15, 3.14159),
                        help="bisection tolerance on the angle (rad)")
    parser.add_argument("--out", type=Path, default=Path("intercept_out"), help="output folder (default intercept_out)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    output_folder(args.out)
    flags = {k: getattr(args, k) for k in ("pursuer", "rho", "pursuer_speed", "center", "radius", "target_angle0",
                                           "target_speed", "direction", "angle_tolerance")}
    problem = InterceptProblem.load(args.config, flags)
    result = problem.solve()
    record = write_intercept(problem, result, args.out)
    i = record["interception"]
    print(f"alpha* = {i['angle']:.6f} rad, T = {i['time']:.6f} s, path {record['path']['word']} "
          f"{record['path']['length']:.6f} m, 4-rho condition: {record['four_rho_condition']} -> {args.out}")
    return 0
