"""Follow scenarios from YAML (``examples/follow_*.yaml``) and the runs ``vistrack follow`` makes
of one: the paper's planner, the vector-field baseline on the same vehicle, and optionally both
again on a city road with line of sight through the buildings.

Keys (every one optional except vehicle; lengths m, speeds m/s, angles in degrees
counter-clockwise from east unless a compass word is given)::

    description: text
    georeference: {lat, lon, alt} # where local (0, 0) lies on the Earth (--export), WGS84
    uav: {speed: 21, min_turn_radius: 50, altitude: 200, dynamics: roll}   # dubins: the paper's vehicle
    vehicle:                      # one of legs (with start), track, or path (with legs)
      start: [0, 0]
      legs: [{heading: south, speed: 10, duration: 300, end_speed: 10}]   # or heading_deg: -90
      track: file.csv             # t,x,y per line (header allowed)
      route: {from: [lon, lat], to: [lon, lat], crs: lonlat}   # with legs: the city run drives their
                                  # speeds along this road route of the city (vistrack.routes)
    follow: {period, turn_margin, threshold, hysteresis, loiter_pattern, loiter_radius,
             loiter_direction, compensation, update_period, strategy, strategy_margin,
             standoff_radius}  # standoff_radius: m, the standoff orbit's (0: Lemma 6 per update)
                                  # threshold: auto (default) or h; strategy: paper (default), standoff, auto
    offset: {distance: 0, angle_deg: 0, reference: heading, changes: [{t, distance, angle_deg}]}
    wind: {east: 0, north: 10, gusts: {seed, intensity, length_scale}}  # the true wind (towards)
    wind_estimate: {east: 0, north: 10}      # what the planner compensates (default: the true wind)
    camera: {fov_deg: 74, max_gimbal_deg: 25, mount: roll}   # or pan_tilt (pointed at the vehicle,
                                  # max_gimbal_deg from the body's down axis), fixed (the paper's camera)
    flight: {dt: 0.02, integration: discrete, max_time: 0, guidance: l1, l1_period: 8, l1_damping: 0.75}
                                  # guidance law5: each 1 s leg by the paper's law (5)
    baseline: {radius: 0, beta: 0.025, k_psi: 20, direction: ccw}   # radius 0: Lemma 6; false: none
    reports: {position_noise: 0, velocity_noise: 0, latency: 0, dropout: 0, timeout: 5, seed: 1}
                                  # the vehicle's 1 Hz reports as both followers get them (beyond the paper)
    city: {mesh: city.obj, up: y, road: road.csv}   # the legs' speeds on a road, at uav.altitude
                                  # (a CSV polyline; or vehicle.route on the city's road network)
    city_orbit: {planner: horizon, horizon: 24, reach: 400, margin: 3, radius: lemma6, lookahead: [3, 6]}
                                  # the city follower (vt.follow.city_orbit.CityOrbitOptions): bank commands
                                  # over a 24 s horizon (follow.city_horizon), or planner: orbit

uav, wind, camera, city and georeference are the blocks every scenario shares
(:mod:`vistrack.scenario_blocks`).
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Mapping, Optional

import numpy as np

from .._core import Control, Environment, Uav, VisibilityScene
from ..flight import Wind
from ..georeference import Georeference
from ..io.documents import read_yaml_mapping
from ..routes import route_ends, route_nodes
from ..scenario_blocks import (
    City,
    Rename,
    camera_block,
    city_block,
    georeference_block,
    origin_to_georeference,
    renamed,
    uav_block,
    uav_dict,
    upgrade,
    wind_block,
    with_dynamics,
)
from ..schema import fail, number, positive, reject_unknown, resolve_path, section
from .city_horizon import city_horizon_follow
from .city_orbit import CityOrbitOptions, CityOrbitResult, city_orbit_follow
from .fdm import FollowFdm, fly_follow_fdm
from .files import read_road_path, read_vehicle_track
from .keys import HEADINGS, baseline_block, city_orbit_block, reports_block, threshold_value, vehicle_legs
from .simulation import (
    DownwardCamera,
    FollowFlight,
    FollowParameters,
    FollowResult,
    GroundVehicle,
    VehicleLeg,
    VehicleReportOptions,
    baseline,
    baseline_infeasibility,
    default_uav,
    planner_note,
    simulate,
    threshold_warning,
)
from .simulation import (
    baseline_radius as lemma6_radius,
)

__all__ = ["HEADINGS", "TOP_KEYS", "CityRoad", "FollowScenario", "FollowStudy"]

# The follow camera's mounts (vt.follow.DownwardCamera.mount), the default first.
CAMERA_MOUNTS = ("roll", "pan_tilt", "fixed")
TOP_KEYS = {"description", "georeference", "uav", "vehicle", "follow", "offset", "wind", "wind_estimate", "camera",
            "flight", "baseline", "city", "reports", "city_orbit"}
# Spellings from before the one scenario schema, still read (city.map: see _old_city_map).
RENAMES = (Rename("origin", "georeference", origin_to_georeference),)
# How scenario files fly the plan unless they say: its planned path by L1 guidance (beyond the
# paper); "law5" flies each 1 s leg by the paper's law (5), the C++ default.
LEG_GUIDANCE = ("l1", "law5")
DEFAULT_LEG_GUIDANCE = "l1"
# The UAV where the file gives none: the C++ follower's (kFollowUav).
DEFAULT_UAV = default_uav()

CityRoad = City  # the scenario's city block with its road (the name predates the one schema)


@dataclass
class FollowScenario:
    """One follow scenario, validated (errors name the key)."""

    vehicle: GroundVehicle
    legs: list[VehicleLeg] = field(default_factory=list)
    uav: Uav = field(default_factory=lambda: with_dynamics(default_uav()))  # as a file without a uav block
    parameters: FollowParameters = field(default_factory=FollowParameters)
    offset_schedule: list[tuple[float, float, float]] = field(default_factory=list)
    wind: Wind = field(default_factory=Wind)
    wind_estimate: Optional[tuple[float, float]] = None
    camera: DownwardCamera = field(default_factory=DownwardCamera)
    flight: FollowFlight = field(default_factory=lambda: FollowFlight(guidance=DEFAULT_LEG_GUIDANCE))
    baseline_radius: Optional[float] = None  # None: Lemma 6 (vt.follow.baseline_radius)
    baseline_control: Optional[Control] = field(default_factory=Control)  # None: no baseline
    reports: VehicleReportOptions = field(default_factory=VehicleReportOptions)
    city: Optional[City] = None
    city_orbit: CityOrbitOptions = field(default_factory=CityOrbitOptions)
    route: Optional[dict[str, Any]] = None  # vehicle.route {from, to, crs}: the city run's road route
    description: str = ""
    path: Optional[Path] = None
    origin: Optional[Georeference] = None  # where local (0, 0) lies on the Earth (mission export)
    aircraft: Optional[str] = None  # uav.dynamics: jsbsim: the planner also flown on this 6-DOF aircraft

    @classmethod
    def load(cls, path: str | Path) -> "FollowScenario":
        file = Path(path)
        return cls.from_mapping(read_yaml_mapping(file, "scenario"), file.resolve().parent, file)

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any], base: Path, path: Optional[Path] = None) -> "FollowScenario":
        data = upgrade(_old_city_map(data), RENAMES)
        reject_unknown(data, TOP_KEYS)
        block = uav_block(data, default_uav(), fdm=True)
        uav = block.uav
        vehicle, legs, route = _vehicle(data, base)
        parameters = _parameters(data)
        schedule = _offset_schedule(data)
        wind = wind_block(data)
        estimate = None
        if data.get("wind_estimate") is not None:
            e = section(data, "wind_estimate", {"east", "north"})
            estimate = (number("wind_estimate.east", e.get("east", 0.0)),
                        number("wind_estimate.north", e.get("north", 0.0)))
        defaults = DownwardCamera()
        c = camera_block(data, math.degrees(defaults.fov), math.degrees(defaults.max_gimbal), mounts=CAMERA_MOUNTS)
        camera = DownwardCamera(fov=math.radians(c.fov_deg), max_gimbal=math.radians(c.max_gimbal_deg), mount=c.mount)
        f, fd = section(data, "flight", {"dt", "integration", "max_time", "guidance", "l1_period", "l1_damping"}), \
            FollowFlight()
        integration = f.get("integration", fd.integration)
        if integration not in ("discrete", "continuous"):
            raise fail("flight.integration", integration, 'must be "discrete" or "continuous"')
        guidance = f.get("guidance", DEFAULT_LEG_GUIDANCE)
        if guidance not in LEG_GUIDANCE:
            raise fail("flight.guidance", guidance, "must be one of " + ", ".join(LEG_GUIDANCE))
        flight = FollowFlight(integration=integration, dt=positive("flight.dt", f.get("dt", fd.dt)),
                              max_time=number("flight.max_time", f.get("max_time", fd.max_time), low=0.0),
                              guidance=guidance,
                              l1_period=positive("flight.l1_period", f.get("l1_period", fd.l1_period)),
                              l1_damping=positive("flight.l1_damping", f.get("l1_damping", fd.l1_damping)))
        radius, control = baseline_block(data)
        return cls(vehicle=vehicle, legs=legs, uav=uav, parameters=parameters, offset_schedule=schedule, wind=wind,
                   wind_estimate=estimate, camera=camera, flight=flight, baseline_radius=radius,
                   baseline_control=control, reports=reports_block(data), city=_city(data, base, route), route=route,
                   city_orbit=city_orbit_block(data),
                   description=str(data.get("description", "")),
                   path=path, origin=georeference_block(data), aircraft=block.aircraft)

    def known_wind(self, parameters: FollowParameters) -> Optional[tuple[float, float]]:
        """The wind the planner knows: wind_estimate, else the true mean wind when it compensates, else none."""
        return self.wind_estimate or ((self.wind.east, self.wind.north) if parameters.wind_compensation else None)

    def city_available(self) -> bool:
        """Whether the scenario has a city section whose map and road files exist (the shared
        data is optional: without it the city runs are skipped)."""
        city = self.city
        if city is None or city.path is None or not city.path.is_file():
            return False
        return self.route is not None or (isinstance(city.road, Path) and city.road.is_file())

    def city_vehicle(self, env: Optional[Environment] = None) -> GroundVehicle:
        """The scenario's speed profile driven along the city road (its legs' headings ignored): the
        road route ``vehicle.route: {from, to, crs}`` of the city's road network (``env``, the
        loaded city; loaded here when not given), or the CSV polyline ``city.road``."""
        if self.city is None or (self.city.road is None and self.route is None) or not self.legs:
            raise fail("city", None, "needs a city section, a road (vehicle.route or city.road) and a vehicle "
                                     "given by legs")
        if self.route is not None:
            env = env if env is not None else self.city.load(self.origin)
            ends = self.route
            nodes = route_nodes(env, ends["from"], ends["to"], ends["crs"], key="vehicle.route")
            return GroundVehicle.along_path(np.asarray(env.roads.nodes)[nodes], self.legs)
        assert isinstance(self.city.road, Path)
        road = read_road_path(self.city.road, "city.road")
        return GroundVehicle.along_path(road, self.legs)

    def shared_conditions(self) -> dict[str, Any]:
        """What the planner's run and the baseline's share (a fair baseline): wind, flight, camera,
        offset schedule and vehicle reports, as keyword arguments of ``simulate`` and ``baseline``."""
        return {"wind": self.wind, "flight": self.flight, "camera": self.camera,
                "offset_schedule": self.offset_schedule, "reports": self.reports}

    def baseline_run(self, vehicle: GroundVehicle, parameters: FollowParameters, **extra: Any) -> FollowResult:
        """The baseline (the tracking paper's vector field at the file's constant radius and control)
        about ``vehicle`` as ``run`` flies it, under the planner's conditions (shared_conditions);
        ``extra``: more of ``baseline``'s arguments (``scene``, ``start``)."""
        return baseline(vehicle, self.uav, self.baseline_radius, control=self.baseline_control,
                        parameters=parameters, **self.shared_conditions(), **extra)

    def run(self, compensation: Optional[bool] = None, city: bool = True,
            stage: Optional[Callable[[str], Any]] = None) -> "FollowStudy":
        """The planner's run, the baseline's, and with ``city`` (when the scenario has one) both
        again on the city road with line of sight. compensation overrides the file's.
        ``stage(name)`` runs before each run; what it returns, if callable, gets the city follower's progress."""
        say = stage or (lambda _name: None)
        parameters = self.parameters
        if compensation is not None:
            parameters = copy.copy(parameters)  # not the scenario's own
            parameters.wind_compensation = compensation
        if parameters.strategy == "auto" and parameters.standoff_radius == 0.0:
            # Auto's standoff candidate is the baseline's orbit: its constant radius (and its law, follow_run.cpp).
            parameters = copy.copy(parameters)  # not the scenario's own
            parameters.standoff_radius = self.baseline_radius or lemma6_radius(self.vehicle, self.uav, parameters)
        common = self.shared_conditions()
        say("follow")
        follow = simulate(self.vehicle, self.uav, parameters, wind_estimate=self.wind_estimate, **common)
        flies = self.baseline_control is not None
        orbit = None
        reason = baseline_infeasibility(self.vehicle, self.uav) if flies else None
        if flies and reason is None:
            say("baseline")
            orbit = self.baseline_run(self.vehicle, parameters)
        study = FollowStudy(self, parameters, follow, orbit, baseline_reason=reason)
        if self.aircraft is not None:
            if self.offset_schedule:
                raise fail("offset_schedule", len(self.offset_schedule), "is not flown on a 6-DOF aircraft (jsbsim)")
            r = self.reports  # the 6-DOF planner observes the vehicle exactly at each update
            if (r.position_noise, r.velocity_noise, r.latency, r.dropout) != (0.0, 0.0, 0.0, 0.0):
                raise fail("reports", {"position_noise": r.position_noise, "velocity_noise": r.velocity_noise,
                                       "latency": r.latency, "dropout": r.dropout},
                           "imperfect vehicle reports are not flown on a 6-DOF aircraft (jsbsim)")
            say(f"6-DOF follow on {self.aircraft}")
            study.fdm = fly_follow_fdm(self.vehicle, self.uav, parameters, follow.state[0], aircraft=self.aircraft,
                                       wind=self.wind, wind_estimate=self.wind_estimate, flight=self.flight,
                                       camera=self.camera)
        if city and self.city is not None:
            say("city")
            env = self.city.load(self.origin)
            scene = VisibilityScene(env)
            vehicle = self.city_vehicle(env)
            uav = self.uav
            study.environment = env
            study.city_follow = simulate(vehicle, uav, parameters, wind_estimate=self.wind_estimate, scene=scene,
                                         **common)
            study.city_baseline_reason = baseline_infeasibility(vehicle, uav) if flies else None
            if flies and study.city_baseline_reason is None:
                study.city_baseline = self.baseline_run(vehicle, parameters, scene=scene)
            # Beyond every anchor (follow.city_horizon, or follow.city_orbit's orbits inside the visibility
            # polygons); it observes the vehicle at each update itself, about the vehicle (no offset schedule).
            bar = say(f"city {self.city_orbit.planner}")
            known = self.known_wind(parameters)
            city_follow = city_horizon_follow if self.city_orbit.planner == "horizon" else city_orbit_follow
            study.city_orbit = city_follow(vehicle, uav, scene, parameters=parameters, wind_estimate=known,
                                           wind=self.wind, flight=self.flight, camera=self.camera,
                                           options=self.city_orbit, progress=bar if callable(bar) else None)
        return study


@dataclass
class FollowStudy:
    """The runs of one scenario."""

    scenario: FollowScenario
    parameters: FollowParameters
    follow: FollowResult
    baseline: Optional[FollowResult] = None
    city_follow: Optional[FollowResult] = None
    city_baseline: Optional[FollowResult] = None
    environment: Optional[Environment] = None
    baseline_reason: Optional[str] = None  # why the baseline was not flown (a vehicle faster than the UAV)
    city_baseline_reason: Optional[str] = None
    fdm: Optional[FollowFdm] = None  # the planner on a 6-DOF JSBSim aircraft (uav.dynamics: jsbsim)
    city_orbit: Optional[CityOrbitResult] = None  # the city follower's run (follow.city_horizon or city_orbit)

    def metrics(self) -> dict[str, Any]:
        """metrics.json: the planner's run at the top level (with a ``note`` when it flew its
        straight mode), then the baseline (``feasible``; when false, the ``reason`` instead of its
        scores) and the city runs."""
        out = _run_metrics(self.follow)
        warnings = self.warnings()
        if warnings:
            out["warnings"] = warnings
        out["uav"] = uav_dict(self.scenario.uav)
        out["wind_compensation"] = bool(self.parameters.wind_compensation)
        out["updates"] = len(self.follow.ticks)
        block = _baseline_metrics(self.baseline, self.baseline_reason)
        if block is not None:
            out["baseline"] = block
        if self.fdm is not None:
            out["fdm"] = {"aircraft": self.fdm.trajectory.aircraft, **self.fdm.metrics()}
        if self.city_follow is not None:
            out["city"] = {"follow": _run_metrics(self.city_follow)}
            block = _baseline_metrics(self.city_baseline, self.city_baseline_reason)
            if block is not None:
                out["city"]["baseline"] = block
            if self.city_orbit is not None:
                out["city"]["orbit"] = self.city_orbit.metrics
        return out


    def warnings(self) -> list[str]:
        """What the user should know about the settings (a threshold whose sinusoid the camera cannot
        follow), once per distinct message."""
        found = [threshold_warning(r) for r in (self.follow, self.city_follow) if r is not None]
        return list(dict.fromkeys(w for w in found if w is not None))


def _run_metrics(result: FollowResult) -> dict[str, Any]:
    out = dict(result.metrics)
    note = planner_note(result)
    if note is not None:
        out["note"] = note
    return out


def _baseline_metrics(result: Optional[FollowResult], reason: Optional[str]) -> Optional[dict[str, Any]]:
    """The baseline's block: ``feasible`` and its scores, or ``feasible: false`` and the reason."""
    if reason is not None:
        return {"feasible": False, "reason": reason}
    if result is None:
        return None
    out: dict[str, Any] = {"feasible": True, **result.metrics}
    out["radius_m"] = float(np.median(np.linalg.norm(result.desired - result.offset_point, axis=1)))
    return out


def _vehicle(data: Mapping[str, Any], base: Path) -> tuple[GroundVehicle, list[VehicleLeg], Optional[dict]]:
    v = section(data, "vehicle", {"start", "legs", "track", "route"})
    if ("legs" in v) == ("track" in v):
        raise fail("vehicle", dict(v), "give either legs (with an optional start) or track (a t,x,y CSV file)")
    route = None
    if "route" in v:
        if "track" in v:
            raise fail("vehicle.route", v["route"], "needs legs (their speeds are driven along the route), "
                                                    "not a track")
        if not isinstance(v["route"], Mapping):
            raise fail("vehicle.route", v["route"], "must be {from: [lon, lat], to: [lon, lat], crs: lonlat | local}")
        route = route_ends(v["route"], "vehicle.route")
    if "track" in v:
        t, xy = read_vehicle_track(resolve_path(base, v["track"], "vehicle.track"), "vehicle.track")
        return GroundVehicle(t, xy), [], None
    start = v.get("start", [0.0, 0.0])
    if not isinstance(start, (list, tuple)) or len(start) != 2:
        raise fail("vehicle.start", start, "must be [x, y]")
    legs = vehicle_legs(v["legs"])
    xy = np.array([number(f"vehicle.start[{i}]", s) for i, s in enumerate(start)])
    return GroundVehicle.from_legs(legs, xy), legs, route


def _parameters(data: Mapping[str, Any]) -> FollowParameters:
    f = section(data, "follow", {"period", "turn_margin", "threshold", "hysteresis", "loiter_pattern",
                                 "loiter_radius", "loiter_direction", "compensation", "update_period", "strategy",
                                 "strategy_margin", "standoff_radius"})
    o = section(data, "offset", {"distance", "angle_deg", "reference", "changes"})
    d = FollowParameters()
    compensation = f.get("compensation", d.wind_compensation)
    if not isinstance(compensation, bool):
        raise fail("follow.compensation", compensation, "must be true or false")
    checks = {"period": positive, "turn_margin": positive, "threshold": threshold_value, "update_period": positive,
              "strategy_margin": lambda k, x: number(k, x, low=0.0, high=1.0),
              "hysteresis": lambda k, x: number(k, x, low=0.0), "loiter_radius": lambda k, x: number(k, x, low=0.0),
              "standoff_radius": lambda k, x: number(k, x, low=0.0)}
    values: dict[str, Any] = {name: check(f"follow.{name}", f[name]) for name, check in checks.items() if name in f}
    for name in ("loiter_pattern", "loiter_direction", "strategy"):
        if name in f:
            values[name] = str(f[name])
    try:
        return FollowParameters(wind_compensation=compensation,
                                offset_distance=number("offset.distance", o.get("distance", d.offset_distance),
                                                       low=0.0),
                                offset_angle=math.radians(number("offset.angle_deg",
                                                                 o.get("angle_deg", math.degrees(d.offset_angle)))),
                                offset_reference=str(o.get("reference", d.offset_reference)), **values)
    except ValueError as error:  # the core names the field (follow.hysteresis, ...)
        raise type(error)(str(error).replace("direction =", "follow.loiter_direction =", 1)) from None


def _offset_schedule(data: Mapping[str, Any]) -> list[tuple[float, float, float]]:
    changes = (data.get("offset") or {}).get("changes") if isinstance(data.get("offset"), Mapping) else None
    if changes is None:
        return []
    if not isinstance(changes, list):
        raise fail("offset.changes", changes, "must be a list of {t, distance, angle_deg}")
    keys = []
    for i, c in enumerate(changes):
        key = f"offset.changes[{i}]"
        if not isinstance(c, Mapping) or "t" not in c:
            raise fail(key, c, "must be a mapping with t, distance and angle_deg")
        keys.append((number(f"{key}.t", c["t"]), number(f"{key}.distance", c.get("distance", 0.0), low=0.0),
                     math.radians(number(f"{key}.angle_deg", c.get("angle_deg", 0.0)))))
    return keys


def _city(data: Mapping[str, Any], base: Path, route: Optional[dict]) -> Optional[City]:
    city = city_block(data, base, road=True)
    if city is None:
        if route is not None:
            raise fail("vehicle.route", data["vehicle"]["route"], "needs a city (city: {osm: FILE} or another map "
                                                                  "with roads)")
        return None
    if city.kind == "demo" or (city.road is None) == (route is None):
        raise fail("city", data["city"], "needs a map (mesh, geojson or osm: FILE) and one road: road: a CSV path, "
                                         "or vehicle.route: {from, to}")
    return city


def _old_city_map(data: Mapping[str, Any]) -> Mapping[str, Any]:
    """The follow city block before the one schema: ``map`` (read by its suffix, ``up`` y by default)
    becomes ``mesh`` or ``geojson``; ``altitude`` is refused, the flight altitude being uav.altitude."""
    city = data.get("city")
    if not isinstance(city, Mapping) or not ("map" in city or "altitude" in city):
        return data
    if "altitude" in city:
        raise fail("city.altitude", city["altitude"], "the flight altitude is uav.altitude, one per scenario: give the "
                                                      "city run a file of its own (examples/follow_*_city.yaml)")
    new = dict(city)
    path = new.pop("map")
    kind = "geojson" if str(path).lower().endswith((".geojson", ".json")) else "mesh"
    if kind == "mesh":
        new.setdefault("up", "y")
    new[kind] = path
    renamed("city.map", f"city.{kind}")
    return {**data, "city": new}
