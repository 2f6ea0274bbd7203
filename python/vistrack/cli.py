"""The ``vistrack`` command: one sub-command per stage, each in vistrack/commands/<name>.py.

Every command module exposes ``register(subparsers)``, which adds its parser and sets
``func(args) -> int``.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from typing import Sequence

from . import VistrackError, __version__

# Order shown in --help.
COMMANDS = [
    "demo", "run", "volumes", "orbits", "simulate", "tune", "intercept", "waypoints", "loiter", "follow", "sweep",
]


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="vistrack",
        description="Plan and simulate occlusion-aware UAV tracking of a moving ground target.",
    )
    parser.add_argument("--version", action="version", version=f"vistrack {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    subparsers.required = True
    for name in COMMANDS:
        importlib.import_module(f"vistrack.commands.{name}").register(subparsers)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exit_:  # argparse has printed the usage error (or --help / --version)
        return int(exit_.code or 0)
    try:
        return int(args.func(args) or 0)
    except (VistrackError, OSError) as error:
        # One clear line and a non-zero exit on any input or file error.
        print(f"vistrack {args.command}: error: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
