"""The output folder of ``vistrack follow``: figures, trajectory CSVs, metrics.json, report.md and,
as the report options ask, the animation (trajectory.gif) and the interactive page (report.html)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Callable, Optional, Sequence

import numpy as np

from .._core import Environment
from ..follow import DownwardCamera, FollowResult, camera_footprint
from ..follow.files import write_follow_trajectory, write_follow_updates
from ..follow.scenario import FollowStudy
from ..follow.simulation import planner_note
from ..io import write_json
from ..plotting.common import OSM_CREDIT
from ..plotting.follow import figure_compare, figure_paths, figure_scores
from ..plotting.motion import Line, MotionScene, Overlay, Sight, Track
from ..report_options import ReportOptions
from ..scenario_blocks import uav_dict
from .document import Document, Heading, Picture, Table, vehicle_line
from .fdm import fdm_blocks, fdm_figure
from .follow_city import city_orbit_blocks
from .media import write_media

PLANNER = "sinusoid planner (the paper)"
BASELINE = "vector field (74), constant radius"
OPEN_GIF = "trajectory_open.gif"  # the open-ground run, when the main animation is the city run


def write_follow(study: FollowStudy, out: Path, title: str = "",
                 report: Optional[ReportOptions] = None) -> dict[str, Any]:
    """follow_paths.png (the paper's view), follow_scores.png (sigma, mode, errors, camera over
    time), follow_compare.png (planner beside the baseline), follow_city.png (both on the city road
    with line of sight, when run), trajectory.csv (the planner's run), baseline_trajectory.csv,
    city_trajectory.csv, city_baseline_trajectory.csv, report.md, and as ``report`` asks
    trajectory.gif and report.html (the planner's run on the city road when it was run, else on
    open ground; with a city trajectory_open.gif adds the open-ground run), and metrics.json (with the figures' and
    files' names). Returns the metrics record."""
    out.mkdir(parents=True, exist_ok=True)
    report = report or ReportOptions()
    p = study.parameters
    label = "with wind compensation" if p.wind_compensation else "without wind compensation"
    title = f"{title} ({label})" if title else label
    files = [figure_paths(study.follow, out / "follow_paths.png", title),
             figure_scores(study.follow, study.follow.run.threshold.threshold, p.hysteresis, out / "follow_scores.png",
                           title),
             write_follow_trajectory(study.follow, out / "trajectory.csv"),
             write_follow_updates(study.follow, out / "updates.csv")]
    if study.baseline is not None:
        files.append(figure_compare([(PLANNER, study.follow), (BASELINE, study.baseline)],
                                    out / "follow_compare.png", title))
        files.append(write_follow_trajectory(study.baseline, out / "baseline_trajectory.csv"))
    if study.city_follow is not None:
        runs = [(PLANNER, study.city_follow)]
        if study.city_baseline is not None:
            runs.append((BASELINE, study.city_baseline))
        files.append(figure_compare(runs, out / "follow_city.png", f"{title}, on a city road", study.environment))
        files.append(write_follow_trajectory(study.city_follow, out / "city_trajectory.csv"))
        if study.city_baseline is not None:
            files.append(write_follow_trajectory(study.city_baseline, out / "city_baseline_trajectory.csv"))
    record = study.metrics()
    document = _document(study, title, [f.name for f in files])
    if study.fdm is not None:
        six = study.fdm.trajectory
        run = study.follow.run
        state = np.asarray(run.state)
        picture = fdm_figure(out, (run.t, state[:, 0], state[:, 1], run.bank),
                             f"{study.scenario.uav.dynamics} model", six,
                             f"The follow planner on the 6-DOF {six.aircraft} and the kinematic vehicle",
                             np.asarray(run.vehicle), "ground vehicle")
        block = {**record["fdm"], "real_time_factor": float((six.t[-1] - six.t[0]) / six.seconds)}
        rows = [["camera sees the vehicle (%)", f"{100 * record['camera_fraction']:.1f}",
                 f"{100 * block['camera_fraction']:.1f}"],
                ["mean distance to the vehicle (m)", f"{record['mean_vehicle_distance_m']:.1f}",
                 f"{block['mean_vehicle_distance_m']:.1f}"]]
        document.blocks += [*fdm_blocks(block, rows, ["score", "kinematic", "6-DOF"]), picture]
        files.append(out / "fdm.png")
    open_scene = motion_scene(study.follow, study.scenario.camera, study.scenario.uav.altitude,
                              f"{title}: open ground")
    more: list[tuple[str, MotionScene, str]] = []
    if study.city_follow is not None and study.environment is not None:
        scene = motion_scene(study.city_follow, study.scenario.camera, study.scenario.uav.altitude,
                             f"{title}: city road", study.environment)
        hint = ("The planner's run on the city road: buildings, the vehicle, the UAV, the camera footprint and the "
                "line of sight (green: clear, red: through a building). Drag to turn, scroll to zoom.")
        more.append((OPEN_GIF, open_scene, "Animation on open ground (the paper's setting)"))
    else:
        scene, hint = open_scene, "The planner's run: the vehicle, the UAV and the camera footprint. Drag to turn."
    record["report_files"] = write_media(out, scene, document, report, figure_hint=hint, more_gifs=more)
    (out / "report.md").write_text(document.markdown(), encoding="utf-8")
    record["files"] = [f.name for f in files] + ["report.md"] + list(record["report_files"])
    write_json(record, out / "metrics.json")
    return record


def motion_scene(result: FollowResult, camera: DownwardCamera, altitude: float, title: str,
                 env: Optional[Environment] = None) -> MotionScene:
    """One follow run as a scene: the UAV at ``altitude`` above the ground and the vehicle moving,
    the planned (desired) path, the camera's footprint on the ground (the cone of the metric's
    camera, its gimbal rolled towards the vehicle), the true wind, and with line of sight (a city
    run) the sight line green or red and the UAV's path coloured by it."""
    t = result.t
    state = result.state
    vehicle = result.vehicle
    ground = env.ground_level if env is not None else 0.0
    visible = result.line_of_sight
    tracks = [Track("UAV", t, state[:, :2], color="tab:blue", z=ground + altitude, flag=visible),
              Track("vehicle", t, vehicle, color="black", marker="s", z=ground + 0.5, width=2.5)]
    lines = [Line("planned path", result.desired, color="0.45", style="--", width=0.9, z=ground + altitude)]
    # The view holds the paths; a footprint seen at a steep bank may reach beyond it.
    extent = MotionScene(tracks, lines).fit_extent()
    bank = np.asarray(result.run.bank, dtype=float)

    def footprint(time: float) -> Sequence[np.ndarray]:
        k = min(max(int(np.searchsorted(t, time, side="right")) - 1, 0), len(t) - 1)
        return [camera_footprint(camera, (state[k, 0], state[k, 1], altitude), float(state[k, 2]), float(bank[k]),
                                 vehicle[k])]

    overlays = [Overlay("camera footprint", footprint, color="tab:orange", z=ground)]
    wind = np.asarray(result.run.wind, dtype=float)
    wind_field: Optional[Callable[[float], tuple[float, float]]] = None
    if len(wind) and np.any(np.hypot(wind[:, 0], wind[:, 1]) > 0.0):
        def wind_field(time: float) -> tuple[float, float]:
            k = min(max(int(np.searchsorted(t, time, side="right")) - 1, 0), len(t) - 1)
            return float(wind[k, 0]), float(wind[k, 1])

    sight = Sight(0, 1, t, visible) if visible is not None else None
    return MotionScene(tracks, lines, overlays, sight, wind=wind_field, env=env, extent=extent, title=title,
                       credit=OSM_CREDIT if env is not None else None)


def _row(name: str, m: dict[str, Any]) -> list[str]:
    modes = ", ".join(f"{k} {v:.0f} s" for k, v in m["time_in_mode_s"].items() if v > 0)
    sight = m.get("line_of_sight_fraction")
    both = m.get("camera_and_line_of_sight_fraction")
    return [name, f"{m['mean_tracking_error_m']:.2f}", f"{m['max_tracking_error_m']:.1f}",
            f"{m['along_track_lag_m']:.1f}", str(m["mode_switches"]), modes or "-",
            f"{100 * m['camera_fraction']:.1f}", "-" if sight is None else f"{100 * sight:.1f}",
            "-" if both is None else f"{100 * both:.1f}"]


def _threshold_line(m: dict[str, Any]) -> str:
    """The threshold used and the sinusoid flown (effective T, D, A, sigma: min / median / max)."""
    h = m["threshold"]
    how = "auto, from the camera (beyond the paper)" if h["automatic"] else "given"
    reach = ("to the horizon" if h["camera_reach_m"] is None
             else f"{h['camera_reach_m']:.0f} m to the side")
    line = (f"Threshold h = {h['h']:.3g} ({how}): at sigma {h['upper_ratio']:.3g} the amplitude is "
            f"{h['amplitude_at_upper_m']:.0f} m, the camera sees {reach}")
    s = m.get("sinusoid")
    if s is None:
        return line + "; no update flew the sinusoid"
    cells = ", ".join(f"{label} {' / '.join(f'{v:.3g}' for v in s[key])}" for label, key in
                      (("sigma", "speed_ratio"), ("T s", "period_s"), ("D m", "period_distance_m"),
                       ("A m", "amplitude_m")))
    return line + f"; sinusoid flown (min / median / max, per update in updates.csv): {cells}"


def _document(study: FollowStudy, title: str, files: Sequence[str]) -> Document:
    s = study.scenario
    rows = [_row(PLANNER, study.follow.metrics)]
    if study.baseline is not None:
        rows.append(_row(BASELINE, study.baseline.metrics))
    if study.city_follow is not None:
        rows.append(_row(f"{PLANNER}, city road", study.city_follow.metrics))
    if study.city_baseline is not None:
        rows.append(_row(f"{BASELINE}, city road", study.city_baseline.metrics))
    wind = math.hypot(s.wind.east, s.wind.north)
    summary = [f"UAV {s.uav.speed:g} m/s at {s.uav.altitude:g} m, turn radius {s.uav.min_turn_radius:g} m; camera "
               f"{math.degrees(s.camera.fov):.0f} deg on a +-{math.degrees(s.camera.max_gimbal):.0f} deg gimbal",
               f"Wind {s.wind.east:g} east, {s.wind.north:g} north ({wind:.3g} m/s); {len(study.follow.ticks)} "
               "updates at 1 Hz",
               vehicle_line(uav_dict(s.uav), study.follow.metrics["smoothness"])]
    summary += [_threshold_line(study.follow.metrics)]
    summary += [f"Warning: {w}" for w in study.warnings()]
    summary += [f"Planner: {note}" for note in [planner_note(study.follow)] if note is not None]
    summary += [f"Baseline not flown{where}: {reason}" for where, reason in
                (("", study.baseline_reason), (" on the city road", study.city_baseline_reason)) if reason is not None]
    blocks: list[Any] = [Heading("Runs"),
                         Table(["run", "mean tracking error (m)", "max (m)", "along-track lag (m)", "mode switches",
                                "time in mode", "camera sees the vehicle (%)", "line of sight (%)", "both (%)"], rows)]
    titles = {"follow_paths.png": "Paths (the paper's view)", "follow_scores.png": "Scores over time",
              "follow_compare.png": "Planner beside the vector-field baseline",
              "follow_city.png": "On a city road, with line of sight"}
    blocks += [Picture(name, caption) for name, caption in titles.items() if name in files]
    blocks += city_orbit_blocks(study.metrics().get("city"))  # beyond every anchor (follow.city_orbit)
    return Document(f"vistrack report: following a ground vehicle, {title}", summary, blocks)
