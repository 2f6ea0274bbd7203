"""Output folders: what each job writes (JSON/CSV results, figures, meshes, report.md). One module
per planner or job (``run``: a tracking run and ``vt.run``, which computes it and writes its folder;
``orbits``, ``simulation``, ``tune``, ``volumes``; ``waypoint_nav``, ``loiter``, ``follow``,
``intercept``) over shared ``document``, ``html`` and ``media``; the commands call these after the
library has computed."""

from __future__ import annotations

from .run import RunResult, percent, write_report

__all__ = ["RunResult", "percent", "write_report"]
