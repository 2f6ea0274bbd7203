"""Dubins paths: shortest of the six words, batch lengths, path to a circle, target intercept.

Thin re-export of the C++ submodule ``vistrack._core.dubins`` so that both
``vistrack.dubins.shortest_path(...)`` and ``from vistrack import dubins`` work.
"""

from __future__ import annotations

from ._core import dubins as _dubins

DubinsPath = _dubins.DubinsPath
InterceptResult = _dubins.InterceptResult
WORDS: tuple[str, ...] = _dubins.WORDS
SNAP: float = _dubins.SNAP
shortest_path = _dubins.shortest_path
shortest_length = _dubins.shortest_length
path = _dubins.path
word_lengths = _dubins.word_lengths
shortest_lengths = _dubins.shortest_lengths
path_to_circle = _dubins.path_to_circle
length_to_circle = _dubins.length_to_circle
four_rho_condition = _dubins.four_rho_condition
intercept_circle = _dubins.intercept_circle
intercept_travel_times = _dubins.intercept_travel_times

__all__ = [
    "SNAP",
    "WORDS",
    "DubinsPath",
    "InterceptResult",
    "four_rho_condition",
    "intercept_circle",
    "intercept_travel_times",
    "length_to_circle",
    "path",
    "path_to_circle",
    "shortest_length",
    "shortest_lengths",
    "shortest_path",
    "word_lengths",
]
