"""Sweep bases and parameters spelled before the one scenario schema, still read: the vehicle at
the top level (``turn_radius``, ``speed``), the wind by ``speed`` and ``direction_deg``, and the
waypoint kind's gusts as ``true`` or a seed. Each old spelling prints one line on stdout
(:func:`vistrack.scenario_blocks.renamed`) when the sweep is read, and the cases hold the new one;
only a wind varied by its old ``wind.speed`` or ``wind.direction_deg`` is turned into components
when its case runs (:func:`polar_wind`), since either key alone is half of the new pair."""

from __future__ import annotations

import math
from typing import Any, Callable, Mapping, Sequence

from ..scenario_blocks import Rename, renamed, upgrade
from ..schema import fail, number
from .kinds import set_dotted

__all__ = ["POLAR", "WindUpgrade", "gust_seed", "polar_wind", "silent", "upgrade_base", "upgrade_parameter"]

Note = Callable[[str, str], None]
# A kind's upgrade of one wind mapping (the old forms it read), reporting each old form to the note.
WindUpgrade = Callable[[Mapping[str, Any], Note], dict[str, Any]]
POLAR = ("speed", "direction_deg")  # the old polar wind keys


def silent(_old: str, _new: str) -> None:
    """A note that says nothing: a case's own data, once the sweep file was read."""


def polar_wind(value: Mapping[str, Any], note: Note) -> dict[str, Any]:
    """``{speed, direction_deg}`` (the direction the wind blows to, degrees counter-clockwise from
    east) as ``{east, north}``; other keys (gusts) kept."""
    out = dict(value)
    if not any(key in out for key in POLAR):
        return out
    if "east" in out or "north" in out:
        raise fail("wind", dict(value), "give east and north (or the old speed and direction_deg), not both")
    speed = number("wind.speed", out.pop("speed", 0.0), low=0.0)
    angle = math.radians(number("wind.direction_deg", out.pop("direction_deg", 0.0)))
    out["east"], out["north"] = speed * math.cos(angle), speed * math.sin(angle)
    note("wind.speed, wind.direction_deg", "wind.east, wind.north")
    return out


def gust_seed(value: Mapping[str, Any], note: Note) -> dict[str, Any]:
    """The polar wind and the waypoint kind's old gusts: ``true`` (the case's seed) is ``{}``, a seed
    ``s`` is ``{seed: s}`` (the gust model's other keys are the kind's defaults)."""
    out = polar_wind(value, note)
    gusts = out.get("gusts")
    if gusts is True:
        out["gusts"] = {}
        note("wind.gusts: true", "wind.gusts: {}")
    elif isinstance(gusts, int) and not isinstance(gusts, bool):
        out["gusts"] = {"seed": gusts}
        note("wind.gusts: SEED", "wind.gusts: {seed: SEED}")
    return out


def upgrade_base(data: Mapping[str, Any], renames: Sequence[Rename], wind: WindUpgrade) -> dict[str, Any]:
    """A base in the one schema, one line on stdout for each old spelling it used."""
    notes = _Notes()
    out = upgrade(data, renames, notes)
    if isinstance(out.get("wind"), Mapping):
        out["wind"] = wind(out["wind"], notes)
    notes.say()
    return out


def upgrade_parameter(key: str, values: list[Any], renames: Sequence[Rename],
                      wind: WindUpgrade) -> tuple[str, list[Any]]:
    """A varied key and its values in the one schema (one line on stdout for each old spelling).
    ``wind.speed`` and ``wind.direction_deg`` keep their key: :func:`polar_wind` turns the case's
    wind into components when it runs."""
    notes = _Notes()
    for rename in renames:
        if key == rename.old:
            notes(rename.old, rename.new)
            key, values = rename.new, [rename.convert(v) if rename.convert else v for v in values]
            break
    else:
        values = [_section_value(key, value, renames, wind, notes) for value in values]
    if key in (f"wind.{name}" for name in POLAR):
        notes("wind.speed, wind.direction_deg", "wind.east, wind.north")
    elif key == "wind.gusts":
        values = [wind({"gusts": value}, notes)["gusts"] for value in values]
    notes.say()
    return key, values


def _section_value(key: str, value: Any, renames: Sequence[Rename], wind: WindUpgrade, notes: Note) -> Any:
    """A mapping given as the value of a section (``wind``, ``camera``) with its old keys renamed;
    an old key whose new home is another section is refused, naming the parameter to vary instead."""
    if not isinstance(value, Mapping):
        return value
    moved = [r for r in renames if r.old.startswith(f"{key}.") and r.old[len(key) + 1:] in value
             and not r.new.startswith(f"{key}.")]
    if moved:
        raise fail(f"parameters.{key}", dict(value), "; ".join(f"{r.old} is now {r.new}" for r in moved)
                   + ": vary it as a parameter of its own")
    data = upgrade(set_dotted({}, key, value), renames, notes)
    if key == "wind":
        data["wind"] = wind(data["wind"], notes)
    for part in key.split("."):
        data = data[part]
    return data


class _Notes:
    """The old spellings met while reading one base or parameter, each said once."""

    def __init__(self) -> None:
        self.seen: dict[tuple[str, str], None] = {}

    def __call__(self, old: str, new: str) -> None:
        self.seen[(old, new)] = None

    def say(self) -> None:
        for old, new in self.seen:
            renamed(old, new)
