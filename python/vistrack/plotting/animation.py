"""Plan-view animations of a :class:`~.motion.MotionScene` as looping GIFs (matplotlib on Agg,
frames written by Pillow: no ffmpeg).

The static part (buildings, paths, legend, axes) is drawn once; every frame restores that
background and draws only the moving artists (Agg blitting), then Pillow quantizes it to a
palette. matplotlib's ``FuncAnimation.save`` with its ``PillowWriter`` redraws the whole figure
twice per frame (about 0.2 s per frame over the demo city, 6 s for 30 frames); blitting costs
a few milliseconds per frame.
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path
from typing import Any, Union

import numpy as np

from ..report_options import DEFAULT_DURATION_S, DEFAULT_FRAMES
from .city import footprint_path, plot_buildings
from .common import pyplot
from .motion import OCCLUDED_COLOR, VISIBLE_COLOR, MotionScene, Track

# Size of the GIF's frames (frames and duration: report_options).
DEFAULT_SIZE_IN = 5.5
DEFAULT_DPI = 90


def _draw_static(ax: Any, scene: MotionScene) -> list[Any]:
    """Buildings, static paths and legend proxies for the moving parts; returns legend handles."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    handles: list[Any] = []
    if scene.env is not None:
        plot_buildings(ax, scene.env, cmap="Greys", edgecolor="none", vmax=1.6 * max(scene.env.max_height, 1.0))
    for line in scene.lines:
        xy = np.asarray(line.xy, dtype=float)[:, :2]
        if line.fill:
            ax.fill(xy[:, 0], xy[:, 1], color=line.color, alpha=0.25, lw=0, zorder=1)
        ax.plot(xy[:, 0], xy[:, 1], color=line.color, ls=line.style, lw=line.width, zorder=2, label=line.label)
        if line.label:
            handles.append(Line2D([], [], color=line.color, ls=line.style, lw=line.width, label=line.label))
    if any(track.flag is not None for track in scene.tracks) or scene.sight is not None:
        handles += [Line2D([], [], color=VISIBLE_COLOR, lw=2, label="in line of sight"),
                    Line2D([], [], color=OCCLUDED_COLOR, lw=2, label="occluded")]
    if scene.sight is not None:
        handles.append(Line2D([], [], color="0.3", lw=2, ls=(0, (4, 2)), label="line of sight"))
    for overlay in scene.overlays:
        if overlay.fill:
            handles.append(Patch(facecolor=overlay.color, alpha=0.3, edgecolor=overlay.color, label=overlay.label))
        else:
            handles.append(Line2D([], [], color=overlay.color, ls=overlay.style, lw=1.2, label=overlay.label))
    for track in scene.tracks:
        handles.append(Line2D([], [], color=track.color, marker=track.marker, ls="-", lw=1, ms=7,
                              markeredgecolor="white", label=track.label))
    return handles


def _rgba(color: str) -> np.ndarray:
    from matplotlib.colors import to_rgba

    return np.asarray(to_rgba(color))


def write_gif(scene: MotionScene, path: Union[str, Path], frames: int = DEFAULT_FRAMES,
              duration: float = DEFAULT_DURATION_S, size: float = DEFAULT_SIZE_IN, dpi: int = DEFAULT_DPI) -> Path:
    """Animate ``scene`` in plan view into a looping GIF of ``frames`` frames lasting ``duration``
    seconds, ``size`` inches wide at ``dpi``. Returns the path."""
    from matplotlib.collections import LineCollection
    from matplotlib.patches import PathPatch

    if frames < 2:
        raise ValueError(f"frames = {frames}: must be at least 2")
    if not duration > 0:
        raise ValueError(f"duration = {duration}: must be > 0 s")
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(size, size * 1.12), dpi=dpi, layout="constrained")  # legend below
    handles = _draw_static(ax, scene)
    x0, x1, y0, y1 = scene.fit_extent()
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    ax.tick_params(labelsize=7)
    if scene.title:
        ax.set_title("\n".join(textwrap.wrap(scene.title, 90)), fontsize=8)
    if handles:
        fig.legend(handles=handles, loc="outside lower center", ncol=min(3, len(handles)), fontsize=7,
                   frameon=False)
    if scene.credit:
        fig.text(0.99, 0.005, scene.credit, ha="right", va="bottom", fontsize=5.5, color="gray")

    # Moving artists are "animated": left out of the full draw, drawn over the saved background.
    moving: list[Any] = []
    trails, markers = [], []
    for track in scene.tracks:
        trails.append(ax.add_collection(LineCollection([], colors=track.color, linewidths=track.width, alpha=0.9,
                                                       zorder=6, animated=True)))
        markers.append(ax.plot([], [], marker=track.marker, color=track.color, ms=8, markeredgecolor="white",
                               ls="none", zorder=8, animated=True)[0])
    sight_line = ax.plot([], [], lw=2.2, ls=(0, (4, 2)), zorder=7, animated=True)[0]  # dashed: not a trail
    clock = ax.text(0.02, 0.98, "", transform=ax.transAxes, va="top", fontsize=8, zorder=9, animated=True,
                    bbox={"facecolor": "white", "alpha": 0.8, "edgecolor": "none"})
    wind_arrow = wind_text = None
    if scene.wind is not None:
        wind_arrow = ax.quiver([0.9], [0.9], [0.0], [0.0], transform=ax.transAxes, color="tab:purple", zorder=9,
                               scale=1.0, scale_units="width", width=0.008, animated=True)
        wind_text = ax.text(0.9, 0.82, "", transform=ax.transAxes, ha="center", va="top", fontsize=7,
                            color="tab:purple", zorder=9, animated=True)
    canvas = fig.canvas
    canvas.draw()
    background = canvas.copy_from_bbox(fig.bbox)

    times = scene.frame_times(frames)
    positions = [track.at(times) for track in scene.tracks]
    images = []
    for i, time in enumerate(times):
        canvas.restore_region(background)
        moving = []
        for overlay in scene.overlays:
            rings = [np.asarray(r)[:, :2] for r in overlay.shapes(float(time)) if len(r) >= 3]
            if rings:
                # One compound path: holes (opposite orientation) stay open under the nonzero rule.
                patch = PathPatch(footprint_path(rings[0], rings[1:]), zorder=4 if overlay.fill else 5,
                                  facecolor=overlay.color if overlay.fill else "none",
                                  alpha=0.3 if overlay.fill else 0.9, edgecolor=overlay.color,
                                  ls=overlay.style, lw=1.2, animated=True)
                moving.append(ax.add_artist(patch))
        for track, p, marker, trail in zip(scene.tracks, positions, markers, trails):
            _set_trail(trail, track, float(time), p[i, :2])
            marker.set_data([p[i, 0]], [p[i, 1]])
        if scene.sight is not None:
            a, b = positions[scene.sight.observer][i], positions[scene.sight.target][i]
            sight_line.set_data([a[0], b[0]], [a[1], b[1]])
            sight_line.set_color(VISIBLE_COLOR if scene.sight.at(float(time)) else OCCLUDED_COLOR)
            moving.append(sight_line)
        clock.set_text(f"{scene.time_label} = {time:.1f} s")
        moving += [*trails, *markers, clock]
        wind = scene.wind_at(float(time))
        if wind_arrow is not None and wind_text is not None and wind is not None:
            speed = math.hypot(*wind)
            unit = (wind[0] / speed, wind[1] / speed) if speed > 0 else (0.0, 0.0)
            wind_arrow.set_UVC([0.08 * unit[0]], [0.08 * unit[1]])
            wind_text.set_text(f"wind {speed:.2g} m/s")
            moving += [wind_arrow, wind_text]
        for artist in sorted(moving, key=lambda a: a.get_zorder()):
            ax.draw_artist(artist)
        images.append(_to_palette(canvas))
        for artist in moving:
            if isinstance(artist, PathPatch):
                artist.remove()
    plt.close(fig)
    images[0].save(path, save_all=True, append_images=images[1:], duration=round(1000 * duration / frames),
                   loop=0, optimize=False)
    return path


def _set_trail(trail: Any, track: Track, time: float, now: np.ndarray) -> None:
    """The track's path from ``time - track.trail`` (or its start) to ``now``, one polyline per run
    of equal flag (a path per sample segment made each frame cost 40 ms)."""
    first = 0 if track.trail is None else int(np.searchsorted(track.t, time - track.trail))
    last = int(np.searchsorted(track.t, time, side="right"))  # samples before or at time
    xy = np.vstack([track.xy[first:last, :2], now[None, :]])
    if len(xy) < 2:
        trail.set_segments([])
        return
    if track.flag is None:
        trail.set_segments([xy])
        return
    flag = track.flag[first:last] if last > first else track.flag[:1]
    flag = np.append(flag, flag[-1])[: len(xy) - 1]  # segment i -> i+1 takes flag[i]
    starts = np.flatnonzero(np.r_[True, flag[1:] != flag[:-1]])
    stops = np.r_[starts[1:], len(flag)]
    trail.set_segments([xy[a:b + 1] for a, b in zip(starts, stops)])
    trail.set_color([_rgba(track.on_color) if flag[a] else _rgba(track.off_color) for a in starts])


def _to_palette(canvas: Any) -> Any:
    """The canvas as a 255-colour palette image (Pillow's fast octree, no dithering)."""
    from PIL import Image

    width, height = canvas.get_width_height(physical=True)
    rgba = Image.frombuffer("RGBA", (width, height), canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
    return rgba.convert("RGB").quantize(colors=255, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE)
