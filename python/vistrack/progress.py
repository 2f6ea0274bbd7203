"""The one progress helper: tqdm bars fed by the core's ``progress(done, total)`` callbacks, and
timed stages for long jobs. Silent when disabled (``--quiet``)."""

from __future__ import annotations

import time
from types import TracebackType
from typing import Any, Callable, Optional


class Progress:
    """A tqdm bar fed by a ``progress(done, total)`` callback; a no-op when not enabled.

    Use it as the callback of a long core call (``planner.plan(..., progress=bar)``) and close it
    afterwards, or as a context manager.
    """

    def __init__(self, description: str, enabled: bool = True, unit: str = "VV", leave: bool = False) -> None:
        self.bar: Any = None
        if enabled:
            from tqdm import tqdm

            self.bar = tqdm(total=0, desc=description, unit=unit, leave=leave, dynamic_ncols=True)

    def __call__(self, done: int, total: int) -> None:
        if self.bar is None:
            return
        self.bar.total = total
        self.bar.n = done
        self.bar.refresh()

    def note(self, **fields: Any) -> None:
        """Show ``name=value`` fields after the bar (e.g. failed=2)."""
        if self.bar is not None:
            self.bar.set_postfix(fields, refresh=True)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()

    def __enter__(self) -> "Progress":
        return self

    def __exit__(self, kind: Optional[type[BaseException]], error: Optional[BaseException],
                 trace: Optional[TracebackType]) -> None:
        self.close()


class Stages:
    """Times each named stage of a job; unless quiet, prints one line per stage, or shows a bar for
    a stage whose work takes a ``progress(done, total)`` callback as its last argument."""

    def __init__(self, quiet: bool) -> None:
        self.quiet = quiet
        self.timings: dict[str, float] = {}

    def run(self, name: str, work: Callable[..., Any], *args: Any, bar_unit: Optional[str] = None) -> Any:
        start = time.perf_counter()
        if bar_unit is None:
            if not self.quiet:
                print(f"{name} ...", flush=True)
            result = work(*args)
        else:
            with Progress(name, not self.quiet, unit=bar_unit, leave=True) as bar:
                result = work(*args, bar)
        self.timings[name] = time.perf_counter() - start
        return result
