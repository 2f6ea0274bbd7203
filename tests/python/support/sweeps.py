"""Comparing sweep rows."""

from __future__ import annotations

from typing import Any


def without_run_columns(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The rows without their run_* columns (status, worker, timings, seed of each run)."""
    return [{k: v for k, v in row.items() if not k.startswith("run_")} for row in rows]
