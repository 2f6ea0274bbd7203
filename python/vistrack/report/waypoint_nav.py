"""The output folder of ``vistrack waypoints``: metrics.json, one trajectory CSV per flight, the
DWN turning points, the path figure (Figures 11/12), optionally Figure 10 and the Monte Carlo, and
report.md with the animation (trajectory.gif) and the interactive page (report.html)."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional, Sequence

from .._core.flight import Wind
from ..io import write_flight, write_json, write_route, write_rows
from ..plotting.motion import Line, MotionScene, Track
from ..plotting.waypoint_nav import (
    figure_bank,
    figure_monte_carlo,
    figure_paths,
    figure_theta_weight,
    figure_waypoint_zoom,
)
from ..report_options import ReportOptions
from ..waypoint_nav import MonteCarlo, NavigationFlight
from ..waypoint_nav.fdm import FdmNavigation
from .document import Document, Heading, Picture, Table, vehicle_line
from .fdm import fdm_block, fdm_blocks, fdm_figure
from .media import write_media

TRACK_COLORS = ("tab:red", "tab:blue", "tab:orange", "tab:purple", "tab:brown", "tab:olive")


def file_label(flight: NavigationFlight) -> str:
    """"dwn", or "wn_0.1R" for WN at R_WP = 0.1 R."""
    if flight.method == "dwn" or flight.waypoint_radius is None:
        return "dwn"
    return f"wn_{flight.waypoint_radius / flight.turn_radius:g}R"


def motion_scene(flights: Sequence[NavigationFlight], wind: Optional[Wind], title: str) -> MotionScene:
    """The flights as one animation: a track per flight, the route, DWN's turning points, the wind."""
    tracks = [Track(f.label, f.trajectory[:, 0], f.trajectory[:, 1:3], color=color, trail=None, width=1.2)
              for f, color in zip(flights, TRACK_COLORS)]
    lines = [Line("route", flights[0].route_points, color="0.3", style=":", width=1.0)]
    for flight in flights:
        if flight.method == "dwn" and len(flight.turning_points):
            lines.append(Line("DWN turning points", flight.turning_points, color="tab:green", style="--", width=0.8))
    return MotionScene(tracks, lines, wind=None if wind is None else (wind.east, wind.north), title=title)


def write_waypoints(out: Path, flights: Sequence[NavigationFlight], wind: Optional[Wind], route_name: str,
                    settings: dict[str, Any], weights: Optional[dict[str, Any]] = None,
                    mc: Optional[MonteCarlo] = None, report: Optional[ReportOptions] = None,
                    six_dof: Sequence[FdmNavigation] = ()) -> dict[str, Any]:
    """Writes the folder and returns the record stored in metrics.json (with ``six_dof``, the same flights
    on a JSBSim aircraft: its ``fdm`` block and fdm.png)."""
    out.mkdir(parents=True, exist_ok=True)
    record: dict[str, Any] = {"route": route_name, "settings": settings, "flights": [], "figures": []}
    for flight in flights:
        name = file_label(flight)
        entry = flight.metrics()
        entry["trajectory"] = write_flight(flight.flight, out / f"trajectory_{name}.csv").name
        entry["waypoints_file"] = write_rows(entry["waypoints"], out / f"waypoints_{name}.csv").name
        entry["legs_file"] = write_rows(entry["legs"], out / f"legs_{name}.csv").name
        if flight.method == "dwn":
            entry["turning_points_file"] = write_route(flight.turning_points, out / "turning_points_dwn.csv").name
        record["flights"].append(entry)
    record["figures"].append(figure_paths(flights, out / "paths.png", "DWN against WN", wind).name)
    record["figures"].append(figure_waypoint_zoom(flights, out / "waypoints_zoom.png").name)
    record["figures"].append(figure_bank(flights, out / "bank.png").name)
    if weights is not None:
        record["figure10"] = {"arc_weights": weights["arc_weights"].tolist(), "thetas": weights["thetas"].tolist(),
                              "cases": weights["cases"], "theta_range_deg": weights["theta_range_deg"]}
        record["figures"].append(figure_theta_weight(weights, out / "fig10_theta_weight.png").name)
    if mc is not None:
        summary = mc.summary()
        write_json({"settings": mc.settings, "summary": summary}, out / "monte_carlo.json")
        record["monte_carlo"] = summary
        record["figures"].append(figure_monte_carlo(mc, out / "monte_carlo.png").name)
    document = _document(flights, record, route_name)
    if six_dof:
        _add_fdm(out, flights, six_dof, record, document)
    made = write_media(out, motion_scene(flights, wind, f"{route_name}: DWN against WN"), document, report)
    record["report_files"] = made
    (out / "report.md").write_text(document.markdown(), encoding="utf-8")
    write_json(record, out / "metrics.json")
    return record


def _document(flights: Sequence[NavigationFlight], record: dict[str, Any], route_name: str) -> Document:
    R = flights[0].turn_radius
    entries = record["flights"]  # each flight's metrics(), computed once in write_waypoints
    rows = [[e["label"], f"{e['max_miss_over_R']:.3f}", f"{e['miss_at_last_over_R']:.3f}",
             f"{e['overshoot_over_R']:.3f}", str(e["swirls"]), f"{e['path_length']:.4g}", f"{e['duration']:.4g}",
             "yes" if e["all_reached"] else "no",
             "-" if e["smoothness"] is None else f"{e['smoothness']['roll_reversals_per_s']:.2f}"] for e in entries]
    blocks: list[Any] = [Heading("Flights"),
                         Table(["flight", "max miss (R)", "miss at the last (R)", "overshoot (R)",
                                "swirls", "path length", "time", "all reached", "roll reversals/s"], rows),
                         "Every waypoint counts in the max miss. The flight ends on the line through the last "
                         "waypoint perpendicular to the last leg; the last miss is the distance where the path "
                         "crosses it."]
    for e in entries:
        blocks += [Heading(f"{e['label']}: waypoints and legs"),
                   Table(["waypoint", "miss (R)", "at t (s)", "overshoot (R)", "reached"],
                         [[str(r["waypoint"]), f"{r['miss_over_R']:.3f}", f"{r['time']:.4g}",
                           f"{r['overshoot_over_R']:.3f}", "yes" if r["reached"] else "no"]
                          for r in e["waypoints"]]),
                   Table(["leg", "length", "flown", "time (s)"],
                         [[str(r["leg"]), f"{r['length']:.4g}", f"{r['flown']:.4g}", f"{r['time']:.4g}"]
                          for r in e["legs"]])]
    if record.get("monte_carlo"):
        blocks += [Heading("Monte Carlo over random routes and winds"),
                   Table(["gusts", "flight", "flights", "miss median (R)", "miss p90 (R)", "miss max (R)",
                          "swirl rate", "all reached", "path / route", "overshoot median (R)"],
                         [["yes" if r["gusts"] else "no", r["label"], str(r["flights"]), f"{r['miss_median']:.3f}",
                           f"{r['miss_p90']:.3f}", f"{r['miss_max']:.3f}", f"{100 * r['swirl_rate']:.0f} %",
                           f"{100 * r['all_reached_rate']:.0f} %", f"{r['path_ratio_mean']:.3f}",
                           f"{r['overshoot_median']:.3f}"] for r in record["monte_carlo"]])]
    titles = {"paths.png": "Paths (Figures 11/12)", "bank.png": "Bank flown",
              "waypoints_zoom.png": "At each waypoint (within 0.6 R)",
              "fig10_theta_weight.png": "Figure 10: theta against w_a",
              "monte_carlo.png": "Monte Carlo over random routes and winds"}
    blocks += [Picture(name, titles.get(name, name)) for name in record["figures"]]
    settings = record["settings"]
    units = "metres and m/s" if settings.get("units") == "metres" else "the paper's dimensionless units"
    summary = [f"Route {route_name}: {len(flights[0].waypoints)} waypoints, turn radius R = {R:g}, speed "
               f"{settings['speed']:g}, in {units}; each leg flown by {settings.get('guidance', 'law5')}",
               vehicle_line({"dynamics": settings.get("dynamics", "dubins"),
                             "roll_time_constant": settings.get("roll_time_constant"),
                             "max_roll_rate_deg_s": settings.get("max_roll_rate_deg_s")}, None),
               f"Wind {settings['wind']} (unknown to the guidance)"]
    return Document("vistrack report: waypoint navigation", summary, blocks)


def _add_fdm(out: Path, flights: Sequence[NavigationFlight], six_dof: Sequence[FdmNavigation],
             record: dict[str, Any], document: Document) -> None:
    """metrics.json's fdm block, fdm.png (DWN, or the first flight) and the report's 6-DOF table."""
    summaries = [f.summary() for f in six_dof]
    block = fdm_block(six_dof[0].trajectory.aircraft, [f.trajectory for f in six_dof], summaries)
    record["fdm"] = block
    kinematic = {(f.method, f.waypoint_radius): f for f in flights}
    entries = {(f.method, f.waypoint_radius): e for f, e in zip(flights, record["flights"])}  # metrics(), once
    rows = []
    for six, summary in zip(six_dof, summaries):
        key = (six.method, six.waypoint_radius if six.method != "dwn" else None)
        twin = kinematic[key]
        rows.append([twin.label, f"{entries[key]['max_miss_over_R']:.3f}",
                     f"{summary['max_miss_over_R']:.3f}", "yes" if summary["all_reached"] else "no",
                     f"{six.trajectory.altitude_error_max:.2f}", f"{six.trajectory.airspeed_error_max:.2f}"])
    first = six_dof[0]
    twin = kinematic[(first.method, first.waypoint_radius if first.method != "dwn" else None)]
    k = twin.flight
    picture = fdm_figure(out, (k.t, k.x, k.y, k.bank), f"{twin.label}, {record['settings'].get('dynamics')} model",
                         first.trajectory, f"{twin.label} on the 6-DOF {block['aircraft']} and the kinematic vehicle",
                         twin.route_points, "route")
    header = ["flight", "max miss, kinematic (R)", "6-DOF (R)", "6-DOF all reached",
              "altitude err max (m)", "airspeed err max (m/s)"]
    document.blocks += [*fdm_blocks(block, rows, header), picture]
