"""Visibility volumes from Python: the Embree scene is built once per environment and reused.

``visibility_volume`` and ``visibility_volumes`` accept either an :class:`Environment` (a scene
is built for the call) or a :class:`VisibilityScene` (built once: the fast path for many VVs).
"""

from __future__ import annotations

import ctypes
import math
import sys
from dataclasses import dataclass
from typing import Any, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core, schema
from ._core import Environment, Planning, PoiMotion, PoiPath, VisibilityScene, VisibilityVolume

Band = Optional[Tuple[float, float]]


def keep_freed_memory(max_bytes: int = 1 << 30) -> bool:
    """Let this process keep the memory it frees for reuse instead of handing it back to the kernel
    (glibc's malloc: blocks up to 32 MiB come from the heap, and up to ``max_bytes`` of free heap
    stay in the process). Each VV writes 4-5 MB of new arrays (intervals, mesh, slot offsets);
    with glibc's defaults what a batch frees goes back to the kernel, and the next batch pays a page
    fault per 4 KB again. Measured on Charlotte (1-degree VVs in batches of 10, 2 cores, quiet;
    bench/keep_freed_memory.py): 214 -> 265 VVs/s. Process-wide, for the rest of the process's
    life, so the library never calls it itself; the ``vistrack`` command does, in its own process
    (not in the Dask workers of a sweep). The same as starting Python with
    ``GLIBC_TUNABLES=glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=<max_bytes>``.
    True when glibc took both settings; False off Linux, where the C library has no mallopt, or
    where it refused a setting (an allocator that ignores mallopt, such as AddressSanitizer's,
    returns 0)."""
    max_bytes = schema.integer("max_bytes", max_bytes, 0, 2**31 - 1)  # mallopt takes a C int
    if not sys.platform.startswith("linux"):
        return False
    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError, TypeError):
        return False
    mallopt.argtypes = [ctypes.c_int, ctypes.c_int]
    mallopt.restype = ctypes.c_int
    m_trim_threshold, m_mmap_threshold = -1, -3  # <malloc.h>; glibc returns 1 on success
    return mallopt(m_mmap_threshold, 32 << 20) == 1 and mallopt(m_trim_threshold, max_bytes) == 1


def visibility_scene(env: Union[Environment, VisibilityScene]) -> VisibilityScene:
    """The Embree scene of ``env`` (a scene is returned as it is). Building one costs a BVH build
    (about 6 ms for 8k triangles): make it once and pass it for many VVs."""
    if isinstance(env, VisibilityScene):
        return env
    if not isinstance(env, Environment):
        raise TypeError(f"env must be a vistrack.Environment or VisibilityScene, not {type(env).__name__}")
    return VisibilityScene(env)


def visibility_volume(
    env: Union[Environment, VisibilityScene],
    g: Sequence[float],
    d_max: float,
    altitude_band: Band = None,
    resolution_deg: float = Planning().resolution_deg,
    with_mesh: bool = True,
) -> VisibilityVolume:
    """Visibility volume alpha(g) of eq. (4): the points within ``d_max`` of the POI ``g`` (x, y, z),
    inside ``altitude_band`` = (h_lo, h_hi) of world z when given, with a clear line of sight.

    The result holds the per-direction intervals (``near``, ``far`` on ``grid``), a closed,
    outward-oriented triangle mesh (``vertices``, ``faces``), its ``volume``, ``slice(h)`` and
    ``save(path)``. ``with_mesh=False`` leaves the mesh out (``has_mesh`` is False): the same
    intervals and volume for less work; what reads the mesh then raises VistrackError (beyond
    the paper). Raises VistrackError naming the field for bad input.
    """
    return _core.visibility_volume(
        visibility_scene(env), np.asarray(g, dtype=float), float(d_max), altitude_band, float(resolution_deg),
        schema.boolean("with_mesh", with_mesh),
    )


def visibility_volumes(
    env: Union[Environment, VisibilityScene],
    pois: np.ndarray,
    d_max: float,
    altitude_band: Band = None,
    resolution_deg: float = Planning().resolution_deg,
    with_mesh: bool = True,
) -> list[VisibilityVolume]:
    """VVs for every row of ``pois`` (n, 3), computed in parallel over the points (GIL released);
    ``with_mesh`` as in :func:`visibility_volume`."""
    points = np.asarray(pois, dtype=float)
    if points.ndim != 2 or points.shape[1] != 3:
        raise _core.VistrackError(f"pois: shape = {points.shape}: must be (n, 3)")
    return _core.visibility_volumes(
        visibility_scene(env), points, float(d_max), altitude_band, float(resolution_deg),
        schema.boolean("with_mesh", with_mesh),
    )


def check_count(path: PoiPath, spacing: float, max_volumes: int = Planning().max_volumes,
                field: str = "max_volumes", spacing_field: str = "spacing") -> int:
    """The number of POI positions every ``spacing`` metres along ``path`` (ends included);
    VistrackError naming ``field`` when it exceeds ``max_volumes`` (checked before any VV)."""
    spacing = schema.length(spacing_field, spacing)
    count = max(2, math.ceil(path.length / spacing) + 1)
    if count > max_volumes:
        raise _core.VistrackError(
            f"{field} = {max_volumes}: {count} VVs every {spacing:g} m along the {path.length:.6g} m path "
            f"(about {count * _core.volume_bytes(Planning().resolution_deg) / 1e9:.3g} GB at 1 degree); raise "
            f"{field} explicitly to allow it, or raise {spacing_field}")
    return count


def poi_positions(scene: VisibilityScene, points: Optional[np.ndarray] = None, path: Optional[PoiPath] = None,
                  spacing: Optional[float] = None, height: float = PoiMotion().height,
                  max_volumes: int = Planning().max_volumes) -> np.ndarray:
    """POI positions (n, 3) on the scene's surface: the given ``points`` (n, 2 or 3; a missing or
    NaN z is ``height`` above the surface), or every ``spacing`` metres along ``path`` (ends
    included, at most ``max_volumes`` of them), whose z is the height above the surface."""
    if path is not None:
        if spacing is None:
            raise _core.VistrackError("spacing = None: a path needs a spacing in metres")
        count = check_count(path, spacing, max_volumes)
        # Arc length s is reached at time s / v_g.
        chosen = np.array([path.position(s / path.speed) for s in np.linspace(0.0, path.length, count)])
    elif points is not None:
        given = np.asarray(points, dtype=float)
        if given.ndim != 2 or given.shape[1] not in (2, 3) or len(given) == 0:
            raise _core.VistrackError(f"points: shape = {given.shape}: must be (n, 2) or (n, 3) with n > 0")
        chosen = np.column_stack([given[:, :2], given[:, 2] if given.shape[1] == 3 else np.full(len(given), np.nan)])
    else:
        raise _core.VistrackError("poi_positions: give points or a path")
    chosen[:, 2] = np.where(np.isfinite(chosen[:, 2]), chosen[:, 2], height)
    return np.asarray(scene.poi_on_surface(chosen))


def shapely_region(polygons: Sequence[_core.Polygon]) -> Any:
    """A visibility polygon (its polygons with holes) as one shapely geometry."""
    import shapely  # a dependency of the package; imported here to keep `import vistrack` light

    return shapely.union_all([shapely.Polygon(np.asarray(p.outer), [np.asarray(h) for h in p.holes]) for p in polygons])


def polygon_agreement(scene: VisibilityScene, vv: VisibilityVolume, altitude: float, step: float = 1.0) -> float:
    """How well the VP of ``vv`` at world z = ``altitude`` matches eq. (4) itself: the IoU of the
    polygon's area and the lattice points (spacing ``step`` m, offset from the POI's vertical,
    within d_max of g) that ``scene.line_of_sight`` finds visible from g. 1 is perfect; points on
    the lattice are the sample, so values near 1 are resolved to about step / d_max."""
    import shapely  # a dependency of the package; imported here to keep `import vistrack` light

    if not (step > 0.0):
        raise _core.VistrackError(f"step = {step}: must be > 0")
    g = np.asarray(vv.poi, dtype=float)
    region = shapely_region(_core.plane_visibility_polygon(vv, altitude))
    offsets = np.arange(-vv.d_max, vv.d_max, step) + 0.37 * step
    x, y = np.meshgrid(g[0] + offsets, g[1] + offsets)
    points = np.stack([x.ravel(), y.ravel(), np.full(x.size, float(altitude))], axis=1)
    points = points[np.linalg.norm(points - g, axis=1) <= vv.d_max]
    truth = np.asarray(scene.line_of_sight(np.repeat(g[None], len(points), 0), points)).ravel()
    ours = shapely.contains_xy(region, points[:, 0], points[:, 1])
    either = np.sum(truth | ours)
    return float(np.sum(truth & ours) / either) if either else 1.0


@dataclass
class ReferenceRays:
    """The rays of :func:`reference_volume`: one per cell of a ``resolution_deg`` grid, in the
    grid's row-major order (``num_elevation`` rows from the south pole, ``num_azimuth`` columns).
    ``directions`` (n, 3) are unit vectors, ``distances`` (n,) the visible distance along each
    (min(first hit, exact ground plane, d_max)) and ``solid_angles`` (n,) the cell each ray
    stands for (they sum to 4 pi)."""

    directions: np.ndarray
    distances: np.ndarray
    solid_angles: np.ndarray
    num_elevation: int
    num_azimuth: int

    @property
    def volume(self) -> float:
        """The sum of the cells' cones, solid angle times distance cubed over 3 (m^3)."""
        return float(np.sum(self.solid_angles * self.distances**3) / 3.0)

    def mesh_volumes(self, vv: VisibilityVolume) -> np.ndarray:
        """The volume of ``vv``'s mesh per cell (n,): each face's signed tetrahedron with the POI
        (they sum to the mesh's volume: the divergence theorem) in the cell of its centroid's
        direction. Radial walls hold none (their planes pass through the POI). A part of the sphere
        bounded by whole rows and columns of the VV's own grid gets exactly its faces (each stays
        inside its grid slot); elsewhere a face's volume lands in one cell of the several it spans."""
        g = np.asarray(vv.poi, dtype=float)
        corners = np.asarray(vv.vertices)[np.asarray(vv.faces)] - g  # (faces, 3, 3)
        six = np.einsum("ij,ij->i", corners[:, 0], np.cross(corners[:, 1], corners[:, 2]))
        centroid = corners.mean(axis=1)
        elevation = np.arctan2(centroid[:, 2], np.hypot(centroid[:, 0], centroid[:, 1]))
        azimuth = np.mod(np.arctan2(centroid[:, 1], centroid[:, 0]), 2.0 * np.pi)
        row = np.clip(((elevation + np.pi / 2) / (np.pi / self.num_elevation)).astype(int), 0, self.num_elevation - 1)
        column = np.clip((azimuth / (2.0 * np.pi / self.num_azimuth)).astype(int), 0, self.num_azimuth - 1)
        return np.bincount(row * self.num_azimuth + column, weights=six / 6.0,
                           minlength=self.num_elevation * self.num_azimuth)


def reference_rays(
    scene: VisibilityScene, g: Sequence[float], d_max: float, resolution_deg: float = 0.2
) -> ReferenceRays:
    """The brute-force rays behind :func:`reference_volume`, independent of the VV's code: one ray
    per cell of a ``resolution_deg`` grid through a point staggered inside it (Weyl sequences, as
    the VV's cell rays were before file format 4, uniform in solid angle), min(first hit, exact
    ground plane, d_max) along each. bench/vv_error_sources.py compares a VV's mesh with them cell
    by cell."""
    grid = _core.DirectionGrid.from_resolution(resolution_deg)
    ne, na = grid.num_elevation, grid.num_azimuth
    x = np.mod(0.5 + 0.7548776662466927 * np.arange(ne), 1.0)[:, None]
    y = np.mod(0.5 + 0.5698402909980532 * np.arange(na), 1.0)[None, :]
    lo = np.sin(-np.pi / 2 + np.arange(ne) * np.pi / ne)[:, None]
    hi = np.sin(-np.pi / 2 + (np.arange(ne) + 1) * np.pi / ne)[:, None]
    sin_el = lo + y * (hi - lo)
    cos_el = np.sqrt(np.maximum(0.0, 1.0 - sin_el**2))
    az = (np.arange(na)[None, :] + x) * 2.0 * np.pi / na
    dirs = np.stack([cos_el * np.cos(az), cos_el * np.sin(az), sin_el], axis=-1).reshape(-1, 3)
    origin = np.asarray(g, dtype=float).ravel()
    far = np.minimum(np.asarray(scene.first_hits(origin, dirs, d_max)).ravel(), d_max)
    down = dirs[:, 2] < 0.0
    far[down] = np.minimum(far[down], np.maximum(0.0, (scene.ground_level - origin[2]) / dirs[down, 2]))
    cells = np.repeat(np.array([grid.solid_angle(i) for i in range(ne)]), na)
    return ReferenceRays(dirs, far, cells, ne, na)


def reference_volume(scene: VisibilityScene, g: Sequence[float], d_max: float, resolution_deg: float = 0.2) -> float:
    """The volume of the VV at ``g`` without a band by brute force, independent of the VV's code:
    the cones of :func:`reference_rays` (one ray per cell of a ``resolution_deg`` grid) summed.
    The accuracy benchmarks' and tests' reference (0.2 degrees: 1.6 M rays)."""
    return reference_rays(scene, g, d_max, resolution_deg).volume
