"""Argparse types for lists of numbers: comma-separated values, points, a configuration."""

from __future__ import annotations

import argparse
import math
from typing import Callable

import numpy as np

__all__ = ["configuration", "finite_numbers", "point_list", "positive_numbers"]


def positive_numbers(flag: str, example: str) -> Callable[[str], list[float]]:
    """An argparse type for a comma-separated list of positive numbers, e.g. --spacings 50,25."""

    def parse(text: str) -> list[float]:
        try:
            values = [float(v) for v in text.split(",") if v.strip()]
        except ValueError:
            values = []
        if not values or any(not (v > 0 and math.isfinite(v)) for v in values):
            raise argparse.ArgumentTypeError(f"{flag} = {text}: need positive numbers like {example}")
        return values

    return parse


def point_list(flag: str) -> Callable[[str], np.ndarray]:
    """An argparse type for points "x,y[,z];x,y[,z];..." as an (n, 3) array (NaN for a missing z)."""

    def parse(text: str) -> np.ndarray:
        points = []
        for k, item in enumerate(filter(None, (s.strip() for s in text.split(";")))):
            try:
                values = [float(v) for v in item.split(",")]
            except ValueError:
                raise argparse.ArgumentTypeError(f"{flag}[{k}] = {item!r}: expected x,y or x,y,z numbers") from None
            if len(values) not in (2, 3) or not all(math.isfinite(v) for v in values):
                raise argparse.ArgumentTypeError(f"{flag}[{k}] = {item!r}: expected 2 or 3 finite numbers")
            points.append(values + [math.nan] * (3 - len(values)))
        if not points:
            raise argparse.ArgumentTypeError(f"{flag} = {text!r}: no points")
        return np.array(points)

    return parse


def configuration(flag: str) -> Callable[[str], np.ndarray]:
    """An argparse type for a configuration "X,Y,PSI" (metres, metres, radians)."""

    def parse(text: str) -> np.ndarray:
        try:
            values = [float(v) for v in text.replace(",", " ").split()]
        except ValueError:
            values = []
        if len(values) != 3 or not all(math.isfinite(v) for v in values):
            raise argparse.ArgumentTypeError(f"{flag} = {text}: expected three numbers X,Y,PSI")
        return np.array(values)

    return parse


def finite_numbers(flag: str, count: int, example: str, limit: float = math.inf) -> Callable[[str], list[float]]:
    """An argparse type for exactly ``count`` comma-separated finite numbers, e.g. --wind 0,0.08,
    each within [-limit, limit]."""

    def parse(text: str) -> list[float]:
        try:
            values = [float(v) for v in text.split(",") if v.strip()]
        except ValueError:
            values = []
        if len(values) != count or not all(abs(v) <= limit for v in values):  # NaN and inf fail too
            within = "" if limit == math.inf else f" in [{-limit:g}, {limit:g}]"
            raise argparse.ArgumentTypeError(f"{flag} = {text}: need {count} finite numbers{within} like {example}")
        return values

    return parse
