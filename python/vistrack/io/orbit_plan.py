"""Orbit plans as JSON, plain (``vistrack.orbit_plan/1``) or with the VPs
(``vistrack.visibility_orbit_plan/1``)."""

from __future__ import annotations

from pathlib import Path
from typing import Union

from .._core import OrbitPlan, VisibilityOrbitPlan
from .documents import parse_json
from .text import read_text

__all__ = ["AnyPlan", "read_plan", "write_plan"]

AnyPlan = Union[OrbitPlan, VisibilityOrbitPlan]


def read_plan(path: str | Path, key: str = "plan") -> AnyPlan:
    """An orbit plan JSON file, by its ``format``: a VisibilityOrbitPlan (``vistrack orbits``,
    ``vistrack run``) or a plain OrbitPlan (times, radii and the POI path)."""
    text = read_text(path, key)
    data = parse_json(text, key, path)
    if isinstance(data, dict) and data.get("format") == "vistrack.visibility_orbit_plan/1":
        return VisibilityOrbitPlan.from_json(text)
    return OrbitPlan.from_json(text)


def write_plan(plan: AnyPlan, path: str | Path) -> Path:
    """The plan as JSON (what :func:`read_plan` reads back)."""
    file = Path(path)
    file.write_text(plan.to_json(), encoding="utf-8")
    return file
