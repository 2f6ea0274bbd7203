"""The YAML loader behind :func:`.documents.parse_yaml`: PyYAML's SafeLoader with its composer
hooked to bound a document while it is read. Each node's size (its values, aliases expanded) and
height (levels of lists and mappings below it, aliases expanded) are added up as the composer builds
the node tree, where an alias is still one shared node: a "billion laughs" file, or a chain of
aliases each nesting the one before, is refused after reading a few lines of it, never expanded.
Merge keys (``<<: *base``) are aliases too, so a merge bomb is counted the same way."""

from __future__ import annotations

from typing import Any

import yaml

from ..preview import preview

__all__ = ["DocumentTooLarge", "bounded_loader"]


class DocumentTooLarge(yaml.YAMLError):
    """A document past a limit: ``reason`` and the 1-based ``line`` where it was found."""

    def __init__(self, reason: str, mark: Any) -> None:
        super().__init__(reason)
        self.reason = reason
        self.line = mark.line + 1 if mark is not None else None


def bounded_loader(max_depth: int, max_nodes: int) -> type[yaml.SafeLoader]:
    """A SafeLoader class refusing a key given twice in one mapping, nesting deeper than
    ``max_depth`` lists and mappings, more than ``max_nodes`` values and an alias inside its own
    anchor (a recursive tree), aliases expanded in each count."""

    class BoundedLoader(yaml.SafeLoader):
        def __init__(self, stream: Any) -> None:
            super().__init__(stream)
            self._depth = 0  # lists and mappings open around the node being composed
            self._nodes = 0  # values composed so far, aliases expanded
            self._below: list[int] = []  # per open list or mapping: the greatest height of its children
            self._anchored: dict[str, tuple[int, int]] = {}  # anchor -> (size, height) of its finished node

        def _finished(self, size: int, height: int, mark: Any) -> None:
            self._nodes += size
            if self._nodes > max_nodes:
                raise DocumentTooLarge(f"more than {max_nodes} values, each alias counted as what it stands for "
                                       "(the limit for an input document)", mark)
            if self._depth + height > max_depth:
                raise DocumentTooLarge(f"nested deeper than {max_depth} levels, aliases expanded (the limit for an "
                                       "input document)", mark)
            if self._below:
                self._below[-1] = max(self._below[-1], height)

        def compose_node(self, parent: Any, index: Any) -> Any:
            event = self.peek_event()
            if isinstance(event, yaml.AliasEvent):
                node = super().compose_node(parent, index)  # an undefined alias is PyYAML's error
                if event.anchor not in self._anchored:
                    raise DocumentTooLarge(f"the alias *{event.anchor} is inside its own anchor (a recursive tree)",
                                           event.start_mark)
                self._finished(*self._anchored[event.anchor], event.start_mark)
                return node
            self._anchored.pop(event.anchor, None)  # redefined: the new node's counts apply
            container = isinstance(event, (yaml.SequenceStartEvent, yaml.MappingStartEvent))
            if container:
                self._depth += 1
                if self._depth > max_depth:
                    raise DocumentTooLarge(f"nested deeper than {max_depth} levels (the limit for an input document)",
                                           event.start_mark)
                self._below.append(0)
            before = self._nodes
            node = super().compose_node(parent, index)
            height = 0
            if container:
                height = 1 + self._below.pop()
                self._depth -= 1
            size = self._nodes - before + 1
            self._nodes = before
            self._finished(size, height, event.start_mark)
            if event.anchor is not None:
                self._anchored[event.anchor] = (size, height)
            return node

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
                        f"found the key {preview(name)} twice (a YAML key is given once)", key_node.start_mark)
                seen.add(name)
            return super().construct_mapping(node, deep)

    return BoundedLoader
