"""Moved: the code lives in ``vistrack.tracking.pipeline`` (``run``, which writes the report folder, in
``vistrack.report.run``, found on first use); this name stays for old imports."""

from ._moved import forward
from .tracking.pipeline import *  # noqa: F403
from .tracking.pipeline import __all__ as _names
from .tracking.result import RunResult

__getattr__ = forward(__name__, {"run": "vistrack.report.run"})

__all__ = [*_names, "RunResult", "run"]  # noqa: F405  (run: found on first use)
