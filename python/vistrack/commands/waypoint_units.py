"""The units of ``vistrack waypoints``: the flight settings its flags ask for, in metres (the
default aircraft on the roll model, L1 legs) or in the waypoint paper's dimensionless units
(--paper-units: its section 3, the Dubins vehicle and law (5)), after checking that the route's
scale fits them."""

from __future__ import annotations

import argparse
from typing import Any

import numpy as np

from .._core import Uav
from ..waypoint_nav.units import ALTITUDE, L1_PERIOD, leg_gains, leg_guidance, route_scale_error, units_uav
from .types import UsageError, fdm_choice, number

__all__ = ["ALTITUDE", "L1_PERIOD", "add_dwn_arguments", "fdm_aircraft", "flight_options"]


def add_dwn_arguments(parser: argparse.ArgumentParser) -> None:
    """DWN's own flags: --replan-interval and --dwn-tracking (refused when no DWN flight flies)."""
    parser.add_argument("--replan-interval", type=number("--replan-interval", 0.0, 3600.0), default=0.0,
                        help="DWN re-plans its turning point every so many s (default 0: when unreachable)")
    parser.add_argument("--dwn-tracking", choices=["auto", "paper", "path"], default="auto",
                        help="how DWN flies its plan: paper (the leg law to each turning point), path (beyond the "
                             "paper: the planned path followed, the roll anticipated); default auto: paper on the "
                             "dubins vehicle, path on the roll model and a 6-DOF aircraft")


def flight_options(args: argparse.Namespace, route: np.ndarray) -> dict[str, Any]:
    """The keyword arguments of :func:`wn.fly` the flags ask for, in metres or the paper's units,
    after checking that the route's scale fits them (UsageError before any output)."""
    paper = args.paper_units
    units = units_uav(paper)
    R = args.turn_radius if args.turn_radius is not None else units.min_turn_radius
    v = args.speed if args.speed is not None else units.speed
    dynamics = fdm_choice(args)[0] or ("dubins" if paper else "roll")
    if getattr(args, "method", "dwn") not in ("dwn", "both", "all"):
        for flag, value, default in (("--replan-interval", args.replan_interval, 0.0),
                                     ("--dwn-tracking", getattr(args, "dwn_tracking", "auto"), "auto")):
            if value != default:
                shown = value if isinstance(value, str) else f"{value:g}"
                raise UsageError(f"{flag} = {shown}: it is DWN's, and --method {args.method} flies no DWN")
    if paper and dynamics != "dubins":
        # The roll model needs g in m/s^2; the paper's units are dimensionless.
        raise UsageError(f"--dynamics = {dynamics}: the waypoint paper's dimensionless units (--paper-units) fly the "
                         "Dubins vehicle only (the roll model needs a route in metres)")
    if (problem := route_scale_error(route, R, paper)) is not None:
        switch = "drop --paper-units" if paper else "pass --paper-units"
        raise UsageError(f"ROUTE = {args.route}: {problem} {switch}")
    gains = tuple(args.gains) if args.gains is not None else leg_gains(paper, R)
    return {"turn_radius": R, "speed": v, "dt": args.dt, "integration": args.integration, "gains": gains,
            "dynamics": dynamics, "roll_time_constant": Uav().roll_time_constant,
            "max_roll_rate_deg_s": Uav().max_roll_rate_deg_s, "guidance": args.guidance or leg_guidance(paper),
            "l1_period": args.l1_period, "wind_aware": args.wind_aware,
            "replan_interval": args.replan_interval, "dwn_tracking": getattr(args, "dwn_tracking", "auto")}


def fdm_aircraft(args: argparse.Namespace) -> str | None:
    """The 6-DOF aircraft of --dynamics jsbsim (None without it); refused in the paper's units."""
    aircraft = fdm_choice(args)[1]
    if aircraft is not None and args.paper_units:
        raise UsageError("--dynamics jsbsim: a 6-DOF aircraft flies routes in metres, not --paper-units")
    return aircraft
