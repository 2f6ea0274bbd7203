"""Figures, one module per figure family. Everything draws on the Agg backend (no display).

- ``common``: pyplot, figure creation and saving, the OpenStreetMap credit
- ``city``: buildings, roads and the POI path from above
- ``volumes``: visibility volumes in 3D and their visibility polygons from above
- ``orbits``: Figure 4 (XOR metric along the path), Figure 5 (orbits in their VPs), R(t)
- ``simulation``: Figure 10 (trajectory) and Figure 11 (errors and control)
- ``tune``: Figure 9 (turn rate needed against beta)
- ``intercept``: Figure 7 of the intercept paper
- ``waypoint_nav``: Figures 10-12 of the Dubins waypoint navigation paper, the Monte Carlo
- ``loiter``: loiter plans over AOIs (Figures 6, 9, 12, 13), Figure 14, random-scenario distributions, flights in wind
- ``follow``: ground-vehicle following (its Figures 2 and 5-9, planner against baseline, city runs)
"""

from __future__ import annotations

from .city import footprint_path, plot_buildings, plot_city, plot_poi_path, plot_roads
from .common import OSM_CREDIT, add_credit, evenly_spaced_indices, map_credit, new_figure, pyplot, save_figure
from .volumes import figure_volume_3d

__all__ = [
    "OSM_CREDIT", "add_credit", "evenly_spaced_indices", "figure_volume_3d", "footprint_path", "map_credit",
    "new_figure",
    "plot_buildings", "plot_city", "plot_poi_path", "plot_roads", "pyplot", "save_figure",
]
