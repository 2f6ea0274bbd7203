"""Text files in and out: UTF-8 text of a bounded size and JSON results (documents read from files:
:mod:`.documents`). Errors name the key and the file."""

from __future__ import annotations

import errno
import json
import os
import stat
from pathlib import Path
from typing import Any

from .._core import VistrackError
from .._core import limits as _limits

__all__ = ["MAX_INPUT_BYTES", "append_json_line", "input_file", "read_bytes", "read_text", "write_json"]


# Input files above this size are refused before reading: 1 GiB, the C++ loaders' limit
# (vistrack/limits.hpp, docs/limits.md).
MAX_INPUT_BYTES: int = _limits.MAX_INPUT_BYTES

_NOT_REGULAR = ((stat.S_ISFIFO, "a FIFO"), (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
                (stat.S_ISSOCK, "a socket"))


def input_file(path: str | Path, key: str, max_bytes: int = MAX_INPUT_BYTES) -> Path:
    """``path`` if it is a regular file of at most ``max_bytes``; otherwise a one-line VistrackError
    naming ``key`` and the path: missing, a symlink loop, a folder, a FIFO or device (reading one may
    block or never end, so it is never opened) or too large. Every input file is checked here."""
    file = Path(path)
    try:
        info = file.stat()
    except OSError as error:
        reason = "a symlink loop" if error.errno == errno.ELOOP else error.strerror
        raise VistrackError(f"{key} = {path}: cannot read the file ({reason})") from None
    _check_stat(info, key, path, max_bytes)
    return file


def _check_stat(info: os.stat_result, key: str, path: str | Path, max_bytes: int) -> None:
    if stat.S_ISDIR(info.st_mode):
        raise VistrackError(f"{key} = {path}: is a folder, not a file")
    if not stat.S_ISREG(info.st_mode):
        kind = next((name for test, name in _NOT_REGULAR if test(info.st_mode)), "not a regular file")
        raise VistrackError(f"{key} = {path}: is {kind}, not a regular file")
    if info.st_size > max_bytes:
        raise VistrackError(f"{key} = {path}: the file has {info.st_size} bytes, above the limit of {max_bytes} "
                            "bytes for an input file")


def read_bytes(path: str | Path, key: str, max_bytes: int = MAX_INPUT_BYTES) -> bytes:
    """The bytes of a regular input file (:func:`input_file`'s checks), read at most to ``max_bytes``."""
    file = input_file(path, key, max_bytes)
    try:
        # O_NONBLOCK and fstat: a FIFO swapped in after the check neither blocks the open nor is read.
        fd = os.open(file, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as error:
        reason = "a symlink loop" if error.errno == errno.ELOOP else error.strerror
        raise VistrackError(f"{key} = {path}: cannot read the file ({reason})") from None
    with os.fdopen(fd, "rb") as stream:
        info = os.fstat(fd)
        _check_stat(info, key, path, max_bytes)
        data = bytearray()
        try:  # its size (a read of max_bytes would allocate that much), then on while it grows
            while chunk := stream.read(min(max_bytes + 1 - len(data), max(info.st_size + 1 - len(data), 1 << 20))):
                data += chunk
                if len(data) > max_bytes:
                    raise VistrackError(f"{key} = {path}: the file has more than {max_bytes} bytes, the limit for "
                                        "an input file")
        except OSError as error:
            raise VistrackError(f"{key} = {path}: cannot read the file ({error.strerror})") from None
    return bytes(data)


def read_text(path: str | Path, key: str) -> str:
    """The UTF-8 text of a file (newlines as ``\\n``); VistrackError naming ``key`` when it is
    missing, not a regular file (:func:`input_file`), unreadable or not UTF-8 text."""
    try:
        text = read_bytes(path, key).decode("utf-8")
    except UnicodeDecodeError as error:
        raise VistrackError(f"{key} = {path}: not UTF-8 text (byte {error.start})") from None
    return text.replace("\r\n", "\n").replace("\r", "\n")  # as text mode read it


def write_json(data: Any, path: str | Path) -> Path:
    """Indented JSON of plain data (results, metrics, summaries)."""
    file = Path(path)
    file.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
    return file


def append_json_line(data: Any, path: str | Path) -> None:
    """One JSON document as one line at the end of a file (rows of a sweep as they arrive); NaN
    and infinity are refused (ValueError), as JSON has no spelling for them."""
    with Path(path).open("a", encoding="utf-8") as stream:
        stream.write(json.dumps(data, allow_nan=False) + "\n")
