"""The ``vistrack`` command: one sub-command per stage, each in vistrack/commands/<name>.py.

Every command module exposes ``register(subparsers)``, which adds its parser and sets
``func(args) -> int``.

Errors are one line on stderr, ``vistrack COMMAND: error: ...`` naming the option or key and the
value, and the exit status says what went wrong: 2 for a command line that cannot be run as given
(an unknown or malformed option, a value outside its range, a missing or conflicting option:
argparse's errors and :class:`vistrack.commands.UsageError`), 1 for a failure while running (a
file that is missing or not what it should be, input the library refuses, a plan too large for
planning.max_volumes, no memory). Both are found before the long work starts wherever they can be.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from typing import NoReturn, Sequence

from . import VistrackError, __version__
from .visibility import keep_freed_memory

# Order shown in --help.
COMMANDS = [
    "demo", "run", "volumes", "orbits", "simulate", "tune", "intercept", "waypoints", "loiter", "follow", "sweep",
    "city",
]

USAGE_ERROR = 2
FAILURE = 1


class OneLineParser(argparse.ArgumentParser):
    """argparse with its usage errors on one line (the usage text stays in --help)."""

    def error(self, message: str) -> NoReturn:
        self.exit(USAGE_ERROR, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def build_parser() -> argparse.ArgumentParser:
    parser = OneLineParser(
        prog="vistrack",
        description="Plan and simulate occlusion-aware UAV tracking of a moving ground target.",
    )
    parser.add_argument("--version", action="version", version=f"vistrack {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")  # sub-parsers are OneLineParsers
    subparsers.required = True
    for name in COMMANDS:
        importlib.import_module(f"vistrack.commands.{name}").register(subparsers)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    from .commands import UsageError
    from .commands.output_lock import output_locks

    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exit_:  # argparse has printed the usage error (or --help / --version)
        return exit_.code if isinstance(exit_.code, int) else USAGE_ERROR
    keep_freed_memory()  # VV batches reuse freed pages (a process-wide malloc setting: the command's to make)
    try:
        with output_locks():  # the output folders the command locks are released when it ends
            return int(args.func(args) or 0)
    except UsageError as error:
        print(f"vistrack {args.command}: error: {error} (see vistrack {args.command} --help)", file=sys.stderr)
        return USAGE_ERROR
    except (VistrackError, OSError) as error:
        print(f"vistrack {args.command}: error: {_one_line(error)}", file=sys.stderr)
        return FAILURE
    except MemoryError:  # a real exhaustion: the estimates before the work refuse what they can foresee
        from .commands.memory import out_of_memory

        print(f"vistrack {args.command}: error: {out_of_memory(args.command)}", file=sys.stderr)
        return FAILURE


def _one_line(error: BaseException) -> str:
    """The message on one line (a file's text quoted in it may hold newlines)."""
    return " ".join(str(error).split())


if __name__ == "__main__":
    sys.exit(main())
