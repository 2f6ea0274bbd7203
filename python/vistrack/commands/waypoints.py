"""``vistrack waypoints``: Dubins waypoint navigation (DWN) against classical waypoint navigation
(WN) over a route (CSV x,y; a .plan or QGC WPL 110 mission, as --export writes, about --origin or
its home; GeoJSON in lon/lat about --origin). The flight starts at the first waypoint heading to
the second.

Writes metrics.json, one trajectory CSV per flight, the DWN turning points and paths.png (the
paper's Figures 11/12: WN dashed at each waypoint radius, DWN solid). The route is in metres
and the vehicle is the roll model (20 m/s, R 50 m, each leg flown by L1 line tracking) unless
--paper-units asks for the paper's section 3 (dimensionless: R 0.7, v 0.8, dt 0.02, law (5) with
g 0.1, h 5.25, the Dubins vehicle). WN radii 0.1R, 0.5R, R. --figure-weights adds Figure 10,
--monte-carlo N the seeded Monte Carlo over random routes and winds.
"""
from __future__ import annotations

import argparse
from pathlib import Path

from .. import waypoint_nav as wn
from .._core import Uav
from ..flight import Wind
from ..progress import Progress
from ..report.waypoint_nav import write_waypoints
from ..waypoint_nav.fdm import fdm_flights
from .export import add_export_arguments, check_exports, export_mission
from .lists import finite_numbers, positive_numbers
from .output import add_report_arguments, output_folder, report_options
from .types import add_dynamics_argument, coordinate, count, length, number, speed
from .waypoint_units import ALTITUDE, L1_PERIOD, add_dwn_arguments, fdm_aircraft, flight_options


def register(subparsers: argparse._SubParsersAction) -> None:
    d = wn.DEFAULTS
    parser = subparsers.add_parser("waypoints", help="Dubins waypoint navigation against classical WN (Figs. 10-12)",
                                   description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("route", type=Path, help="route: CSV with columns x,y (metres; the paper's units with "
                                                 "--paper-units), a .plan / .waypoints mission, or GeoJSON")
    parser.add_argument("--paper-units", action="store_true", help="the paper's units (R 0.7, v 0.8, law (5), Dubins)")
    parser.add_argument("--method", choices=[*wn.METHODS, "both", "all"], default="both",
                        help="dwn, wn (the paper's), wn_passed_line (ArduPlane's switching, beyond the paper); "
                             "both: dwn and wn (the default); all: the three")
    parser.add_argument("--waypoint-radius", type=positive_numbers("--waypoint-radius", "5,25,50"),
                        help="WN radii in route units, comma-separated (default 0.1R,0.5R,R)")
    parser.add_argument("--wind", type=finite_numbers("--wind", 2, "0,2", 1e4), default=[0.0, 0.0],
                        help="constant wind east,north: the velocity of the air, pointing where it blows to "
                             "(route units per second; default 0,0)")
    parser.add_argument("--gusts", type=count("--gusts", 0, 2**63 - 1), metavar="SEED", help="add Dryden gusts "
                        "with this seed (light turbulence, MIL-F-8785C, see vt.waypoint_nav)")
    parser.add_argument("--turn-radius", type=length("--turn-radius"),
                        help=f"R (default {Uav().min_turn_radius:g} m; {d['turn_radius']} with --paper-units)")
    parser.add_argument("--speed", type=speed("--speed"),
                        help=f"v (default {Uav().speed:g} m/s; {d['speed']} with --paper-units)")
    parser.add_argument("--dt", type=number("--dt", 0.0, 3600.0, low_open=True), default=d["dt"],
                        help=f"step (default {d['dt']})")
    parser.add_argument("--guidance", choices=["l1", "law5"],
                        help="the law on each leg: l1 (L1 line tracking) or law5 (the paper's law (5)); default l1, "
                             "law5 with --paper-units")
    parser.add_argument("--l1-period", type=number("--l1-period", 0.0, 3600.0, low_open=True), default=L1_PERIOD,
                        help=f"guidance l1: the L1 period, s (default {L1_PERIOD:g}, as the follow runs fly)")
    parser.add_argument("--wind-aware", action="store_true", help="the guidance knows the mean wind (--wind): the "
                        "leg law steers the course over the ground, DWN plans its turning points in the air mass")
    add_dwn_arguments(parser)
    parser.add_argument("--gains", type=finite_numbers("--gains", 2, "0.1,5.25"),
                        help="law (5)'s g,h (default the paper's 0.1,5.25, scaled by 0.7 / R in metres)")
    parser.add_argument("--integration", choices=["discrete", "continuous"], default=d["integration"])
    parser.add_argument("--figure-weights", action="store_true", help="also Figure 10 (theta against w_a)")
    parser.add_argument("--monte-carlo", type=count("--monte-carlo", 1, 100000), metavar="N",
                        help="also N seeded random routes and winds")
    parser.add_argument("--seed", type=count("--seed", 0, 2**63 - 1), default=0, help="Monte Carlo seed (default 0)")
    parser.add_argument("--monte-carlo-wind", type=finite_numbers("--monte-carlo-wind", 2, "0,0.2"),
                        default=[0.0, 0.2], help="Monte Carlo wind speeds, fractions of v (default 0,0.2)")
    parser.add_argument("--altitude", type=coordinate("--altitude"), default=ALTITUDE,
                        help=f"flight altitude for --export and the gusts in metres, m (default {ALTITUDE:g})")
    add_export_arguments(parser)
    add_report_arguments(parser)
    add_dynamics_argument(parser, None, fdm=True)
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.add_argument("--out", type=Path, default=Path("waypoints_out"), help="output folder")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    route = wn.read_route(args.route, args.origin, "ROUTE")
    origin = args.origin or wn.route_georeference(args.route, "ROUTE")  # a mission's home places its export
    options, aircraft = flight_options(args, route), fdm_aircraft(args)
    check_exports(args.export, origin, None)  # no origin: an error before any output
    output_folder(args.out)  # a file there is an error now, not after the flights
    east, north = args.wind
    model = None if args.paper_units else {"altitude": args.altitude, "length_unit": 1.0, "speed_unit": 1.0}  # gusts
    wind = Wind(east=east, north=north, gusts=None if args.gusts is None else wn.paper_gusts(args.gusts, model))
    R = options["turn_radius"]
    radii = wn.PAPER_RADII if args.waypoint_radius is None else [r / R for r in args.waypoint_radius]
    methods = {"both": ("dwn", "wn"), "all": wn.METHODS}.get(args.method, (args.method,))
    flights = wn.paper_flights(route, wind=wind, radii=radii, methods=methods, **options)
    weights = wn.theta_against_weight() if args.figure_weights else None
    mc = None
    if args.monte_carlo:
        with Progress("Monte Carlo", not args.quiet, unit="flight pair") as bar:
            mc = wn.monte_carlo(args.monte_carlo, args.seed, wind_fraction=tuple(args.monte_carlo_wind), radii=radii,
                                gust_model=model, progress=bar, **options)
    settings = {**options, "units": "paper" if args.paper_units else "metres", "wind": [east, north],
                "gusts_seed": args.gusts, "radii_over_R": list(radii)}
    six = [] if aircraft is None else fdm_flights(flights, aircraft, wind, args.altitude, options)
    write_waypoints(args.out, flights, wind, str(args.route), settings, weights, mc, report_options(args), six)
    # The mission carries DWN's turning points when DWN flew, else the first WN flight's waypoints.
    export_mission(args.export, lambda ref: flights[0].to_mission(ref, args.altitude, speed=options["speed"]),
                   origin)
    print(f"{options['dynamics']} vehicle, legs by {options['guidance']}, R = {R:g}, v = {options['speed']:g}"
          + ("" if args.paper_units else " (metres, m/s)"))
    for f in flights:
        smooth = f.flight.smoothness()
        print(f"{f.label:>18}: max miss {f.miss_distances.max() / R:.3f} R (the last, at its finish line: "
              f"{f.miss_distances[-1] / R:.3f} R), overshoot {f.overshoot / R:.3f} R, "
              f"swirls {f.swirls}, path {f.path_length:.4g}, time {f.duration:.4g}, all reached {f.all_reached}, "
              f"{smooth.roll_reversals_per_s:.2f} roll reversals/s")
    for f6 in six:
        label = f6.method + ("" if f6.waypoint_radius is None else f" {f6.waypoint_radius / R:g}R")
        print(f"{'6-DOF ' + label:>18}: max miss {f6.summary()['max_miss_over_R']:.3f} R on {aircraft}")
    print(f"-> {args.out}")
    return 0
