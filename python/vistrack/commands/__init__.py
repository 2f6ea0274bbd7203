"""Sub-commands of the ``vistrack`` command line, one module each, and the argparse types they
share. A command parses its arguments, calls the library and prints."""

from __future__ import annotations

import argparse
import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, Callable, Optional

import numpy as np

from .._core import VistrackError
from ..mission import Georeference, Mission, export_orbit_plan

if TYPE_CHECKING:
    from .._core import Environment, OrbitPlan
    from ..scenario import ReportOptions


def positive_numbers(flag: str, example: str) -> Callable[[str], list[float]]:
    """An argparse type for a comma-separated list of positive numbers, e.g. --spacings 50,25."""

    def parse(text: str) -> list[float]:
        try:
            values = [float(v) for v in text.split(",") if v.strip()]
        except ValueError:
            values = []
        if not values or any(not (v > 0 and math.isfinite(v)) for v in values):
            raise argparse.ArgumentTypeError(f"{flag} = {text}: need positive numbers like {example}")
        return values

    return parse


def point_list(flag: str) -> Callable[[str], np.ndarray]:
    """An argparse type for points "x,y[,z];x,y[,z];..." as an (n, 3) array (NaN for a missing z)."""

    def parse(text: str) -> np.ndarray:
        points = []
        for k, item in enumerate(filter(None, (s.strip() for s in text.split(";")))):
            try:
                values = [float(v) for v in item.split(",")]
            except ValueError:
                raise argparse.ArgumentTypeError(f"{flag}[{k}] = {item!r}: expected x,y or x,y,z numbers") from None
            if len(values) not in (2, 3) or not all(math.isfinite(v) for v in values):
                raise argparse.ArgumentTypeError(f"{flag}[{k}] = {item!r}: expected 2 or 3 finite numbers")
            points.append(values + [math.nan] * (3 - len(values)))
        if not points:
            raise argparse.ArgumentTypeError(f"{flag} = {text!r}: no points")
        return np.array(points)

    return parse


def configuration(flag: str) -> Callable[[str], np.ndarray]:
    """An argparse type for a configuration "X,Y,PSI" (metres, metres, radians)."""

    def parse(text: str) -> np.ndarray:
        try:
            values = [float(v) for v in text.replace(",", " ").split()]
        except ValueError:
            values = []
        if len(values) != 3 or not all(math.isfinite(v) for v in values):
            raise argparse.ArgumentTypeError(f"{flag} = {text}: expected three numbers X,Y,PSI")
        return np.array(values)

    return parse


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

    parser.add_argument("--export", action="append", default=[], metavar="FILE",
                        help="also write the route for an autopilot or a map, by suffix: .plan (QGroundControl), "
                             ".waypoints/.txt (QGC WPL 110), .geojson (WGS84); repeatable. Needs --origin, the "
                             "scenario's origin or a longitude/latitude map")
    parser.add_argument("--origin", type=origin, default=None, metavar="LAT,LON[,ALT]",
                        help="where local (0, 0, 0) lies: WGS84 degrees and metres above sea level (projects a "
                             "longitude/latitude GeoJSON map and georeferences --export)")
    if direction:
        parser.add_argument("--direction", default="ccw", choices=["ccw", "cw"], help="orbit direction for --export")


def export_georeference(paths: Sequence[str], georeference: Georeference | None,
                        env: Environment | None = None) -> Georeference:
    """The georeference for --export: --origin / the scenario's, else the map's (env.origin)."""
    reference = georeference or Georeference.of(env)
    if reference is None:
        raise VistrackError(f"--export = {paths[0]}: needs a georeference; give --origin LAT,LON (or origin: "
                            "[lat, lon] in the scenario, or a map in longitude/latitude)")
    return reference


def export_plan(paths: Sequence[str], plan: OrbitPlan, georeference: Georeference | None, env: Environment | None,
                **options: Any) -> None:
    """Write each --export file of an orbit plan (vistrack.mission.export_orbit_plan) and print
    what was written."""
    if paths:
        reference = export_georeference(paths, georeference, env)
        for path in paths:
            print(export_orbit_plan(path, plan, reference, **options))


def export_mission(paths: Sequence[str], build: Callable[[Georeference], Mission], georeference: Georeference | None,
                   env: Environment | None = None) -> None:
    """--export for any planner: ``build(georeference)`` (its ``to_mission``) saved to each file
    by suffix (.plan, .waypoints, .txt, .geojson); prints what was written."""
    if paths:
        mission = build(export_georeference(paths, georeference, env))
        for path in paths:
            print(f"wrote {mission.save(path)}: {len(mission)} mission items")


def add_report_arguments(parser: Any) -> None:
    """The options of a report folder's animation and interactive page (``run``, ``demo`` and any
    command writing trajectory.gif / report.html); read them back with :func:`report_options`."""
    parser.add_argument("--no-animation", action="store_true", help="do not write trajectory.gif")
    parser.add_argument("--no-html", action="store_true", help="do not write the interactive report.html")
    parser.add_argument("--frames", type=int, default=None,
                        help="frames of trajectory.gif (default: the scenario's report.frames, else 60)")
    parser.add_argument("--duration", type=float, default=None,
                        help="seconds trajectory.gif lasts (default: the scenario's report.duration, else 8)")


def report_options(args: argparse.Namespace, base: Optional[ReportOptions] = None) -> ReportOptions:
    """``base`` (a scenario's report section, or the defaults) overridden by the command line,
    validated; errors name the option (``--frames = 1: ...``)."""
    from ..scenario import ReportOptions

    options = base if base is not None else ReportOptions()
    options.animation = options.animation and not args.no_animation
    options.html = options.html and not args.no_html
    if args.frames is not None:
        options.frames = args.frames
    if args.duration is not None:
        options.duration = args.duration
    try:
        options.validate()
    except VistrackError as error:
        raise VistrackError(str(error).replace("report.", "--", 1)) from None
    return options
def finite_numbers(flag: str, count: int, example: str) -> Callable[[str], list[float]]:
    """An argparse type for exactly ``count`` comma-separated finite numbers, e.g. --wind 0,0.08."""

    def parse(text: str) -> list[float]:
        try:
            values = [float(v) for v in text.split(",") if v.strip()]
        except ValueError:
            values = []
        if len(values) != count or not all(math.isfinite(v) for v in values):
            raise argparse.ArgumentTypeError(f"{flag} = {text}: need {count} finite numbers like {example}")
        return values

    return parse
