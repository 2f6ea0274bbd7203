"""Dubins waypoint navigation (DWN) against classical waypoint navigation (WN), after Silverberg &
Xu, *Dubins Waypoint Navigation of Small-Class Unmanned Aerial Vehicles* (OJOp 2019).

Both fly on the flight layer (:mod:`vistrack.flight`) with the paper's feedback law (5). WN
steers to the active waypoint and switches inside the waypoint radius R_WP; DWN steers to the
turning point T_n of the horizon (pose, W_n, W_{n+1}) and moves on when T_n enters the
reachability zone; the last waypoint is flown to directly. Every flight ends on the line through
the last waypoint perpendicular to the last leg. With ``wind_aware=True`` DWN plans its turning
points in the air mass of the known mean wind (:func:`air_mass_turning_point`); ``replan_interval``
re-plans the active turning point more often (the paper's option of section 2.1).

- :func:`turning_point` solves the horizon exactly (four turn cases, theta to 1e-12 rad);
  :func:`horizon_path` and :func:`horizon_lengths` give the path and F(theta) of one case.
- :func:`fly` flies a route and returns a :class:`NavigationFlight` with the trajectory and the
  metrics (miss distances, reached, overshoot, swirls, path length, duration, fuel). Its
  ``turning_points`` are the DWN turning points in the order flown: the route an autopilot would
  be given instead of the waypoints. :func:`navigation_guidance` is the guidance it flies, for a vehicle
  flown elsewhere (the 6-DOF aircraft of ``waypoint_nav.fdm``), with :func:`navigation_time_limit`.
- :func:`paper_flights` flies the comparison of the paper's Figures 11 and 12 (DWN, and WN at
  R_WP = 0.1R, 0.5R, R); :func:`theta_against_weight` is Figure 10;
  :func:`monte_carlo` goes beyond the paper: random routes and winds, with and without gusts.

- ``navigation``: the API above; ``study``: the Monte Carlo; routes come in as CSV
  (:func:`vistrack.io.read_route`).

Defaults are the paper's section 3 (R = 0.7, v = 0.8, dt = 0.02, gains g = 0.1, h = 5.25), from
the bound C++ struct :class:`Options` (``DEFAULTS``: the same as a dict).
"""

from __future__ import annotations

from .navigation import (
    CASES,
    DEFAULTS,
    METHODS,
    PAPER_GUST_MODEL,
    PAPER_RADII,
    DubinsWaypointGuidance,
    HorizonPath,
    NavigationFlight,
    Options,
    TurningPoint,
    air_mass_turning_point,
    default_start,
    fly,
    horizon_lengths,
    horizon_path,
    navigation_guidance,
    navigation_metrics,
    navigation_time_limit,
    paper_flights,
    paper_gusts,
    reachability,
    route_array,
    theta_against_weight,
    turning_point,
    turning_points,
)
from .routes import read_route, route_georeference
from .study import MonteCarlo, monte_carlo, random_route

__all__ = [
    "CASES",
    "DEFAULTS",
    "METHODS",
    "PAPER_GUST_MODEL",
    "PAPER_RADII",
    "DubinsWaypointGuidance",
    "HorizonPath",
    "MonteCarlo",
    "NavigationFlight",
    "Options",
    "TurningPoint",
    "air_mass_turning_point",
    "default_start",
    "fly",
    "horizon_lengths",
    "horizon_path",
    "monte_carlo",
    "navigation_guidance",
    "navigation_metrics",
    "navigation_time_limit",
    "paper_flights",
    "paper_gusts",
    "random_route",
    "reachability",
    "read_route",
    "route_array",
    "route_georeference",
    "theta_against_weight",
    "turning_point",
    "turning_points",
]
