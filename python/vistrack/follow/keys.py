"""Parsing of the follow scenario's newer keys (issue 31): ``follow.threshold`` ("auto" or h) and
the ``reports`` block (the vehicle's 1 Hz reports as both followers get them)."""

from __future__ import annotations

import math
from typing import Any, Mapping

from ..schema import fail, number, section
from .simulation import VehicleReportOptions

__all__ = ["REPORT_KEYS", "reports_block", "threshold_value"]


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


def reports_block(data: Mapping[str, Any]) -> VehicleReportOptions:
    """``reports``: noise (m, m/s; standard deviations per axis), latency (s), dropout (a
    probability), timeout (s) and seed of the vehicle's 1 Hz reports; the core names a bad value."""
    r = section(data, "reports", set(REPORT_KEYS))
    values: dict[str, Any] = {k: number(f"reports.{k}", r[k]) for k in REPORT_KEYS[:5] if k in r}
    if "seed" in r:
        values["seed"] = int(number("reports.seed", r["seed"], low=0.0, high=2.0 ** 63))
    return VehicleReportOptions(**values)
