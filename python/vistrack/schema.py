"""Validation of input read from files (scenario, sweep and planner YAML): every error is a
VistrackError of the form "key = value: what is allowed", naming the key as the user wrote it
(``poi.speed``, ``aois[2].radius``). The physical ranges (:func:`coordinate`, :func:`length`,
:func:`speed`) are the C++ core's (``vistrack._core.limits``; README, Hardening)."""

from __future__ import annotations

import errno
import math
import numbers
import re
from pathlib import Path
from typing import Any, Callable, Iterable, Mapping, TypeVar

from ._core import Planning, VistrackError
from ._core import limits as _limits
from .preview import preview

__all__ = ["absolute_tolerance", "apply_checks", "beta", "by_struct", "coordinate", "fail", "heading_gain", "integer",
           "length", "number", "output_name", "positive", "rate_margin", "relative_tolerance", "resolve_path",
           "section", "speed"]

T = TypeVar("T")


def fail(key: str, value: Any, allowed: str) -> VistrackError:
    """The error for one bad value (raise it); a long value is cut to 80 characters, without ever
    building the text of all of it (:func:`vistrack.preview.preview`: a YAML alias tree of 1e9
    nodes is quoted as cheaply as a number)."""
    return VistrackError(f"{key} = {preview(value)}: {allowed}")


def number(key: str, value: Any, *, low: float | None = None, high: float | None = None,
           low_open: bool = False) -> float:
    """A finite number within [low, high] (low excluded when ``low_open``)."""
    # YAML 1.1 reads 20e6 (no dot) as a string: accept any text float() accepts.
    if isinstance(value, bool):
        raise fail(key, value, "must be a number")
    try:
        result = float(value)
    except (TypeError, ValueError):
        raise fail(key, value, "must be a number") from None
    except OverflowError:  # an integer beyond the doubles (YAML reads 10**400 exactly)
        raise fail(key, f"an integer of {len(str(value))} digits", "must be a finite number") from None
    if not math.isfinite(result):
        raise fail(key, value, "must be a finite number")
    if low is not None and (result < low or (low_open and result == low)):
        bound = f"> {low:g}" if low_open else f">= {low:g}"
        raise fail(key, value, f"must be {bound}" + (f" and <= {high:g}" if high is not None else ""))
    if high is not None and result > high:
        raise fail(key, value, f"must be <= {high:g}" + (f" and >= {low:g}" if low is not None else ""))
    return result


def coordinate(key: str, value: Any) -> float:
    """A coordinate (x, y, z or an altitude) in metres: |value| <= 1e7."""
    return number(key, value, low=-_limits.MAX_COORDINATE, high=_limits.MAX_COORDINATE)


def length(key: str, value: Any) -> float:
    """A length (a radius, a distance, a spacing) in metres: [1e-6, 1e7]."""
    return number(key, value, low=_limits.MIN_LENGTH, high=_limits.MAX_LENGTH)


def speed(key: str, value: Any) -> float:
    """A speed in m/s: [1e-6, 1e4]."""
    return number(key, value, low=_limits.MIN_SPEED, high=_limits.MAX_SPEED)


def beta(key: str, value: Any) -> float:
    """The vector field's gain beta in 1/m: [1e-9, 1e3]."""
    return number(key, value, low=_limits.MIN_GAIN, high=_limits.MAX_BETA)


def heading_gain(key: str, value: Any) -> float:
    """The heading gain k_psi in 1/s: [1e-9, 1e6]."""
    return number(key, value, low=_limits.MIN_GAIN, high=_limits.MAX_HEADING_GAIN)


def relative_tolerance(key: str, value: Any) -> float:
    """An ODE's rtol: [1e-13, 1]."""
    return number(key, value, low=_limits.MIN_RTOL, high=_limits.MAX_RTOL)


def absolute_tolerance(key: str, value: Any) -> float:
    """An ODE's atol: [1e-15, 1e6]."""
    return number(key, value, low=_limits.MIN_ATOL, high=_limits.MAX_ATOL)


def by_struct(make: Callable[[], Any], field: str) -> Callable[[str, Any], float]:
    """A check of one number by its C++ parameter struct's own ``validate()`` (the range lives there
    only): ``make()`` gives a valid struct, ``field`` is set to the value; the error names ``key``
    (an option such as ``--rate-margin``, or a YAML key)."""

    def check(key: str, value: Any) -> float:
        result = number(key, value)
        target = make()
        setattr(target, field, result)
        try:
            target.validate()
        except VistrackError as error:
            raise fail(key, value, str(error).split(": ", 1)[-1]) from None
        return result

    return check


# A share of Lemma 5's radius rate v - v_g kept in reserve: Planning.validate's [0, 1).
rate_margin = by_struct(Planning, "rate_margin")


def integer(key: str, value: Any, low: int, high: int) -> int:
    """An integer (not a bool; numpy integers too) within [low, high], as an int."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or not low <= int(value) <= high:
        raise fail(key, value, f"must be an integer in [{low}, {high}]")
    return int(value)


def pair(key: str, value: Any, what: str = "[x, y] in metres") -> tuple[float, float]:
    """Two finite numbers given as a two-item list, e.g. a point; VistrackError naming ``key``."""
    if not isinstance(value, (list, tuple)) or len(value) != 2:
        raise fail(key, value, f"must be {what}")
    return number(f"{key}[0]", value[0]), number(f"{key}[1]", value[1])


def reject_unknown(data: Mapping[Any, Any], allowed: Iterable[str], prefix: str = "", noun: str = "key",
                   where: str = "") -> None:
    """VistrackError naming the first key of ``data`` outside ``allowed`` (as ``prefix`` + key):
    "unknown key; allowed keys[ where]: ...". YAML keys may be of any type (``0:``, ``true:``), so
    they are sorted as text."""
    names = set(allowed)
    unknown = sorted(set(data) - names, key=str)
    if unknown:
        raise fail(f"{prefix}{unknown[0]}", data[unknown[0]],
                   f"unknown {noun}; allowed {noun}s{where}: {', '.join(sorted(names))}")


def section(data: Mapping[str, Any], name: str, allowed: set[str]) -> dict[str, Any]:
    """The mapping ``data[name]`` (empty when absent), with no key outside ``allowed``."""
    found = data.get(name) or {}
    if not isinstance(found, Mapping):
        raise fail(name, found, "must be a mapping of keys to values")
    reject_unknown(found, allowed, f"{name}.", where=f" in {name}")
    return dict(found)


def output_name(key: str, value: Any) -> str:
    """A name from a file that becomes a path component under --out (a scenario's or sweep's name):
    letters, digits, '_', '-' and '.' only, so it can never climb out of the output folder."""
    if not isinstance(value, str) or not re.fullmatch(r"[\w.-]+", value) or set(value) == {"."}:
        raise fail(key, value, "must be a non-empty name of letters, digits, '_', '-' or '.' "
                               "(it names the output folder)")
    return value


def resolve_path(base: Path, value: Any, key: str) -> Path:
    """A file path from a file, relative paths taken from the file's folder ``base``."""
    if not isinstance(value, (str, Path)) or not str(value):
        raise fail(key, value, "must be a file path")
    try:
        path = Path(value).expanduser()
    except RuntimeError:  # "~name/..." for a user this machine does not have
        raise fail(key, value, "cannot be resolved (its '~' names no home directory here)") from None
    try:
        return (path if path.is_absolute() else base / path).resolve()
    except RuntimeError:  # Path.resolve's "Symlink loop" (an OSError from Python 3.13)
        raise fail(key, value, "cannot be resolved (a symlink loop)") from None
    except OSError as error:
        reason = "a symlink loop" if error.errno == errno.ELOOP else error.strerror
        raise fail(key, value, f"cannot be resolved ({reason})") from None


def apply_checks(target: T, section: Mapping[str, Any], prefix: str,
                 checks: dict[str, Callable[[str, Any], Any]]) -> T:
    """Set each present key of ``section`` on ``target`` through its check, then ``target.validate()``."""
    for key, check in checks.items():
        if key in section:
            setattr(target, key, check(f"{prefix}.{key}", section[key]))
    target.validate()  # type: ignore[attr-defined]
    return target


def boolean(key: str, value: Any) -> bool:
    """true or false (YAML booleans only; 0, 1 and strings are refused)."""
    if not isinstance(value, bool):
        raise fail(key, value, "must be true or false")
    return value


def positive(key: str, value: Any) -> float:
    """A finite number > 0."""
    return number(key, value, low=0.0, low_open=True)
