"""What a command writes: the output folder, checked before the work, and the options of a report
folder's animation and interactive page."""

from __future__ import annotations

import argparse
import os
from pathlib import Path
from typing import Any, Optional

from .._core import VistrackError
from ..report_options import ReportOptions
from .output_lock import lock_folder
from .types import UsageError, count, number

__all__ = ["add_report_arguments", "output_folder", "report_options"]


def output_folder(path: str | Path, flag: str = "--out") -> Path:
    """The folder a command writes into, checked and locked now (:mod:`.output_lock`: a second run
    into a busy folder is refused; the folder is created, and removed again if the run leaves it
    empty): a path that is a file, or under a file, or in a folder that cannot be written, is an
    error before the work starts rather than after it. Every command writing a folder calls this."""
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
    lock_folder(folder, flag)
    return folder


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
