"""The ``tracking`` case kind: one run of the map-to-report pipeline (:func:`vistrack.tracking.pipeline.compute`)
without its report, on the worker's shared environment and orbit planner.

Its base is a scenario (a file or a mapping, as ``vistrack run`` reads); a parameter sets any
scenario key (``uav.altitude``, ``sensor.d_max``, ``planning.cutoff``, ``control.beta``, a whole
section such as ``city``...). Metrics are those of ``metrics.json`` flattened
(``plan.initial_radius_m``, ``simulation.visibility_fraction``, ``baselines.40.visibility_fraction``),
without timings; ``plan.volumes_computed`` depends on what the worker's VV cache already held, so
it is run metadata (``run_volumes_computed``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Mapping

import numpy as np

from .._core import RoadNetwork
from ..scenario_blocks import OSM_OPTIONS
from ..schema import fail, resolve_path
from ..tracking.pipeline import compute
from ..tracking.scenario import Scenario
from .kinds import CaseContext, CaseKind, CaseOutput, dotted_keys, flatten, register_kind, set_dotted

__all__ = ["TRACKING"]

# One source per section: setting one removes the others.
_SOURCES = {"city": ("demo", "geojson", "mesh", "osm"), "poi": ("path", "waypoints", "nodes", "route")}

_METRICS = (
    "environment", "environment_triangles", "environment_max_height_m", "origin",
    "poi.length_m", "poi.duration_s", "poi.speed_mps",
    "plan.samples", "plan.feasible", "plan.infeasibility", "plan.initial_radius_m", "plan.final_radius_m",
    "plan.min_radius_m", "plan.max_radius_m", "plan.min_feasible_radius_m", "plan.max_metric_m3", "plan.cutoff_m3",
    # The locus (metrics.locus_summary): which one, and for the smooth one what its check found.
    "plan.locus", "plan.tracking_margin_m", "plan.check_points", "plan.check_volumes_computed", "plan.check_rounds",
    "plan.paper_violations", "plan.paper_max_violation_m", "plan.min_clearance_m", "plan.max_lowering_m",
    "plan.max_lowering_at_s", "plan.max_lowering_at_m", "plan.mean_lowering_m", "plan.knots",
    "plan.max_abs_rate_mps", "plan.max_abs_acceleration_mps2",
    "simulation.duration_s", "simulation.samples", "simulation.rhs_evaluations", "simulation.accepted_steps",
    "simulation.rejected_steps", "simulation.restarts", "simulation.initial_radial_error_m",
    "simulation.converge_after_s", "simulation.radial_error_after_mean_m", "simulation.radial_error_after_max_abs_m",
    "simulation.heading_error_after_max_abs_rad", "simulation.control_max_abs", "simulation.saturated_fraction",
    "simulation.orbit_radius_first_m", "simulation.orbit_radius_last_m", "simulation.visibility_fraction",
    "simulation.smoothness.*", "uav.*", "other_model.*",
    "baselines.*.radius_m", "baselines.*.visibility_fraction",
)


def _scenario(data: Mapping[str, Any], folder: Path) -> Scenario:
    return Scenario.from_dict(data, base=folder)


def _load_base(value: Any, folder: Path) -> dict[str, Any]:
    if isinstance(value, str):
        scenario = Scenario.load(resolve_path(folder, value, "base"))
    elif isinstance(value, Mapping):
        scenario = _scenario(value, folder)
    else:
        raise fail("base", value, "must be a scenario file or a scenario mapping")
    return scenario.to_dict()


def _keys(base: Mapping[str, Any]) -> set[str]:
    keys = dotted_keys(base) | {f"{section}.{source}" for section, names in _SOURCES.items() for source in names}
    return (keys | {"city.up"} | {f"city.{option}" for option in OSM_OPTIONS}) - {"name"}


def _apply(data: dict[str, Any], key: str, value: Any) -> dict[str, Any]:
    section, _, name = key.partition(".")
    result = set_dotted(data, key, value)
    if name in _SOURCES.get(section, ()):
        for other in _SOURCES[section]:
            if other != name:
                result[section].pop(other, None)
        if section == "city" and name != "mesh":
            result[section].pop("up", None)
        if section == "city" and name != "osm":
            for option in OSM_OPTIONS:
                result[section].pop(option, None)
    return result


def _run(data: dict[str, Any], context: CaseContext) -> CaseOutput:
    scenario = _scenario(data, context.folder)
    spec, origin = scenario.environment, scenario.origin
    # The origin places a WGS84 GeoJSON map in the local frame: part of the map's key.
    where = "" if origin is None else repr((origin.lat, origin.lon, origin.alt))
    key = context.resources.map_key(spec.kind, spec.path, spec.up, where, repr(sorted(spec.options.items())))
    env = context.resources.environment(key, lambda: spec.load(origin))
    # VVs are shared between cases with the same POI path and discretization (Resources.planner).
    poi = scenario.poi.build(env)
    p = scenario.planning
    share = (np.asarray(poi.waypoints).tobytes(), poi.speed, p.resolution_deg, p.spacing, p.min_spacing,
             p.max_depth, p.cutoff)
    planner = context.resources.planner(key, env, scenario.sensor, context.cache_dir, share)
    result = compute(scenario, environment=env, planner=planner, metric_spacings=())
    metrics = dict(result.metrics)
    for volatile in ("scenario", "timings_s", "volume_cache"):
        metrics.pop(volatile, None)
    flat = flatten(metrics)
    volumes = flat.pop("plan.volumes_computed")
    return CaseOutput(flat, {"volumes_computed": volumes})


def _roads(base: Mapping[str, Any], folder: Path) -> RoadNetwork:
    scenario = _scenario(base, folder)
    return scenario.environment.load(scenario.origin).roads


TRACKING = register_kind(CaseKind(
    name="tracking",
    description="visibility-volume orbit plan and closed-loop tracking of a POI (vistrack run)",
    load_base=_load_base, keys=_keys, run=_run, apply=_apply, metric_names=_METRICS,
    figure_metrics=("simulation.visibility_fraction", "simulation.radial_error_after_max_abs_m",
                    "plan.initial_radius_m", "plan.min_radius_m", "plan.samples"),
    roads=_roads, route_key="poi.waypoints",
))
