"""The animated and interactive outputs of any job that moves a vehicle: trajectory.gif (plan
view) and report.html (3D, with the job's report embedded), from one
:class:`~vistrack.plotting.motion.MotionScene` and the job's :class:`~.document.Document`.

A planner's report folder gets both in a few lines::

    from vistrack.plotting.motion import MotionScene, Track, Line, Overlay, sampled, ellipse_ring
    from vistrack.report.document import Document, Picture, Table
    from vistrack.report.media import write_media
    from vistrack.report_options import ReportOptions

    scene = MotionScene(tracks=[Track("UAV", t, xy, z=altitude)], lines=[Line("planned path", path_xy)],
                        overlays=[Overlay("camera footprint", sampled(t, rings))], wind=(0.0, 0.08),
                        title="loiter: LDLPP")
    doc = Document("loiter: LDLPP", summary=["flight time 18.3 min"], blocks=[Picture("plans.png", "Plans")])
    made = write_media(out, scene, doc, ReportOptions())     # trajectory.gif, report.html
    (out / "report.md").write_text(doc.markdown())
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Optional, Sequence

from ..plotting.animation import write_gif
from ..plotting.interactive import MeshLayer, figure_3d
from ..plotting.motion import MotionScene
from ..report_options import ReportOptions
from .document import Document, Heading, Picture, Table
from .html import write_html

GIF_NAME = "trajectory.gif"
HTML_NAME = "report.html"


def write_media(out: Path, scene: MotionScene, document: Document, options: Optional[ReportOptions] = None,
                layers: Sequence[MeshLayer] = (), figure_hint: str = "", gif_caption: str = "",
                gif_name: str = GIF_NAME, more_gifs: Sequence[tuple[str, MotionScene, str]] = ()
                ) -> dict[str, dict[str, float]]:
    """Write ``gif_name`` and report.html into ``out`` as ``options`` ask (default: both).

    The GIF is added to ``document`` as a picture (after its last picture), a "Report files"
    table (sizes, seconds) is appended, and once report.html is written its size joins the
    summary, so that ``document.markdown()`` afterwards describes both files. ``more_gifs``
    (file name, scene, title) are further animations written with the same options and placed
    after the first. Returns ``{file name: {"bytes": ..., "seconds": ...}}`` (also for the
    metrics file)."""
    options = options or ReportOptions()
    out.mkdir(parents=True, exist_ok=True)
    made: dict[str, dict[str, float]] = {}
    if options.animation:
        last = max((i for i, b in enumerate(document.blocks) if isinstance(b, Picture)), default=None)
        at = len(document.blocks) if last is None else last + 1
        animations = [(gif_name, scene, "Animation", gif_caption), *((n, s, t, "") for n, s, t in more_gifs)]
        for name, shown, title, caption in animations:
            began = time.perf_counter()
            path = write_gif(shown, out / name, options.frames, options.duration)
            made[name] = {"bytes": path.stat().st_size, "seconds": time.perf_counter() - began,
                          "frames": options.frames}
            document.blocks.insert(at, Picture(name, title, caption or
                                               f"Plan view, {options.frames} frames over {options.duration:g} s."))
            at += 1
    rows: list[list[str]] = []  # the "Report files" table, shared with the document

    def row(name: str) -> list[str]:
        return [name, f"{made[name]['bytes'] / 1e6:.2f}", f"{made[name]['seconds']:.2f}"]

    if made:
        rows += [row(name) for name in made]
        document.blocks += [Heading("Report files"), Table(["file", "size (MB)", "seconds to write"], rows)]
    if options.html:
        began = time.perf_counter()
        figure = figure_3d(scene, layers)
        path = write_html(out / HTML_NAME, document, figure, out, figure_hint)
        made[HTML_NAME] = {"bytes": path.stat().st_size, "seconds": time.perf_counter() - began}
        document.summary.append(f"Interactive 3D view: `{HTML_NAME}` ({made[HTML_NAME]['bytes'] / 1e6:.1f} MB, "
                                "self-contained, opens offline)")
        rows.append(row(HTML_NAME))
        if len(rows) == 1:
            document.blocks += [Heading("Report files"), Table(["file", "size (MB)", "seconds to write"], rows)]
    return made
