"""A report's content, once, for both of its renderings: report.md (:meth:`Document.markdown`)
and report.html (:func:`.html.write_html`).

Text is a small Markdown subset that both render: paragraphs, ``- `` bullet lists and
```code``` spans; tables and pictures (figure files in the report folder) are blocks of their own.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Sequence, Union


@dataclass
class Table:
    """A table of text cells."""

    header: Sequence[str]
    rows: Sequence[Sequence[str]]

    def markdown(self) -> list[str]:
        return (["| " + " | ".join(self.header) + " |", "|" + "---|" * len(self.header)]
                + ["| " + " | ".join(row) + " |" for row in self.rows])


@dataclass
class Picture:
    """A figure file of the report folder (PNG or GIF) with its title and caption."""

    file: str
    title: str
    caption: str = ""


@dataclass
class Heading:
    text: str


Block = Union[str, Table, Picture, Heading]  # str: a paragraph or a "- " bullet list


@dataclass
class Document:
    """Title, a summary (bullet lines shown first) and the blocks that follow in order."""

    title: str
    summary: list[str] = field(default_factory=list)
    blocks: list[Block] = field(default_factory=list)

    def markdown(self) -> str:
        lines = [f"# {self.title}", ""]
        lines += [f"- {item}" for item in self.summary]
        for block in self.blocks:
            lines.append("")
            if isinstance(block, Heading):
                lines.append(f"## {block.text}")
            elif isinstance(block, Table):
                lines += block.markdown()
            elif isinstance(block, Picture):
                lines += [f"## {block.title}", "", f"![{block.title}]({block.file})"]
                if block.caption:
                    lines += ["", block.caption]
            else:
                lines.append(block)
        return "\n".join(lines) + "\n"


def vehicle_line(uav: dict, smoothness: dict | None) -> str:
    """The vehicle model a flight used and how smoothly it banked (the ``uav`` and ``smoothness``
    entries of metrics.json), as one summary line."""
    if uav.get("dynamics") == "roll":
        model = (f"roll model (bank a state: time constant {uav['roll_time_constant']:g} s, at most "
                 f"{uav['max_roll_rate_deg_s']:g} deg/s)")
    else:
        model = "Dubins model (the turn rate follows the command at once, the papers' vehicle)"
    if not smoothness:
        return f"Vehicle: {model}"
    return (f"Vehicle: {model}; bank {smoothness['bank_rms_deg']:.1f} deg RMS about its 5 s mean, "
            f"{smoothness['roll_reversals_per_s']:.2f} roll reversals/s, largest roll rate "
            f"{smoothness['max_roll_rate_deg_s']:.0f} deg/s")
