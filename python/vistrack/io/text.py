"""Text files in and out: UTF-8 text, JSON results and YAML documents (a key given twice in one
mapping is an error, not the last one silently kept). Errors name the key and the file."""

from __future__ import annotations

import errno
import json
import os
import stat
from pathlib import Path
from typing import Any

from .._core import VistrackError
from .._core import limits as _limits

__all__ = ["MAX_INPUT_BYTES", "append_json_line", "input_file", "parse_yaml", "read_bytes", "read_text",
           "read_yaml_mapping", "write_json"]


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


def parse_yaml(text: str, key: str, path: str | Path) -> Any:
    """The YAML document in ``text`` (read from ``path``) as plain data, through a safe loader that
    refuses a key given twice in one mapping (PyYAML would keep the last one without a word);
    VistrackError naming ``key``, the file and the line for anything that is not valid YAML."""
    import yaml

    class UniqueKeyLoader(yaml.SafeLoader):
        def construct_mapping(self, node: yaml.MappingNode, deep: bool = False) -> dict[Any, Any]:
            seen: set[Any] = set()
            for key_node, _ in node.value:
                if key_node.tag == "tag:yaml.org,2002:merge":
                    continue  # "<<: *base" merges keys that the mapping may override
                name = self.construct_object(key_node, deep=deep)
                try:
                    duplicated = name in seen
                except TypeError:  # an unhashable key: SafeLoader reports it
                    continue
                if duplicated:
                    raise yaml.constructor.ConstructorError(
                        "while constructing a mapping", node.start_mark,
                        f"found the key {name!r} twice (a YAML key is given once)", key_node.start_mark)
                seen.add(name)
            return super().construct_mapping(node, deep)

    try:
        return yaml.load(text, Loader=UniqueKeyLoader)
    except yaml.YAMLError as error:
        reason = " ".join(str(error).split())
        raise VistrackError(f"{key} = {path}: not valid YAML ({reason})") from None
    except RecursionError:
        raise VistrackError(f"{key} = {path}: not valid YAML (nested too deeply)") from None
    except ValueError:  # Python refuses integers of more than 4300 digits
        raise VistrackError(f"{key} = {path}: not valid YAML (a number too long to read)") from None


def read_yaml_mapping(path: str | Path, key: str) -> dict[str, Any]:
    """A YAML file holding one mapping (empty file: empty mapping)."""
    data = parse_yaml(read_text(path, key), key, path)
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise VistrackError(f"{key} = {path}: expected a mapping of keys to values, not {type(data).__name__}")
    return data


def append_json_line(data: Any, path: str | Path) -> None:
    """One JSON document as one line at the end of a file (rows of a sweep as they arrive); NaN
    and infinity are refused (ValueError), as JSON has no spelling for them."""
    with Path(path).open("a", encoding="utf-8") as stream:
        stream.write(json.dumps(data, allow_nan=False) + "\n")
