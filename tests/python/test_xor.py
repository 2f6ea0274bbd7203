"""XOR volume (eq. 56): the CGAL mesh path on analytic shapes; grid vs mesh vs Monte Carlo on
Charlotte VVs."""

from __future__ import annotations

import numpy as np
import pytest

import vistrack as vt


def box(lo, hi):
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    v = np.array([[hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]] for i in range(8)])
    f = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                  [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]], dtype=np.int32)
    return v, f


def test_mesh_xor_of_boxes_is_analytic():
    a = box([0, 0, 0], [2, 2, 2])
    assert vt.mesh_xor_volume(*a, *box([1, 0, 0], [3, 2, 2])) == pytest.approx(8.0, abs=1e-9)
    assert vt.mesh_xor_volume(*a, *box([1, 1, 1], [3, 3, 3])) == pytest.approx(14.0, abs=1e-9)
    # Seeded random boxes: |A xor B| = |A| + |B| - 2 |A n B| with the box intersection in closed form.
    rng = np.random.default_rng(11)
    for _ in range(10):
        lo1, lo2 = rng.uniform(-5, 5, 3), rng.uniform(-5, 5, 3)
        hi1, hi2 = lo1 + rng.uniform(0.5, 6, 3), lo2 + rng.uniform(0.5, 6, 3)
        inter = np.prod(np.clip(np.minimum(hi1, hi2) - np.maximum(lo1, lo2), 0, None))
        expected = np.prod(hi1 - lo1) + np.prod(hi2 - lo2) - 2 * inter
        assert vt.mesh_xor_volume(*box(lo1, hi1), *box(lo2, hi2)) == pytest.approx(expected, rel=1e-9, abs=1e-9)


def test_mesh_xor_rejects_open_meshes_and_bad_options():
    v, f = box([0, 0, 0], [1, 1, 1])
    with pytest.raises(vt.VistrackError, match="not closed"):
        vt.mesh_xor_volume(v, f[:-1], v, f)
    with pytest.raises(vt.VistrackError, match="time_limit"):
        vt.mesh_xor_volume(v, f, v, f, time_limit=-1.0)
