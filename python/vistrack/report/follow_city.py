"""The city follower in a follow report (beyond every anchor: the horizon follower by default, or the
city orbit): camera, line of sight, both, and the share of the time a flyable circle existed inside
the visibility polygon, beside the planner's and the baseline's runs on the same city road."""

from __future__ import annotations

from typing import Any, Optional

from .document import Heading, Table


def _percent(value: Optional[float]) -> str:
    return "-" if value is None else f"{100 * value:.1f}"


def _name(orbit: dict[str, Any]) -> str:
    return "horizon follower" if orbit.get("strategy") == "city_horizon" else "city orbit"


def city_orbit_blocks(city: Optional[dict[str, Any]]) -> list[Any]:
    """A heading and a table of the city runs (metrics.json's ``city`` block), or nothing."""
    if not city or "orbit" not in city:
        return []
    rows = []
    orbit = city["orbit"]
    ours = ("horizon follower (bank commands planned ahead)" if _name(orbit) == "horizon follower"
            else "city orbit (inside the visibility polygon)")
    for name, key in (("planner (sinusoid and loiter)", "follow"), ("vector-field baseline", "baseline"),
                      (ours, "orbit")):
        m = city.get(key)
        if not m or m.get("feasible") is False:
            continue
        rows.append([name, _percent(m.get("camera_fraction")), _percent(m.get("line_of_sight_fraction")),
                     _percent(m.get("camera_and_line_of_sight_fraction")),
                     _percent(m.get("flyable_circle_about_vehicle_fraction")),
                     _percent(m.get("flyable_circle_in_polygon_fraction"))])
    shape = (f"mean radius {orbit['mean_radius_m']:.0f} m" if "mean_radius_m" in orbit else
             f"{orbit.get('updates_heading_for_vehicle', 0)} updates with nothing in sight over the horizon")
    note = (f"{_name(orbit).capitalize()} (beyond every anchor): {orbit['volumes']} visibility volumes over "
            f"{orbit['updates']} updates (at most {orbit['max_new_volumes_per_update']} new per update), {shape}. "
            "A flyable circle: radius at least the turn-limited 1.25 r_min, less a margin, inside the visibility "
            "polygon of the vehicle's predicted position.")
    return [Heading("On the city road: line of sight and flyable circles"),
            Table(["run", "camera (%)", "line of sight (%)", "both (%)", "flyable circle about the vehicle (%)",
                   "flyable circle in the polygon (%)"], rows), note]


def city_orbit_line(city: Optional[dict[str, Any]]) -> Optional[str]:
    """The command's line for the city follower, or None."""
    if not city or "orbit" not in city:
        return None
    o, base = city["orbit"], city.get("baseline") or {}
    line = (f"{_name(o)}: camera and line of sight {100 * o['camera_and_line_of_sight_fraction']:.1f} % (camera "
            f"{100 * o['camera_fraction']:.1f} %, line of sight {100 * o['line_of_sight_fraction']:.1f} %)")
    if "camera_and_line_of_sight_fraction" in base:
        line += f", baseline {100 * base['camera_and_line_of_sight_fraction']:.1f} %"
    return line + (f"; a flyable visible circle {100 * o['flyable_circle_in_polygon_fraction']:.1f} % of the time; "
                   f"{o['volumes']} VVs over {o['updates']} updates")
