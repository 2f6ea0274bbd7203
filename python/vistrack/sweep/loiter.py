"""The ``loiter`` case kind: one loiter plan over areas of interest (Fly-Through, TLPP or LDLPP,
:func:`vistrack.loiter.plan`) scored by camera coverage, and optionally flown through the flight
layer in a wind the guidance does not know (:func:`vistrack.loiter.fly_and_score`): what ``vistrack
loiter`` does per method and scenario.

Its base is a mapping (inline or a YAML file) in a loiter scenario's schema (the shared ``uav``,
``camera`` and ``wind`` blocks); missing keys take section 4.1's values (the bound
``vt.loiter.Parameters``, ``CoverageOptions`` and ``Camera``)::

    scenario: loiter_6aoi.yaml      # a loiter scenario file (its AOIs and settings), or
    aois: [[x, y], ...]             # AOI centres (m), or
    random: {count: 6, seed: 0}     # a seeded random layout (vt.loiter.random_scenario: AOIs in
                                    # 800 x 800 m, 160 m apart; no seed: the case's own seed)
    method: ldlpp                   # fly_through | tlpp | ldlpp
    order: given                    # given | best (the visiting order with the shortest plan)
    turns: 1                        # full loiters per AOI
    aoi_radius: 46.0                # R (m), >= r
    uav: {speed: 12.0, min_turn_radius: 46.0, altitude: 61.0}   # v, r and the camera's height
    start: [0, 0]
    end: [0, 0]
    camera: {fov_deg: 74.0, max_gimbal_deg: 25.0, mount: levelled}
    threshold: 0.75                 # share of an AOI's disk in the footprint to count as covered
    dt: 1.0                         # coverage time step (s)
    wind: {east: 0, north: 0}       # not calm: also fly the plan in it

A ``scenario`` file's AOIs and settings are read once into the base (keys given beside it win, one
by one inside a block). To compare methods on the same random layouts, vary ``random.seed`` and
``method`` together. Spellings from before the one schema still load, one line on stdout each:
``turn_radius``, ``speed``, ``camera.altitude``, ``camera.levelled`` (as in a loiter scenario file)
and ``wind: {speed, direction_deg}`` (now ``east``, ``north``).

Metrics: the plan's (``vt.loiter.metrics`` without its lists: ``length_m``, ``flight_time_s``,
``transit_time_s``, ``loiter_time_s``, ``coverage_time_s``, ``coverage_area_m2s``,
``steps_by_role.<role>.steps|covered_steps``), ``aois``, ``coverage_per_aoi_s`` and
``min_coverage_per_aoi_s``; with wind, the flown path's as ``flown.*`` (``flown.flight_time_s``,
``flown.coverage_time_s``, ``flown.loiter_covered_fraction``, ``flown.loiter_coverage_lost``,
``flown.max_cross_track_m``, ...).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Mapping

import numpy as np

from .. import loiter
from ..flight import Wind
from ..loiter.files import RENAMES, read_loiter_scenario, vehicle_and_camera
from ..scenario_blocks import CAMERA_MOUNTS, uav_dict, wind_block
from ..schema import fail, integer, number, pair, positive, reject_unknown, resolve_path
from .kinds import (
    CaseContext,
    CaseKind,
    CaseOutput,
    dotted_keys,
    flatten,
    overlay,
    read_base,
    register_kind,
    set_case_value,
)
from .spellings import polar_wind, silent, upgrade_base, upgrade_parameter

__all__ = ["LOITER"]

_SOURCES = ("aois", "random")
_SETTINGS = ("method", "order", "turns", "aoi_radius", "uav", "start", "end", "camera", "threshold", "dt", "wind")
_UAV = ("speed", "min_turn_radius", "altitude")
_CAMERA = ("fov_deg", "max_gimbal_deg", "mount")
_WIND = ("east", "north")
_RANDOM = ("count", "seed")
_FLOWN = ("finished", "flight_time_s", "coverage_time_s", "coverage_area_m2s", "loiter_covered_fraction",
          "planned_loiter_covered_fraction", "loiter_coverage_lost", "max_cross_track_m", "rms_cross_track_m")
_METRICS = ("method", "aois", "length_m", "flight_time_s", "flight_time_min", "transit_time_s", "loiter_time_s",
            "coverage_time_s", "coverage_area_m2s", "coverage_per_aoi_s", "min_coverage_per_aoi_s",
            "steps_by_role.*", *(f"flown.{name}" for name in _FLOWN), "flown.smoothness.*")


def _defaults() -> dict[str, Any]:
    """Section 4.1's case: every value from the bound C++ structs."""
    p, camera, cover, calm = loiter.Parameters(), loiter.Camera(), loiter.CoverageOptions(), Wind()
    return {"method": "ldlpp", "order": "given", "turns": p.turns, "aoi_radius": p.aoi_radius,
            "uav": {"speed": p.speed, "min_turn_radius": p.turn_radius, "altitude": camera.altitude},
            "start": [0.0, 0.0], "end": [0.0, 0.0], "camera": _camera(camera), "threshold": cover.threshold,
            "dt": cover.dt, "wind": {"east": calm.east, "north": calm.north}}


def _from_file(scenario: loiter.Scenario) -> dict[str, Any]:
    """A loiter scenario file's AOIs and settings, as base keys."""
    camera = scenario.camera
    return {"aois": scenario.aois.tolist(), "start": list(scenario.start), "end": list(scenario.end),
            "uav": uav_dict(scenario.uav()),
            "aoi_radius": scenario.aoi_radius, "turns": scenario.turns, "threshold": scenario.threshold,
            "dt": scenario.dt, "camera": _camera(camera)}


def _camera(camera: loiter.Camera) -> dict[str, Any]:
    """A camera as the camera block (its height is uav.altitude)."""
    return {"fov_deg": camera.fov_deg, "max_gimbal_deg": camera.max_gimbal_deg,
            "mount": CAMERA_MOUNTS[0] if camera.levelled else CAMERA_MOUNTS[1]}


def _base(value: Any, folder: Path) -> dict[str, Any]:
    data, folder = read_base(value, folder, "a loiter mapping")
    data = upgrade_base(data, RENAMES, polar_wind)
    reject_unknown(data, ("scenario", *_SOURCES, *_SETTINGS))
    full = _defaults()
    if data.get("scenario") is not None:  # the file's AOIs and settings, read once
        full.update(_from_file(read_loiter_scenario(resolve_path(folder, data["scenario"], "scenario"))))
    overlay(full, {k: v for k, v in data.items() if k != "scenario"})  # a block given in part keeps the rest
    if sum(full.get(k) is not None for k in _SOURCES) != 1:
        raise fail("aois", {k: full.get(k) for k in ("scenario", *_SOURCES)},
                   "give exactly one of scenario: FILE, aois: [[x, y], ...], random: {count, seed}")
    _scenario(full, seed=0)  # validates the base
    return full


def _keys(base: Mapping[str, Any]) -> set[str]:
    return (dotted_keys(base) | set(_SOURCES) | {f"uav.{k}" for k in _UAV} | {f"camera.{k}" for k in _CAMERA}
            | {f"wind.{k}" for k in _WIND} | {f"random.{k}" for k in _RANDOM}
            | {"wind.speed", "wind.direction_deg"})  # the old polar wind, turned into east, north


def _apply(data: dict[str, Any], key: str, value: Any) -> dict[str, Any]:
    return set_case_value(data, key, value, _SOURCES)


def _parameter(key: str, values: list[Any]) -> tuple[str, list[Any]]:
    return upgrade_parameter(key, values, RENAMES, polar_wind)


def _wind(value: Any) -> tuple[float, float]:
    if not isinstance(value, Mapping):
        raise fail("wind", value, "must be {east, north} in m/s")
    wind = wind_block({"wind": polar_wind(value, silent)})
    if wind.gusts is not None:
        raise fail("wind.gusts", value.get("gusts"), "a loiter case flies in a constant wind")
    return wind.east, wind.north


def _scenario(data: Mapping[str, Any], seed: int) -> tuple[loiter.Scenario, str, str, tuple[float, float]]:
    """The case's scenario, method, order and wind, validated (errors name the key and the value)."""
    method, order = data["method"], data["order"]
    if method not in loiter.METHODS:
        raise fail("method", method, "must be " + ", ".join(loiter.METHODS))
    if order not in loiter.ORDERS:
        raise fail("order", order, "must be " + ", ".join(loiter.ORDERS))
    uav, camera = vehicle_and_camera(data)
    settings: dict[str, Any] = {
        "start": pair("start", data["start"]), "end": pair("end", data["end"]),
        "turn_radius": uav.min_turn_radius, "speed": uav.speed, "dynamics": str(uav.dynamics),
        "roll_time_constant": uav.roll_time_constant, "max_roll_rate_deg_s": uav.max_roll_rate_deg_s,
        "aoi_radius": positive("aoi_radius", data["aoi_radius"]), "turns": integer("turns", data["turns"], 1, 1000),
        "camera": camera, "dt": positive("dt", data["dt"]),
        "threshold": number("threshold", data["threshold"], low=0.0, high=1.0, low_open=True),
    }
    if data.get("aois") is not None:
        aois = data["aois"]
        if not isinstance(aois, list) or not aois:
            raise fail("aois", aois, "must be a non-empty list of [x, y] AOI centres")
        centres = np.array([pair(f"aois[{i}]", a) for i, a in enumerate(aois)], dtype=float)
        scenario = loiter.Scenario(aois=centres, name="aois", **settings)
    else:
        spec = data["random"]
        if not isinstance(spec, Mapping) or set(spec) - set(_RANDOM):
            raise fail("random", spec, "must be {count: n, seed: s} (no seed: the case's own)")
        count = integer("random.count", spec.get("count", 6), 1, 1000)
        if spec.get("seed") is not None:
            seed = integer("random.seed", spec["seed"], 0, 2**63 - 1)
        scenario = loiter.random_scenario(count, seed, **settings)
    scenario.plan(method)  # the planner's own checks (R < r, overlapping circles) name the field
    return scenario, method, order, _wind(data["wind"])


def run_loiter_case(scenario: loiter.Scenario, method: str, order: str = "given",
                    wind: tuple[float, float] = (0.0, 0.0)) -> dict[str, Any]:
    """One case's metrics (flat): plan, coverage and, in a wind, the flown path's scores."""
    plan = scenario.plan(method, order)
    coverage = scenario.coverage(plan)
    record = loiter.metrics(plan, coverage, scenario.dt, scenario.threshold)
    metrics = {k: v for k, v in flatten(record).items() if not isinstance(v, list)}
    per_aoi = np.asarray(coverage.time_per_aoi, dtype=float)
    metrics.update({"aois": len(scenario.aois), "coverage_per_aoi_s": float(per_aoi.mean()),
                    "min_coverage_per_aoi_s": float(per_aoi.min())})
    if wind != (0.0, 0.0):
        flown = loiter.fly_and_score(scenario, plan, wind, planned=coverage, keep_trajectory=False)
        metrics.update({f"flown.{name}": flown[name] for name in _FLOWN})
        metrics.update({f"flown.{name}": value for name, value in flatten({"smoothness": flown["smoothness"]}).items()})
    return metrics


def _run(data: dict[str, Any], context: CaseContext) -> CaseOutput:
    scenario, method, order, wind = _scenario(data, context.seed)
    return CaseOutput(run_loiter_case(scenario, method, order, wind))


LOITER = register_kind(CaseKind(
    name="loiter",
    description="Fly-Through, TLPP or LDLPP loiter plan over AOIs, camera coverage, flown in wind (vistrack loiter)",
    load_base=_base, keys=_keys, run=_run, apply=_apply, metric_names=_METRICS,
    figure_metrics=("flight_time_s", "transit_time_s", "coverage_time_s", "coverage_per_aoi_s"),
    upgrade_parameter=_parameter,
))
