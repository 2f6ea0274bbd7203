"""The ``loiter`` case kind: one loiter plan over areas of interest (Fly-Through, TLPP or LDLPP,
:func:`vistrack.loiter.plan`) scored by camera coverage, and optionally flown through the flight
layer in a wind the guidance does not know (:func:`vistrack.loiter.fly_and_score`): what ``vistrack
loiter`` does per method and scenario.

Its base is a mapping (inline or a YAML file); missing keys take section 4.1's values::

    scenario: loiter_6aoi.yaml      # a loiter scenario file (its AOIs and settings), or
    aois: [[x, y], ...]             # AOI centres (m), or
    random: {count: 6, seed: 0}     # a seeded random layout (vt.loiter.random_scenario: AOIs in
                                    # 800 x 800 m, 160 m apart; no seed: the case's own seed)
    method: ldlpp                   # fly_through | tlpp | ldlpp
    order: given                    # given | best (the visiting order with the shortest plan)
    turns: 1                        # full loiters per AOI
    turn_radius: 46.0               # r (m)
    aoi_radius: 46.0                # R (m), >= r
    speed: 12.0                     # m/s
    start: [0, 0]
    end: [0, 0]
    camera: {fov_deg: 74.0, max_gimbal_deg: 25.0, altitude: 61.0}
    threshold: 0.75                 # share of an AOI's disk in the footprint to count as covered
    dt: 1.0                         # coverage time step (s)
    wind: {east: 0, north: 0}       # or {speed, direction_deg}; not calm: also fly the plan in it

A ``scenario`` file's AOIs and settings are read once into the base (keys given beside it win).
To compare methods on the same random layouts, vary ``random.seed`` and ``method`` together.

Metrics: the plan's (``vt.loiter.metrics`` without its lists: ``length_m``, ``flight_time_s``,
``transit_time_s``, ``loiter_time_s``, ``coverage_time_s``, ``coverage_area_m2``,
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
from ..loiter.files import read_loiter_scenario
from ..schema import boolean, fail, integer, number, pair, positive, reject_unknown, resolve_path
from .kinds import (
    CaseContext,
    CaseKind,
    CaseOutput,
    dotted_keys,
    flatten,
    read_base,
    register_kind,
    set_case_value,
    wind_components,
)

__all__ = ["LOITER"]

_SOURCES = ("aois", "random")
_SETTINGS = ("method", "order", "turns", "turn_radius", "aoi_radius", "speed", "start", "end", "camera",
             "threshold", "dt", "wind")
_FROM_FILE = ("aois", "start", "end", "turn_radius", "speed", "aoi_radius", "turns", "threshold", "dt")
_CAMERA = ("fov_deg", "max_gimbal_deg", "altitude", "levelled")
_WIND = ("east", "north", "speed", "direction_deg")
_RANDOM = ("count", "seed")
_FLOWN = ("finished", "flight_time_s", "coverage_time_s", "coverage_area_m2", "loiter_covered_fraction",
          "planned_loiter_covered_fraction", "loiter_coverage_lost", "max_cross_track_m", "rms_cross_track_m")
_METRICS = ("method", "aois", "length_m", "flight_time_s", "flight_time_min", "transit_time_s", "loiter_time_s",
            "coverage_time_s", "coverage_area_m2", "coverage_per_aoi_s", "min_coverage_per_aoi_s",
            "steps_by_role.*", *(f"flown.{name}" for name in _FLOWN))


def _defaults() -> dict[str, Any]:
    camera = loiter.Camera()
    return {"method": "ldlpp", "order": "given", "turns": 1, "turn_radius": 46.0, "aoi_radius": 46.0, "speed": 12.0,
            "start": [0.0, 0.0], "end": [0.0, 0.0],
            "camera": {"fov_deg": camera.fov_deg, "max_gimbal_deg": camera.max_gimbal_deg,
                       "altitude": camera.altitude, "levelled": camera.levelled},
            "threshold": 0.75, "dt": 1.0, "wind": {"east": 0.0, "north": 0.0}}


def _base(value: Any, folder: Path) -> dict[str, Any]:
    data, folder = read_base(value, folder, "a loiter mapping")
    allowed = ("scenario", *_SOURCES, *_SETTINGS)
    reject_unknown(data, allowed)
    full = _defaults()
    if data.get("scenario") is not None:  # the file's AOIs and settings, read once
        scenario = read_loiter_scenario(resolve_path(folder, data["scenario"], "scenario"))
        full.update({"aois": scenario.aois.tolist(), "start": list(scenario.start), "end": list(scenario.end),
                     "turn_radius": scenario.turn_radius, "speed": scenario.speed, "aoi_radius": scenario.aoi_radius,
                     "turns": scenario.turns, "threshold": scenario.threshold, "dt": scenario.dt,
                     "camera": {"fov_deg": scenario.camera.fov_deg, "max_gimbal_deg": scenario.camera.max_gimbal_deg,
                                "altitude": scenario.camera.altitude}})
    full.update({k: v for k, v in data.items() if k != "scenario"})
    if sum(full.get(k) is not None for k in _SOURCES) != 1:
        raise fail("aois", {k: full.get(k) for k in ("scenario", *_SOURCES)},
                   "give exactly one of scenario: FILE, aois: [[x, y], ...], random: {count, seed}")
    _scenario(full, seed=0)  # validates the base
    return full


def _keys(base: Mapping[str, Any]) -> set[str]:
    return (dotted_keys(base) | set(_SOURCES) | {f"camera.{k}" for k in _CAMERA} | {f"wind.{k}" for k in _WIND}
            | {f"random.{k}" for k in _RANDOM})


def _apply(data: dict[str, Any], key: str, value: Any) -> dict[str, Any]:
    return set_case_value(data, key, value, _SOURCES)


def _wind(value: Any) -> tuple[float, float]:
    if not isinstance(value, Mapping) or set(value) - set(_WIND):
        raise fail("wind", value, "must be {east, north} or {speed, direction_deg} in m/s")
    return wind_components(value)


def _scenario(data: Mapping[str, Any], seed: int) -> tuple[loiter.Scenario, str, str, tuple[float, float]]:
    """The case's scenario, method, order and wind, validated (errors name the key and the value)."""
    method, order = data["method"], data["order"]
    if method not in loiter.METHODS:
        raise fail("method", method, "must be " + ", ".join(loiter.METHODS))
    if order not in loiter.ORDERS:
        raise fail("order", order, "must be " + ", ".join(loiter.ORDERS))
    camera_data = data["camera"]
    if not isinstance(camera_data, Mapping) or set(camera_data) - set(_CAMERA):
        raise fail("camera", camera_data, "must be {fov_deg, max_gimbal_deg, altitude, levelled}")
    defaults = loiter.Camera()
    camera = loiter.Camera(fov_deg=positive("camera.fov_deg", camera_data.get("fov_deg", defaults.fov_deg)),
                           max_gimbal_deg=number("camera.max_gimbal_deg",
                                                 camera_data.get("max_gimbal_deg", defaults.max_gimbal_deg), low=0.0),
                           altitude=positive("camera.altitude", camera_data.get("altitude", defaults.altitude)),
                           levelled=boolean("camera.levelled", camera_data.get("levelled", defaults.levelled)))
    settings: dict[str, Any] = {
        "start": pair("start", data["start"]), "end": pair("end", data["end"]),
        "turn_radius": positive("turn_radius", data["turn_radius"]), "speed": positive("speed", data["speed"]),
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
    return metrics


def _run(data: dict[str, Any], context: CaseContext) -> CaseOutput:
    scenario, method, order, wind = _scenario(data, context.seed)
    return CaseOutput(run_loiter_case(scenario, method, order, wind))


LOITER = register_kind(CaseKind(
    name="loiter",
    description="Fly-Through, TLPP or LDLPP loiter plan over AOIs, camera coverage, flown in wind (vistrack loiter)",
    load_base=_base, keys=_keys, run=_run, apply=_apply, metric_names=_METRICS,
    figure_metrics=("flight_time_s", "transit_time_s", "coverage_time_s", "coverage_per_aoi_s"),
))
