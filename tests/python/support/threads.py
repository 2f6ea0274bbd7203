"""Whether a call releases the GIL, seen from another Python thread."""

from __future__ import annotations

import threading
import time
from typing import Any, Callable


def ticks_during(call: Callable[[], Any]) -> tuple[int, float]:
    """Run ``call()`` while another Python thread ticks every millisecond; return the ticks that
    fell inside the call and its duration. Zero ticks over a long call means it held the GIL."""
    ticks: list[float] = []
    stop = threading.Event()

    def ticker() -> None:
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    thread = threading.Thread(target=ticker)
    thread.start()
    time.sleep(0.01)  # the ticker is running before the call starts
    try:
        start = time.perf_counter()
        call()
        end = time.perf_counter()
    finally:
        stop.set()
        thread.join()
    return sum(start < t < end for t in ticks), end - start
