"""Visibility volumes from Python: the Embree scene is built once per environment and reused.

``visibility_volume`` and ``visibility_volumes`` accept either an :class:`Environment` (its
scene is built on first use and kept in a small cache keyed by the environment's content
fingerprint) or a :class:`VisibilityScene` (no lookup at all: the fastest path for many VVs).
"""

from __future__ import annotations

from collections import OrderedDict
from typing import Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import Environment, VisibilityScene, VisibilityVolume

_CACHE_SIZE = 4
_scenes: "OrderedDict[int, VisibilityScene]" = OrderedDict()

Band = Optional[Tuple[float, float]]


def visibility_scene(env: Union[Environment, VisibilityScene]) -> VisibilityScene:
    """The Embree scene of ``env``, built once per environment content (LRU of 4 scenes)."""
    if isinstance(env, VisibilityScene):
        return env
    if not isinstance(env, Environment):
        raise TypeError(f"env must be a vistrack.Environment or VisibilityScene, not {type(env).__name__}")
    key = env.fingerprint
    scene = _scenes.get(key)
    if scene is None:
        scene = VisibilityScene(env)
        _scenes[key] = scene
        while len(_scenes) > _CACHE_SIZE:
            _scenes.popitem(last=False)
    else:
        _scenes.move_to_end(key)
    return scene


def visibility_volume(
    env: Union[Environment, VisibilityScene],
    g: Sequence[float],
    d_max: float,
    altitude_band: Band = None,
    resolution_deg: float = 1.0,
) -> VisibilityVolume:
    """Visibility volume alpha(g) of eq. (4): the points within ``d_max`` of the POI ``g`` (x, y, z),
    inside ``altitude_band`` = (h_lo, h_hi) of world z when given, with a clear line of sight.

    The result holds the per-direction intervals (``near``, ``far`` on ``grid``), a closed,
    outward-oriented triangle mesh (``vertices``, ``faces``), its ``volume``, ``slice(h)`` and
    ``save(path)``. Raises VistrackError naming the field for bad input.
    """
    return _core.visibility_volume(
        visibility_scene(env), np.asarray(g, dtype=float), float(d_max), altitude_band, float(resolution_deg)
    )


def visibility_volumes(
    env: Union[Environment, VisibilityScene],
    pois: np.ndarray,
    d_max: float,
    altitude_band: Band = None,
    resolution_deg: float = 1.0,
) -> list[VisibilityVolume]:
    """VVs for every row of ``pois`` (n, 3), computed in parallel over the points (GIL released)."""
    points = np.asarray(pois, dtype=float)
    if points.ndim != 2 or points.shape[1] != 3:
        raise _core.VistrackError(f"pois: shape = {points.shape}: must be (n, 3)")
    return _core.visibility_volumes(
        visibility_scene(env), points, float(d_max), altitude_band, float(resolution_deg)
    )
