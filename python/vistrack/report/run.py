"""The report folder of a tracking run (``vistrack run`` / ``demo``): figures, report.md,
report.html (interactive 3D), trajectory.gif, metrics.json, plan.json, trajectory.csv and the VV
meshes."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional, Sequence, Union

import numpy as np

from .._core import (
    Environment,
    OrbitPlan,
    OrbitPlanner,
    SimulationResult,
    VisibilityOrbitPlan,
)
from ..io import write_json, write_plan, write_trajectory
from ..plotting import OSM_CREDIT, evenly_spaced_indices, figure_volume_3d, new_figure, plot_city, save_figure
from ..plotting.fdm import figure_fdm
from ..plotting.interactive import volume_layers
from ..plotting.motion import tracking_scene
from ..plotting.orbits import figure_metric, figure_orbits, figure_radius
from ..plotting.simulation import figure_errors, figure_trajectory
from ..progress import Stages
from ..tracking.pipeline import METRIC_SPACINGS, compute
from ..tracking.result import RunResult
from ..tracking.scenario import Scenario
from .document import Block, Document, Heading, Picture, Table, vehicle_line
from .media import write_media

# Most VV meshes written into a report (evenly picked along the path).
MAX_SAVED_VOLUMES = 12

HTML_HINT = ("Drag to turn, scroll to zoom. The upper slider picks a visibility volume along the path (with its "
             "VP and orbit at the flight altitude); the lower slider or ▶ play moves the UAV and the POI, with the "
             "line of sight green while the POI is visible and red while it is occluded.")

GIF_CAPTION = ("Plan view: the VP of the current sample (green), the orbit of the moment (dashed), the paths "
               "coloured by line of sight and the line of sight itself (green: visible, red: occluded).")

OSM_NOTE = ("Building geometry from OpenStreetMap (© OpenStreetMap contributors, ODbL 1.0) via the "
            "public DubinsVisibilityTracking repository, where the map comes from ../shared/data.")


def run(scenario: Scenario, out: str | Path | None = None, *, quiet: bool = True,
        cache_dir: str | Path | None = None, environment: Optional[Environment] = None,
        planner: Optional[OrbitPlanner] = None, metric_spacings: Sequence[float] = METRIC_SPACINGS) -> RunResult:
    """Run a scenario end to end (:func:`vistrack.tracking.pipeline.compute`: a caller running many
    scenarios on one map passes its ``environment`` and ``planner``; ``metric_spacings`` are Figure
    4's fixed spacings); with ``out``, also write the report folder there."""
    result = compute(scenario, quiet=quiet, cache_dir=cache_dir, environment=environment, planner=planner,
                     metric_spacings=metric_spacings)
    if out is not None:
        stages = Stages(quiet)
        stages.timings = result.timings  # the report's time joins the run's
        stages.run("report", write_report, result, Path(out))
    return result


def write_report(result: RunResult, out: Path) -> list[Path]:
    """Write every file of the report into ``out`` (created) and return their paths: figures,
    trajectory.gif and report.html (unless the scenario's report options turn them off),
    plan.json, trajectory.csv, VV meshes, metrics.json and report.md."""

    out.mkdir(parents=True, exist_ok=True)
    files: list[Path] = []
    s = result.scenario
    options = s.report
    pictures: list[Picture] = []

    fig, ax = new_figure((8.5, 8.0))
    plot_city(ax, result.env, result.poi, title=f"{s.name}: city and POI path")
    files.append(save_figure(fig, out / "city.png"))
    pictures.append(Picture("city.png", "City and POI path", f"{s.environment.describe()}; POI at "
                            f"{result.poi.speed:g} m/s over {result.poi.length:.0f} m."))

    credit = None if s.environment.kind == "demo" else OSM_CREDIT
    figure_metric(result.metric_runs, s.planning.cutoff, out / "metric.png",
                  title=f"{s.name}: XOR metric between neighbouring VVs (Fig. 4)", credit=credit)
    files.append(out / "metric.png")
    pictures.append(Picture("metric.png", "Figure 4: VV difference metric along the path",
                            "Eq. (56) between neighbouring VVs for fixed spacings and the adaptive method, "
                            f"cutoff {s.planning.cutoff:.3g} m³."))

    figure_orbits(result.plan, result.env, out / "orbits.png", credit=credit)
    files.append(out / "orbits.png")
    pictures.append(Picture("orbits.png", "Figure 5: orbits inside their visibility polygons",
                            "Circles of radius R(t_k) centred on the POI inside the VP at "
                            f"h_UAV = {s.uav.altitude:g} m."))

    figure_radius(result.plan, out / "radius.png")
    files.append(out / "radius.png")
    pictures.append(Picture("radius.png", "Orbit radius and its rate limits",
                            "MaxRadius per sample (and along the path, for the smooth locus), the R(t) the guidance "
                            "follows beside Algorithm 1's piecewise-linear one, Lemma 6's threshold, dR/dt against "
                            "Lemma 5's bound and d2R/dt2."))

    # Baselines are drawn with the visibility plan's orbits.
    runs: list[tuple[str, Union[OrbitPlan, VisibilityOrbitPlan], SimulationResult]] = [
        ("visibility orbit", result.plan, result.simulation)]
    runs += [(f"R = {r:g} m", result.plan, b) for r, b in result.baselines.items()]
    figure_trajectory(runs, result.env, out / "trajectory.png", title=f"{s.name}: UAV tracking the POI (Fig. 10)",
                      credit=credit)
    files.append(out / "trajectory.png")
    pictures.append(Picture("trajectory.png", "Figure 10: trajectory",
                            "UAV path (red) with the reference orbits and the POI path" +
                            (", and the constant-radius baselines." if result.baselines else ".")))

    figure_errors(result.simulation, out / "errors.png", window=None,
                  title=f"{s.name}: errors and control (Fig. 11)",
                  max_turn_rate=s.uav.speed / s.uav.min_turn_radius)
    files.append(out / "errors.png")
    pictures.append(Picture("errors.png", "Figure 11: errors and control",
                            "Radial error r - R, heading and heading error, and the steering command against time."))

    if result.fdm is not None:
        sim = result.simulation
        state = np.asarray(sim.state)
        six = result.fdm.trajectory
        kinematic = (np.asarray(sim.t), state[:, 0], state[:, 1], np.asarray(sim.bank))
        figure_fdm(kinematic, f"{s.uav.dynamics} model", six, out / "fdm.png",
                   title=f"{s.name}: the plan on the 6-DOF {six.aircraft} and the kinematic vehicle",
                   reference=np.asarray(sim.poi)[:, :2], reference_label="POI path")
        files.append(out / "fdm.png")
        pictures.append(Picture("fdm.png", "6-DOF flight (JSBSim) beside the kinematic one",
                                "The same guidance (vector field (74), steering law (86)) flown by vistrack's "
                                f"autopilot on {six.aircraft} in JSBSim, trimmed level at {six.speed:g} m/s and "
                                f"{six.altitude_command:g} m: ground tracks, altitude, airspeed and bank."))

    # The most constrained sample (smallest MaxRadius): where the buildings shape the VV most.
    k = int(np.argmin(result.plan.max_radii))
    plan = result.plan
    figure_volume_3d(result.planner.scene, plan.volume(k), out / "volume3d.png", caption=credit or "",
                     env=result.env, view=options.view, orbit=(plan.centers[k], plan.radii[k], s.uav.altitude),
                     polygons=plan.polygons[k])
    files.append(out / "volume3d.png")
    pictures.append(Picture("volume3d.png", "Visibility volume in 3D",
                            f"The VV (eq. 4, d_max = {s.sensor.d_max:g} m) of sample {k} (t = {plan.times[k]:.1f} s, "
                            "the smallest MaxRadius of the plan) with the buildings that carve it; its slice at "
                            "h_UAV is the VP holding the orbit."))

    files.append(write_plan(result.plan, out / "plan.json"))
    files.append(write_trajectory(result.simulation, out / "trajectory.csv"))
    files += _save_volumes(result, out / "volumes")

    scene = tracking_scene(result.plan, result.simulation, result.env, title=f"{s.name}: UAV tracking the POI",
                           credit=credit)
    document = _document(result, pictures)
    layers = volume_layers(result.planner.scene, result.plan, options.volumes) if options.html else []
    made = write_media(out, scene, document, options, layers, HTML_HINT, GIF_CAPTION)
    files += [out / name for name in made]
    result.metrics["report_files"] = {name: {key: round(v, 4) for key, v in m.items()} for name, m in made.items()}
    files.append(write_json(result.metrics, out / "metrics.json"))
    report = out / "report.md"
    report.write_text(document.markdown())
    files.append(report)
    result.out = out
    result.files = files
    return files


def _save_volumes(result: RunResult, folder: Path) -> list[Path]:
    folder.mkdir(parents=True, exist_ok=True)
    n = result.plan.num_volumes
    picked = evenly_spaced_indices(n, MAX_SAVED_VOLUMES)
    files = []
    for k in picked:
        path = folder / f"vv_{k:03d}_t{result.plan.times[k]:07.2f}.ply"
        result.plan.volume(k).save(str(path))
        files.append(path)
    return files


def _document(result: RunResult, pictures: list[Picture]) -> Document:
    m = result.metrics
    plan, sim = m["plan"], m["simulation"]
    summary = [f"Environment: {m['environment']} ({m['environment_triangles']} triangles, "
               f"tallest {m['environment_max_height_m']:.1f} m)",
               f"POI: {m['poi']['length_m']:.1f} m at {m['poi']['speed_mps']:g} m/s ({m['poi']['duration_s']:.2f} s)",
               f"Plan: {plan['samples']} samples ({plan['volumes_computed']} VVs computed), "
               f"{'feasible' if plan['feasible'] else 'INFEASIBLE: ' + plan['infeasibility']}; "
               f"R from {plan['initial_radius_m']:.1f} m to {plan['final_radius_m']:.1f} m "
               f"(min {plan['min_radius_m']:.1f} m, Lemma 6 needs >= {plan['min_feasible_radius_m']:.1f} m)",
               f"Locus: {locus_line(plan)}",
               f"Simulation: {sim['duration_s']:.2f} s; POI in line of sight "
               f"{percent(sim['visibility_fraction'])} of the samples; largest |radial error| after "
               f"settling (after {sim['converge_after_s']:g} s) {sim['radial_error_after_max_abs_m']:.2f} m",
               vehicle_line(m["uav"], sim.get("smoothness"))]
    blocks: list[Block] = []
    rows = [[f"visibility-informed R(t), {m['uav']['dynamics']} model", percent(sim["visibility_fraction"])]]
    other = m.get("other_model")
    if other:
        rows.append([f"visibility-informed R(t), {other['dynamics']} model", percent(other["visibility_fraction"])])
    six = m.get("fdm")
    if six:
        rows.append([f"visibility-informed R(t), 6-DOF {six['aircraft']} (JSBSim)",
                     percent(six["simulation"]["visibility_fraction"])])
        summary.append(f"6-DOF flight on {six['aircraft']} (JSBSim, vistrack's autopilot): POI in view "
                       f"{percent(six['simulation']['visibility_fraction'])}; altitude within "
                       f"{six['altitude_error_max_m']:.2f} m and airspeed within "
                       f"{six['airspeed_error_max_m_s']:.2f} m/s "
                       f"of the commands; {six['real_time_factor']:.0f} x real time")
    rows += [[f"constant R = {b['radius_m']:g} m", percent(b["visibility_fraction"])] for b in m["baselines"].values()]
    blocks.append(Table(["orbit", "visibility"], rows))
    blocks.append("Files: `metrics.json`, `plan.json`, `trajectory.csv`, `volumes/*.ply`.")
    blocks += pictures
    blocks += [Heading("Timings"), Table(["stage", "seconds"], [[k, f"{v:.3f}"] for k, v in m["timings_s"].items()])]
    if result.scenario.environment.kind != "demo":
        blocks.append(OSM_NOTE)
    return Document(f"vistrack report: {m['scenario']}", summary, blocks)


def locus_line(plan: dict[str, Any]) -> str:
    """How the locus was built, and for the smooth one what its check found (from metrics.json)."""
    if plan.get("locus") != "smooth":
        return "the paper's (Algorithm 1's radii, piecewise linear between the samples; not checked between them)"
    acceleration = plan.get("max_abs_acceleration_mps2")  # None when the reference is not smooth (infeasible)
    smoothness = ("not C1 (no smooth reference: the plan is infeasible)" if acceleration is None
                  else f"C1 with |d2R/dt2| <= {acceleration:.2f} m/s²")
    return (f"smooth (beyond the paper): MaxRadius checked at {plan['check_points']} points along the path "
            f"({plan['check_volumes_computed']} more VVs, {plan['check_rounds']} refinement rounds); the paper's "
            f"piecewise-linear R(t) leaves the VP at {plan['paper_violations']} of them, by up to "
            f"{plan['paper_max_violation_m']:.2f} m. R(t) stays {plan['tracking_margin_m']:g} m inside MaxRadius "
            f"(smallest clearance {plan['min_clearance_m']:.2f} m), {smoothness}; it lies "
            f"{plan['mean_lowering_m']:.2f} m below the paper's "
            f"on average, at most {plan['max_lowering_m']:.2f} m at t = {plan['max_lowering_at_s']:.1f} s "
            f"({plan['max_lowering_at_m']:.0f} m along the path)")


def percent(value: Any) -> str:
    """A fraction as a percentage with one decimal, or n/a."""
    return "n/a" if value is None else f"{100.0 * value:.1f}%"
