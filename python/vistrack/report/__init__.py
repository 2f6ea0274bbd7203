"""Output folders: what each job writes (JSON/CSV results, figures, meshes) and, for a tracking
run, report.md. One module per job; the commands call these after the library has computed."""

from __future__ import annotations

from .run import RunResult, percent, write_report

__all__ = ["RunResult", "percent", "write_report"]
