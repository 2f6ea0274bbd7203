"""The ``waypoints`` case kind: one flight of Dubins waypoint navigation (DWN) or classical
waypoint navigation (WN) over a route (:func:`vistrack.waypoint_nav.fly`, what ``vistrack
waypoints`` flies per method), in a wind the guidance does not know unless ``wind_aware``.

Its base is a mapping (inline or a YAML file) of :func:`~vistrack.waypoint_nav.fly`'s settings in
the shared ``uav`` and ``wind`` blocks. Like ``vistrack waypoints`` it works in metres and m/s
unless ``units: paper`` asks for the waypoint paper's dimensionless set; missing keys take the
defaults of those units::

    units: metres                   # metres: the default aircraft (vt.Uav: 20 m/s, R 50 m) on the
                                    # roll model, each leg flown by L1 (period 8 s), law (5)'s gains
                                    # scaled by 0.7 / R; gusts in metres at uav.altitude (60 m).
                                    # paper: section 3 (R 0.7, v 0.8, law (5) with g 0.1, h 5.25,
                                    # the Dubins vehicle; gusts read with 1 = 20 m, 1 s)
    route: waypoints_metres.csv     # CSV x,y; or waypoints: [[x, y], ...];
                                    # or random_route: {count: 6, legs: [4, 10], seed: 0} (legs in
                                    # units of R, as vt.waypoint_nav.random_route; no seed: the case's)
    start: null                     # [x, y, psi]; null: at the first waypoint, heading to the second
    method: dwn                     # dwn | wn | wn_passed_line
    waypoint_radius: null           # WN's R_WP (null: R)
    uav: {speed: 20, min_turn_radius: 50, altitude: 60, dynamics: roll}   # paper: {speed: 0.8,
                                    # min_turn_radius: 0.7}, the Dubins vehicle only
    dt: 0.02
    gains: null                     # law (5)'s [g, h]; null: the paper's, scaled by 0.7 / R in metres
    guidance: null                  # l1 | law5; null: l1 in metres, law5 in the paper's units
    l1_period: 8.0
    wind_aware: false               # the guidance knows the mean wind (DWN plans in the air mass)
    replan_interval: 0.0            # DWN re-plans every so many s (0: at the reachability switch)
    weights: [1.0, 1.0]
    integration: discrete           # discrete | continuous
    max_time: null
    wind: {east: 0.0, north: 0.0, gusts: null}  # gusts: {seed, intensity, length_scale} (Dryden);
                                                # missing keys: the gust model of the units
                                                # (vt.waypoint_nav.paper_gusts) seeded by the case

A route in metres whose longest leg is under 2 R, or one in the paper's units longer than 100 R,
is refused naming ``route`` (the other units are likely meant), as the command does.

Spellings from before the one schema still load, one line on stdout each: ``turn_radius`` and
``speed`` (now ``uav.min_turn_radius``, ``uav.speed``), ``wind: {speed, direction_deg}`` (now
``east``, ``north``), ``gusts: true`` (now ``{}``) and ``gusts: SEED`` (now ``{seed: SEED}``).

To fly several methods or winds over the same random route and gusts, vary ``random_route.seed``
(and give ``wind.gusts`` a seed) as parameters: cases without them draw from their own seeds.

Metrics: ``fly(...).metrics()`` without its lists (miss distances per waypoint, turning points),
plus ``waypoints``, ``route_length``, ``path_ratio`` (flown length over the route's) and
``mean_miss_over_R``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Mapping, Optional

import numpy as np

from .. import waypoint_nav as wn
from ..flight import Wind
from ..io import read_route
from ..scenario_blocks import Rename, uav_block, wind_block
from ..schema import fail, integer, number, pair, positive, reject_unknown, resolve_path
from ..waypoint_nav.units import L1_PERIOD, leg_gains, leg_guidance, route_scale_error, units_uav
from .kinds import (
    CaseContext,
    CaseKind,
    CaseOutput,
    dotted_keys,
    overlay,
    read_base,
    register_kind,
    set_case_value,
)
from .spellings import gust_seed, silent, upgrade_base, upgrade_parameter

__all__ = ["RENAMES", "WAYPOINTS"]

_SOURCES = ("route", "waypoints", "random_route")
_SETTINGS = ("units", "start", "method", "waypoint_radius", "uav", "dt", "gains", "weights", "integration", "max_time",
             "wind", "guidance", "l1_period", "wind_aware", "replan_interval")
_UAV = ("speed", "min_turn_radius", "altitude", "dynamics")
_UNITS = ("metres", "paper")
_WIND = ("east", "north", "gusts")
_GUSTS = ("seed", "intensity", "length_scale")
_RANDOM = ("count", "legs", "seed")
_METRICS = ("method", "label", "waypoint_radius", "waypoints", "route_length", "max_miss_over_R",
            "mean_miss_over_R", "all_reached", "finished", "swirls", "overshoot", "overshoot_over_R", "undershoot",
            "undershoot_over_R", "path_length", "path_ratio", "duration", "fuel")
# Spellings from before the one scenario schema, still read (and wind's, by spellings.gust_seed).
RENAMES = (Rename("turn_radius", "uav.min_turn_radius"), Rename("speed", "uav.speed"))


def _base(value: Any, folder: Path) -> dict[str, Any]:
    data, folder = read_base(value, folder, "a waypoint-navigation mapping")
    full = _defaults(upgrade_base(data, RENAMES, gust_seed), folder)
    _flight_inputs(full, folder, seed=0)  # validates the base
    return full


def _defaults(data: Mapping[str, Any], folder: Path) -> dict[str, Any]:
    """The base with every setting present (the paper's defaults: the bound Options') and file
    paths absolute."""
    reject_unknown(data, (*_SOURCES, *_SETTINGS))
    units = data.get("units", "metres")
    if units not in _UNITS:
        raise fail("units", units, 'must be "metres" or "paper"')
    d, calm = wn.Options(), Wind()
    # uav: the units' defaults fill it when a case flies (units_uav), so that units may vary too.
    full: dict[str, Any] = {"units": units, "start": None, "method": d.method, "waypoint_radius": None, "uav": {},
                            "dt": d.dt, "gains": None, "weights": list(d.weights), "integration": d.integration,
                            "max_time": None, "wind": {"east": calm.east, "north": calm.north, "gusts": None},
                            "guidance": None, "l1_period": L1_PERIOD, "wind_aware": False,
                            "replan_interval": d.replan_interval}
    overlay(full, {k: v for k, v in data.items() if k in _SETTINGS})  # a block given in part keeps the rest
    sources = [k for k in _SOURCES if data.get(k) is not None]
    if len(sources) != 1:
        raise fail("route", {k: data.get(k) for k in _SOURCES},
                   "give exactly one of route: CSV, waypoints: [[x, y], ...], random_route: {count, legs}")
    key = sources[0]
    full[key] = str(resolve_path(folder, data[key], "route")) if key == "route" else data[key]
    return full


def _keys(base: Mapping[str, Any]) -> set[str]:
    return (dotted_keys(base) | set(_SOURCES) | {f"uav.{k}" for k in _UAV} | {f"wind.{k}" for k in _WIND}
            | {f"wind.gusts.{k}" for k in _GUSTS} | {f"random_route.{k}" for k in _RANDOM}
            | {"wind.speed", "wind.direction_deg"})  # the old polar wind, turned into east, north


def _apply(data: dict[str, Any], key: str, value: Any) -> dict[str, Any]:
    return set_case_value(data, key, value, _SOURCES)


def _parameter(key: str, values: list[Any]) -> tuple[str, list[Any]]:
    return upgrade_parameter(key, values, RENAMES, gust_seed)


def _route(data: Mapping[str, Any], folder: Path, seed: int, turn_radius: float) -> np.ndarray:
    if data.get("route") is not None:
        return read_route(resolve_path(folder, data["route"], "route"), "route")
    if data.get("waypoints") is not None:
        return wn.route_array(data["waypoints"], "waypoints")
    spec = data.get("random_route")
    if not isinstance(spec, Mapping) or set(spec) - set(_RANDOM):
        raise fail("random_route", spec, "must be {count: n, legs: [low, high], seed: s} (legs in units of R)")
    count = integer("random_route.count", spec.get("count", 6), 2, 10_000)
    legs = pair("random_route.legs", spec.get("legs", [4.0, 10.0]), "a pair [a, b]")
    if not 0.0 < legs[0] <= legs[1]:
        raise fail("random_route.legs", spec.get("legs"), "must be 0 < low <= high")
    if spec.get("seed") is not None:
        seed = integer("random_route.seed", spec["seed"], 0, 2**63 - 1)
    return wn.random_route(np.random.default_rng(seed), count, turn_radius, legs)


def _wind(value: Any, seed: int, model: Optional[dict[str, float]]) -> Wind:
    """The shared wind block; gusts given in part take the rest from the gust model of the units
    (``model`` for wn.paper_gusts), seeded by the case (a wind varied by the old wind.speed or
    direction_deg is turned into components)."""
    if not isinstance(value, Mapping):
        raise fail("wind", value, "must be {east, north, gusts}")
    wind = gust_seed(value, silent)
    if isinstance(wind.get("gusts"), Mapping):
        paper = wn.paper_gusts(seed, model)
        defaults = {"seed": paper.seed, "intensity": paper.intensity, "length_scale": paper.length_scale}
        wind["gusts"] = {**defaults, **wind["gusts"]}
    return wind_block({"wind": wind})


def _flight_inputs(data: Mapping[str, Any], folder: Path, seed: int) -> tuple[np.ndarray, dict[str, Any]]:
    """The route and fly()'s keyword arguments, validated (errors name the key and the value)."""
    units = data.get("units", "metres")
    if units not in _UNITS:
        raise fail("units", units, 'must be "metres" or "paper"')
    paper = units == "paper"
    uav = uav_block(data, units_uav(paper)).uav
    given = data.get("uav", {}).get("dynamics") if isinstance(data.get("uav"), Mapping) else None
    if paper and given is not None and str(uav.dynamics) != "dubins":
        # The roll model needs g in m/s^2; the paper's units are dimensionless.
        raise fail("uav.dynamics", given, "the waypoint paper's dimensionless units (units: paper) fly the Dubins "
                                          "vehicle only")
    R = uav.min_turn_radius
    model = None if paper else {"altitude": uav.altitude, "length_unit": 1.0, "speed_unit": 1.0}
    gains = data.get("gains")
    guidance = data.get("guidance") or leg_guidance(paper)
    options: dict[str, Any] = {
        "method": data["method"], "turn_radius": R, "speed": uav.speed, "dt": positive("dt", data["dt"]),
        "gains": pair("gains", gains, "a pair [a, b]") if gains is not None else leg_gains(paper, R),
        "weights": pair("weights", data["weights"], "a pair [a, b]"), "integration": data["integration"],
        "wind": _wind(data["wind"], seed, model), "guidance": guidance,
        "l1_period": positive("l1_period", data.get("l1_period", L1_PERIOD)),
        "wind_aware": data.get("wind_aware", False),
        "replan_interval": number("replan_interval", data.get("replan_interval", 0.0), low=0.0),
    }
    if not paper:
        options.update({"dynamics": str(uav.dynamics), "roll_time_constant": uav.roll_time_constant,
                        "max_roll_rate_deg_s": uav.max_roll_rate_deg_s})
    if options["method"] not in wn.METHODS:
        raise fail("method", options["method"], "must be one of " + ", ".join(f'"{m}"' for m in wn.METHODS))
    if options["integration"] not in ("discrete", "continuous"):
        raise fail("integration", options["integration"], 'must be "discrete" or "continuous"')
    if guidance not in ("l1", "law5"):
        raise fail("guidance", guidance, 'must be "l1" or "law5"')
    if not isinstance(options["wind_aware"], bool):
        raise fail("wind_aware", options["wind_aware"], "must be true or false")
    if data.get("waypoint_radius") is not None:
        options["waypoint_radius"] = positive("waypoint_radius", data["waypoint_radius"])
    if data.get("max_time") is not None:
        options["max_time"] = positive("max_time", data["max_time"])
    if data.get("start") is not None:
        start = data["start"]
        if not isinstance(start, list) or len(start) != 3:
            raise fail("start", start, "must be [x, y, psi] or null")
        options["start"] = tuple(number(f"start[{i}]", c) for i, c in enumerate(start))
    route = _route(data, folder, seed, R)
    if (problem := route_scale_error(route, R, paper)) is not None:
        given = data.get("route") or ("random_route" if data.get("random_route") is not None else "waypoints")
        raise fail("route", given, problem + (" drop units: paper" if paper else " set units: paper"))
    return route, options


def _run(data: dict[str, Any], context: CaseContext) -> CaseOutput:
    route, options = _flight_inputs(data, context.folder, context.seed)
    flight = wn.fly(route, **options)
    metrics = {k: v for k, v in flight.metrics().items() if not isinstance(v, list)}
    route_length = float(np.sum(np.linalg.norm(np.diff(route, axis=0), axis=1)))  # through the waypoints
    metrics.update({"waypoints": len(route), "route_length": route_length,
                    "path_ratio": flight.path_length / route_length if route_length > 0 else None,
                    "mean_miss_over_R": float(np.mean(flight.miss_distances) / flight.turn_radius)})
    return CaseOutput(metrics)


WAYPOINTS = register_kind(CaseKind(
    name="waypoints",
    description="Dubins (DWN) or classical (WN) waypoint navigation over a route in unknown wind (vistrack waypoints)",
    load_base=_base, keys=_keys, run=_run, apply=_apply, metric_names=_METRICS,
    figure_metrics=("max_miss_over_R", "mean_miss_over_R", "swirls", "overshoot_over_R", "path_ratio", "duration"),
    route_key="waypoints",  # routes of a road file (routes.roads) become the waypoints
    upgrade_parameter=_parameter,
))
