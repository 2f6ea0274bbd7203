"""A value quoted in a message, cut short without ever building its whole text: a value read from
a file may be a list of a million items or, through YAML aliases, a tree of a billion nodes, whose
``repr`` would exhaust memory before it could be cut. :func:`preview` walks only as many items as
it prints, and gives ``repr``'s text for a value that fits."""

from __future__ import annotations

import math
from typing import Any

__all__ = ["PREVIEW_CHARACTERS", "preview"]

PREVIEW_CHARACTERS = 80  # the longest quote of a value in a message, "..." included
_DEEPEST = 12  # containers below this depth are quoted as [...] or {...}


class _Full(Exception):
    """The preview has all the characters it may hold."""


class _Writer:
    def __init__(self, limit: int) -> None:
        self.parts: list[str] = []
        self.size = 0
        self.limit = limit

    def write(self, text: str) -> None:
        self.parts.append(text)
        self.size += len(text)
        if self.size > self.limit:
            raise _Full

    def value(self, item: Any, depth: int) -> None:
        if isinstance(item, (str, bytes, bytearray)):
            self.write(repr(item[: self.limit + 1]))  # cut before quoting: a str of 1 GB is never copied
        elif isinstance(item, int) and not isinstance(item, bool) and item.bit_length() > 4 * self.limit:
            digits = int(item.bit_length() * math.log10(2)) + 1  # str() refuses above 4300 digits
            self.write(f"<an integer of about {digits} digits>")
        elif isinstance(item, (set, frozenset)) and not item:
            self.write(repr(item))  # set(), frozenset()
        elif isinstance(item, frozenset):
            self.write("frozenset(")
            self.container(item, depth)
            self.write(")")
        elif isinstance(item, (list, tuple, dict, set)):
            self.container(item, depth)
        else:
            self.write(repr(item))

    def container(self, item: Any, depth: int) -> None:
        opening, closing = ("[", "]") if isinstance(item, list) else ("(", ")") if isinstance(item, tuple) else "{}"
        if depth >= _DEEPEST and len(item):
            self.write(f"{opening}...{closing}")
            return
        self.write(opening)
        for k, entry in enumerate(item.items() if isinstance(item, dict) else item):
            if k:
                self.write(", ")
            if isinstance(item, dict):
                self.value(entry[0], depth + 1)
                self.write(": ")
                entry = entry[1]
            self.value(entry, depth + 1)
        if isinstance(item, tuple) and len(item) == 1:
            self.write(",")
        self.write(closing)


def preview(value: Any, limit: int = PREVIEW_CHARACTERS) -> str:
    """``repr(value)`` when it has at most ``limit`` characters, else its first ``limit - 3`` and
    "..." (an integer too long to show: its number of digits), built from at most about ``limit``
    items of the value (lists, tuples, dicts and sets are walked item by item, at most 12 levels
    deep; strings and bytes cut before they are quoted)."""
    writer = _Writer(limit)
    try:
        writer.value(value, 0)
    except _Full:
        pass
    text = "".join(writer.parts)
    return text if len(text) <= limit else text[: limit - 3] + "..."
