"""Sub-commands of the ``vistrack`` command line, one module each (``cli`` finds them by name). A
command parses its arguments, calls the library and prints. What they share:

- ``types``: argparse types from the library's checks (lengths, speeds, counts) and UsageError
- ``lists``: comma-separated numbers, points, a configuration
- ``output``: the output folder and the report folder's options
- ``export``: --export and --origin (missions and GeoJSON for an autopilot or a map)
"""

from __future__ import annotations

from .export import (
    DEFAULT_EXPORT_ORIGIN,
    add_export_arguments,
    check_exports,
    export_georeference,
    export_mission,
    export_missions,
    export_plan,
)
from .lists import configuration, finite_numbers, point_list, positive_numbers
from .output import add_report_arguments, output_folder, report_options
from .types import UsageError, checked, coordinate, count, length, number, speed

__all__ = [
    "DEFAULT_EXPORT_ORIGIN", "UsageError", "add_export_arguments", "add_report_arguments", "check_exports", "checked",
    "configuration", "coordinate", "count", "export_georeference", "export_mission", "export_missions", "export_plan",
    "finite_numbers", "length", "number", "output_folder", "point_list", "positive_numbers", "report_options", "speed",
]
