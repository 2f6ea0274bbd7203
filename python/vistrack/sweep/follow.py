"""The ``follow`` case kind: one run of the ground-vehicle follower (sinusoid and loiter modes,
:class:`vistrack.follow.scenario.FollowScenario`) and, unless the base says ``baseline: false``,
the vector-field baseline on the same vehicle: what ``vistrack follow --no-city`` flies.

Its base is a follow scenario (a file such as ``examples/follow_truck.yaml``, or a mapping with the
same keys; see :mod:`vistrack.follow.scenario`). A parameter sets any of its keys
(``follow.period``, ``follow.threshold``, ``follow.hysteresis``, ``follow.compensation``,
``offset.distance``, ``offset.angle_deg``, ``wind.north``, ``uav.speed``, ``vehicle.legs``...) and
``vehicle.speed_scale``, which multiplies every leg's speed (and end speed): a faster or slower
truck on the same route timing. The city section is not flown (line of sight needs the map; run
``vistrack follow`` for it). A vehicle track file is taken relative to the base file.

Metrics: ``metrics.json`` of ``vistrack follow`` flattened, without the constant strategy names:
``mean_tracking_error_m``, ``max_tracking_error_m``, ``along_track_lag_m``, ``mode_switches``,
``time_in_mode_s.sinusoid|loiter|straight``, ``camera_fraction``, ``centre_offset_east_m``,
``updates``, ``note`` (when the planner flew its straight mode), ... and the baseline's as
``baseline.*``: ``baseline.feasible`` false and ``baseline.reason`` (no scores) when the vehicle is
not slower than the UAV, so no constant orbit about it is flyable.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Mapping

from ..follow.scenario import TOP_KEYS, FollowScenario
from ..schema import fail, number, resolve_path
from .kinds import CaseContext, CaseKind, CaseOutput, dotted_keys, flatten, read_base, register_kind, set_dotted

__all__ = ["FOLLOW", "follow_metrics"]

_SECTIONS = {
    "uav": ("speed", "min_turn_radius", "altitude"),
    "vehicle": ("start", "legs", "track", "speed_scale"),
    "follow": ("period", "turn_margin", "threshold", "hysteresis", "loiter_pattern", "loiter_radius", "strategy",
               "loiter_direction", "compensation", "update_period"),
    "offset": ("distance", "angle_deg", "reference", "changes"),
    "wind": ("east", "north", "gusts"),
    "wind_estimate": ("east", "north"),
    "camera": ("fov_deg", "max_gimbal_deg"),
    "flight": ("dt", "integration", "max_time"),
    "baseline": ("radius", "beta", "k_psi", "direction"),
}
_RUN_METRICS = ("duration_s", "mean_tracking_error_m", "max_tracking_error_m", "along_track_lag_m",
                "max_along_track_lag_m", "final_along_track_lag_m", "mode_switches", "time_capturing_s",
                "time_in_mode_s.sinusoid", "time_in_mode_s.loiter", "time_in_mode_s.straight",
                "time_in_mode_s.standoff", "camera_fraction", "mean_vehicle_distance_m", "mean_offset_distance_m",
                "centre_offset_east_m", "centre_offset_north_m", "smoothness.bank_rms_deg",
                "smoothness.roll_reversals_per_s", "smoothness.roll_reversals", "smoothness.max_roll_rate_deg_s",
                "lost_s", "lost_episodes", "reacquire_s.mean", "reacquire_s.max")
# The planner's alone: the threshold it used (the sinusoid it flew is per run: metrics.json, updates.csv).
_PLANNER_METRICS = ("threshold.*",)
_METRICS = (*_RUN_METRICS, *_PLANNER_METRICS, "note", "wind_compensation", "updates", "uav.*",
            *(f"baseline.{m}" for m in _RUN_METRICS), "baseline.radius_m", "baseline.feasible", "baseline.reason")


def _base(value: Any, folder: Path) -> dict[str, Any]:
    data, folder = read_base(value, folder, "a follow scenario mapping")
    data.pop("city", None)  # no line-of-sight runs in a sweep
    vehicle = data.get("vehicle")
    if isinstance(vehicle, Mapping) and isinstance(vehicle.get("track"), str):
        data["vehicle"] = {**vehicle, "track": str(resolve_path(folder, vehicle["track"], "vehicle.track"))}
    _scenario(data, folder)  # validates the base
    return data


def _keys(base: Mapping[str, Any]) -> set[str]:
    keys = dotted_keys(base) | (TOP_KEYS - {"city", "description", "georeference"})
    return keys | {f"{section}.{name}" for section, names in _SECTIONS.items() for name in names}


def _apply(data: dict[str, Any], key: str, value: Any) -> dict[str, Any]:
    result = set_dotted(data, key, value)
    if key in ("vehicle.legs", "vehicle.track"):  # one way to give the vehicle
        result["vehicle"].pop("track" if key == "vehicle.legs" else "legs", None)
    return result


def _scenario(data: Mapping[str, Any], folder: Path) -> FollowScenario:
    """The case's scenario, validated (errors name the key); vehicle.speed_scale applied to the legs."""
    data = dict(data)
    vehicle = data.get("vehicle")
    if isinstance(vehicle, Mapping) and "speed_scale" in vehicle:
        vehicle = dict(vehicle)
        scale = number("vehicle.speed_scale", vehicle.pop("speed_scale"), low=0.0)
        if isinstance(vehicle.get("legs"), list):
            vehicle["legs"] = [_scaled(leg, scale) for leg in vehicle["legs"]]
        elif scale != 1.0:
            raise fail("vehicle.speed_scale", scale, "scales the speeds of vehicle.legs; a track has none")
        data["vehicle"] = vehicle
    return FollowScenario.from_mapping(data, folder)


def _scaled(leg: Any, scale: float) -> Any:
    if not isinstance(leg, Mapping):
        return leg  # FollowScenario names the bad leg
    out = dict(leg)
    for key in ("speed", "end_speed"):
        if isinstance(out.get(key), (int, float)) and not isinstance(out.get(key), bool):
            out[key] = out[key] * scale
    return out


def follow_metrics(scenario: FollowScenario) -> dict[str, Any]:
    """One case's metrics (flat): the follower's run and the baseline's (``vistrack follow
    --no-city``'s metrics.json without the strategy names, the centre offset split in two)."""
    record = scenario.run(city=False).metrics()
    record.pop("sinusoid", None)
    record.pop("warnings", None)
    for run in (record, record.get("baseline")):
        if run is not None and "centre_offset_m" in run:  # an infeasible baseline has its reason only
            run.pop("strategy", None)
            east, north = run.pop("centre_offset_m")
            run["centre_offset_east_m"], run["centre_offset_north_m"] = east, north
    return flatten(record)


def _run(data: dict[str, Any], context: CaseContext) -> CaseOutput:
    return CaseOutput(follow_metrics(_scenario(data, context.folder)))


FOLLOW = register_kind(CaseKind(
    name="follow",
    description="following a ground vehicle: sinusoid and loiter modes, and the vector-field baseline "
                "(vistrack follow)",
    load_base=_base, keys=_keys, run=_run, apply=_apply, metric_names=_METRICS,
    figure_metrics=("mean_tracking_error_m", "along_track_lag_m", "camera_fraction", "mode_switches"),
))
