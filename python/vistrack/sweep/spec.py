"""Sweep files: a base case of one kind, the parameters to vary and how to combine them.

```yaml
name: altitude-dmax            # names the output folder (default: the file's name)
kind: tracking                 # a registered case kind (vistrack.sweep.KINDS)
base: ../python/vistrack/scenarios/demo.yaml   # a file (relative to this one) or a mapping
parameters:                    # dotted keys of the base, each with its values:
  uav.altitude: [180, 200, 220]                        # a list
  sensor.d_max: {start: 250, stop: 350, step: 50}      # a range, stop included
  control.beta: {start: 0.01, stop: 0.05, num: 5}      # evenly spaced
  control.k_psi: {random: uniform, low: 10, high: 30, count: 4}   # seeded draws (also normal:
                                                       # mean, std; integers: low, high; choice: values)
routes:                        # optional: every road route between chosen nodes, as parameter "route"
  roads: roads.geojson         # a road file (default: the base map's road network)
  nodes: [0, 8, 72, 80]        # or points: [[x, y], ...] (the nearest nodes), or nodes: all
  ordered: false               # true: both directions
  sample: 20                   # optional: a seeded random subset of the routes
  height: 0.5                  # optional: the POI's height above the ground (default: none, z = 0)
combine: grid                  # grid (every combination) or zip (i-th value of each)
seed: 0                        # random draws and the seeds handed to cases
metrics: [simulation.visibility_fraction, plan.*]      # columns kept (default: all)
cache: vv-cache                # optional VV disk cache folder shared by the workers (tracking)
out: results                   # optional output folder (default ./vistrack-out/<name>)
```
Relative paths are taken from the sweep file's folder. Errors name the key and the value.
"""

from __future__ import annotations

import difflib
import itertools
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping, Optional, Sequence

import numpy as np

from .._core import RoadNetwork, VistrackError
from ..io import read_roads, read_yaml_mapping
from ..schema import fail, integer, number, output_name, reject_unknown, resolve_path
from .case_list import CaseList
from .kinds import CaseKind, get_kind

__all__ = ["MAX_CASES", "Case", "Route", "SweepSpec"]

MAX_CASES = 1_000_000
ROUTE = "route"  # the parameter a routes section adds
_KEYS = ("name", "kind", "base", "parameters", "routes", "combine", "seed", "metrics", "cache", "out")


@dataclass(frozen=True)
class Case:
    """One case of a sweep, plain data (what a Dask task receives)."""

    index: int
    kind: str
    parameters: dict[str, Any]  # the varied values, as they go into the table
    data: dict[str, Any]  # the base with this case's values set
    folder: str  # the sweep file's folder, for relative paths
    seed: int
    metrics: tuple[str, ...] = ()  # kept metric names or patterns; empty: all
    cache_dir: Optional[str] = None


@dataclass(frozen=True)
class Route:
    """A road route: its label "from-to" (node indices) and its points along the roads."""

    label: str
    points: list[list[float]]


@dataclass
class SweepSpec:
    """A validated sweep. Build one with SweepSpec.load(path) or SweepSpec.from_dict(data, folder)."""

    kind: CaseKind
    base: dict[str, Any]
    folder: Path
    name: str = "sweep"
    parameters: dict[str, list[Any]] = field(default_factory=dict)
    routes: dict[str, Route] = field(default_factory=dict)  # by label, when the sweep has routes
    combine: str = "grid"
    seed: int = 0
    metrics: tuple[str, ...] = ()
    cache: Optional[Path] = None
    out: Optional[Path] = None
    source: Optional[Path] = None

    @classmethod
    def load(cls, path: str | Path) -> "SweepSpec":
        """Read and validate a sweep file."""
        file = Path(path)
        spec = cls.from_dict(read_yaml_mapping(file, "sweep"), file.resolve().parent, default_name=file.stem)
        spec.source = file
        return spec

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], folder: str | Path = ".", default_name: str = "sweep") -> "SweepSpec":
        """Validate a sweep given as a mapping; relative paths are taken from ``folder``."""
        folder = Path(folder).resolve()
        if not isinstance(data, Mapping):
            raise fail("sweep", data, "must be a mapping with keys " + ", ".join(_KEYS))
        reject_unknown(data, _KEYS)
        kind = get_kind(data.get("kind", "tracking"))
        if "base" not in data:
            raise fail("base", None, f"required: the base case of kind {kind.name} (a file or a mapping)")
        try:
            base = kind.load_base(data["base"], folder)
        except VistrackError as error:
            raise VistrackError(f"base: {error}") from None
        spec = cls(kind, base, folder, name=output_name("name", data.get("name", default_name)))
        spec.seed = integer("seed", data.get("seed", 0), 0, 2**63 - 1)
        spec.combine = data.get("combine", "grid")
        if spec.combine not in ("grid", "zip"):
            raise fail("combine", spec.combine, 'must be "grid" or "zip"')
        parameters = _parameters(data.get("parameters"), kind, base, spec.seed)
        if "routes" in data:
            # The other parameters first: the case count is known before any route is computed.
            others = math.prod(len(v) for v in parameters.values()) if spec.combine == "grid" else 1
            spec.routes = _routes(data["routes"], kind, base, folder, spec.seed, others)
            spec.parameters[ROUTE] = list(spec.routes)
        spec.parameters.update(parameters)
        if not spec.parameters:
            raise fail("parameters", data.get("parameters"), "give at least one parameter to vary (or routes)")
        spec.metrics = _metrics(data.get("metrics"), kind)
        if data.get("cache") is not None:
            spec.cache = resolve_path(folder, data["cache"], "cache")
        if data.get("out") is not None:
            spec.out = resolve_path(folder, data["out"], "out")
        if spec.combine == "zip":
            lengths = {name: len(values) for name, values in spec.parameters.items()}
            if len(set(lengths.values())) > 1:
                raise fail("combine", "zip", f"needs as many values for every parameter; got {lengths}")
        if spec.case_count > MAX_CASES:
            raise fail("parameters", f"{spec.case_count} cases", f"at most {MAX_CASES} cases in one sweep")
        return spec

    @property
    def case_count(self) -> int:
        """The number of cases."""
        lengths = [len(values) for values in self.parameters.values()]
        return math.prod(lengths) if self.combine == "grid" else (lengths[0] if lengths else 0)

    def cases(self) -> CaseList[Case]:
        """Every case, in index order (grid: the last parameter varies fastest), built one at a
        time as they are read (:class:`~vistrack.sweep.case_list.CaseList`)."""
        return CaseList(list(self.parameters.values()), self.combine, self.case)

    def case(self, index: int, values: Sequence[Any]) -> Case:
        """Case ``index`` of the parameters' ``values`` (in the parameters' order): the base with
        them set (a copy)."""
        names = list(self.parameters)
        data = self.base
        for name, value in zip(names, values):
            if name == ROUTE:
                data = self.kind.set(data, self.kind.route_key or "", self.routes[value].points)
            else:
                data = self.kind.set(data, name, value)
        return Case(index, self.kind.name, dict(zip(names, values)), data, str(self.folder),
                    case_seed(self.seed, index), self.metrics, None if self.cache is None else str(self.cache))

    def describe(self) -> dict[str, Any]:
        """The sweep as plain data (sweep.json)."""
        return {"name": self.name, "kind": self.kind.name, "source": None if self.source is None else str(self.source),
                "cases": self.case_count, "combine": self.combine, "seed": self.seed,
                "parameters": self.parameters, "metrics": list(self.metrics),
                "routes": {label: route.points for label, route in self.routes.items()},
                "base": self.base}


def case_seed(seed: int, index: int) -> int:
    """The seed handed to case ``index`` (independent streams from one sweep seed)."""
    return int(np.random.SeedSequence(seed, spawn_key=(1, index)).generate_state(1)[0])


def _parameters(data: Any, kind: CaseKind, base: Mapping[str, Any], seed: int) -> dict[str, list[Any]]:
    if data is None:
        return {}
    if not isinstance(data, Mapping):
        raise fail("parameters", data, "must be a mapping of dotted keys to values")
    allowed = kind.keys(base)
    parameters: dict[str, list[Any]] = {}
    for position, (key, value) in enumerate(data.items()):
        values = _values(f"parameters.{key}", value, np.random.SeedSequence(seed, spawn_key=(0, position)))
        if kind.upgrade_parameter is not None and isinstance(key, str):  # an old spelling as the new one
            key, values = kind.upgrade_parameter(key, values)
        if key in parameters:
            raise fail(f"parameters.{key}", value, "given twice (once in its old spelling)")
        if key not in allowed:
            close = difflib.get_close_matches(str(key), sorted(allowed), n=3)
            hint = f"; did you mean {', '.join(close)}?" if close else ""
            raise fail(f"parameters.{key}", value, f"not a key of a {kind.name} case{hint}")
        parameters[key] = values
    return parameters


def _values(key: str, value: Any, seeds: np.random.SeedSequence) -> list[Any]:
    """A parameter's values from a list, a range, evenly spaced numbers or seeded draws."""
    if isinstance(value, list):
        if not value:
            raise fail(key, value, "must hold at least one value")
        return value
    if not isinstance(value, Mapping):
        raise fail(key, value, "must be a list of values, {start, stop, step}, {start, stop, num} or "
                               "{random: uniform|normal|integers|choice, ..., count}")
    if "random" in value:
        return _draws(key, value, np.random.default_rng(seeds))
    keys = set(value)
    if keys == {"start", "stop", "step"}:
        start, stop = number(f"{key}.start", value["start"]), number(f"{key}.stop", value["stop"])
        step = number(f"{key}.step", value["step"], low=0.0, low_open=True)
        if stop < start:
            raise fail(f"{key}.stop", value["stop"], f"must be >= start = {value['start']}")
        count = math.floor((stop - start) / step + 1e-9) + 1  # stop included despite rounding (0.3 / 0.1)
        if count > MAX_CASES:
            raise fail(f"{key}.step", value["step"], f"gives {count} values, more than {MAX_CASES}")
        if all(isinstance(value[k], int) for k in ("start", "step")):
            return [int(value["start"]) + i * int(value["step"]) for i in range(count)]
        return [start + i * step for i in range(count)]
    if keys == {"start", "stop", "num"}:
        start, stop = number(f"{key}.start", value["start"]), number(f"{key}.stop", value["stop"])
        count = integer(f"{key}.num", value["num"], 1, MAX_CASES)
        return [float(v) for v in np.linspace(start, stop, count)]
    raise fail(key, dict(value), "a range is {start, stop, step} or {start, stop, num}; "
                                 "draws are {random: ..., count: n}")


_DRAWS = {"uniform": ("low", "high"), "normal": ("mean", "std"), "integers": ("low", "high"), "choice": ("values",)}


def _draws(key: str, value: Mapping[str, Any], rng: np.random.Generator) -> list[Any]:
    law = value["random"]
    if not isinstance(law, str) or law not in _DRAWS:  # a mapping or list is unhashable: name it
        raise fail(f"{key}.random", law, "must be one of " + ", ".join(_DRAWS))
    expected = {"random", "count", *_DRAWS[law]}
    if set(value) != expected:
        raise fail(key, dict(value), f"random: {law} takes exactly " + ", ".join(sorted(expected)))
    count = integer(f"{key}.count", value["count"], 1, MAX_CASES)
    if law == "choice":
        options = value["values"]
        if not isinstance(options, list) or not options:
            raise fail(f"{key}.values", options, "must be a non-empty list")
        return [options[i] for i in rng.integers(0, len(options), count)]
    if law == "integers":
        low = integer(f"{key}.low", value["low"], -(2**62), 2**62)
        high = integer(f"{key}.high", value["high"], low, 2**62)
        return [int(v) for v in rng.integers(low, high, count, endpoint=True)]
    a = number(f"{key}.{_DRAWS[law][0]}", value[_DRAWS[law][0]])
    if law == "uniform":
        b = number(f"{key}.high", value["high"], low=a)
        return [float(v) for v in rng.uniform(a, b, count)]
    b = number(f"{key}.std", value["std"], low=0.0)
    return [float(v) for v in rng.normal(a, b, count)]


def _metrics(data: Any, kind: CaseKind) -> tuple[str, ...]:
    if data is None:
        return ()
    if not isinstance(data, list) or not all(isinstance(m, str) and m for m in data):
        raise fail("metrics", data, "must be a list of metric names (fnmatch patterns allowed)")
    for pattern in data:
        kind.check_metric(pattern)
    return tuple(data)


def _routes(data: Any, kind: CaseKind, base: Mapping[str, Any], folder: Path, seed: int,
            others: int = 1) -> dict[str, Route]:
    """The routes between the chosen nodes; their number (times ``others``, the cases of the other
    parameters) is checked against MAX_CASES before any route is computed."""
    if not isinstance(data, Mapping):
        raise fail("routes", data, "must be a mapping (roads, nodes or points, ordered, sample)")
    reject_unknown(data, {"roads", "nodes", "points", "ordered", "sample", "height"}, "routes.")
    if kind.route_key is None:
        raise fail("routes", dict(data), f"kind {kind.name} has no road route to vary")
    if data.get("roads") is not None:
        roads = read_roads(resolve_path(folder, data["roads"], "routes.roads"))
    elif kind.roads is not None:
        roads = kind.roads(base, folder)
    else:
        raise fail("routes.roads", None, f"required: kind {kind.name} has no map road network")
    count = len(roads.nodes)
    if count < 2:
        raise fail("routes.roads", data.get("roads", "the map's road network"), "has fewer than two road nodes")
    nodes = _route_nodes(data, roads)
    ordered = data.get("ordered", False)
    if not isinstance(ordered, bool):
        raise fail("routes.ordered", ordered, "must be true or false")
    n = len(nodes)
    total = n * (n - 1) if ordered else n * (n - 1) // 2
    if total == 0:
        raise fail("routes.nodes", nodes, "needs at least two different nodes")
    size = total if data.get("sample") is None else integer("routes.sample", data["sample"], 1, total)
    if size * others > MAX_CASES:
        given = data.get("nodes", f"{n} nodes nearest the points")
        raise fail("routes.nodes" if data.get("sample") is None else "routes.sample",
                   given if data.get("sample") is None else size,
                   f"gives {size} routes x {others} cases of the other parameters = {size * others} cases, more "
                   f"than {MAX_CASES} (checked before any route is computed): choose fewer nodes or draw "
                   "routes.sample of them")
    if data.get("sample") is not None:
        rng = np.random.default_rng(np.random.SeedSequence(seed, spawn_key=(2,)))
        pairs = [_pair(nodes, int(i), ordered) for i in sorted(rng.choice(total, size, replace=False))]
    else:
        pairs = list(itertools.permutations(nodes, 2) if ordered else itertools.combinations(nodes, 2))
    # A mesh map's ground is geometry: a POI at z = 0 on it lies inside it; give it a height.
    height = [] if data.get("height") is None else [number("routes.height", data["height"], low=0.0)]
    routes = {}
    xy = np.asarray(roads.nodes)
    for a, b in pairs:
        try:
            path = roads.shortest_route(a, b)
        except VistrackError as error:
            raise VistrackError(f"routes: no road route from node {a} to node {b} ({error})") from None
        routes[f"{a}-{b}"] = Route(f"{a}-{b}", [[float(xy[n, 0]), float(xy[n, 1]), *height] for n in path])
    return routes


def _pair(nodes: Sequence[int], index: int, ordered: bool) -> tuple[int, int]:
    """The ``index``-th pair of itertools.permutations(nodes, 2) (ordered) or
    itertools.combinations(nodes, 2), without listing the others."""
    n = len(nodes)
    if ordered:
        first, j = divmod(index, n - 1)
        return nodes[first], nodes[j if j < first else j + 1]
    first = 0
    while index >= n - 1 - first:  # combinations: n - 1 - first pairs start at nodes[first]
        index -= n - 1 - first
        first += 1
    return nodes[first], nodes[first + 1 + index]


def _route_nodes(data: Mapping[str, Any], roads: RoadNetwork) -> list[int]:
    count = len(roads.nodes)
    if ("nodes" in data) == ("points" in data):
        raise fail("routes", dict(data), "give one of nodes: [...] (or all) and points: [[x, y], ...]")
    if "points" in data:
        points = data["points"]
        if not isinstance(points, list):
            raise fail("routes.points", points, "must be a list of [x, y] points")
        nodes = []
        for i, point in enumerate(points):
            if not isinstance(point, list) or len(point) != 2:
                raise fail(f"routes.points[{i}]", point, "must be [x, y]")
            xy = np.array([number(f"routes.points[{i}][{k}]", c) for k, c in enumerate(point)])
            nodes.append(roads.nearest_node(xy))
    elif data["nodes"] == "all":
        nodes = list(range(count))
    else:
        if not isinstance(data["nodes"], list):
            raise fail("routes.nodes", data["nodes"], "must be a list of road-node indices or all")
        nodes = [integer(f"routes.nodes[{i}]", n, 0, count - 1) for i, n in enumerate(data["nodes"])]
    return list(dict.fromkeys(nodes))  # each node once, in the given order
