"""Scenario files: one YAML document describing a whole tracking run.

A scenario names the environment, the POI's path, the UAV, the sensor, the planning, control and
simulation settings, and optional constant-radius baselines. Every numeric default comes from
the C++ parameter structs (cpp/include/vistrack/parameters.hpp), the single place defaults live;
``vistrack run --print-defaults`` prints a complete scenario with them.

Relative paths inside a scenario file are resolved against the file's own folder.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Mapping, Sequence

import yaml

from ._core import Control, Planning, Sensor, SimulationOptions, Uav, VistrackError

__all__ = ["Scenario", "EnvironmentSpec", "PoiSpec", "default_scenario_text", "road_route"]

DEMO_SCENARIO = Path(__file__).with_name("scenarios") / "demo.yaml"


def road_route(roads: Any, via_points: Sequence[Sequence[float]]) -> list[int]:
    """Road nodes from the node nearest the first point, through the nodes nearest the others,
    joined by shortest routes along the road edges."""
    import numpy as np

    via = [roads.nearest_node(np.asarray(p, dtype=float)) for p in via_points]
    nodes = [via[0]]
    for a, b in zip(via, via[1:]):
        nodes += roads.shortest_route(a, b)[1:]
    return nodes


def _fail(key: str, value: Any, allowed: str) -> VistrackError:
    return VistrackError(f"{key} = {value!r}: {allowed}")


def _number(key: str, value: Any, *, low: float | None = None, high: float | None = None,
            low_open: bool = False) -> float:
    # YAML 1.1 reads 20e6 (no dot) as a string: accept any text float() accepts.
    if isinstance(value, bool):
        raise _fail(key, value, "must be a number")
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise _fail(key, value, "must be a number") from None
    if not math.isfinite(number):
        raise _fail(key, value, "must be a finite number")
    if low is not None and (number < low or (low_open and number == low)):
        bound = f"> {low}" if low_open else f">= {low}"
        raise _fail(key, value, f"must be {bound}" + (f" and <= {high}" if high is not None else ""))
    if high is not None and number > high:
        raise _fail(key, value, f"must be <= {high}")
    return number


def _integer(key: str, value: Any, low: int, high: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise _fail(key, value, f"must be an integer in [{low}, {high}]")
    if not low <= value <= high:
        raise _fail(key, value, f"must be an integer in [{low}, {high}]")
    return value


def _section(data: Mapping[str, Any], name: str, allowed: set[str]) -> dict[str, Any]:
    section = data.get(name) or {}
    if not isinstance(section, Mapping):
        raise _fail(name, section, "must be a mapping of keys to values")
    unknown = sorted(set(section) - allowed)
    if unknown:
        raise _fail(f"{name}.{unknown[0]}", section[unknown[0]],
                    f"unknown key; allowed keys in {name}: {', '.join(sorted(allowed))}")
    return dict(section)


def _resolve(base: Path, value: Any, key: str) -> Path:
    if not isinstance(value, (str, Path)) or not str(value):
        raise _fail(key, value, "must be a file path")
    path = Path(value).expanduser()
    return (path if path.is_absolute() else base / path).resolve()


@dataclass
class EnvironmentSpec:
    """Where the environment comes from: the demo city, a GeoJSON file or a mesh file."""

    kind: str = "demo"  # "demo", "geojson" or "mesh"
    path: Path | None = None
    up: str = "z"

    def load(self):
        from ._core import Environment

        if self.kind == "demo":
            return Environment.demo()
        if self.kind == "geojson":
            return Environment.from_geojson(str(self.path))
        return Environment.from_mesh(str(self.path), up=self.up)

    def describe(self) -> str:
        return "demo city" if self.kind == "demo" else f"{self.kind} {self.path}"


@dataclass
class PoiSpec:
    """The POI's path: a CSV file, explicit waypoints, road-network nodes, or a route along the
    roads through the nodes nearest to given points; and its speed."""

    speed: float = 5.0
    path: Path | None = None
    waypoints: list[list[float]] | None = None
    nodes: list[int] | None = None
    route: list[list[float]] | None = None

    def build(self, env):
        import numpy as np

        from ._core import PoiPath

        if self.path is not None:
            return PoiPath.from_csv(str(self.path), self.speed)
        if self.waypoints is not None:
            return PoiPath(np.asarray(self.waypoints, dtype=float), self.speed)
        if self.nodes is not None:
            return PoiPath.from_nodes(env.roads, self.nodes, self.speed)
        if self.route is not None:
            return PoiPath.from_nodes(env.roads, road_route(env.roads, self.route), self.speed)
        raise VistrackError("poi: no path given (path: CSV, waypoints: [[x, y], ...] or nodes: [...])")


@dataclass
class Scenario:
    """A validated scenario. Build one with Scenario.load(path) or Scenario.from_dict(data)."""

    environment: EnvironmentSpec = field(default_factory=EnvironmentSpec)
    poi: PoiSpec = field(default_factory=PoiSpec)
    uav: Uav = field(default_factory=Uav)
    start: tuple[float, float, float] | None = None  # UAV start (x, y, psi); None: on the orbit
    sensor: Sensor = field(default_factory=Sensor)
    planning: Planning = field(default_factory=Planning)
    control: Control = field(default_factory=Control)
    simulation: SimulationOptions = field(default_factory=SimulationOptions)
    baselines: list[float] = field(default_factory=list)  # constant orbit radii to compare, m
    name: str = "scenario"
    source: Path | None = None

    SECTIONS = ("name", "environment", "poi", "uav", "sensor", "planning", "control",
                "simulation", "baselines")

    @classmethod
    def load(cls, path: str | Path) -> "Scenario":
        """Read and validate a scenario YAML file; errors name the key, the value and the range."""
        path = Path(path)
        try:
            text = path.read_text(encoding="utf-8")
        except OSError as error:
            raise _fail("scenario", str(path), f"cannot read the file ({error.strerror})") from None
        try:
            data = yaml.safe_load(text)
        except yaml.YAMLError as error:
            raise _fail("scenario", str(path), f"not valid YAML ({error})") from None
        scenario = cls.from_dict(data if data is not None else {}, base=path.parent)
        scenario.source = path
        if scenario.name == "scenario":
            scenario.name = path.stem
        return scenario

    @classmethod
    def demo(cls) -> "Scenario":
        """The scenario ``vistrack demo`` runs: the embedded city, no files needed."""
        return cls.load(DEMO_SCENARIO)

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], base: str | Path = ".") -> "Scenario":
        """Validate a scenario given as a mapping (the parsed YAML)."""
        base = Path(base)
        if not isinstance(data, Mapping):
            raise _fail("scenario", data, "must be a mapping with sections " + ", ".join(cls.SECTIONS))
        unknown = sorted(set(data) - set(cls.SECTIONS))
        if unknown:
            raise _fail(unknown[0], data[unknown[0]],
                        "unknown section; allowed sections: " + ", ".join(cls.SECTIONS))
        scenario = cls()
        if "name" in data:
            name = data["name"]
            if not isinstance(name, str) or not re.fullmatch(r"[\w.-]+", name) or set(name) == {"."}:
                raise _fail("name", name, "must be a non-empty name of letters, digits, '_', '-' or '.' "
                                          "(it names the output folder)")
            scenario.name = data["name"]
        scenario.environment = _environment(_section(data, "environment", {"demo", "geojson", "mesh", "up"}), base)
        scenario.poi = _poi(_section(data, "poi", {"path", "waypoints", "nodes", "route", "speed"}), base)
        scenario.uav, scenario.start = _uav(_section(data, "uav", {"speed", "min_turn_radius", "altitude", "start"}))
        scenario.sensor = _sensor(_section(data, "sensor", {"d_max", "altitude_band"}))
        scenario.planning = _planning(_section(
            data, "planning", {"spacing", "cutoff", "resolution_deg", "min_spacing", "max_depth", "rate_margin"}))
        scenario.control = _control(_section(data, "control", {"beta", "k_psi", "direction"}))
        scenario.simulation = _simulation(_section(
            data, "simulation", {"rtol", "atol", "max_step", "output_step"}))
        scenario.baselines = _baselines(data.get("baselines", []))
        if not scenario.uav.speed > scenario.poi.speed:
            raise _fail("uav.speed", scenario.uav.speed,
                        f"must exceed poi.speed = {scenario.poi.speed} (the UAV must outrun the POI)")
        return scenario

    def to_dict(self) -> dict[str, Any]:
        """The scenario as plain data, every default filled in (what --print-defaults shows)."""
        env: dict[str, Any] = {"demo": True} if self.environment.kind == "demo" else {
            self.environment.kind: str(self.environment.path)}
        if self.environment.kind == "mesh":
            env["up"] = self.environment.up
        poi: dict[str, Any] = {"speed": self.poi.speed}
        if self.poi.path is not None:
            poi["path"] = str(self.poi.path)
        if self.poi.waypoints is not None:
            poi["waypoints"] = self.poi.waypoints
        if self.poi.nodes is not None:
            poi["nodes"] = self.poi.nodes
        if self.poi.route is not None:
            poi["route"] = self.poi.route
        band = self.sensor.altitude_band
        return {
            "name": self.name,
            "environment": env,
            "poi": poi,
            "uav": {"speed": self.uav.speed, "min_turn_radius": self.uav.min_turn_radius,
                    "altitude": self.uav.altitude,
                    "start": list(self.start) if self.start is not None else None},
            "sensor": {"d_max": self.sensor.d_max, "altitude_band": list(band) if band else None},
            "planning": {"spacing": self.planning.spacing, "cutoff": self.planning.cutoff,
                         "resolution_deg": self.planning.resolution_deg,
                         "min_spacing": self.planning.min_spacing, "max_depth": self.planning.max_depth,
                         "rate_margin": self.planning.rate_margin},
            "control": {"beta": self.control.beta, "k_psi": self.control.k_psi,
                        "direction": self.control.direction},
            "simulation": {"rtol": self.simulation.rtol, "atol": self.simulation.atol,
                           "max_step": self.simulation.max_step,
                           "output_step": self.simulation.output_step},
            "baselines": list(self.baselines),
        }


def _environment(section: dict[str, Any], base: Path) -> EnvironmentSpec:
    sources = [key for key in ("demo", "geojson", "mesh") if section.get(key) not in (None, False)]
    if not section:
        return EnvironmentSpec()
    if len(sources) != 1:
        raise _fail("environment", section, "give exactly one of demo: true, geojson: FILE, mesh: FILE")
    kind = sources[0]
    if kind == "demo":
        if section["demo"] is not True:
            raise _fail("environment.demo", section["demo"], "must be true")
        if "up" in section:
            raise _fail("environment.up", section["up"], "only applies to environment.mesh")
        return EnvironmentSpec()
    up = section.get("up", "z")
    if up not in ("y", "z"):
        raise _fail("environment.up", up, 'must be "z" or "y"')
    if kind == "geojson" and "up" in section:
        raise _fail("environment.up", up, "only applies to environment.mesh")
    return EnvironmentSpec(kind, _resolve(base, section[kind], f"environment.{kind}"), up)


def _poi(section: dict[str, Any], base: Path) -> PoiSpec:
    spec = PoiSpec()
    if "speed" in section:
        spec.speed = _number("poi.speed", section["speed"], low=0.0, low_open=True)
    sources = [key for key in ("path", "waypoints", "nodes", "route") if key in section]
    if len(sources) > 1:
        raise _fail("poi", section, "give one of path: CSV, waypoints: [[x, y], ...], nodes: [...], "
                                    "route: [[x, y], ...]")
    if not sources:
        return spec  # PoiSpec.build says what is missing when the scenario is run
    key = sources[0]
    value = section[key]
    if key == "path":
        spec.path = _resolve(base, value, "poi.path")
    elif key in ("waypoints", "route"):
        if not isinstance(value, list) or len(value) < 2:
            raise _fail(f"poi.{key}", value, "must be a list of at least two points")
        points = []
        for i, point in enumerate(value):
            sizes = (2, 3) if key == "waypoints" else (2,)
            if not isinstance(point, list) or len(point) not in sizes:
                raise _fail(f"poi.{key}[{i}]", point, "must be [x, y] or [x, y, z]" if key == "waypoints" else "must be [x, y]")
            points.append([_number(f"poi.{key}[{i}][{k}]", c) for k, c in enumerate(point)])
        setattr(spec, key, points)
    else:
        if not isinstance(value, list) or len(value) < 2:
            raise _fail("poi.nodes", value, "must be a list of at least two road-node indices")
        spec.nodes = [_integer(f"poi.nodes[{i}]", n, 0, 10**9) for i, n in enumerate(value)]
    return spec


def _apply(target: Any, section: dict[str, Any], prefix: str,
           checks: dict[str, Callable[[str, Any], Any]]) -> Any:
    for key, check in checks.items():
        if key in section:
            setattr(target, key, check(f"{prefix}.{key}", section[key]))
    target.validate()
    return target


def _positive(key: str, value: Any) -> float:
    return _number(key, value, low=0.0, low_open=True)


def _uav(section: dict[str, Any]) -> tuple[Uav, tuple[float, float, float] | None]:
    uav = _apply(Uav(), section, "uav", {"speed": _positive, "min_turn_radius": _positive,
                                         "altitude": lambda k, v: _number(k, v)})
    start = section.get("start")
    if start is not None:
        if not isinstance(start, list) or len(start) != 3:
            raise _fail("uav.start", start, "must be [x, y, psi] (metres, metres, radians)")
        start = tuple(_number(f"uav.start[{i}]", c) for i, c in enumerate(start))
    return uav, start


def _sensor(section: dict[str, Any]) -> Sensor:
    sensor = Sensor()
    if "d_max" in section:
        sensor.d_max = _positive("sensor.d_max", section["d_max"])
    band = section.get("altitude_band")
    if band is not None:
        if not isinstance(band, list) or len(band) != 2:
            raise _fail("sensor.altitude_band", band, "must be [h_lo, h_hi] in metres, or null")
        sensor.altitude_band = (_number("sensor.altitude_band[0]", band[0]),
                                _number("sensor.altitude_band[1]", band[1]))
    sensor.validate()
    return sensor


def _planning(section: dict[str, Any]) -> Planning:
    return _apply(Planning(), section, "planning", {
        "spacing": _positive, "cutoff": _positive,
        "resolution_deg": lambda k, v: _number(k, v, low=0.1, high=30.0),
        "min_spacing": _positive,
        "max_depth": lambda k, v: _integer(k, v, 0, 30),
        "rate_margin": lambda k, v: _number(k, v, low=0.0)})  # < 1: checked by Planning.validate


def _control(section: dict[str, Any]) -> Control:
    def direction(key: str, value: Any) -> str:
        if value not in ("ccw", "cw"):
            raise _fail(key, value, 'must be "ccw" or "cw"')
        return value

    return _apply(Control(), section, "control", {"beta": _positive, "k_psi": _positive,
                                                  "direction": direction})


def _simulation(section: dict[str, Any]) -> SimulationOptions:
    return _apply(SimulationOptions(), section, "simulation", {
        "rtol": lambda k, v: _number(k, v, low=0.0, high=1.0, low_open=True),
        "atol": _positive, "max_step": _positive, "output_step": _positive})


def _baselines(value: Any) -> list[float]:
    if value is None:
        return []
    if not isinstance(value, list):
        raise _fail("baselines", value, "must be a list of orbit radii in metres")
    return [_positive(f"baselines[{i}]", r) for i, r in enumerate(value)]


def default_scenario_text() -> str:
    """A complete scenario with every default written out (the demo city and route)."""
    scenario = Scenario.demo()
    scenario.name = "scenario"
    return yaml.safe_dump(scenario.to_dict(), sort_keys=False)
