"""Orbit plans as JSON, plain (``vistrack.orbit_plan/1``) or with the VPs
(``vistrack.visibility_orbit_plan/1``)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Union

from .._core import OrbitPlan, VisibilityOrbitPlan, VistrackError
from .text import read_text

__all__ = ["AnyPlan", "read_plan", "write_plan"]

AnyPlan = Union[OrbitPlan, VisibilityOrbitPlan]


def read_plan(path: str | Path, key: str = "plan") -> AnyPlan:
    """An orbit plan JSON file, by its ``format``: a VisibilityOrbitPlan (``vistrack orbits``,
    ``vistrack run``) or a plain OrbitPlan (times, radii and the POI path)."""
    text = read_text(path, key)
    try:
        data = json.loads(text)
    except json.JSONDecodeError as error:
        raise VistrackError(f"{key} = {path}: not JSON ({error.msg} at line {error.lineno})") from None
    except RecursionError:
        raise VistrackError(f"{key} = {path}: not JSON (nested too deeply)") from None
    except ValueError:  # after JSONDecodeError, its subclass: integers of more than 4300 digits
        raise VistrackError(f"{key} = {path}: not JSON (a number too long to read)") from None
    if isinstance(data, dict) and data.get("format") == "vistrack.visibility_orbit_plan/1":
        return VisibilityOrbitPlan.from_json(text)
    return OrbitPlan.from_json(text)


def write_plan(plan: AnyPlan, path: str | Path) -> Path:
    """The plan as JSON (what :func:`read_plan` reads back)."""
    file = Path(path)
    file.write_text(plan.to_json(), encoding="utf-8")
    return file
