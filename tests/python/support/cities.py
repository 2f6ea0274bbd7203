"""Small synthetic cities built in memory, for tests that need buildings but not a real map."""

from __future__ import annotations

import numpy as np

import vistrack as vt

# A street from the west into the crossing, then north, passing between the four blocks.
STREET_BETWEEN_BLOCKS = np.array([[-90.0, 0.0], [0.0, 0.0], [0.0, 90.0]])


def square(cx: float, cy: float, half: float) -> np.ndarray:
    """The corners of a square footprint centred on (cx, cy), counter-clockwise."""
    return np.array([[cx - half, cy - half], [cx + half, cy - half], [cx + half, cy + half], [cx - half, cy + half]])


def four_blocks() -> vt.Environment:
    """Four 44 m square buildings (25 to 55 m tall) around a crossing at the origin."""
    return vt.Environment.from_buildings(
        [(square(-40, -40, 22), 40.0), (square(40, -40, 22), 25.0), (square(-40, 40, 22), 30.0),
         (square(40, 40, 22), 55.0)])
