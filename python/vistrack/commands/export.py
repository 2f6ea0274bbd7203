"""--export and --origin: where a planned route goes for an autopilot or a map, and the
georeference that places it."""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable

from .. import schema
from ..mission import MISSION_SUFFIXES, Georeference, Mission
from ..tracking.to_mission import export_orbit_plan
from .types import UsageError, checked

if TYPE_CHECKING:
    from .._core import Environment, OrbitPlan

__all__ = ["DEFAULT_EXPORT_ORIGIN", "add_export_arguments", "check_exports", "export_georeference", "export_mission",
           "export_missions", "export_plan"]


def add_export_arguments(parser: argparse.ArgumentParser, direction: bool = False) -> None:
    """--export FILE (repeatable) and --origin LAT,LON[,ALT] for commands that plan a route (and
    --direction, the circulation written, where no scenario gives it)."""

    def origin(text: str) -> Georeference:
        try:
            return Georeference.from_value([float(v) for v in text.split(",")], "--origin")
        except ValueError as error:  # VistrackError is a ValueError; float() raises one too
            raise argparse.ArgumentTypeError(str(error) if "--origin" in str(error) else
                                             f"--origin = {text}: need LAT,LON or LAT,LON,ALT in degrees and metres"
                                             ) from None

    def mission_file(key: str, text: str) -> str:
        if Path(text).suffix.lower() not in MISSION_SUFFIXES:
            raise schema.fail(key, text, "unknown format; the suffix must be one of " + ", ".join(MISSION_SUFFIXES))
        return text

    parser.add_argument("--export", action="append", default=[], metavar="FILE",
                        type=checked("--export", mission_file, numeric=False),
                        help="also write the route for an autopilot or a map, by suffix: .plan (QGroundControl), "
                             ".waypoints/.txt (QGC WPL 110), .geojson (WGS84); repeatable. Placed by --origin, "
                             "else the scenario's origin or a longitude/latitude map (loiter and follow: else "
                             "Charlotte's origin, with a note)")
    parser.add_argument("--origin", type=origin, default=None, metavar="LAT,LON[,ALT]",
                        help="where local (0, 0, 0) lies: WGS84 degrees and metres above sea level (projects a "
                             "longitude/latitude GeoJSON map and georeferences --export)")
    if direction:
        parser.add_argument("--direction", default="ccw", choices=["ccw", "cw"], help="orbit direction for --export")


# Where planners without a map (loiter, follow) put their missions when no --origin is given: the
# Charlotte data's origin (a printed note says so).
DEFAULT_EXPORT_ORIGIN = Georeference(35.2249, -80.8403)


def export_georeference(paths: Sequence[str], georeference: Georeference | None,
                        env: Environment | None = None, fallback: Georeference | None = None) -> Georeference:
    """The georeference for --export: --origin / the scenario's, else the map's (env.origin), else
    ``fallback`` (with a printed note)."""
    reference = georeference or Georeference.of(env)
    if reference is None and fallback is not None:
        print(f"--export: no --origin given; local (0, 0) placed at {fallback.lat},{fallback.lon} "
              "(give --origin LAT,LON to fly it elsewhere)")
        reference = fallback
    if reference is None:
        raise UsageError(f"--export = {paths[0]}: needs a georeference; give --origin LAT,LON (or origin: "
                         "[lat, lon] in the scenario, or a map in longitude/latitude)")
    return reference


def check_exports(paths: Sequence[str], georeference: Georeference | None, map_path: str | Path | None) -> None:
    """--export checked before the work (its suffixes are checked as the command line is parsed):
    a georeference unless the map may bring one (a GeoJSON map in longitude/latitude; the rest is
    checked once it is read)."""
    may_bring_origin = map_path is not None and Path(map_path).suffix.lower() in (".geojson", ".json")
    if paths and georeference is None and not may_bring_origin:
        export_georeference(paths, None)


def export_plan(paths: Sequence[str], plan: OrbitPlan, georeference: Georeference | None, env: Environment | None,
                **options: Any) -> None:
    """Write each --export file of an orbit plan (vistrack.tracking.to_mission.export_orbit_plan) and print
    what was written."""
    if paths:
        reference = export_georeference(paths, georeference, env)
        for path in paths:
            print(export_orbit_plan(path, plan, reference, **options))


def export_mission(paths: Sequence[str], build: Callable[[Georeference], Mission], georeference: Georeference | None,
                   env: Environment | None = None, fallback: Georeference | None = None) -> None:
    """--export for any planner: ``build(georeference)`` (its ``to_mission``) saved to each file
    by suffix (.plan, .waypoints, .txt, .geojson); prints what was written."""
    if paths:
        mission = build(export_georeference(paths, georeference, env, fallback))
        for path in paths:
            print(f"wrote {mission.save(path)}: {len(mission)} mission items")


def export_missions(paths: Sequence[str], builds: dict[str, Callable[[Georeference], Mission]],
                    georeference: Georeference | None, fallback: Georeference | None = None) -> None:
    """--export of several plans (by label, e.g. one per method): one plan goes to the files as
    given, several to FILE_<label>.suffix each."""
    if not paths:
        return
    reference = export_georeference(paths, georeference, None, fallback)
    for label, build in builds.items():
        files = paths if len(builds) == 1 else [str(Path(p).with_stem(f"{Path(p).stem}_{label}")) for p in paths]
        export_mission(files, build, reference)
