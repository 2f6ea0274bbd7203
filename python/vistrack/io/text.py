"""Text files in and out: UTF-8 text, JSON results and YAML documents (a key given twice in one
mapping is an error, not the last one silently kept). Errors name the key and the file."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from .._core import VistrackError

__all__ = ["append_json_line", "parse_yaml", "read_text", "read_yaml_mapping", "write_json"]


def read_text(path: str | Path, key: str) -> str:
    """The UTF-8 text of a file; VistrackError naming ``key`` when it is missing, a folder,
    unreadable or not UTF-8 text."""
    file = Path(path)
    if file.is_dir():
        raise VistrackError(f"{key} = {path}: is a folder, not a file")
    try:
        return file.read_text(encoding="utf-8")
    except OSError as error:
        raise VistrackError(f"{key} = {path}: cannot read the file ({error.strerror})") from None
    except UnicodeDecodeError as error:
        raise VistrackError(f"{key} = {path}: not UTF-8 text (byte {error.start})") from None


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
    """One JSON document as one line at the end of a file (rows of a sweep as they arrive)."""
    with Path(path).open("a", encoding="utf-8") as stream:
        stream.write(json.dumps(data) + "\n")
