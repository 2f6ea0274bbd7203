"""The report folder of a run: figures, report.md, metrics.json, plan.json, trajectory.csv and
the VV meshes (see pipeline.run)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Any


if TYPE_CHECKING:
    from .pipeline import RunResult

OSM_NOTE = ("Building geometry from OpenStreetMap (© OpenStreetMap contributors, ODbL 1.0) via the "
            "public DubinsVisibilityTracking repository, where the map comes from ../shared/data.")


def write_report(result: "RunResult", out: Path) -> list[Path]:
    """Write every file of the report into ``out`` (created) and return their paths."""
    from . import planning
    from .commands import simulate as sim_cmd
    from .plotting import OSM_CREDIT, figure_volume_3d, new_figure, plot_city, save_figure

    out.mkdir(parents=True, exist_ok=True)
    files: list[Path] = []
    s = result.scenario
    figures: list[tuple[str, str, str]] = []  # (file, title, caption)

    fig, ax = new_figure((8.5, 8.0))
    plot_city(ax, result.env, result.poi, title=f"{s.name}: city and POI path")
    files.append(save_figure(fig, out / "city.png"))
    figures.append(("city.png", "City and POI path", f"{s.environment.describe()}; POI at "
                    f"{result.poi.speed:g} m/s over {result.poi.length:.0f} m."))

    credit = None if s.environment.kind == "demo" else OSM_CREDIT
    planning.figure_metric(result.metric_runs, s.planning.cutoff, out / "metric.png",
                           title=f"{s.name}: XOR metric between neighbouring VVs (Fig. 4)", credit=credit)
    files.append(out / "metric.png")
    figures.append(("metric.png", "Figure 4: VV difference metric along the path",
                    "Eq. (56) between neighbouring VVs for fixed spacings and the adaptive method, "
                    f"cutoff {s.planning.cutoff:.3g} m³."))

    planning.figure_orbits(result.plan, result.env, out / "orbits.png", credit=credit)
    files.append(out / "orbits.png")
    figures.append(("orbits.png", "Figure 5: orbits inside their visibility polygons",
                    f"Circles of radius R(t_k) centred on the POI inside the VP at h_UAV = {s.uav.altitude:g} m."))

    planning.figure_radius(result.plan, out / "radius.png")
    files.append(out / "radius.png")
    figures.append(("radius.png", "Orbit radius and its rate limits",
                    "MaxRadius per sample, R(t) after Algorithm 1, Lemma 6's threshold and Lemma 5's rate bound."))

    runs = [("visibility orbit", result.plan, result.simulation)]
    runs += [(f"R = {r:g} m", None, b) for r, b in result.baselines.items()]
    sim_cmd.figure_trajectory([(label, plan if plan is not None else result.plan, sim) for label, plan, sim in runs],
                              result.env, out / "trajectory.png", title=f"{s.name}: UAV tracking the POI (Fig. 10)",
                              credit=credit)
    files.append(out / "trajectory.png")
    figures.append(("trajectory.png", "Figure 10: trajectory",
                    "UAV path (red) with the reference orbits and the POI path" +
                    (", and the constant-radius baselines." if result.baselines else ".")))

    sim_cmd.figure_errors(result.simulation, out / "errors.png", window=None,
                          title=f"{s.name}: errors and control (Fig. 11)",
                          max_turn_rate=s.uav.speed / s.uav.min_turn_radius)
    files.append(out / "errors.png")
    figures.append(("errors.png", "Figure 11: errors and control",
                    "Radial error r - R, heading and heading error, and the steering command against time."))

    first = result.plan.volume(0)
    figure_volume_3d(result.planner.scene, first, out / "volume3d.png", caption=credit or "")
    files.append(out / "volume3d.png")
    figures.append(("volume3d.png", "Visibility volume in 3D",
                    f"The VV of the first sample (eq. 4), d_max = {s.sensor.d_max:g} m; the orbit lies "
                    "in its slice at h_UAV."))

    (out / "plan.json").write_text(result.plan.to_json())
    (out / "trajectory.csv").write_text(result.simulation.to_csv())
    files += [out / "plan.json", out / "trajectory.csv"]
    files += _save_volumes(result, out / "volumes")

    (out / "metrics.json").write_text(json.dumps(result.metrics, indent=1))
    files.append(out / "metrics.json")
    report = out / "report.md"
    report.write_text(_markdown(result, figures))
    files.append(report)
    result.out = out
    result.files = files
    return files


def _save_volumes(result: "RunResult", folder: Path) -> list[Path]:
    from .pipeline import MAX_SAVED_VOLUMES
    from .plotting import evenly_spaced_indices

    folder.mkdir(parents=True, exist_ok=True)
    n = result.plan.num_volumes
    picked = evenly_spaced_indices(n, MAX_SAVED_VOLUMES)
    files = []
    for k in picked:
        path = folder / f"vv_{k:03d}_t{result.plan.times[k]:07.2f}.ply"
        result.plan.volume(k).save(str(path))
        files.append(path)
    return files


def _markdown(result: "RunResult", figures: list[tuple[str, str, str]]) -> str:
    m = result.metrics
    plan, sim = m["plan"], m["simulation"]
    lines = [f"# vistrack report: {m['scenario']}", "",
             f"- Environment: {m['environment']} ({m['environment_triangles']} triangles, "
             f"tallest {m['environment_max_height_m']:.1f} m)",
             f"- POI: {m['poi']['length_m']:.1f} m at {m['poi']['speed_mps']:g} m/s "
             f"({m['poi']['duration_s']:.2f} s)",
             f"- Plan: {plan['samples']} samples ({plan['volumes_computed']} VVs computed), "
             f"{'feasible' if plan['feasible'] else 'INFEASIBLE: ' + plan['infeasibility']}; "
             f"R from {plan['initial_radius_m']:.1f} m to {plan['final_radius_m']:.1f} m "
             f"(min {plan['min_radius_m']:.1f} m, Lemma 6 needs >= {plan['min_feasible_radius_m']:.1f} m)",
             f"- Simulation: {sim['duration_s']:.2f} s; POI in line of sight "
             f"{percent(sim['visibility_fraction'])} of the samples; largest |radial error| after "
             f"settling (after {sim['converge_after_s']:g} s) {sim['radial_error_after_max_abs_m']:.2f} m",
             ]
    if m["baselines"]:
        lines += ["", "| orbit | visibility |", "|---|---|",
                  f"| visibility-informed R(t) | {percent(sim['visibility_fraction'])} |"]
        lines += [f"| constant R = {b['radius_m']:g} m | {percent(b['visibility_fraction'])} |"
                  for b in m["baselines"].values()]
    lines += ["", "Files: `metrics.json`, `plan.json`, `trajectory.csv`, `volumes/*.ply`.", ""]
    for file, title, caption in figures:
        lines += [f"## {title}", "", f"![{title}]({file})", "", caption, ""]
    lines += ["## Timings", "", "| stage | seconds |", "|---|---|"]
    lines += [f"| {k} | {v:.3f} |" for k, v in m["timings_s"].items()]
    if result.scenario.environment.kind != "demo":
        lines += ["", OSM_NOTE]
    return "\n".join(lines) + "\n"


def percent(value: Any) -> str:
    """A fraction as a percentage with one decimal, or n/a."""
    return "n/a" if value is None else f"{100.0 * value:.1f}%"
