"""Checks shared by the tests of report folders (report.html, trajectory.gif): the page parses,
is self-contained and embeds every figure of report.md; the plotly figure decoded from it; the GIF
has the frames, size and timing asked for."""

from __future__ import annotations

import json
from html.parser import HTMLParser
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

from vistrack.plotting.animation import DEFAULT_DPI, DEFAULT_SIZE_IN

MAX_BYTES = 20e6  # the bound for the Charlotte examples; every report is held to it


class PageParser(HTMLParser):
    """Collects every tag with its attributes and the text of scripts."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.tags: list[tuple[str, dict[str, str]]] = []
        self.scripts: list[str] = []
        self._in_script = False

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append((tag, {k: v or "" for k, v in attrs}))
        self._in_script = tag == "script"
        if self._in_script:
            self.scripts.append("")

    def handle_endtag(self, tag: str) -> None:
        if tag == "script":
            self._in_script = False

    def handle_data(self, data: str) -> None:
        if self._in_script:
            self.scripts[-1] += data


def plotly_figure(page: str) -> dict[str, Any]:
    """data, layout and frames of the page's plotly figure, decoded from its newPlot/addFrames calls."""
    decoder = json.JSONDecoder()

    def arguments(call: str) -> list[Any]:
        at = page.index(call) + len(call)
        at = page.index(",", at) + 1  # after the div id
        values = []
        while page[at:].lstrip()[0] in "[{":
            at += len(page[at:]) - len(page[at:].lstrip())
            value, at = decoder.raw_decode(page, at)
            values.append(value)
            at = page.index(",", at) + 1 if page[at:].lstrip().startswith(",") else at
        return values

    data, layout, *_ = arguments("Plotly.newPlot(")
    frames = arguments("Plotly.addFrames(")[0] if "Plotly.addFrames(" in page else []
    return {"data": data, "layout": layout, "frames": frames}


def check_page(out: Path) -> tuple[PageParser, dict[str, Any]]:
    path = out / "report.html"
    page = path.read_text(encoding="utf-8")
    assert path.stat().st_size < MAX_BYTES
    parser = PageParser()
    parser.feed(page)
    parser.close()
    tags = [t for t, _ in parser.tags]
    assert tags[:2] == ["html", "head"] and "body" in tags and "title" in tags
    # Self-contained: no script, style, image or frame is fetched from anywhere.
    for tag, attrs in parser.tags:
        for key in ("src", "href", "data"):
            value = attrs.get(key, "")
            assert not value.lower().startswith(("http:", "https:", "//")), (tag, key, value[:80])
        if tag == "script":
            assert "src" not in attrs
        if tag == "img":
            assert attrs["src"].startswith(("data:image/png;base64,", "data:image/gif;base64,"))
        assert tag not in ("link", "iframe")
    assert any("Plotly.newPlot" in s for s in parser.scripts)
    assert any(len(s) > 3_000_000 and "plotly" in s.lower() for s in parser.scripts)  # plotly.js itself
    # Every figure of report.md is embedded.
    markdown = (out / "report.md").read_text()
    images = [a["alt"] for t, a in parser.tags if t == "img"]
    for line in markdown.splitlines():
        if line.startswith("!["):
            assert line[2:line.index("]")] in images
    assert f"`report.html` ({path.stat().st_size / 1e6:.1f} MB" in markdown
    return parser, plotly_figure(page)


def check_gif(path: Path, frames: int, duration: float) -> None:
    with Image.open(path) as gif:
        assert gif.n_frames == frames
        assert gif.size == (round(DEFAULT_SIZE_IN * DEFAULT_DPI), round(DEFAULT_SIZE_IN * 1.12 * DEFAULT_DPI))
        assert gif.info["loop"] == 0
        assert gif.info["duration"] == pytest.approx(1000 * duration / frames, abs=10)
        first = np.asarray(gif.convert("RGB"))
        gif.seek(frames - 1)
        last = np.asarray(gif.convert("RGB"))
    assert (first != last).any(axis=2).mean() > 0.001  # the UAV, POI and clock moved
