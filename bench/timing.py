"""Wall-clock timing shared by the benchmarks: the best of several runs (the least disturbed by
other work on a shared machine)."""

from __future__ import annotations

import time
from typing import Any, Callable


def timed(fn: Callable[[], Any], repeat: int) -> tuple[float, Any]:
    """Best wall-clock seconds of `repeat` calls, and the last call's value."""
    best, value = float("inf"), None
    for _ in range(repeat):
        start = time.perf_counter()
        value = fn()
        best = min(best, time.perf_counter() - start)
    return best, value


def best_of(repeat: int, fn: Callable[[], Any]) -> float:
    """Best wall-clock seconds of `repeat` calls."""
    return timed(fn, repeat)[0]
