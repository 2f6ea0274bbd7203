"""The blocks every scenario file shares, parsed in this one place (docs: Scenario files)::

    uav:          {speed, min_turn_radius, altitude, dynamics,    # the flight altitude lives here only
                   roll_time_constant, max_roll_rate_deg_s}      # dynamics: roll (default) | dubins
    wind:         {east, north, gusts: {seed, intensity, length_scale}}   # m/s, the direction it blows to
    camera:       {fov_deg, max_gimbal_deg, mount}                # mount: levelled | roll
    city:         {mesh | geojson | osm | demo, up, road,         # the environment; an OSM file's
                   level_height, roof_height, default_height}    # height options (osm only)
    georeference: {lat, lon, alt}                                 # where local (0, 0, 0) lies, WGS84

Each product takes the blocks it uses (tracking: uav, city, georeference; loiter: uav, camera,
georeference; follow: all five). Types are parsed here; the ranges are the C++ structs' own
``validate()``, whose messages name the key. Spellings from before the one schema still load
where the change is a rename (:func:`upgrade`), each with one line on stdout naming the new key.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Mapping, Optional, Sequence

from ._core import Environment, Uav
from .flight import Gusts, Wind
from .georeference import Georeference, degrees
from .io.mesh import load_environment
from .io.osm import read_osm
from .schema import fail, integer, number, positive, reject_unknown, resolve_path, section

__all__ = [
    "CAMERA_MOUNTS",
    "DEFAULT_DYNAMICS",
    "DYNAMICS",
    "OSM_OPTIONS",
    "CameraBlock",
    "City",
    "Rename",
    "UavBlock",
    "camera_block",
    "city_block",
    "dynamics_name",
    "georeference_block",
    "renamed",
    "uav_block",
    "uav_dict",
    "upgrade",
    "wind_block",
    "with_dynamics",
]

# The vehicle models a flight can use (vistrack.Uav.dynamics): "roll" banks with a first-order,
# rate-limited response, as an aircraft does; "dubins" turns at once, the papers' vehicle.
DYNAMICS = ("roll", "dubins")
# Scenario files flown in metres fly the roll model unless they say otherwise.
DEFAULT_DYNAMICS = "roll"
# levelled: the gimbal angle is measured from the vertical (it also takes out the bank);
# roll: a roll gimbal under the banked body, so the axis tilts by gimbal - bank.
CAMERA_MOUNTS = ("levelled", "roll")
UAV_NUMBERS = ("speed", "min_turn_radius", "altitude", "roll_time_constant", "max_roll_rate_deg_s")
UAV_KEYS = {*UAV_NUMBERS, "dynamics", "aircraft"}
# The 6-DOF model: flown beside the kinematic one (vistrack.fdm), on the aircraft uav.aircraft.
FDM_DYNAMICS = "jsbsim"


@dataclass(frozen=True)
class Rename:
    """An old spelling (a top-level key, or ``section.key``) and the key that replaced it; ``convert``
    turns the old value into the new one where its form changed too."""

    old: str
    new: str
    convert: Optional[Callable[[Any], Any]] = None


def renamed(old: str, new: str) -> None:
    """The one line on stdout saying that an old spelling was read as its new key."""
    print(f"vistrack: '{old}' is now '{new}' (still read; see the docs' Scenario files)")


def upgrade(data: Mapping[str, Any], renames: Sequence[Rename], note: Callable[[str, str], None] = renamed) -> dict:
    """``data`` with every old spelling moved to its new key (one line on stdout for each, by
    :func:`renamed`, or passed to ``note``); a file giving both the old and the new key is refused,
    naming the old one."""
    out = {key: dict(value) if isinstance(value, Mapping) else value for key, value in data.items()}
    for rename in renames:
        found, value = _pop(out, rename.old)
        if not found:
            continue
        if _has(out, rename.new):
            raise fail(rename.old, value, f"renamed to {rename.new}: give only {rename.new}")
        _put(out, rename.new, rename.convert(value) if rename.convert else value)
        note(rename.old, rename.new)
    return out


def _has(data: Mapping[str, Any], dotted: str) -> bool:
    head, _, tail = dotted.partition(".")
    if not tail:
        return head in data
    inner = data.get(head)
    return isinstance(inner, Mapping) and tail in inner


def _pop(data: dict, dotted: str) -> tuple[bool, Any]:
    head, _, tail = dotted.partition(".")
    if not tail:
        return (True, data.pop(head)) if head in data else (False, None)
    inner = data.get(head)
    if isinstance(inner, dict) and tail in inner:
        return True, inner.pop(tail)
    return False, None


def _put(data: dict, dotted: str, value: Any) -> None:
    head, _, tail = dotted.partition(".")
    if not tail:
        data[head] = value
        return
    inner = data.get(head)
    if inner is None:
        inner = data[head] = {}
    if not isinstance(inner, dict):
        raise fail(head, inner, "must be a mapping of keys to values")
    inner[tail] = value


@dataclass
class UavBlock:
    """The ``uav`` block: the vehicle (its ``dynamics`` included) and the product's own extra keys
    (e.g. ``start``)."""

    uav: Uav
    extra: dict[str, Any]
    aircraft: Optional[str] = None  # uav.dynamics: jsbsim: the 6-DOF aircraft flown beside the kinematic model

    @property
    def dynamics(self) -> str:
        return str(self.uav.dynamics)


def dynamics_name(value: Any) -> str:
    """A vehicle model's name, checked: ``"roll"`` or ``"dubins"`` (any letter case)."""
    if not isinstance(value, str) or value.lower() not in DYNAMICS:
        raise fail("uav.dynamics", value, "must be one of " + ", ".join(DYNAMICS))
    return value.lower()


def uav_dict(uav: Uav) -> dict[str, Any]:
    """The ``uav`` block of a vehicle, every key (what --print-defaults shows; also ``Uav``'s
    keyword arguments, so ``Uav(**uav_dict(u))`` is a copy)."""
    out: dict[str, Any] = {key: getattr(uav, key) for key in ("speed", "min_turn_radius", "altitude")}
    out["dynamics"] = str(uav.dynamics)
    out.update({key: getattr(uav, key) for key in ("roll_time_constant", "max_roll_rate_deg_s")})
    return out


def with_dynamics(uav: Uav, dynamics: str = DEFAULT_DYNAMICS) -> Uav:
    """A copy of ``uav`` on the model ``dynamics`` (by default the scenario files',
    :data:`DEFAULT_DYNAMICS`)."""
    return Uav(**{**uav_dict(uav), "dynamics": dynamics})


def uav_block(data: Mapping[str, Any], default: Uav, extra: Sequence[str] = (), fdm: bool = False) -> UavBlock:
    """``uav: {speed, min_turn_radius, altitude, dynamics, roll_time_constant, max_roll_rate_deg_s}``
    over ``default`` (its numbers; the model is :data:`DEFAULT_DYNAMICS` unless given); ``extra``
    keys are returned unparsed for the product. With ``fdm`` (a product that flies a 6-DOF aircraft),
    also ``dynamics: jsbsim`` and ``aircraft``."""
    found = section(data, "uav", UAV_KEYS | set(extra))
    uav = Uav(**uav_dict(default))
    for key in UAV_NUMBERS:
        if key in found:
            setattr(uav, key, number(f"uav.{key}", found[key]))
    dynamics = found.get("dynamics", DEFAULT_DYNAMICS)
    aircraft = None
    if fdm and isinstance(dynamics, str) and dynamics.lower() == FDM_DYNAMICS:
        aircraft = aircraft_name(found.get("aircraft"))
        dynamics = DEFAULT_DYNAMICS  # the kinematic flight beside the 6-DOF one
    elif "aircraft" in found:
        raise fail("uav.aircraft", found["aircraft"], f"needs uav.dynamics: {FDM_DYNAMICS}" if fdm
                   else "a 6-DOF aircraft is not flown by this product")
    uav.dynamics = dynamics_name(dynamics)
    uav.validate()
    return UavBlock(uav, {key: found[key] for key in extra if key in found}, aircraft)


def aircraft_name(value: Any) -> str:
    """A 6-DOF aircraft's name, checked against vistrack.fdm's aircraft (None: the default)."""
    from .fdm.aircraft import DEFAULT_AIRCRAFT, aircraft_names

    if value is None:
        return DEFAULT_AIRCRAFT
    names = aircraft_names()
    if not isinstance(value, str) or value not in names:
        raise fail("uav.aircraft", value, "must be one of " + ", ".join(names))
    return value


def wind_block(data: Mapping[str, Any]) -> Wind:
    """``wind: {east, north, gusts: {seed, intensity, length_scale}}`` (calm when absent). Whether
    the wind is slower than the airspeed is the flight's check (WindField), made where both are known."""
    found = section(data, "wind", {"east", "north", "gusts"})
    gusts = None
    if found.get("gusts") not in (None, False):  # false or null: no gusts
        g = found["gusts"]
        if not isinstance(g, Mapping):
            raise fail("wind.gusts", g, "must be {seed, intensity, length_scale}")
        reject_unknown(g, {"seed", "intensity", "length_scale"}, "wind.gusts.", where=" in wind.gusts")
        defaults = Gusts()
        gusts = Gusts(seed=integer("wind.gusts.seed", g.get("seed", defaults.seed), 0, 2**64 - 1),
                      intensity=number("wind.gusts.intensity", g.get("intensity", defaults.intensity), low=0.0),
                      length_scale=positive("wind.gusts.length_scale", g.get("length_scale", defaults.length_scale)))
    return Wind(east=number("wind.east", found.get("east", 0.0)), north=number("wind.north", found.get("north", 0.0)),
                gusts=gusts)


@dataclass
class CameraBlock:
    """The ``camera`` block: the full cone angle and the gimbal's range (degrees) and its mount."""

    fov_deg: float
    max_gimbal_deg: float
    mount: str


def camera_block(data: Mapping[str, Any], fov_deg: float, max_gimbal_deg: float,
                 mounts: Sequence[str] = CAMERA_MOUNTS) -> CameraBlock:
    """``camera: {fov_deg, max_gimbal_deg, mount}`` over the product's camera defaults; ``mounts``
    are the mounts the product models (the first is its default)."""
    found = section(data, "camera", {"fov_deg", "max_gimbal_deg", "mount"})
    mount = found.get("mount", mounts[0])
    if mount not in mounts:
        raise fail("camera.mount", mount, "must be one of " + ", ".join(mounts))
    return CameraBlock(number("camera.fov_deg", found.get("fov_deg", fov_deg)),
                       number("camera.max_gimbal_deg", found.get("max_gimbal_deg", max_gimbal_deg)), mount)


OSM_OPTIONS = ("level_height", "roof_height", "default_height")


@dataclass
class City:
    """The ``city`` block: where the environment comes from (the demo city, a GeoJSON, mesh or
    OpenStreetMap file, ``up`` a mesh's vertical axis, ``options`` an OSM file's height options)
    and, for the products that drive on it, a road path."""

    kind: str = "demo"  # "demo", "geojson", "mesh" or "osm"
    path: Optional[Path] = None
    up: str = "z"
    road: Optional[Path] = None  # a CSV path the product drives along
    options: dict[str, float] = field(default_factory=dict)

    def load(self, origin: Optional[Georeference] = None) -> Environment:
        """The environment; ``origin`` (the scenario's georeference) becomes ``env.origin`` and is what
        a longitude/latitude GeoJSON or an OSM file is projected about (without it: the data's centre)."""
        if self.kind == "demo" or self.path is None:
            env = Environment.demo()
            env.origin = origin
            return env
        if self.kind == "osm":
            return read_osm(self.path, origin=origin, key="city.osm", **self.options).environment
        return load_environment(self.path, self.up, self.kind, origin, key=f"city.{self.kind}")

    def describe(self) -> str:
        return "demo city" if self.kind == "demo" else f"{self.kind} {self.path}"


def city_block(data: Mapping[str, Any], base: Path, road: bool = False) -> Optional[City]:
    """``city: {mesh | geojson | osm | demo, up, road, level_height, roof_height, default_height}``;
    None when absent. ``road`` (a CSV path the product drives along; a road route between two
    points is the product's own key: a follow scenario's ``vehicle.route``, a tracking scenario's
    ``poi.route``) is accepted only for products that use one; the height options only with
    ``osm``."""
    if data.get("city") is None:
        return None
    keys = {"demo", "geojson", "mesh", "osm", "up", *OSM_OPTIONS}
    found = section(data, "city", keys | ({"road"} if road else set()))
    sources = [key for key in ("demo", "geojson", "mesh", "osm") if found.get(key) not in (None, False)]
    if len(sources) != 1:
        raise fail("city", found, "give exactly one of demo: true, geojson: FILE, mesh: FILE, osm: FILE")
    kind = sources[0]
    road_path: Optional[Path] = None
    if isinstance(found.get("road"), Mapping):
        raise fail("city.road", found["road"], "must be a CSV path: a road route {from, to} is vehicle.route "
                                               "(follow) or poi.route (tracking)")
    if found.get("road") is not None:
        road_path = resolve_path(base, found["road"], "city.road")
    if kind == "demo" and found["demo"] is not True:
        raise fail("city.demo", found["demo"], "must be true")
    if kind != "mesh" and "up" in found:
        raise fail("city.up", found["up"], "only applies to city.mesh")
    for key in OSM_OPTIONS:
        if kind != "osm" and key in found:
            raise fail(f"city.{key}", found[key], "only applies to city.osm")
    if kind == "demo":
        return City(road=road_path)
    up = found.get("up", "z")
    if up not in ("y", "z"):
        raise fail("city.up", up, 'must be "z" or "y"')
    options = {key: number(f"city.{key}", found[key]) for key in OSM_OPTIONS if key in found}
    return City(kind, resolve_path(base, found[kind], f"city.{kind}"), up, road_path, options)


def georeference_block(data: Mapping[str, Any]) -> Optional[Georeference]:
    """``georeference: {lat, lon, alt}`` (degrees, degrees, metres above mean sea level); None when
    absent."""
    value = data.get("georeference")
    if value is None:
        return None
    if not isinstance(value, Mapping):
        raise fail("georeference", value, "must be {lat, lon, alt} (degrees, degrees, metres AMSL)")
    reject_unknown(value, {"lat", "lon", "alt"}, "georeference.", where=" in georeference")
    for key in ("lat", "lon"):
        if key not in value:
            raise fail(f"georeference.{key}", None, "is required (degrees)")
    return Georeference(degrees("georeference.lat", value["lat"], 90.0),
                        degrees("georeference.lon", value["lon"], 180.0),
                        number("georeference.alt", value.get("alt", 0.0)))


def origin_to_georeference(value: Any) -> Any:
    """The old ``origin: [lat, lon(, alt)]`` as a ``georeference`` mapping (refused as before when
    malformed)."""
    reference = Georeference.from_value(value, "origin")
    return {"lat": reference.lat, "lon": reference.lon, "alt": reference.alt}

