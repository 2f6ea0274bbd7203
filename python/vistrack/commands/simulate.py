"""``vistrack simulate``: the closed loop of section VI around an orbit plan.

Writes trajectory.csv (one sample per line), metrics.json, trajectory.png (Figure 10 style: the
UAV's path over the city with the reference orbits) and errors.png (Figure 11 style: radial
error, heading error and control against time). With ``--map`` the line of sight UAV -> POI is
evaluated at every sample; ``--baseline-radius`` adds the same loop around constant-radius orbits.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from .. import _core, schema
from ..io import load_environment, read_plan
from ..report.simulation import write_simulation
from ..scenario_blocks import DEFAULT_DYNAMICS, uav_dict
from ..tracking.metrics import CONVERGE_AFTER
from ..tracking.pipeline import simulate_with_baselines, start_on_orbit
from .lists import configuration
from .output import output_folder
from .types import add_dynamics_argument, checked, coordinate, length, number, speed


def fixed_step(key: str, value: object) -> float:
    """0 (adaptive steps) or a step in [1e-9, 1e9] s, as simulate() takes it."""
    step = schema.number(key, value, low=0.0, high=1e9)
    if 0.0 < step < 1e-9:
        raise schema.fail(key, value, "must be 0 (adaptive steps) or in [1e-9, 1e9] s")
    return step


def register(subparsers: argparse._SubParsersAction) -> None:
    p = subparsers.add_parser(
        "simulate", help="closed-loop simulation of the UAV around an orbit plan",
        description="The UAV (roll or Dubins model) steered by the guidance law (86) around the plan's "
        "time-varying orbit (section VI). Writes trajectory.csv, metrics.json, trajectory.png and errors.png.")
    uav, control, options = _core.Uav(), _core.Control(), _core.SimulationOptions()
    p.add_argument("--plan", required=True, help="orbit plan JSON (vistrack orbits writes plan.json)")
    p.add_argument("--out", default="simulate_out", help="output folder (created)")
    p.add_argument("--map", help="city for line-of-sight evaluation: .geojson footprints or a mesh")
    p.add_argument("--up", default="z", choices=["z", "y"], help="up axis of a mesh file (y: north is -Z)")
    p.add_argument("--speed", type=speed("--speed"), default=uav.speed, help="UAV speed v, m/s")
    p.add_argument("--min-turn-radius", type=length("--min-turn-radius"), default=uav.min_turn_radius, help="r_min, m")
    p.add_argument("--altitude", type=coordinate("--altitude"), default=uav.altitude, help="h_UAV, m")
    add_dynamics_argument(p, DEFAULT_DYNAMICS)
    p.add_argument("--beta", type=checked("--beta", schema.beta), default=control.beta,
                   help="beta of the vector field, 1/m")
    p.add_argument("--k-psi", type=checked("--k-psi", schema.heading_gain), default=control.k_psi,
                   help="heading gain k_psi, 1/s")
    p.add_argument("--direction", default=control.direction, choices=["ccw", "cw"], help="circulation")
    p.add_argument("--x0", type=configuration("--x0"), help="start X,Y,PSI (default: on the first orbit east of "
                   "the POI)")
    p.add_argument("--rtol", type=checked("--rtol", schema.relative_tolerance), default=options.rtol)
    p.add_argument("--atol", type=checked("--atol", schema.absolute_tolerance), default=options.atol)
    p.add_argument("--max-step", type=number("--max-step", 1e-9, 1e9), default=options.max_step, help="s")
    p.add_argument("--output-step", type=number("--output-step", 1e-6, 1e9), default=options.output_step, help="s")
    p.add_argument("--fixed-step", type=checked("--fixed-step", fixed_step), default=0.0,
                   help="fixed integration step, s (0: adaptive)")
    p.add_argument("--baseline-radius", type=length("--baseline-radius"), action="append", default=[],
                   help="also simulate constant-radius orbits of this radius (repeatable)")
    p.add_argument("--window", type=number("--window", 0.0, 1e9, low_open=True), default=None,
                   help="errors.png shows only the first WINDOW s")
    p.add_argument("--converge-after", type=number("--converge-after", 0.0, 1e9), default=CONVERGE_AFTER,
                   help="metrics of errors after this time, s")
    p.add_argument("--title", default="", help="figure title")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    output_folder(args.out)
    plan = read_plan(args.plan, "--plan")
    uav = _core.Uav(speed=args.speed, min_turn_radius=args.min_turn_radius, altitude=args.altitude,
                    dynamics=args.dynamics)
    control = _core.Control(beta=args.beta, k_psi=args.k_psi, direction=args.direction)
    options = _core.SimulationOptions(rtol=args.rtol, atol=args.atol, max_step=args.max_step,
                                      output_step=args.output_step)
    env = load_environment(args.map, args.up) if args.map else None
    scene = _core.VisibilityScene(env) if env is not None else None  # one BVH for every run
    x0 = args.x0 if args.x0 is not None else start_on_orbit(plan, control.direction)
    runs = simulate_with_baselines(plan, x0, uav, control, options, scene, args.baseline_radius, args.fixed_step)
    header = {"plan": str(args.plan), "x0": [float(v) for v in x0],
              "uav": uav_dict(uav),
              "control": {"beta": control.beta, "k_psi": control.k_psi, "direction": control.direction},
              "lemma7_min_gain": _core.lemma7_min_gain(uav.speed, control.beta)}
    summary = write_simulation(Path(args.out), runs, env, header, args.converge_after,
                               uav.speed / uav.min_turn_radius, args.title, args.window)
    for label, *_ in runs:
        m = summary[label]
        vis = "" if m["visibility_fraction"] is None else f", visible {100 * m['visibility_fraction']:.1f}%"
        print(f"{label}: {m['samples']} samples, {m['rhs_evaluations']} RHS evaluations in {m['seconds'] * 1e3:.1f} "
              f"ms; |r - R| <= {m['radial_error_after_max_abs_m']:.3g} m after {args.converge_after:g} s{vis}")
    print(f"wrote {args.out}/trajectory.csv, metrics.json, trajectory.png, errors.png")
    return 0
