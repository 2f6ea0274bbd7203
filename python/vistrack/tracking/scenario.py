"""Scenario files: one YAML document describing a whole tracking run.

A scenario names the environment, the POI's path, the UAV, the sensor, the planning, control and
simulation settings, and optional constant-radius baselines. Every numeric default comes from
the C++ parameter structs (cpp/include/vistrack/<area>_parameters.hpp), the single place defaults live;
``vistrack run --print-defaults`` prints a complete scenario with them.

Relative paths inside a scenario file are resolved against the file's own folder.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

import numpy as np
import yaml

from .._core import (
    Control,
    Environment,
    Planning,
    PoiMotion,
    PoiPath,
    Sensor,
    SimulationOptions,
    Uav,
    VistrackError,
)
from ..georeference import Georeference
from ..io.documents import parse_yaml
from ..io.text import read_text
from ..report_options import ReportOptions, report_options
from ..routes import road_route, route_ends, route_nodes
from ..scenario_blocks import (
    City,
    Rename,
    city_block,
    georeference_block,
    origin_to_georeference,
    uav_block,
    uav_dict,
    upgrade,
    with_dynamics,
)
from ..schema import (
    apply_checks,
    coordinate,
    fail,
    integer,
    length,
    number,
    output_name,
    reject_unknown,
    resolve_path,
    section,
    speed,
)

__all__ = ["EnvironmentSpec", "PoiSpec", "ReportOptions", "Scenario", "default_scenario_text", "road_route"]

DEMO_SCENARIO = Path(__file__).parent.parent / "scenarios" / "demo.yaml"


EnvironmentSpec = City  # the scenario's city block (the name predates the one schema)


@dataclass
class PoiSpec:
    """The POI's path: a CSV file, explicit waypoints, road-network nodes, or a route along the
    roads through the nodes nearest to given points; and its speed."""

    speed: float = PoiMotion().speed
    path: Path | None = None
    waypoints: list[list[float]] | None = None
    nodes: list[int] | None = None
    route: list[list[float]] | dict[str, Any] | None = None  # via points, or {from, to, crs}

    def build(self, env: Environment) -> PoiPath:
        if self.path is not None:
            return PoiPath.from_csv(str(self.path), self.speed)
        if self.waypoints is not None:
            return PoiPath(np.asarray(self.waypoints, dtype=float), self.speed)
        if self.nodes is not None:
            return PoiPath.from_nodes(env.roads, self.nodes, self.speed)
        if isinstance(self.route, dict):
            nodes = route_nodes(env, self.route["from"], self.route["to"], self.route["crs"], key="poi.route")
            return PoiPath.from_nodes(env.roads, nodes, self.speed)
        if self.route is not None:
            return PoiPath.from_nodes(env.roads, road_route(env.roads, self.route), self.speed)
        raise VistrackError("poi: no path given (path: CSV, waypoints: [[x, y], ...] or nodes: [...])")


@dataclass
class Scenario:
    """A validated scenario. Build one with Scenario.load(path) or Scenario.from_dict(data)."""

    environment: City = field(default_factory=City)
    poi: PoiSpec = field(default_factory=PoiSpec)
    uav: Uav = field(default_factory=lambda: with_dynamics(Uav()))  # the scenario files' model (roll)
    start: tuple[float, float, float] | None = None  # UAV start (x, y, psi); None: on the orbit
    aircraft: str | None = None  # uav.dynamics: jsbsim: also flown on this 6-DOF aircraft (vistrack.fdm)
    sensor: Sensor = field(default_factory=Sensor)
    planning: Planning = field(default_factory=Planning)
    control: Control = field(default_factory=Control)
    simulation: SimulationOptions = field(default_factory=SimulationOptions)
    baselines: list[float] = field(default_factory=list)  # constant orbit radii to compare, m
    origin: Georeference | None = None  # where local (0, 0, 0) lies on the Earth (maps in, routes out)
    report: ReportOptions = field(default_factory=ReportOptions)
    name: str = "scenario"
    source: Path | None = None

    SECTIONS = ("name", "georeference", "city", "poi", "uav", "sensor", "planning", "control",
                "simulation", "baselines", "report")
    # Spellings from before the one scenario schema, still read.
    RENAMES = (Rename("origin", "georeference", origin_to_georeference), Rename("environment", "city"))

    @classmethod
    def load(cls, path: str | Path) -> "Scenario":
        """Read and validate a scenario YAML file; errors name the key, the value and the range."""
        path = Path(path)
        data = parse_yaml(read_text(path, "scenario"), "scenario", path)
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
            raise fail("scenario", data, "must be a mapping with sections " + ", ".join(cls.SECTIONS))
        data = upgrade(data, cls.RENAMES)
        reject_unknown(data, cls.SECTIONS, noun="section")
        scenario = cls()
        if "name" in data:
            scenario.name = output_name("name", data["name"])
        scenario.origin = georeference_block(data)
        scenario.environment = city_block(data, base) or City()
        scenario.poi = _poi(section(data, "poi", {"path", "waypoints", "nodes", "route", "speed"}), base)
        uav = uav_block(data, Uav(), extra=("start",), fdm=True)
        scenario.uav, scenario.start, scenario.aircraft = uav.uav, _start(uav.extra), uav.aircraft
        scenario.sensor = _sensor(section(data, "sensor", {"d_max", "altitude_band"}))
        scenario.planning = _planning(section(
            data, "planning", {"spacing", "cutoff", "resolution_deg", "min_spacing", "max_depth", "rate_margin",
                               "locus", "tracking_margin", "check_spacing", "check_min_spacing", "turn_share",
                               "radius_smoothing", "max_volumes"}))
        scenario.control = _control(section(data, "control", {"beta", "k_psi", "direction"}))
        scenario.simulation = _simulation(section(
            data, "simulation", {"rtol", "atol", "max_step", "output_step"}))
        scenario.baselines = _baselines(data.get("baselines", []))
        scenario.report = report_options(section(data, "report", {"html", "animation", "frames", "duration", "volumes",
                                                           "view"}))
        if not scenario.uav.speed > scenario.poi.speed:
            raise fail("uav.speed", scenario.uav.speed,
                        f"must exceed poi.speed = {scenario.poi.speed} (the UAV must outrun the POI)")
        return scenario

    def to_dict(self) -> dict[str, Any]:
        """The scenario as plain data, every default filled in (what --print-defaults shows)."""
        env: dict[str, Any] = {"demo": True} if self.environment.kind == "demo" else {
            self.environment.kind: str(self.environment.path)}
        if self.environment.kind == "mesh":
            env["up"] = self.environment.up
        env.update(self.environment.options)
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
        origin = self.origin
        return {
            "name": self.name,
            "georeference": None if origin is None else {"lat": origin.lat, "lon": origin.lon, "alt": origin.alt},
            "city": env,
            "poi": poi,
            "uav": {**uav_dict(self.uav), "start": list(self.start) if self.start is not None else None,
                    **({"dynamics": "jsbsim", "aircraft": self.aircraft} if self.aircraft else {})},
            "sensor": {"d_max": self.sensor.d_max, "altitude_band": list(band) if band else None},
            "planning": {"spacing": self.planning.spacing, "cutoff": self.planning.cutoff,
                         "resolution_deg": self.planning.resolution_deg,
                         "min_spacing": self.planning.min_spacing, "max_depth": self.planning.max_depth,
                         "rate_margin": self.planning.rate_margin, "locus": self.planning.locus,
                         "tracking_margin": self.planning.tracking_margin,
                         "check_spacing": self.planning.check_spacing,
                         "check_min_spacing": self.planning.check_min_spacing,
                         "turn_share": self.planning.turn_share,
                         "radius_smoothing": self.planning.radius_smoothing,
                         "max_volumes": self.planning.max_volumes},
            "control": {"beta": self.control.beta, "k_psi": self.control.k_psi,
                        "direction": self.control.direction},
            "simulation": {"rtol": self.simulation.rtol, "atol": self.simulation.atol,
                           "max_step": self.simulation.max_step,
                           "output_step": self.simulation.output_step},
            "baselines": list(self.baselines),
            "report": {"html": self.report.html, "animation": self.report.animation, "frames": self.report.frames,
                       "duration": self.report.duration, "volumes": self.report.volumes,
                       "view": list(self.report.view)},
        }


def _poi(section: dict[str, Any], base: Path) -> PoiSpec:
    spec = PoiSpec()
    if "speed" in section:
        spec.speed = speed("poi.speed", section["speed"])
    sources = [key for key in ("path", "waypoints", "nodes", "route") if key in section]
    if len(sources) > 1:
        raise fail("poi", section, "give one of path: CSV, waypoints: [[x, y], ...], nodes: [...], "
                                    "route: [[x, y], ...]")
    if not sources:
        return spec  # PoiSpec.build says what is missing when the scenario is run
    key = sources[0]
    value = section[key]
    if key == "path":
        spec.path = resolve_path(base, value, "poi.path")
    elif key == "route" and isinstance(value, Mapping):
        ends = dict(value)
        if "speed" in ends:  # the spelling poi: {route: {from, to, speed}}
            if "speed" in section:
                raise fail("poi.route.speed", ends["speed"], "give the speed once: poi.speed or poi.route.speed")
            spec.speed = speed("poi.route.speed", ends.pop("speed"))
        spec.route = route_ends(ends, "poi.route")
    elif key in ("waypoints", "route"):
        if not isinstance(value, list) or len(value) < 2:
            raise fail(f"poi.{key}", value, "must be a list of at least two points")
        points = []
        for i, point in enumerate(value):
            sizes = (2, 3) if key == "waypoints" else (2,)
            if not isinstance(point, list) or len(point) not in sizes:
                allowed = "must be [x, y] or [x, y, z]" if key == "waypoints" else "must be [x, y]"
                raise fail(f"poi.{key}[{i}]", point, allowed)
            if i > 0 and len(point) != len(value[0]):  # one array of rows: every point as long as the first
                raise fail(f"poi.{key}[{i}]", point, f"must have {len(value[0])} coordinates, as poi.{key}[0]")
            points.append([coordinate(f"poi.{key}[{i}][{k}]", c) for k, c in enumerate(point)])
        setattr(spec, key, points)
    else:
        if not isinstance(value, list) or len(value) < 2:
            raise fail("poi.nodes", value, "must be a list of at least two road-node indices")
        spec.nodes = [integer(f"poi.nodes[{i}]", n, 0, 10**9) for i, n in enumerate(value)]
    return spec


def _start(extra: Mapping[str, Any]) -> tuple[float, float, float] | None:
    start = extra.get("start")
    if start is None:
        return None
    if not isinstance(start, list) or len(start) != 3:
        raise fail("uav.start", start, "must be [x, y, psi] (metres, metres, radians)")
    return (coordinate("uav.start[0]", start[0]), coordinate("uav.start[1]", start[1]),
            number("uav.start[2]", start[2], low=-1e9, high=1e9))


def _sensor(section: dict[str, Any]) -> Sensor:
    sensor = Sensor()
    if "d_max" in section:
        sensor.d_max = number("sensor.d_max", section["d_max"])
    band = section.get("altitude_band")
    if band is not None:
        if not isinstance(band, list) or len(band) != 2:
            raise fail("sensor.altitude_band", band, "must be [h_lo, h_hi] in metres, or null")
        sensor.altitude_band = (number("sensor.altitude_band[0]", band[0]), number("sensor.altitude_band[1]", band[1]))
    sensor.validate()
    return sensor


# Each section's values are parsed to their types here; the ranges are the C++ structs' validate().
def _planning(section: dict[str, Any]) -> Planning:
    def locus(key: str, value: Any) -> str:
        if value not in ("smooth", "paper"):
            raise fail(key, value, '"smooth" (checked between samples, C1; the default) or "paper" (Algorithm 1, '
                                   'piecewise linear)')
        return value

    numbers = ("spacing", "cutoff", "resolution_deg", "min_spacing", "rate_margin", "tracking_margin", "check_spacing",
               "check_min_spacing", "turn_share", "radius_smoothing")
    return apply_checks(Planning(), section, "planning", {
        **dict.fromkeys(numbers, number), "locus": locus,
        "max_depth": lambda k, v: integer(k, v, 0, 30), "max_volumes": lambda k, v: integer(k, v, 1, 10**12)})


def _control(section: dict[str, Any]) -> Control:
    def direction(key: str, value: Any) -> str:
        if value not in ("ccw", "cw"):
            raise fail(key, value, 'must be "ccw" or "cw"')
        return value

    return apply_checks(Control(), section, "control", {"beta": number, "k_psi": number, "direction": direction})


def _simulation(section: dict[str, Any]) -> SimulationOptions:
    return apply_checks(SimulationOptions(), section, "simulation", dict.fromkeys(
        ("rtol", "atol", "max_step", "output_step"), number))


def _baselines(value: Any) -> list[float]:
    if value is None:
        return []
    if not isinstance(value, list):
        raise fail("baselines", value, "must be a list of orbit radii in metres")
    return [length(f"baselines[{i}]", r) for i, r in enumerate(value)]


def default_scenario_text() -> str:
    """A complete scenario with every default written out (the demo city and route)."""
    scenario = Scenario.demo()
    scenario.name = "scenario"
    return yaml.safe_dump(scenario.to_dict(), sort_keys=False)
