"""Comparing sweep rows, and two spellings of one sweep."""

from __future__ import annotations

from typing import Any

import vistrack as vt
from vistrack.sweep import SERIAL, SweepSpec


def without_run_columns(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The rows without their run_* columns (status, worker, timings, seed of each run)."""
    return [{k: v for k, v in row.items() if not k.startswith("run_")} for row in rows]


def renamed_note(old: str, new: str) -> str:
    """The line on stdout for an old spelling read as its new key (scenario_blocks.renamed)."""
    return f"vistrack: '{old}' is now '{new}' (still read; see the docs' Scenario files)"


def assert_same_sweep(old: SweepSpec, new: SweepSpec) -> list[dict[str, Any]]:
    """Two spellings of one sweep: the same base, parameters and cases, every case runs, and the
    rows are the same (serially); the rows."""
    assert old.base == new.base and old.parameters == new.parameters
    assert [case.data for case in old.cases()] == [case.data for case in new.cases()]
    rows = vt.sweep.run_cases(old.cases(), SERIAL)
    assert all(row["run_status"] == "ok" for row in rows), [row["run_error"] for row in rows]
    assert without_run_columns(rows) == without_run_columns(vt.sweep.run_cases(new.cases(), SERIAL))
    return rows
