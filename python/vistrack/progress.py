"""The one progress helper: tqdm bars fed by the core's ``progress(done, total)`` callbacks, and
timed stages for long jobs. Silent when disabled (``--quiet``)."""

from __future__ import annotations

import time
from types import TracebackType
from typing import Any, Callable, Optional


class Progress:
    """A tqdm bar fed by a ``progress(done, total)`` callback; a no-op when not enabled.

    Use it as the callback of a long core call (``planner.plan(..., progress=bar)``) and close it
    afterwards, or as a context manager. The bar is drawn at the first report, not when it is
    made: a call that refuses its input before any work (``vistrack tune``'s Lemma 5 check) ends in
    its one-line error without a bar printed before it.
    """

    def __init__(self, description: str, enabled: bool = True, unit: str = "VV", leave: bool = False) -> None:
        self.bar: Any = None
        self._settings = {"desc": description, "unit": unit, "leave": leave} if enabled else None

    def _open(self) -> Any:
        if self.bar is None and self._settings is not None:
            from tqdm import tqdm

            self.bar = tqdm(total=0, dynamic_ncols=True, **self._settings)
        return self.bar

    def __call__(self, done: int, total: int) -> None:
        bar = self._open()
        if bar is None:
            return
        bar.total = total
        bar.n = done
        bar.refresh()

    def note(self, **fields: Any) -> None:
        """Show ``name=value`` fields after the bar (e.g. failed=2)."""
        bar = self._open()
        if bar is not None:
            bar.set_postfix(fields, refresh=True)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
        self._settings = None  # closed: later reports draw nothing

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
