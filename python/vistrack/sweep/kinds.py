"""The registry of case kinds a sweep can run, and the dotted-key helpers they share.

A kind says how to read a sweep's ``base`` (validated once, kept as plain data), which dotted keys
a parameter may set, how to run one case (validating the case's own values, so a bad value fails
that case only) and what flat metrics it returns. Kinds: ``tracking`` (the map-to-report
pipeline, :mod:`vistrack.sweep.tracking`); other planners register theirs with
:func:`register_kind`.
"""

from __future__ import annotations

import copy
import fnmatch
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Mapping, Optional

from .._core import RoadNetwork, VistrackError
from ..io import read_yaml_mapping
from ..preview import preview
from ..schema import fail, resolve_path
from .resources import Resources

__all__ = ["KINDS", "CaseContext", "CaseKind", "CaseOutput", "dotted_keys", "flatten", "get_kind", "overlay",
           "register_kind", "set_dotted"]

Metrics = dict[str, Any]


@dataclass
class CaseContext:
    """What a case runs with besides its data: the sweep file's folder (relative paths), the
    case's seed, the worker's heavy objects and the sweep's VV cache folder (None: no disk cache)."""

    folder: Path
    seed: int
    resources: Resources
    cache_dir: Optional[Path] = None


@dataclass
class CaseOutput:
    """What one case returns: its metrics (flat, dotted names, deterministic) and run metadata that
    may differ between runs of the same case (cache hits...), written as ``run_<name>`` columns."""

    metrics: Metrics
    meta: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class CaseKind:
    """One kind of case.

    - ``load_base(data, folder)``: the sweep's ``base`` (a mapping, or a file path string relative
      to ``folder``) validated and returned as plain data with every default filled in and paths
      absolute.
    - ``keys(base)``: the dotted keys a parameter may set.
    - ``apply(base, key, value)``: a copy of the data with one key set (no validation).
    - ``run(data, context)``: validate the case's data, run it, return its output.
    - ``metric_names``: the metrics it returns (``*`` where names depend on the case).
    - ``figure_metrics``: the metrics drawn by default in the summary figures.
    - ``roads(base, folder)``: the base map's road network (for ``routes`` without a road file).
    - ``route_key``: the dotted key a road route's [[x, y], ...] points are written to.
    - ``upgrade_parameter(key, values)``: a varied key spelled before the one scenario schema, and
      its values, as the new key and values (:mod:`vistrack.sweep.spellings`).
    """

    name: str
    description: str
    load_base: Callable[[Any, Path], dict[str, Any]]
    keys: Callable[[Mapping[str, Any]], set[str]]
    run: Callable[[dict[str, Any], CaseContext], CaseOutput]
    metric_names: tuple[str, ...]
    figure_metrics: tuple[str, ...]
    apply: Optional[Callable[[dict[str, Any], str, Any], dict[str, Any]]] = None
    roads: Optional[Callable[[Mapping[str, Any], Path], RoadNetwork]] = None
    route_key: Optional[str] = None
    upgrade_parameter: Optional[Callable[[str, list[Any]], tuple[str, list[Any]]]] = None

    def set(self, data: dict[str, Any], key: str, value: Any) -> dict[str, Any]:
        """``data`` with ``key`` set to ``value`` (a copy)."""
        return self.apply(data, key, value) if self.apply is not None else set_dotted(data, key, value)

    def check_metric(self, pattern: str) -> None:
        """VistrackError unless ``pattern`` (a name, or an fnmatch pattern) can match a metric."""
        if not any(fnmatch.fnmatchcase(name, pattern) or fnmatch.fnmatchcase(pattern, name)
                   for name in self.metric_names):
            raise VistrackError(f"metrics = {preview(pattern)}: no such metric of kind {self.name}; it returns "
                                + ", ".join(self.metric_names))


KINDS: dict[str, CaseKind] = {}


def register_kind(kind: CaseKind) -> CaseKind:
    """Add a kind to the registry (its name is the sweep file's ``kind:``)."""
    KINDS[kind.name] = kind
    return kind


def get_kind(name: Any) -> CaseKind:
    """The registered kind of that name; VistrackError naming ``kind`` and the known kinds."""
    if not isinstance(name, str) or name not in KINDS:
        raise VistrackError(f"kind = {preview(name)}: unknown case kind; known kinds: {', '.join(sorted(KINDS))}")
    return KINDS[name]


WIND_FORMS = (("east", "north"), ("speed", "direction_deg"))  # two ways to give a constant wind


def set_case_value(data: Mapping[str, Any], key: str, value: Any, sources: tuple[str, ...]) -> dict[str, Any]:
    """:func:`set_dotted`, keeping one way to give each thing: setting (a key under) one of the
    exclusive top-level ``sources`` drops the others, and setting ``wind.east``/``north`` drops
    ``wind.speed``/``direction_deg`` (and the other way round)."""
    result = set_dotted(data, key, value)
    top, _, name = key.partition(".")
    if top in sources:
        for other in sources:
            if other != top:
                result.pop(other, None)
    for form, other_form in (WIND_FORMS, WIND_FORMS[::-1]):
        if top == "wind" and name in form:
            for other in other_form:
                result["wind"].pop(other, None)
    return result


def read_base(value: Any, folder: Path, what: str) -> tuple[dict[str, Any], Path]:
    """A kind's ``base``: a mapping (copied) or the path of a YAML file of one (relative to
    ``folder``); with the folder its relative paths resolve against. VistrackError naming ``base``
    otherwise (``what`` says what the mapping holds)."""
    if isinstance(value, str):
        path = resolve_path(folder, value, "base")
        return dict(read_yaml_mapping(path, "base")), path.parent
    if isinstance(value, Mapping):
        return copy.deepcopy(dict(value)), folder
    raise fail("base", value, f"must be {what} or a YAML file of one")


def overlay(base: dict[str, Any], given: Mapping[str, Any]) -> None:
    """Set ``given``'s keys in ``base``; a block (mapping) given where ``base`` has one keeps the
    base's other keys."""
    for key, value in given.items():
        both = isinstance(base.get(key), dict) and isinstance(value, Mapping)
        base[key] = {**base[key], **value} if both else value


def set_dotted(data: Mapping[str, Any], key: str, value: Any) -> dict[str, Any]:
    """A deep copy of ``data`` with the dotted ``key`` (``uav.altitude``) set to ``value``;
    missing intermediate mappings are created."""
    result = copy.deepcopy(dict(data))
    parts = key.split(".")
    node = result
    for part in parts[:-1]:
        child = node.get(part)
        if not isinstance(child, dict):
            child = {}
            node[part] = child
        node = child
    node[parts[-1]] = copy.deepcopy(value)
    return result


def flatten(data: Mapping[str, Any], prefix: str = "") -> Metrics:
    """Nested mappings as one level with dotted keys (lists and scalars are values)."""
    flat: Metrics = {}
    for key, value in data.items():
        name = f"{prefix}{key}"
        if isinstance(value, Mapping):
            flat.update(flatten(value, name + "."))
        else:
            flat[name] = value
    return flat


def dotted_keys(data: Mapping[str, Any], prefix: str = "") -> set[str]:
    """Every dotted key of nested mappings: the mappings themselves and their leaves."""
    keys: set[str] = set()
    for key, value in data.items():
        name = f"{prefix}{key}"
        keys.add(name)
        if isinstance(value, Mapping):
            keys |= dotted_keys(value, name + ".")
    return keys
