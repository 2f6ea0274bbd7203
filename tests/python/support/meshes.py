"""Triangle meshes written out by hand."""

from __future__ import annotations

import numpy as np


def box(lo: tuple[float, float, float], hi: tuple[float, float, float]) -> tuple[np.ndarray, np.ndarray]:
    """The vertices and outward-facing triangles of the axis-aligned box from ``lo`` to ``hi``."""
    lo_, hi_ = np.asarray(lo, float), np.asarray(hi, float)
    v = np.array([[hi_[0] if i & 1 else lo_[0], hi_[1] if i & 2 else lo_[1], hi_[2] if i & 4 else lo_[2]]
                  for i in range(8)])
    f = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                  [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]], dtype=np.int32)
    return v, f
