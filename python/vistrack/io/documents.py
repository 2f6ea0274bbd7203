"""JSON and YAML documents from input files, through one bounded reader: the file's size is limited
(:func:`.text.read_text`), its nesting to ``MAX_DOCUMENT_DEPTH`` levels and its values to
``MAX_DOCUMENT_NODES``, each YAML alias counted as the tree it stands for, so a "billion laughs" file
of a kilobyte is refused while it is read, before anything walks or quotes the tree (docs/limits.md).
A key given twice in one YAML mapping is an error, not the last one silently kept. Errors are one
line naming the key and the file."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from .._core import VistrackError
from .._core import limits as _limits
from .text import read_text

__all__ = ["MAX_DOCUMENT_DEPTH", "MAX_DOCUMENT_NODES", "parse_json", "parse_yaml", "read_json",
           "read_yaml_mapping"]

MAX_DOCUMENT_DEPTH: int = _limits.MAX_DOCUMENT_DEPTH  # nested lists and mappings (vistrack/limits.hpp)
MAX_DOCUMENT_NODES: int = _limits.MAX_DOCUMENT_NODES  # values, each alias as what it expands to


def _too_deep(key: str, path: str | Path) -> VistrackError:
    return VistrackError(f"{key} = {path}: nested deeper than {MAX_DOCUMENT_DEPTH} levels (the limit for an "
                         "input document)")


def _depth(data: Any) -> int:
    """The nesting depth of parsed JSON (a scalar 0, ``[]`` 1), walked without recursion, stopping
    once past the limit."""
    deepest, stack = 0, [(data, 1)]
    while stack and deepest <= MAX_DOCUMENT_DEPTH:
        item, depth = stack.pop()
        children = item.values() if isinstance(item, dict) else item if isinstance(item, list) else None
        if children is not None:
            deepest = max(deepest, depth)
            stack.extend((child, depth + 1) for child in children)
    return deepest


def parse_json(text: str, key: str, path: str | Path) -> Any:
    """The JSON document in ``text`` (read from ``path``); VistrackError naming ``key`` and the file
    for text that is not JSON, a number too long to read, or nesting deeper than
    ``MAX_DOCUMENT_DEPTH`` (Python's recursion stops a deeper parse at about 1,000 levels, where
    the same error is given). A JSON file has no aliases: its values are bounded by its size."""
    try:
        data = json.loads(text)
    except json.JSONDecodeError as error:
        raise VistrackError(f"{key} = {path}: not valid JSON ({error.msg} at line {error.lineno})") from None
    except RecursionError:
        raise _too_deep(key, path) from None
    except ValueError:  # after JSONDecodeError, its subclass: integers of more than 4300 digits
        raise VistrackError(f"{key} = {path}: not valid JSON (a number too long to read)") from None
    if _depth(data) > MAX_DOCUMENT_DEPTH:
        raise _too_deep(key, path)
    return data


def read_json(path: str | Path, key: str) -> Any:
    """The JSON document in a file (:func:`parse_json`)."""
    return parse_json(read_text(path, key), key, path)


def parse_yaml(text: str, key: str, path: str | Path) -> Any:
    """The YAML document in ``text`` (read from ``path``) as plain data, through a safe loader that
    refuses a key given twice in one mapping (PyYAML would keep the last one without a word),
    nesting deeper than ``MAX_DOCUMENT_DEPTH``, more than ``MAX_DOCUMENT_NODES`` values with each
    alias counted as what it expands to, and an alias inside its own anchor (a recursive tree);
    VistrackError naming ``key``, the file and the line."""
    import yaml

    from ._bounded_yaml import DocumentTooLarge, bounded_loader

    try:
        return yaml.load(text, Loader=bounded_loader(MAX_DOCUMENT_DEPTH, MAX_DOCUMENT_NODES))
    except DocumentTooLarge as error:
        raise VistrackError(f"{key} = {path}: {error.reason} at line {error.line}") from None
    except yaml.YAMLError as error:
        reason = " ".join(str(error).split())
        raise VistrackError(f"{key} = {path}: not valid YAML ({reason})") from None
    except RecursionError:
        raise _too_deep(key, path) from None
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

