"""The output folder of ``vistrack loiter``: metrics JSON, sampled paths as CSV, the figures, and the
tables beside the paper's (Table 1, Figure 14), of wind and of random scenarios; for one scenario
also report.md, the animation (trajectory.gif) and the interactive page (report.html)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any, Optional

import numpy as np

from .. import loiter
from ..io import write_json
from ..loiter import METHOD_NAMES
from ..loiter.files import write_loiter_samples_csv
from ..loiter.study import MethodRun, paper_numbers, summary, wind_summary
from ..plotting import loiter as figures
from ..plotting.motion import Line, MotionScene, Overlay, Shapes, Track, circle_ring, ellipse_ring
from ..report_options import ReportOptions
from .document import Document, Heading, Picture, Table
from .media import write_media


def write_scenario(out: Path, scenario: loiter.Scenario, runs: Sequence[MethodRun],
                   report: Optional[ReportOptions] = None,
                   wind: Optional[tuple[float, float]] = None) -> list[Path]:
    """metrics.json, one sampled-path CSV per method, the methods figure (and the wind figure),
    report.md, and as ``report`` asks trajectory.gif and report.html: every method's aircraft
    flying its plan at once (in ``wind``, unknown to the guidance, when given) with the camera
    footprint the coverage metric uses."""
    out.mkdir(parents=True, exist_ok=True)
    written = [write_json({
        "scenario": scenario.name, "aois": scenario.aois.tolist(), "start": list(scenario.start),
        "end": list(scenario.end), "turn_radius": scenario.turn_radius, "speed": scenario.speed,
        "aoi_radius": scenario.aoi_radius, "turns": scenario.turns, "threshold": scenario.threshold,
        "dt": scenario.dt, "camera": {"fov_deg": scenario.camera.fov_deg,
                                      "max_gimbal_deg": scenario.camera.max_gimbal_deg,
                                      "altitude": scenario.camera.altitude,
                                      "mount": "levelled" if scenario.camera.levelled else "roll"},
        "methods": [run.record(scenario) for run in runs],
        "loiters": {run.method: loiter.loiter_circles(run.plan) for run in runs},
        "segments": {run.method: loiter.segment_records(run.plan) for run in runs},
    }, out / "metrics.json")]
    for run in runs:
        written.append(write_loiter_samples_csv(out / f"path_{run.method}.csv", run.plan, run.coverage,
                                                   scenario.dt, scenario.threshold))
    plans = {run.method: run.plan for run in runs}
    written.append(figures.methods_figure(plans, {run.method: run.coverage for run in runs},
                                          out / "plans.png", scenario.name))
    written.append(figures.timeline_figure(runs, scenario.threshold, scenario.dt, out / "timeline.png",
                                           scenario.name))
    best = {run.method: run.best_plan for run in runs if run.best_plan is not None}
    if best:
        written.append(figures.methods_figure(best, {run.method: run.best_coverage for run in runs
                                                     if run.best_coverage is not None},
                                              out / "plans_best_order.png", scenario.name + " (best order)"))
    for run in runs:
        if run.wind_paths:
            shown = run.wind_paths[:: max(1, len(run.wind_paths) // 4)][:4]  # at most four flights drawn
            written.append(figures.wind_figure(run.plan, shown, out / f"wind_{run.method}.png",
                                               f"{METHOD_NAMES[run.method]} flown in unknown wind"))
    document = scenario_document(scenario, runs, [p.name for p in written])
    scene = motion_scene(scenario, runs, wind)
    hint = ("Every method's aircraft flies its plan at the camera's altitude; on the ground its camera footprint "
            "(the ellipse the coverage metric scores) and the AOIs. Drag to turn, scroll to zoom.")
    made = write_media(out, scene, document, report, figure_hint=hint)
    written += [out / name for name in made]
    written.append(_write_text(out / "report.md", document.markdown()))
    return written


def flown_states(scenario: loiter.Scenario, plan: loiter.Plan, planned: loiter.Coverage,
                 wind: Optional[tuple[float, float]] = None) -> tuple[np.ndarray, np.ndarray, loiter.Coverage]:
    """What the animation shows of one plan, every ``scenario.dt``: times, poses (n, 3) x, y, psi and
    their coverage. Without wind the plan's own samples (those ``planned`` scored); in wind the
    plan flown by the flight layer (``loiter.fly``), scored the same way."""
    if wind is None:
        samples = plan.sample_states(scenario.dt, False)
        return np.asarray(samples.t, dtype=float), np.asarray(samples.poses, dtype=float), planned
    rows, _ = loiter.flown_samples(loiter.fly(plan, wind, uav=scenario.uav()), scenario.dt)
    return scenario.dt * np.arange(len(rows)), rows[:, :3], scenario.coverage(rows)


def footprint_ring(camera: loiter.Camera, pose: np.ndarray, tilt: float) -> np.ndarray:
    """The footprint the coverage metric scored at one step: the camera axis at the tilt of the
    bank and the gimbal angle it chose (``cov.tilt``), as one elliptic ring."""
    f = camera.footprint((float(pose[0]), float(pose[1]), float(pose[2])), float(tilt))
    return ellipse_ring(f.center, f.semi_along, f.semi_across, math.atan2(f.along[1], f.along[0]))


def footprint_shapes(camera: loiter.Camera, t: np.ndarray, poses: np.ndarray, cov: loiter.Coverage) -> Shapes:
    """At time s, the footprint (:func:`footprint_ring`) of the last step at or before s, computed
    when a frame asks for it: a long plan costs the frames drawn, not one ring per step."""
    tilt = np.asarray(cov.tilt)

    def at(time: float) -> list[np.ndarray]:
        k = min(max(int(np.searchsorted(t, time, side="right")) - 1, 0), len(t) - 1)
        return [footprint_ring(camera, poses[k], tilt[k])]

    return at


def motion_scene(scenario: loiter.Scenario, runs: Sequence[MethodRun],
                 wind: Optional[tuple[float, float]] = None) -> MotionScene:
    """The scenario's methods as one scene: the AOIs, each planned path, each aircraft at the
    camera's altitude and its camera footprint of the moment on the ground, the wind."""
    altitude = scenario.camera.altitude
    lines = [Line("AOI" if k == 0 else None, _closed(circle_ring(c, scenario.aoi_radius)), color="0.55", style="-",
                  width=0.8, fill=True) for k, c in enumerate(np.asarray(scenario.aois, dtype=float))]
    tracks, overlays = [], []
    for run in runs:
        name, color = METHOD_NAMES[run.method], figures.METHOD_COLORS[run.method]
        lines.append(Line(f"{name} plan", figures.plan_outline(run.plan), color=color, style=":", width=0.9,
                          z=altitude))
        t, poses, cov = flown_states(scenario, run.plan, run.coverage, wind)
        tracks.append(Track(name, t, poses[:, :2], color=color, z=altitude, width=1.4))
        overlays.append(Overlay(f"{name} camera footprint", footprint_shapes(scenario.camera, t, poses, cov),
                                color=color))
    names = " / ".join(METHOD_NAMES[run.method] for run in runs)
    title = f"{scenario.name}: {names}" + ("" if wind is None else f", wind ({wind[0]:g}, {wind[1]:g}) m/s")
    return MotionScene(tracks, lines, overlays, wind=wind, title=title)


def _closed(ring: np.ndarray) -> np.ndarray:
    return np.vstack([ring, ring[:1]])


def scenario_document(scenario: loiter.Scenario, runs: Sequence[MethodRun], files: Sequence[str]) -> Document:
    """report.md of one scenario: the methods' numbers, the figures and the wind table."""
    rows = []
    for run in runs:
        row = [METHOD_NAMES[run.method], f"{run.plan.flight_time / 60:.2f}", f"{run.plan.transit_time:.0f}",
               f"{run.coverage.time:.0f}", f"{run.coverage.area / 1e3:.0f}",
               " ".join(str(int(i)) for i in run.plan.order)]
        if run.best_plan is not None:
            row.append(f"{run.best_plan.flight_time / 60:.2f}")
        if scenario.paper:
            paper = paper_numbers(scenario, run.method)
            minutes, seconds = paper["paper_flight_time_min"], paper["paper_covered_time_s"]
            row += ["-" if minutes is None else f"{minutes:.2f}", "-" if seconds is None else f"{seconds:.1f}"]
        rows.append(row)
    header = ["method", "flight time (min)", "transit (s)", "covered time (s)", "coverage (10^3 m^2 s)", "order"]
    if any(run.best_plan is not None for run in runs):
        header.append("best order (min)")
    if scenario.paper:
        header += ["paper: flight time (min)", "paper: covered time (s)"]
    cam = scenario.camera
    summary_lines = [f"{len(scenario.aois)} AOIs of radius {scenario.aoi_radius:g} m, turn radius "
                     f"{scenario.turn_radius:g} m, {scenario.speed:g} m/s, start {tuple(scenario.start)}, end "
                     f"{tuple(scenario.end)}",
                     f"Camera {cam.fov_deg:g} deg on a +-{cam.max_gimbal_deg:g} deg roll gimbal at {cam.altitude:g} m; "
                     f"an AOI is covered when {100 * scenario.threshold:.0f} % of it is in view, steps of "
                     f"{scenario.dt:g} s; the camera " + ("levelled (the gimbal angle from the vertical, as the paper)"
                                                         if cam.levelled else
                                                         "on the banked body (the gimbal angle from the wings)"),
                     "Coverage: covered time is the seconds an AOI is covered, summed over AOIs; coverage in m^2 s "
                     "adds, every step, the area of each covered AOI in view, times the step. The paper labels its "
                     "coverage m^2; its TLPP and LDLPP values are whole multiples of 6,669.56 m^2, the area it counts "
                     "per covered second, so its covered time is that value / 6,669.56",
                     "AOIs are numbered from 0 in the order of the scenario file, everywhere; * beyond the paper"]
    blocks: list[Any] = [Heading("Methods"), Table(header, rows)]
    titles = {"plans.png": "Plans (the paper's Figures 6, 9, 12)", "timeline.png": "Coverage and gimbal over time",
              "plans_best_order.png": "Plans in the best order"}
    blocks += [Picture(name, titles[name]) for name in titles if name in files]
    blocks += [Picture(f"wind_{run.method}.png", f"{METHOD_NAMES[run.method]} flown in unknown wind")
               for run in runs if f"wind_{run.method}.png" in files]
    winds = wind_summary([run.record(scenario) for run in runs])
    if winds:
        blocks += [Heading("Flown in unknown wind"), wind_table(winds), WIND_NOTE]
    six = fdm_wind_summary([run.record(scenario) for run in runs])
    if six:
        blocks += [Heading(f"The same flights on the 6-DOF {scenario.aircraft} (JSBSim, vistrack's autopilot)"),
                   wind_table(six), WIND_NOTE]
    return Document(f"vistrack report: loiter, {scenario.name}", summary_lines, blocks)


def table_markdown(rows: Sequence[dict[str, Any]]) -> str:
    """Table 1 beside ours: flight time (min) and AOI coverage per method and size, in covered
    seconds (the paper's m^2 over the area it counts per covered second, PAPER_AREA_PER_SECOND) and
    in 10^3 m^2 s (the paper's unit label says m^2)."""
    sizes = sorted({int(r["aois"]) for r in rows})
    lines = ["| method | | " + " | ".join(f"{n} AOIs" for n in sizes) + " |",
             "|---|---|" + "---|" * len(sizes)]
    for method in [m for m in METHOD_NAMES if any(r["method"] == m for r in rows)]:
        by_size = {int(r["aois"]): r for r in rows if r["method"] == method}

        def cells(key: str, scale: float, digits: int, by_size: dict[int, dict[str, Any]] = by_size) -> str:
            return " | ".join(
                "-" if by_size[n].get(key) is None else f"{by_size[n][key] * scale:.{digits}f}" for n in sizes)

        name = METHOD_NAMES[method]
        lines.append(f"| {name} | flight time, paper (min) | {cells('paper_flight_time_min', 1.0, 2)} |")
        lines.append(f"| | flight time, ours (min) | {cells('flight_time_min', 1.0, 2)} |")
        lines.append(f"| | covered time, paper (s) | {cells('paper_covered_time_s', 1.0, 1)} |")
        lines.append(f"| | covered time, ours (s) | {cells('coverage_time_s', 1.0, 0)} |")
        lines.append(f"| | coverage, paper (10^3 m^2 s) | {cells('paper_coverage_m2', 1e-3, 0)} |")
        lines.append(f"| | coverage, ours (10^3 m^2 s) | {cells('coverage_area_m2s', 1e-3, 0)} |")
        lines.append(f"| | transit time, ours (s) | {cells('transit_time_s', 1.0, 0)} |")
        if all("best_flight_time_s" in by_size[n] for n in sizes):
            lines.append(f"| | best order, ours (min) | {cells('best_flight_time_s', 1 / 60.0, 2)} |")
    return "\n".join(lines) + "\n"


def roles_markdown(rows: Sequence[dict[str, Any]]) -> str:
    """Over all rows, per method: the time on each kind of segment and the share of it with some AOI
    covered (where each method gains or loses coverage)."""
    lines = ["| method | " + " | ".join(f"{role}: time (s), covered" for role in ("transit", "entry", "loiter", "exit"))
             + " |", "|---|---|---|---|---|"]
    for method in [m for m in METHOD_NAMES if any(r["method"] == m for r in rows)]:
        cells = []
        for role in ("transit", "entry", "loiter", "exit"):
            steps = sum(r["steps_by_role"][role]["steps"] for r in rows if r["method"] == method)
            covered = sum(r["steps_by_role"][role]["covered_steps"] for r in rows if r["method"] == method)
            cells.append(f"{steps} s, {100 * covered / steps:.0f} %" if steps else "-")
        lines.append(f"| {METHOD_NAMES[method]} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n\nTime steps of 1 s summed over the scenarios; covered: some AOI counts as covered.\n"


WIND_NOTE = "Median (min-max) over scenarios and wind directions; the guidance does not know the wind."


def wind_table(rows: Sequence[dict[str, Any]]) -> Table:
    """Per method and wind speed (vistrack.loiter.study.wind_summary rows): the share of the loiter time with
    the AOI covered, flight and covered time against the plan, the largest distance off it."""
    def q(values: Sequence[float], scale: float = 1.0, digits: int = 0) -> str:
        return f"{values[1] * scale:.{digits}f} ({values[0] * scale:.{digits}f}-{values[2] * scale:.{digits}f})"

    header = ["method", "wind (m/s)", "flights", "loiter time with the AOI covered (plan: 100 %)", "flight time / plan",
              "covered time / plan", "largest distance off the plan (m)"]
    return Table(header, [[METHOD_NAMES[r["method"]], f"{r['wind_speed']:g}", str(r["flights"]),
                           f"{q(r['loiter_covered'], 100.0)} %", q(r["flight_time_ratio"], 1.0, 2),
                           q(r["coverage_time_ratio"], 1.0, 2), q(r["max_cross_track_m"])] for r in rows])


def fdm_wind_summary(rows: Sequence[dict[str, Any]]) -> list[dict[str, Any]]:
    """wind_summary of the 6-DOF flights flown beside the kinematic ones (each wind record's ``fdm``)."""
    return wind_summary([{**r, "wind": [w["fdm"] for w in r.get("wind", []) if "fdm" in w]} for r in rows])


def fdm_markdown(rows: Sequence[dict[str, Any]]) -> str:
    """The 6-DOF flights' wind table under its own heading ("" when none flew)."""
    six = fdm_wind_summary(rows)
    return "" if not six else "\n6-DOF (JSBSim) flights of the same plans:\n\n" + wind_markdown(six)


def wind_markdown(rows: Sequence[dict[str, Any]]) -> str:
    return "\n".join(wind_table(rows).markdown()) + "\n\n" + WIND_NOTE + "\n"


def write_table(out: Path, scenarios: Sequence[loiter.Scenario], rows: Sequence[dict[str, Any]]) -> list[Path]:
    """The study over several scenarios: table.json, table.md, Figure 13 and Figure 14."""
    out.mkdir(parents=True, exist_ok=True)
    plans = [s.plan("ldlpp") for s in scenarios]
    text = table_markdown(rows) + "\n" + roles_markdown(rows)
    winds = wind_summary(rows)
    if winds:
        text += "\n" + wind_markdown(winds)
    return [
        write_json({"rows": list(rows), "wind": winds}, out / "table.json"),
        _write_text(out / "table.md", text),
        figures.scenarios_figure(plans, [f"{s.name} (LDLPP)" for s in scenarios], out / "fig13_scenarios.png"),
        figures.comparison_figure(rows, out / "fig14_comparison.png"),
    ]


def _write_text(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def summary_markdown(rows: Sequence[dict[str, Any]]) -> str:
    def q(values: Sequence[float], scale: float = 1.0, digits: int = 0) -> str:
        return f"{values[1] * scale:.{digits}f} ({values[0] * scale:.{digits}f}-{values[2] * scale:.{digits}f})"

    saved = any("time_saved_s" in r for r in rows)
    head = ("| method | flight time (min) | transit (s) | covered per AOI (s) | fastest | shortest transit | "
            "most coverage |" + (" best order saves |" if saved else ""))
    lines = [head, "|---" * (7 + saved) + "|"]
    for r in rows:
        line = (f"| {METHOD_NAMES[r['method']]} | {q(r['flight_time_s'], 1 / 60.0, 2)} | {q(r['transit_time_s'])} | "
                f"{q(r['coverage_per_aoi_s'], 1.0, 1)} | {100 * r['fastest']:.0f} % | "
                f"{100 * r['shortest_transit']:.0f} % | {100 * r['most_coverage']:.0f} % |")
        if saved:
            line += f" {q(r['time_saved_fraction'], 100.0, 1)} % |"
        lines.append(line)
    return "\n".join(lines) + "\n\nMedians (quartiles in brackets); shares of the scenarios where the method is best.\n"


def write_random(out: Path, records: Sequence[dict[str, Any]]) -> list[Path]:
    out.mkdir(parents=True, exist_ok=True)
    rows = summary(records)
    return [
        write_json({"summary": rows, "records": list(records)}, out / "random.json"),
        _write_text(out / "random.md", summary_markdown(rows)),
        figures.distribution_figure(records, out / "random_distribution.png"),
    ]
