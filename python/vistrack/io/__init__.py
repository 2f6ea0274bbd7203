"""The generic file formats vistrack reads and writes, one module per format (autopilot missions:
``vistrack.mission``; a product's own files: its package).

- ``text``: UTF-8 text of a bounded size, JSON results (:func:`read_text`, :func:`write_json`)
- ``documents``: the one bounded JSON/YAML reader of input files (:func:`parse_json`,
  :func:`read_json`, :func:`parse_yaml`, :func:`read_yaml_mapping`): nesting, values (YAML aliases
  expanded) and size limited; a key given twice in one YAML mapping is an error
- ``mesh``: maps, GeoJSON footprints or any triangle mesh (:func:`load_environment`)
- ``orbit_plan``: orbit plans as JSON (:func:`read_plan`, :func:`write_plan`)
- ``tables``: CSV of closed-loop and flown trajectories, waypoint routes x,y (:func:`read_route`),
  numeric rows, and a sweep's results table (``results.csv`` + ``results.parquet``)
- ``geojson``: trajectories and orbit plans in WGS84, road networks (:func:`read_roads`)
- ``volumes``: the VV cache's ``vv-*.bin`` files (:func:`volume_files`)
- ``osm``: OpenStreetMap buildings and roads (:func:`read_osm`; ``Environment.from_osm``)

The loiter and follow readers and writers once here live in ``vistrack.loiter.files`` and
``vistrack.follow.files``; their old names here still answer. Every error names the option or
key and the file: a missing or unreadable file, a file that is not text, or text that is not the
expected format raises VistrackError.
"""

from __future__ import annotations

from .._moved import forward
from .documents import parse_json, parse_yaml, read_json, read_yaml_mapping
from .geojson import (
    ROAD_MERGE_DISTANCE,
    feature_collection,
    line_feature,
    lon_lat,
    orbit_plan_geojson,
    point_feature,
    read_roads,
    trajectory_geojson,
    write_geojson,
)
from .mesh import GEOJSON_SUFFIXES, footprint_environment, load_environment
from .orbit_plan import AnyPlan, read_plan, write_plan
from .osm import OsmCity, OsmSummary, read_osm
from .tables import (
    numeric_rows,
    read_results_table,
    read_route,
    write_flight,
    write_results_table,
    write_route,
    write_rows,
    write_trajectory,
)
from .text import append_json_line, read_text, write_json
from .volumes import volume_files

__getattr__ = forward(__name__, {
    "mission_geojson": "vistrack.mission.model",
    "read_loiter_scenario": "vistrack.loiter.files",
    "write_loiter_samples_csv": "vistrack.loiter.files",
    "read_vehicle_track": "vistrack.follow.files",
    "read_road_path": "vistrack.follow.files",
    "write_follow_trajectory": "vistrack.follow.files",
})

__all__ = [
    "GEOJSON_SUFFIXES",
    "ROAD_MERGE_DISTANCE",
    "AnyPlan",
    "OsmCity",
    "OsmSummary",
    "append_json_line",
    "feature_collection",
    "footprint_environment",
    "line_feature",
    "load_environment",
    "lon_lat",
    "numeric_rows",
    "orbit_plan_geojson",
    "parse_json",
    "parse_yaml",
    "point_feature",
    "read_json",
    "read_osm",
    "read_plan",
    "read_results_table",
    "read_roads",
    "read_route",
    "read_text",
    "read_yaml_mapping",
    "trajectory_geojson",
    "volume_files",
    "write_flight",
    "write_geojson",
    "write_json",
    "write_plan",
    "write_results_table",
    "write_route",
    "write_rows",
    "write_trajectory",
]
