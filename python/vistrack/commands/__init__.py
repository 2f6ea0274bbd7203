"""Sub-commands of the ``vistrack`` command line, one module each, and the argparse types they
share. A command parses its arguments, calls the library and prints."""

from __future__ import annotations

import argparse
import math
import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Optional

import numpy as np

from .. import schema
from .._core import VistrackError
from ..mission import MISSION_SUFFIXES, Georeference, Mission
from ..tracking.to_mission import export_orbit_plan

if TYPE_CHECKING:
    from .._core import Environment, OrbitPlan
    from ..report_options import ReportOptions


class UsageError(VistrackError):
    """A command line that cannot be run as given (a missing or conflicting option): exit status 2
    (a failure while running is 1)."""


def checked(flag: str, check: Callable[[str, Any], Any], numeric: bool = True) -> Callable[[str], Any]:
    """An argparse type from a schema check (``schema.length``, ``schema.speed``, ...): the value's
    range is checked while the command line is parsed (a usage error, exit 2), before any work.
    ``numeric``: the text goes to the check as a float when it reads as one (the message then shows
    the number), else as it is."""

    def parse(text: str) -> Any:
        value: Any = text
        if numeric:
            try:
                value = float(text)
            except ValueError:
                pass
        try:
            return check(flag, value)
        except VistrackError as error:
            raise argparse.ArgumentTypeError(str(error)) from None

    parse.__name__ = getattr(check, "__name__", "value")  # argparse names the type in some messages
    return parse


def length(flag: str) -> Callable[[str], float]:
    """A length in metres, [1e-6, 1e7]."""
    return checked(flag, schema.length)


def speed(flag: str) -> Callable[[str], float]:
    """A speed in m/s, [1e-6, 1e4]."""
    return checked(flag, schema.speed)


def coordinate(flag: str) -> Callable[[str], float]:
    """A coordinate or an altitude in metres, |value| <= 1e7."""
    return checked(flag, schema.coordinate)


def number(flag: str, low: float | None = None, high: float | None = None, low_open: bool = False
           ) -> Callable[[str], float]:
    """A finite number within [low, high] (low excluded when ``low_open``)."""
    return checked(flag, lambda key, value: schema.number(key, value, low=low, high=high, low_open=low_open))


def count(flag: str, low: int, high: int) -> Callable[[str], int]:
    """An integer within [low, high]."""

    def parse(key: str, text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise schema.fail(key, text, f"must be an integer in [{low}, {high}]") from None
        return schema.integer(key, value, low, high)

    return checked(flag, parse, numeric=False)


def output_folder(path: str | Path, flag: str = "--out") -> Path:
    """The folder a command writes into, checked now (not created: a failed run leaves nothing): a
    path that is a file, or under a file, or in a folder that cannot be written, is an error before
    the work starts rather than after it."""
    folder = Path(path)
    if folder.exists() and not folder.is_dir():
        raise VistrackError(f"{flag} = {path}: is a file, not a folder")
    existing = folder
    while not existing.exists() and existing != existing.parent:
        existing = existing.parent
    if not existing.is_dir():
        raise VistrackError(f"{flag} = {path}: {existing} is a file, not a folder")
    if not os.access(existing, os.W_OK | os.X_OK):
        raise VistrackError(f"{flag} = {path}: cannot create the folder ({existing} is not writable)")
    return folder


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
    """Write each --export file of an orbit plan (vistrack.mission.export_orbit_plan) and print
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


def add_report_arguments(parser: Any) -> None:
    """The options of a report folder's animation and interactive page (``run``, ``demo`` and any
    command writing trajectory.gif / report.html); read them back with :func:`report_options`."""
    parser.add_argument("--no-animation", action="store_true", help="do not write trajectory.gif")
    parser.add_argument("--no-html", action="store_true", help="do not write the interactive report.html")
    parser.add_argument("--frames", type=count("--frames", 2, 1000), default=None,
                        help="frames of trajectory.gif (default: the scenario's report.frames, else 60)")
    parser.add_argument("--duration", type=number("--duration", 0.0, 3600.0, low_open=True), default=None,
                        help="seconds trajectory.gif lasts (default: the scenario's report.duration, else 8)")


def report_options(args: argparse.Namespace, base: Optional[ReportOptions] = None) -> ReportOptions:
    """``base`` (a scenario's report section, or the defaults) overridden by the command line,
    validated; errors name the option (``--frames = 1: ...``)."""
    from ..report_options import ReportOptions

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
        raise UsageError(str(error).replace("report.", "--", 1)) from None
    return options
def finite_numbers(flag: str, count: int, example: str, limit: float = math.inf) -> Callable[[str], list[float]]:
    """An argparse type for exactly ``count`` comma-separated finite numbers, e.g. --wind 0,0.08,
    each within [-limit, limit]."""

    def parse(text: str) -> list[float]:
        try:
            values = [float(v) for v in text.split(",") if v.strip()]
        except ValueError:
            values = []
        if len(values) != count or not all(abs(v) <= limit for v in values):  # NaN and inf fail too
            within = "" if limit == math.inf else f" in [{-limit:g}, {limit:g}]"
            raise argparse.ArgumentTypeError(f"{flag} = {text}: need {count} finite numbers{within} like {example}")
        return values

    return parse
