"""The output folder of ``vistrack waypoints``: metrics.json, one trajectory CSV per flight, the
DWN turning points, the path figure (Figures 11/12), and optionally Figure 10 and the Monte Carlo."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional, Sequence

from .._core.flight import Wind
from ..io import write_flight, write_json, write_route
from ..plotting.waypoints import figure_monte_carlo, figure_paths, figure_theta_weight
from ..waypoint_nav import MonteCarlo, NavigationFlight


def file_label(flight: NavigationFlight) -> str:
    """"dwn", or "wn_0.1R" for WN at R_WP = 0.1 R."""
    if flight.method == "dwn" or flight.waypoint_radius is None:
        return "dwn"
    return f"wn_{flight.waypoint_radius / flight.turn_radius:g}R"


def write_waypoints(out: Path, flights: Sequence[NavigationFlight], wind: Optional[Wind], route_name: str,
                    settings: dict[str, Any], weights: Optional[dict[str, Any]] = None,
                    mc: Optional[MonteCarlo] = None) -> dict[str, Any]:
    """Writes the folder and returns the record stored in metrics.json."""
    out.mkdir(parents=True, exist_ok=True)
    record: dict[str, Any] = {"route": route_name, "settings": settings, "flights": [], "figures": []}
    for flight in flights:
        name = file_label(flight)
        entry = flight.metrics()
        entry["trajectory"] = write_flight(flight.flight, out / f"trajectory_{name}.csv").name
        if flight.method == "dwn":
            entry["turning_points_file"] = write_route(flight.turning_points, out / "turning_points_dwn.csv").name
        record["flights"].append(entry)
    record["figures"].append(figure_paths(flights, out / "paths.png", "DWN against WN", wind).name)
    if weights is not None:
        record["figure10"] = {"arc_weights": weights["arc_weights"].tolist(), "thetas": weights["thetas"].tolist(),
                              "cases": weights["cases"], "theta_range_deg": weights["theta_range_deg"]}
        record["figures"].append(figure_theta_weight(weights, out / "fig10_theta_weight.png").name)
    if mc is not None:
        summary = mc.summary()
        write_json({"settings": mc.settings, "summary": summary}, out / "monte_carlo.json")
        record["monte_carlo"] = summary
        record["figures"].append(figure_monte_carlo(mc, out / "monte_carlo.png").name)
    write_json(record, out / "metrics.json")
    return record
