"""Parsing of follow scenario keys: the vehicle's legs (headings as compass words or degrees),
``follow.threshold`` ("auto" or h), the ``reports`` block (the vehicle's 1 Hz reports as both
followers get them) and the ``city_orbit`` block (the city orbit's options)."""

from __future__ import annotations

import dataclasses
import math
from typing import Any, Mapping, Optional

from .._core import Control
from .._core import limits as _limits
from ..schema import beta as schema_beta
from ..schema import boolean, fail, heading_gain, number, positive, reject_unknown, section
from .city_orbit import CityOrbitOptions
from .simulation import VehicleLeg, VehicleReportOptions

__all__ = ["HEADINGS", "REPORT_KEYS", "STRATEGIES", "city_orbit_block", "reports_block", "threshold_value",
           "vehicle_legs"]

# Compass words as angles counter-clockwise from east (radians).
HEADINGS = {name: math.radians(deg) for name, deg in (
    ("east", 0.0), ("northeast", 45.0), ("north", 90.0), ("northwest", 135.0), ("west", 180.0),
    ("southwest", -135.0), ("south", -90.0), ("southeast", -45.0))}


STRATEGIES = ("paper", "standoff", "auto")  # follow.strategy (FollowStrategy in the core)


def threshold_value(key: str, value: Any) -> float | str:
    """follow.threshold: "auto" (picked from the camera; the default) or the paper's h, a speed ratio > 1."""
    if value == "auto":
        return "auto"
    try:
        h = number(key, value)
    except ValueError:
        h = math.nan
    if not h > 1.0:
        raise fail(key, value, 'must be "auto" or a number > 1 (a speed ratio v_p / v_g; the paper\'s is 3)')
    return h


REPORT_KEYS = ("position_noise", "velocity_noise", "latency", "dropout", "timeout", "seed")


def baseline_block(data: Mapping[str, Any]) -> tuple[Optional[float], Optional[Control]]:
    """The file's baseline: its constant radius (None: Lemma 6's) and control, or (None, None) for
    ``baseline: false``."""
    if data.get("baseline") is False:
        return None, None
    b = section(data, "baseline", {"radius", "beta", "k_psi", "direction"})
    radius = number("baseline.radius", b.get("radius", 0.0), low=0.0)
    d = Control()
    control = Control(beta=schema_beta("baseline.beta", b.get("beta", d.beta)),
                      k_psi=heading_gain("baseline.k_psi", b.get("k_psi", d.k_psi)),
                      direction=str(b.get("direction", d.direction)))
    return (radius or None), control


def reports_block(data: Mapping[str, Any]) -> VehicleReportOptions:
    """``reports``: noise (m, m/s; standard deviations per axis), latency (s), dropout (a
    probability), timeout (s) and seed of the vehicle's 1 Hz reports; the core names a bad value."""
    r = section(data, "reports", set(REPORT_KEYS))
    values: dict[str, Any] = {k: number(f"reports.{k}", r[k]) for k in REPORT_KEYS[:5] if k in r}
    if "seed" in r:
        values["seed"] = int(number("reports.seed", r["seed"], low=0.0, high=2.0 ** 63))
    return VehicleReportOptions(**values)


def city_orbit_block(data: Mapping[str, Any]) -> CityOrbitOptions:
    """``city_orbit``: the city orbit's options, every field of ``CityOrbitOptions`` by its name
    (lookahead a list of seconds); its ``validate`` names a bad value."""
    options = CityOrbitOptions()
    for key, value in section(data, "city_orbit", {f.name for f in dataclasses.fields(options)}).items():
        name = f"city_orbit.{key}"
        default = getattr(options, key)
        if key == "off_centre_max_speed":  # a speed, or null for none
            value = None if value is None else number(name, value, low=0.0)
        elif isinstance(default, bool):
            value = boolean(name, value)
        elif isinstance(default, float):
            value = number(name, value)
        elif key == "horizon":  # whole seconds
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
                    or value != int(value):
                raise fail(name, value, "must be a whole number of seconds")
            value = int(value)
        elif key == "lookahead":
            if not isinstance(value, list) or not value:
                raise fail(name, value, "must be a non-empty list of times (s)")
            value = tuple(number(f"{name}[{i}]", t) for i, t in enumerate(value))
        elif not isinstance(value, str):
            raise fail(name, value, "must be text")
        setattr(options, key, value)
    options.validate()
    return options


def _heading(key: str, leg: Mapping[str, Any]) -> float:
    if "heading" in leg and "heading_deg" in leg:
        raise fail(key, leg, "give heading (a compass word) or heading_deg, not both")
    if "heading" in leg:
        word = leg["heading"]
        if not isinstance(word, str) or word.lower() not in HEADINGS:
            raise fail(f"{key}.heading", word, f"must be one of {', '.join(HEADINGS)} (or use heading_deg)")
        return HEADINGS[word.lower()]
    # The angle limit (|a| <= MAX_ANGLE rad), in the degrees the key is given in.
    limit = math.degrees(_limits.MAX_ANGLE)
    return math.radians(number(f"{key}.heading_deg", leg.get("heading_deg", 0.0), low=-limit, high=limit))


def vehicle_legs(items: Any) -> list[VehicleLeg]:
    """vehicle.legs: [{heading | heading_deg, speed, duration, end_speed}, ...] as VehicleLegs."""
    if not isinstance(items, list) or not items:
        raise fail("vehicle.legs", items, "must be a non-empty list of legs")
    legs = []
    allowed = {"heading", "heading_deg", "speed", "duration", "end_speed"}
    for i, leg in enumerate(items):
        key = f"vehicle.legs[{i}]"
        if not isinstance(leg, Mapping):
            raise fail(key, leg, "must be a mapping with heading, speed, duration")
        reject_unknown(leg, allowed, f"{key}.")
        speed = number(f"{key}.speed", leg.get("speed", 0.0), low=0.0)
        end = leg.get("end_speed")
        legs.append(VehicleLeg(_heading(key, leg), speed, positive(f"{key}.duration", leg.get("duration")),
                               None if end is None else number(f"{key}.end_speed", end, low=0.0)))
    return legs
