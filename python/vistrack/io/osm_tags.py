"""OpenStreetMap tags to building heights and drivable roads: pure functions, no I/O.

The rules follow the OSM wiki's Simple 3D Buildings
(https://wiki.openstreetmap.org/wiki/Simple_3D_Buildings) and Key:highway
(https://wiki.openstreetmap.org/wiki/Key:highway):

- the top: ``height`` (else ``building:height``), a length in metres unless a unit says otherwise
  (``m``, ``ft``/``feet``, ``'`` and ``"`` as in ``12'6"``); a value that does not parse or is not
  positive is counted as bad and ignored. Else ``building:levels`` x ``level_height`` plus the roof:
  ``roof:height`` if tagged, else ``roof:levels`` x ``level_height``, else ``roof_height``. Else
  ``default_height``.
- the base: ``min_height`` (a length), else ``building:min_level`` x ``level_height``; 0 otherwise.
  Tagged tops (``height``, ``building:levels``) are measured from the ground, as the wiki says
  ("height: distance between the lowest possible position with ground contact and the top of the
  roof"; ``building:levels`` counts the levels from the ground, ``building:min_level`` the levels
  skipped under a part), so a tagged top at or below the base is a contradiction (skipped). A part
  with a base and no tagged top takes ``default_height`` above its base (top = base +
  ``default_height``): the default stands for the part's unknown extent, and a part known to
  exist above its base is not dropped for want of a height.
- a road's direction (https://wiki.openstreetmap.org/wiki/Key:oneway): ``oneway`` ``yes`` /
  ``true`` / ``1`` driven in the way's node order only, ``-1`` against it only, ``no`` (or any
  other value: ``reversible`` and ``alternating`` change with the time of day) both ways; absent,
  ``junction=roundabout`` / ``circular`` and ``highway=motorway`` imply ``oneway=yes`` (the wiki's
  implied values), every other way is two-way.
- a drivable road: ``highway`` in :data:`DRIVABLE` (motorway to residential, unclassified,
  living_street, service and the ``_link`` roads); not footways, cycleways, steps, paths.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Optional

__all__ = ["DRIVABLE", "Height", "building_height", "oneway", "parse_count", "parse_length", "road_skip_reason"]

_MAIN_ROADS = ("motorway", "trunk", "primary", "secondary", "tertiary")
DRIVABLE = frozenset(_MAIN_ROADS + tuple(f"{road}_link" for road in _MAIN_ROADS)
                     + ("residential", "unclassified", "living_street", "service"))

_FEET = 0.3048
_INCH = 0.0254
_NUMBER = r"[0-9]+(?:\.[0-9]*)?|\.[0-9]+"
_METRIC = re.compile(rf"^\s*({_NUMBER})\s*(m|metres|meters)?\s*$", re.IGNORECASE)
_FEET_WORD = re.compile(rf"^\s*({_NUMBER})\s*(ft|feet|foot)\s*$", re.IGNORECASE)
_FEET_INCHES = re.compile(rf"^\s*(?:({_NUMBER})\s*')?\s*(?:({_NUMBER})\s*\")?\s*$")


def parse_length(text: str, allow_zero: bool = False) -> Optional[float]:
    """A length tag in metres: ``12``, ``12.5 m``, ``40 ft``, ``40 feet``, ``12'``, ``12'6"``;
    None when the text is none of these or not positive (0 allowed with ``allow_zero``: a base
    ``min_height=0`` is on the ground) (the caller counts it as bad)."""
    value: Optional[float] = None
    if match := _METRIC.match(text):
        value = float(match.group(1))
    elif match := _FEET_WORD.match(text):
        value = float(match.group(1)) * _FEET
    elif (match := _FEET_INCHES.match(text)) and (match.group(1) or match.group(2)):
        value = float(match.group(1) or 0.0) * _FEET + float(match.group(2) or 0.0) * _INCH
    if value is None or value < 0.0 or (value == 0.0 and not allow_zero):
        return None
    return value


def parse_count(text: str) -> Optional[float]:
    """A level count (``building:levels``, ``building:min_level``, ``roof:levels``): a
    non-negative number; None otherwise."""
    try:
        value = float(text.strip())
    except ValueError:
        return None
    return value if 0.0 <= value < 1e4 else None


@dataclass
class Height:
    """A building's top and base (metres above the ground), where the top came from ("height",
    "levels" or "default") and the tags that were present but bad (their keys)."""

    top: float
    base: float
    source: str
    bad: list[str] = field(default_factory=list)


def _length_tag(tags: Mapping[str, str], key: str, bad: list[str], allow_zero: bool = False) -> Optional[float]:
    if key not in tags:
        return None
    value = parse_length(tags[key], allow_zero)
    if value is None:
        bad.append(key)
    return value


def _count_tag(tags: Mapping[str, str], key: str, bad: list[str]) -> Optional[float]:
    if key not in tags:
        return None
    value = parse_count(tags[key])
    if value is None:
        bad.append(key)
    return value


def building_height(tags: Mapping[str, str], level_height: float, roof_height: float,
                    default_height: float) -> Height:
    """The top and base of one building or building part from its tags (the rules above)."""
    bad: list[str] = []
    top = _length_tag(tags, "height", bad)
    alternative = _length_tag(tags, "building:height", bad)
    source = "height"
    if top is None:
        top = alternative
    if top is None:
        levels = _count_tag(tags, "building:levels", bad)
        if levels is not None and levels > 0:
            roof = _length_tag(tags, "roof:height", bad)
            if roof is None:
                roof_levels = _count_tag(tags, "roof:levels", bad)
                roof = roof_height if roof_levels is None else roof_levels * level_height
            top, source = levels * level_height + roof, "levels"
    base = _length_tag(tags, "min_height", bad, allow_zero=True)
    if base is None:
        min_level = _count_tag(tags, "building:min_level", bad)
        base = 0.0 if min_level is None else min_level * level_height
    if top is None:
        top, source = base + default_height, "default"  # the default extent, above the base
    return Height(top, base, source, bad)


def _negative_layer(tags: Mapping[str, str]) -> bool:
    try:
        return int(tags.get("layer", "0").strip()) < 0
    except ValueError:
        return False


def road_skip_reason(tags: Mapping[str, str]) -> Optional[str]:
    """Why a drivable way is not a road on the ground plane: "tunnel", "covered" or
    "below_ground" (a negative ``layer``), else None. Such ways pass under buildings."""
    if tags.get("tunnel", "no") != "no":
        return "tunnel"
    if tags.get("covered", "no") != "no":
        return "covered"
    if _negative_layer(tags):
        return "below_ground"
    return None


_FORWARD = ("yes", "true", "1")
_IMPLIED_ONEWAY = {("junction", "roundabout"), ("junction", "circular"), ("highway", "motorway")}


def oneway(tags: Mapping[str, str]) -> int:
    """A way's direction from its tags (the rule above): 1 forward only, -1 backward only, 0 both."""
    value = tags.get("oneway")
    if value is None:
        return 1 if any(tags.get(key) == v for key, v in _IMPLIED_ONEWAY) else 0
    value = value.strip().lower()
    return 1 if value in _FORWARD else -1 if value == "-1" else 0
