"""Argparse types from the library's schema checks: a value's range is checked while the command
line is parsed (a usage error, exit 2), before any work."""

from __future__ import annotations

import argparse
from typing import Any, Callable

from .. import schema
from .._core import VistrackError

__all__ = ["UsageError", "add_dynamics_argument", "checked", "coordinate", "count", "fdm_choice", "length", "number",
           "speed"]


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


def add_dynamics_argument(parser: argparse.ArgumentParser, default: str | None = None, fdm: bool = False) -> None:
    """``--dynamics roll|dubins``: the vehicle model every flight of the command uses (None: the
    scenario's ``uav.dynamics``, whose default is roll). With ``fdm``, also ``jsbsim`` and
    ``--aircraft NAME``: the flights are flown on the 6-DOF aircraft too (:func:`fdm_choice`)."""
    from ..scenario_blocks import DYNAMICS, FDM_DYNAMICS

    parser.add_argument("--dynamics", choices=(*DYNAMICS, FDM_DYNAMICS) if fdm else DYNAMICS, default=default,
                        help="vehicle model: roll (the bank a first-order, rate-limited state) or dubins (the "
                             "turn rate at once, the papers' vehicle)"
                             + ("; jsbsim: also on a 6-DOF JSBSim aircraft with vistrack's autopilot" if fdm else "")
                             + "; default: " + (default or "the scenario's uav.dynamics, else roll"))
    if fdm:
        parser.add_argument("--aircraft", default=None,
                            help="the 6-DOF aircraft of --dynamics jsbsim (default aerosonde; also c172p)")


def fdm_choice(args: argparse.Namespace) -> tuple[str | None, str | None]:
    """(kinematic model or None: the scenario's, 6-DOF aircraft or None) from --dynamics and --aircraft."""
    from ..scenario_blocks import FDM_DYNAMICS, aircraft_name

    aircraft = getattr(args, "aircraft", None)  # the sweeps' namespaces have no --aircraft
    if args.dynamics == FDM_DYNAMICS:
        return None, aircraft_name(aircraft)
    if aircraft is not None:
        raise UsageError(f"--aircraft {aircraft} needs --dynamics {FDM_DYNAMICS}")
    return args.dynamics, None
