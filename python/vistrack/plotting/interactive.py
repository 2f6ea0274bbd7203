"""Interactive 3D views (plotly): the city as a mesh, translucent meshes under a slider (visibility
volumes with their VP and orbit), and a :class:`~.motion.MotionScene` with a time slider that
moves every track, the line of sight and the overlays of the moment.

The figure is built as plain plotly JSON (dicts; plotly's graph objects validate every property
and took seconds for a hundred frames), with arrays as plotly.js typed-array specs (base64 float32
/ int32): a Charlotte report's meshes stay a few megabytes. Meshes are kept small by the callers
(VVs recomputed on a coarser direction grid, the city cropped to the scene).
"""

from __future__ import annotations

import base64
import math
from dataclasses import dataclass, field
from typing import Any, Optional, Sequence

import numpy as np

from .._core import Environment, VisibilityOrbitPlan, VisibilityScene
from ..report_options import DEFAULT_VOLUMES
from .common import evenly_spaced_indices
from .motion import OCCLUDED_COLOR, VISIBLE_COLOR, Line, MotionScene, Track, circle_ring, polygon_rings

Trace = dict[str, Any]  # one plotly trace as JSON
DEFAULT_TIME_STEPS = 100  # frames of the time slider
DEFAULT_VOLUME_RESOLUTION_DEG = 3.0  # direction grid of the VVs shown (the plan's are finer)
CITY_COLORSCALE = [[0.0, "#d9d9d9"], [1.0, "#4d5a6a"]]
VOLUME_COLOR = "#31a354"


@dataclass
class MeshLayer:
    """One step of the layer slider: a translucent mesh (e.g. a VV) and lines drawn with it
    (e.g. its VP and orbit at the flight altitude)."""

    label: str
    vertices: np.ndarray
    faces: np.ndarray
    lines: Sequence[Line] = ()
    color: str = VOLUME_COLOR
    opacity: float = 0.35
    notes: list[str] = field(default_factory=list)


def _f32(a: Any) -> dict[str, str]:
    """A plotly.js typed-array spec of float32 (NaN stays NaN: a gap in a line)."""
    return {"dtype": "f4", "bdata": base64.b64encode(np.ascontiguousarray(a, dtype="<f4").tobytes()).decode()}


def _i32(a: Any) -> dict[str, str]:
    return {"dtype": "i4", "bdata": base64.b64encode(np.ascontiguousarray(a, dtype="<i4").tobytes()).decode()}


def decode_array(spec: Any) -> np.ndarray:
    """The numbers of a plotly array (a list or a typed-array spec), e.g. to check a figure."""
    if isinstance(spec, dict) and "bdata" in spec:
        return np.frombuffer(base64.b64decode(spec["bdata"]), dtype=np.dtype(spec["dtype"]).newbyteorder("<"))
    return np.asarray(spec, dtype=float)


def _join_rings(rings: Sequence[np.ndarray], z: float, tolerance: float = 0.0) -> np.ndarray:
    """Closed rings as one (n, 3) polyline, NaN rows between rings (plotly breaks the line there);
    rings simplified to ``tolerance`` metres (shapely) to keep frames small."""
    parts = []
    for ring in rings:
        r = np.asarray(ring, dtype=float)[:, :2]
        if len(r) < 2:
            continue
        if tolerance > 0 and len(r) > 8:
            from shapely.geometry import LinearRing

            simple = LinearRing(r).simplify(tolerance, preserve_topology=False)
            if not simple.is_empty and len(simple.coords) >= 4:
                r = np.asarray(simple.coords)[:-1]
        closed = np.vstack([r, r[:1]])
        parts.append(np.column_stack([closed, np.full(len(closed), z)]))
        parts.append(np.full((1, 3), np.nan))
    return np.vstack(parts) if parts else np.full((1, 3), np.nan)


def _xyz(points: np.ndarray) -> dict[str, Any]:
    p = np.asarray(points, dtype=float)
    return {"x": _f32(p[:, 0]), "y": _f32(p[:, 1]), "z": _f32(p[:, 2])}


def _mesh(vertices: np.ndarray, faces: np.ndarray, **properties: Any) -> Trace:
    f = np.asarray(faces)
    return {"type": "mesh3d", **_xyz(vertices), "i": _i32(f[:, 0]), "j": _i32(f[:, 1]), "k": _i32(f[:, 2]),
            "hoverinfo": "skip", **properties}


def _polyline(points: np.ndarray, color: str, width: float, name: str, dash: str = "solid",
              **properties: Any) -> Trace:
    return {"type": "scatter3d", "mode": "lines", **_xyz(points),
            "line": {"color": _css(color), "width": width, "dash": dash}, "name": name, "hoverinfo": "skip",
            **properties}


def city_trace(env: Environment, extent: Optional[tuple[float, float, float, float]] = None,
               margin: float = 50.0) -> Trace:
    """The environment's triangles (footprint extrusions or the mesh) shaded by height; with
    ``extent`` (xmin, xmax, ymin, ymax), only triangles whose centroid lies within it plus
    ``margin``."""
    vertices, faces = np.asarray(env.vertices), np.asarray(env.faces)
    if extent is not None and len(faces):
        c = vertices[faces].mean(axis=1)
        x0, x1, y0, y1 = extent
        keep = (c[:, 0] >= x0 - margin) & (c[:, 0] <= x1 + margin) & (c[:, 1] >= y0 - margin) & (c[:, 1] <= y1 + margin)
        faces = faces[keep]
    used, inverse = np.unique(faces, return_inverse=True)
    vertices = vertices[used]
    return _mesh(vertices, inverse.reshape(-1, 3), intensity=_f32(vertices[:, 2] - env.ground_level),
                 colorscale=CITY_COLORSCALE, showscale=False, flatshading=True,
                 name=f"buildings ({inverse.size // 3} triangles)", showlegend=True,
                 lighting={"ambient": 0.55, "diffuse": 0.7, "specular": 0.05, "roughness": 0.9},
                 lightposition={"x": 1000, "y": -2000, "z": 3000})


def ground_trace(extent: tuple[float, float, float, float], level: float) -> Trace:
    """A flat light rectangle just under ``level`` over ``extent``."""
    x0, x1, y0, y1 = extent
    z = level - 0.3
    corners = np.array([[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]])
    return _mesh(corners, np.array([[0, 1, 2], [0, 2, 3]]), color="#f4f1ea", name="ground", showlegend=False)


def volume_layers(scene: VisibilityScene, plan: VisibilityOrbitPlan, count: int = DEFAULT_VOLUMES,
                  resolution_deg: float = DEFAULT_VOLUME_RESOLUTION_DEG) -> list[MeshLayer]:
    """Up to ``count`` of the plan's VVs, evenly spread along the path, each recomputed on a
    ``resolution_deg`` direction grid for display (same POI, d_max and band; the plan's own
    grid is used when it is already that coarse), with its VP and orbit at the flight altitude."""
    from .. import _core

    altitude = plan.uav.altitude
    layers = []
    for k in evenly_spaced_indices(len(plan.times), count):
        vv = plan.volume(k)
        grid_deg = 180.0 / vv.grid.num_elevation
        shown = vv if grid_deg >= resolution_deg else _core.visibility_volume(
            scene, vv.poi, vv.d_max, vv.altitude_band, resolution_deg)
        center, radius = plan.centers[k], plan.radii[k]
        lines = [Line(f"VP at {altitude:g} m", _join_rings(polygon_rings(plan.polygons[k]), altitude),
                      color="#238b45", style="-", width=3.0),
                 Line(f"orbit R = {radius:.1f} m", _join_rings([circle_ring(center, radius)], altitude),
                      color="black", style="--", width=4.0)]
        note = (f"VV {k}: {vv.volume / 1e6:.3g}e6 m³, shown at {max(grid_deg, resolution_deg):g}° "
                f"({len(shown.faces)} faces)")
        layers.append(MeshLayer(f"t = {plan.times[k]:.1f} s", shown.vertices, shown.faces, lines, notes=[note]))
    return layers


def _dash(style: str) -> str:
    return {"--": "dash", ":": "dot", "-.": "dashdot"}.get(style, "solid")


def _line_trace(line: Line, visible: bool = True, legend: bool = True) -> Trace:
    return _polyline(line.xyz(), line.color, max(2.0, 2 * line.width), line.label or "", _dash(line.style),
                     showlegend=bool(line.label) and legend, visible=visible)


def _track_traces(track: Track) -> list[Trace]:
    """The track's whole path: one trace, or with a flag, one per value (NaN-separated runs)."""
    xyz = track.xyz()
    if track.flag is None:
        return [_polyline(xyz, track.color, 2 * track.width, f"{track.label} path")]
    traces = []
    for value, color, text in ((True, track.on_color, "in line of sight"), (False, track.off_color, "occluded")):
        mask = track.flag[:-1] == value  # segment i -> i+1 takes point i's flag
        if not mask.any():
            continue
        rows = []
        for start, stop in _runs(mask):
            rows += [xyz[start:stop + 1], np.full((1, 3), np.nan)]
        traces.append(_polyline(np.vstack(rows), color, 2 * track.width, f"{track.label} path, {text}"))
    return traces


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """(start, stop) of each run of True in ``mask``, stop exclusive."""
    edges = np.diff(np.r_[0, mask.astype(np.int8), 0])
    return list(zip(np.flatnonzero(edges == 1).tolist(), np.flatnonzero(edges == -1).tolist()))


def _css(color: str) -> str:
    from matplotlib.colors import to_hex

    return str(to_hex(color))


def figure_3d(scene: MotionScene, layers: Sequence[MeshLayer] = (), time_steps: int = DEFAULT_TIME_STEPS,
              height_px: int = 760) -> dict[str, Any]:
    """The scene in 3D as a plotly figure (JSON dict): the city (cropped to the scene), the static
    lines, every track's path (coloured by its flag), ``layers`` under a slider (one visible at a
    time), and a time slider with play/pause moving the tracks' markers, the line of sight and the
    overlays. Trace names say what each is (tests and readers rely on them)."""
    extent = scene.fit_extent(margin=0.02)
    span = max(extent[1] - extent[0], extent[3] - extent[2])
    traces: list[Trace] = []
    if scene.env is not None:
        traces.append(ground_trace(extent, scene.env.ground_level))
        traces.append(city_trace(scene.env, extent))
    traces += [_line_trace(line) for line in scene.lines]
    for track in scene.tracks:
        traces += _track_traces(track)

    # Layers: one mesh and its lines per slider step; the first visible.
    layer_indices: list[list[int]] = []
    for n, layer in enumerate(layers):
        first = len(traces)
        # All in the legend: plotly lists only the visible layer's (its orbit radius names it).
        traces.append(_mesh(layer.vertices, layer.faces, color=_css(layer.color), opacity=layer.opacity,
                            name="visibility volume", legendgroup="layer", showlegend=True, visible=n == 0,
                            lighting={"ambient": 0.6, "diffuse": 0.6, "specular": 0.1}))
        traces += [_line_trace(line, visible=n == 0) | {"legendgroup": "layer"} for line in layer.lines]
        layer_indices.append(list(range(first, len(traces))))
    if scene.wind is not None:
        traces.append(_wind_trace(scene, extent, span))

    # Moving traces, updated by the frames.
    times = scene.frame_times(time_steps)
    positions = [track.at(times) for track in scene.tracks]
    tolerance = span * 1e-3
    simplified: dict[tuple[int, float], np.ndarray] = {}  # the same rings recur over many frames

    def rings_at(overlay_index: int, time: float) -> np.ndarray:
        overlay = scene.overlays[overlay_index]
        rings = overlay.shapes(time)
        key = (id(rings), overlay.z)
        if key not in simplified:
            simplified[key] = _join_rings(rings, overlay.z, tolerance)
        return simplified[key]

    def moving(i: int) -> list[Trace]:
        time = float(times[i])
        data: list[Trace] = []
        for track, p in zip(scene.tracks, positions):
            data.append({"type": "scatter3d", "mode": "markers", **_xyz(p[i:i + 1]), "name": track.label,
                         "marker": {"size": 7, "color": _css(track.color),
                                    "symbol": "square" if track.marker == "s" else "circle",
                                    "line": {"color": "white", "width": 1}}})
        if scene.sight is not None:
            a, b = positions[scene.sight.observer][i], positions[scene.sight.target][i]
            color = VISIBLE_COLOR if scene.sight.at(time) else OCCLUDED_COLOR
            data.append(_polyline(np.array([a, b]), color, 5, "line of sight"))
        for n, overlay in enumerate(scene.overlays):
            data.append(_polyline(rings_at(n, time), overlay.color, 4, overlay.label, _dash(overlay.style)))
        return data

    moving_first = len(traces)
    traces += moving(0)
    moving_indices = list(range(moving_first, len(traces)))
    title = scene.title or "3D view"
    frames = [{"name": f"f{i}", "traces": moving_indices, "data": moving(i),
               "layout": {"title": {"text": f"{title}: {scene.time_label} = {t:.1f} s"}}}
              for i, t in enumerate(times)]

    sliders = [_time_slider(times, scene.time_label)]
    if layers:
        sliders.append(_layer_slider(layers, layer_indices))
    z_low, z_top = _height_range(scene, positions, layers)
    layout = {
        "height": height_px, "margin": {"l": 0, "r": 0, "t": 40, "b": 0},
        "title": {"text": f"{title}: {scene.time_label} = {times[0]:.1f} s", "x": 0.01, "y": 0.99},
        "legend": {"x": 0.0, "y": 0.8, "bgcolor": "rgba(255,255,255,0.7)", "font": {"size": 11}},
        "scene": {"xaxis": {"title": {"text": "east (m)"}, "range": [extent[0], extent[1]]},
                  "yaxis": {"title": {"text": "north (m)"}, "range": [extent[2], extent[3]]},
                  "zaxis": {"title": {"text": "up (m)"}, "range": [z_low, z_top]},
                  "aspectmode": "manual",
                  "aspectratio": {"x": (extent[1] - extent[0]) / span, "y": (extent[3] - extent[2]) / span,
                                  "z": max(0.2, (z_top - z_low) / span)},
                  "camera": {"eye": {"x": -0.62, "y": -0.88, "z": 1.25}},  # from the south-west, 50° up
                  "domain": {"x": [0.12, 1.0], "y": [0.0, 1.0]}},
        "sliders": sliders,
        "updatemenus": [{
            "type": "buttons", "direction": "left", "x": 0.0, "y": 0.0, "xanchor": "left", "yanchor": "top",
            "pad": {"t": 10, "r": 10},
            "buttons": [
                {"label": "▶ play", "method": "animate",
                 "args": [None, {"frame": {"duration": 120, "redraw": True}, "fromcurrent": True,
                                 "transition": {"duration": 0}}]},
                {"label": "❚❚ pause", "method": "animate",
                 "args": [[None], {"frame": {"duration": 0, "redraw": False}, "mode": "immediate",
                                   "transition": {"duration": 0}}]}]}],
    }
    if scene.credit:
        layout["annotations"] = [{"text": scene.credit, "x": 1.0, "y": 0.0, "xref": "paper", "yref": "paper",
                                  "xanchor": "right", "yanchor": "bottom", "showarrow": False,
                                  "font": {"size": 10, "color": "gray"}}]
    return {"data": traces, "layout": layout, "frames": frames}


def _height_range(scene: MotionScene, positions: Sequence[np.ndarray],
                  layers: Sequence[MeshLayer]) -> tuple[float, float]:
    """The z axis: from the ground (or the lowest line or overlay: AOIs, a camera footprint) to a
    little above the tracks, the lines and the layers' meshes. Taller buildings are cut at the top
    of the box (plotly clips to the axis ranges), so that a low flight among towers stays in view."""
    z = np.concatenate([p[:, 2] for p in positions] + [np.asarray(layer.vertices)[:, 2] for layer in layers]
                       + [line.xyz()[:, 2] for line in scene.lines] + [np.array([o.z for o in scene.overlays])])
    z = z[np.isfinite(z)]
    low, top = float(z.min()), float(z.max())
    if scene.env is not None:
        low = min(low, scene.env.ground_level)
        if not layers:
            top = max(top, scene.env.ground_level + scene.env.max_height)
    return low, low + 1.15 * (top - low) + 1.0


def _time_slider(times: np.ndarray, label: str) -> dict[str, Any]:
    """Animate steps; only about ten carry a label (a hundred labels would overlap), the title
    shows the time of the frame."""
    every = max(1, len(times) // 10)
    steps = [{"method": "animate", "value": f"f{i}",
              "label": f"{t:.0f} s" if i % every == 0 or i == len(times) - 1 else "",
              "args": [[f"f{i}"], {"mode": "immediate", "frame": {"duration": 0, "redraw": True},
                                   "transition": {"duration": 0}}]} for i, t in enumerate(times)]
    return {"active": 0, "steps": steps, "x": 0.12, "len": 0.88, "y": 0.0, "yanchor": "top", "pad": {"t": 10},
            "currentvalue": {"visible": False}, "font": {"size": 10}, "ticklen": 4, "minorticklen": 2}


def _layer_slider(layers: Sequence[MeshLayer], indices: Sequence[Sequence[int]]) -> dict[str, Any]:
    every = [i for group in indices for i in group]
    steps = []
    for n, layer in enumerate(layers):
        shown = set(indices[n])
        steps.append({"method": "restyle", "label": layer.label,
                      "args": [{"visible": [i in shown for i in every]}, every]})
    return {"active": 0, "steps": steps, "x": 0.12, "len": 0.88, "y": 1.0, "yanchor": "top", "pad": {"t": 30},
            "currentvalue": {"prefix": "visibility volume at ", "font": {"size": 12}}, "font": {"size": 10}}


def _wind_trace(scene: MotionScene, extent: tuple[float, float, float, float], span: float) -> Trace:
    """The wind (at the start) as a cone in the north-west corner, its length a tenth of the scene."""
    t0 = scene.time_span()[0]
    east, north = scene.wind_at(t0) or (0.0, 0.0)
    speed = math.hypot(east, north)
    unit = (east / speed, north / speed) if speed > 0 else (0.0, 0.0)
    top = max(float(np.max(tr.xyz()[:, 2])) for tr in scene.tracks)
    return {"type": "cone", "x": [extent[0] + 0.1 * span], "y": [extent[3] - 0.1 * span], "z": [top],
            "u": [unit[0]], "v": [unit[1]], "w": [0.0], "sizemode": "absolute", "sizeref": 0.1 * span,
            "anchor": "tail", "showscale": False, "colorscale": [[0, "purple"], [1, "purple"]],
            "name": f"wind {speed:.2g} m/s", "showlegend": True, "hoverinfo": "name"}
