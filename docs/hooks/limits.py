"""MkDocs hook: the limits page's tables, read from cpp/include/vistrack/limits.hpp at build time.

The header is the one place the ranges are decided; the page shows them without a copy that
could go stale. The marker ``<!-- limits.hpp -->`` in docs/limits.md is replaced by the header's
range table, its reasons and its constants. If the header's shape changes so that a part is no
longer found, the build stops with an error instead of publishing an empty table.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from mkdocs.exceptions import PluginError

HEADER = Path("cpp/include/vistrack/limits.hpp")
MARKER = "<!-- limits.hpp -->"
PAGE = "limits.md"

# "//   speeds (v, v_g, pursuer, target)        [1e-6, 1e4] m/s": a description, two or more
# spaces, a range. Continuation rows are indented deeper and belong to the row above's group
# ("guidance gains: beta ..." then "k_psi ...").
ROW = re.compile(r"^//(?P<indent> {2,})(?P<input>\S.*?) {2,}(?P<range>\S.*)$")
CONSTANT = re.compile(r"^inline constexpr (?:double|int) (?P<name>k\w+) = (?P<value>[^;]+);\s*(?://\s*(?P<note>.*))?$")


def _cell(text: str) -> str:
    return text.replace("|", "\\|").strip()


def _comment_lines(source: str) -> list[str]:
    lines = []
    for line in source.splitlines():
        if not line.startswith("//"):
            break
        lines.append(line)
    return lines


def parse_ranges(comment: list[str]) -> list[tuple[str, str]]:
    rows: list[tuple[str, str]] = []
    base_indent, group = None, ""
    for line in comment:
        match = ROW.match(line)
        if not match:
            continue
        indent = len(match["indent"])
        text = match["input"]
        if base_indent is None or indent <= base_indent:
            base_indent = indent
            group = text.split(": ", 1)[0] + ": " if ": " in text else ""
        else:
            text = group + text
        rows.append((text, match["range"]))
    return rows


def parse_reasons(comment: list[str]) -> str:
    text = " ".join(line[2:].strip() for line in comment)
    start = text.find("Why: ")
    return text[start + len("Why: "):].strip() if start >= 0 else ""


def parse_constants(source: str) -> list[tuple[str, str, str]]:
    found = (CONSTANT.match(line.strip()) for line in source.splitlines())
    return [(m["name"], m["value"].strip(), (m["note"] or "").strip()) for m in found if m]


def render(source: str) -> str:
    comment = _comment_lines(source)
    ranges, reasons, constants = parse_ranges(comment), parse_reasons(comment), parse_constants(source)
    missing = [name for name, part in (("the range table", ranges), ("the 'Why:' paragraph", reasons),
                                       ("the constexpr constants", constants)) if not part]
    if missing:
        raise PluginError(f"docs/hooks/limits.py: {HEADER} no longer has the shape this hook reads; "
                          f"not found: {', '.join(missing)}")
    out = ["| input | range |", "| --- | --- |"]
    out += [f"| {_cell(text)} | {_cell(span)} |" for text, span in ranges]
    out += ["", f"Why these ranges ({HEADER}): {reasons}", "",
            "The constants (namespace `vistrack::limits`):", "", "| constant | value | unit or use |",
            "| --- | --- | --- |"]
    out += [f"| `{name}` | `{value}` | {_cell(note)} |" for name, value, note in constants]
    return "\n".join(out)


def on_page_markdown(markdown: str, page: Any, config: Any, **kwargs: Any) -> str:
    if page.file.src_uri != PAGE:
        return markdown
    if MARKER not in markdown:
        raise PluginError(f"docs/hooks/limits.py: docs/{PAGE} lost its marker {MARKER}")
    header = Path(config.config_file_path).parent / HEADER
    return markdown.replace(MARKER, render(header.read_text(encoding="utf-8")))
