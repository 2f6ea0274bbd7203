"""report.html: one self-contained page (it opens offline) holding an interactive 3D figure
(plotly, its JavaScript inlined), the report's summary, tables and figures (PNG and GIF files of
the report folder embedded as data URIs).

Every job renders the same :class:`~.document.Document` it writes as report.md::

    doc = Document("loiter: ldlpp", summary=[...], blocks=[Table(...), Picture("plans.png", "Plans")])
    figure = figure_3d(scene)                      # plotting.interactive, from a MotionScene
    write_html(out / "report.html", doc, figure, folder=out)
"""

from __future__ import annotations

import base64
import html
import re
from pathlib import Path
from typing import Any, Mapping, Optional

from .document import Document, Heading, Picture, Table

SIZE_MARK = "@@REPORT_SIZE@@"  # replaced by the page's own size once it is known
MIME = {".png": "image/png", ".gif": "image/gif", ".jpg": "image/jpeg", ".jpeg": "image/jpeg"}

STYLE = """
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, sans-serif; margin: 0 auto; max-width: 1500px;
       padding: 0 18px 40px; color: #222; }
h1 { font-size: 1.45em; margin: 14px 0 6px; }
h2 { font-size: 1.15em; margin: 28px 0 8px; border-bottom: 1px solid #ddd; padding-bottom: 3px; }
.figure3d { border: 1px solid #e3e3e3; border-radius: 4px; }
.hint { color: #666; font-size: 0.9em; margin: 4px 0 10px; }
table { border-collapse: collapse; margin: 8px 0; font-size: 0.93em; }
th, td { border: 1px solid #d6d6d6; padding: 3px 9px; text-align: left; }
th { background: #f3f3f3; }
img { max-width: 100%; border: 1px solid #eee; }
figure { margin: 0 0 10px; }
figcaption { color: #555; font-size: 0.92em; margin-top: 4px; }
code { background: #f4f4f4; padding: 0 3px; border-radius: 3px; }
footer { color: #888; font-size: 0.85em; margin-top: 30px; }
"""


def inline(text: str) -> str:
    """The Markdown subset of a report's text as HTML: escaped, with `code` and **bold**."""
    out = html.escape(text, quote=False)
    out = re.sub(r"`([^`]+)`", r"<code>\1</code>", out)
    return re.sub(r"\*\*([^*]+)\*\*", r"<strong>\1</strong>", out)


def _paragraph(text: str) -> str:
    lines = text.splitlines()
    if lines and all(line.startswith("- ") for line in lines):
        return "<ul>" + "".join(f"<li>{inline(line[2:])}</li>" for line in lines) + "</ul>"
    return f"<p>{inline(text)}</p>"


def _table(table: Table) -> str:
    head = "".join(f"<th>{inline(c)}</th>" for c in table.header)
    body = "".join("<tr>" + "".join(f"<td>{inline(c)}</td>" for c in row) + "</tr>" for row in table.rows)
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _picture(picture: Picture, folder: Path) -> str:
    path = folder / picture.file
    title = f"<h2>{inline(picture.title)}</h2>"
    if not path.is_file():
        return title + f"<p class='hint'>({html.escape(picture.file)} was not written)</p>"
    data = base64.b64encode(path.read_bytes()).decode()
    mime = MIME.get(path.suffix.lower(), "application/octet-stream")
    caption = f"<figcaption>{inline(picture.caption)}</figcaption>" if picture.caption else ""
    return (f"{title}<figure><img alt='{html.escape(picture.title, quote=True)}' "
            f"src='data:{mime};base64,{data}'>{caption}</figure>")


def figure_html(figure: Mapping[str, Any], height_px: int = 760) -> str:
    """The plotly figure (JSON dict) as a div with plotly.js inlined (no network access)."""
    import plotly.io as pio

    config = {"displaylogo": False, "responsive": True, "scrollZoom": True,
              "toImageButtonOptions": {"format": "png", "scale": 2}}
    return str(pio.to_html(dict(figure), include_plotlyjs=True, full_html=False, auto_play=False, validate=False,
                           config=config, default_height=f"{height_px}px", div_id="figure3d"))


def render_html(document: Document, figure: Optional[Mapping[str, Any]], folder: Path,
                figure_hint: str = "") -> str:
    """The page as a string (``SIZE_MARK`` still in its footer)."""
    parts = ["<!DOCTYPE html>", "<html lang='en'><head><meta charset='utf-8'>",
             "<meta name='viewport' content='width=device-width, initial-scale=1'>",
             f"<title>{html.escape(document.title)}</title><style>{STYLE}</style></head><body>",
             f"<h1>{inline(document.title)}</h1>"]
    if figure is not None:
        if figure_hint:
            parts.append(f"<p class='hint'>{inline(figure_hint)}</p>")
        parts.append(f"<div class='figure3d'>{figure_html(figure)}</div>")
    if document.summary:
        parts.append("<h2>Summary</h2>" + _paragraph("\n".join(f"- {s}" for s in document.summary)))
    for block in document.blocks:
        if isinstance(block, Heading):
            parts.append(f"<h2>{inline(block.text)}</h2>")
        elif isinstance(block, Table):
            parts.append(_table(block))
        elif isinstance(block, Picture):
            parts.append(_picture(block, folder))
        else:
            parts.append(_paragraph(block))
    parts.append(f"<footer>vistrack report; this page is self-contained ({SIZE_MARK}) and opens offline."
                 "</footer></body></html>")
    return "\n".join(parts)


def write_html(path: Path, document: Document, figure: Optional[Mapping[str, Any]] = None,
               folder: Optional[Path] = None, figure_hint: str = "") -> Path:
    """Write report.html (``folder``: where the pictures are; default the page's folder)."""
    path = Path(path)
    page = render_html(document, figure, Path(folder) if folder is not None else path.parent, figure_hint)
    size = len(page.encode("utf-8"))
    path.write_text(page.replace(SIZE_MARK, f"{size / 1e6:.1f} MB"), encoding="utf-8")
    return path
