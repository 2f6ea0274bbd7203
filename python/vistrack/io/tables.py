"""CSV tables: closed-loop and flown trajectories, waypoint routes (x,y), numeric rows, and a
sweep's results table (``results.csv`` + ``results.parquet``)."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import TYPE_CHECKING, Any, Optional

import numpy as np

from .._core import SimulationResult, VistrackError
from ..preview import preview
from .text import read_text

if TYPE_CHECKING:
    from .._core.flight import FlightTrajectory

__all__ = ["numeric_rows", "read_results_table", "read_route", "write_flight", "write_results_table", "write_route",
           "write_trajectory"]


def write_trajectory(result: SimulationResult, path: str | Path) -> Path:
    """A closed-loop trajectory as CSV, one sample per line, full double precision (the header is
    in ``SimulationResult.to_csv``)."""
    file = Path(path)
    file.write_text(result.to_csv(), encoding="utf-8")
    return file


def read_route(path: str | Path, key: str = "route") -> np.ndarray:
    """A route as an (n, 2) array from CSV: a header naming columns ``x`` and ``y`` (others are
    ignored), or two numeric columns without a header; ``#`` starts a comment line. Errors name
    ``key``, the file and the line."""
    import csv

    text = read_text(path, key)
    lines = [(number, line) for number, line in enumerate(text.splitlines(), start=1)
             if line.strip() and not line.lstrip().startswith("#")]
    if not lines:
        raise VistrackError(f"{key} = {path}: no waypoints in the file")
    rows = list(csv.reader(line for _, line in lines))
    header = [cell.strip().lower() for cell in rows[0]]
    columns = (0, 1)
    body = list(zip((n for n, _ in lines), rows))
    if "x" in header or "y" in header:
        if "x" not in header or "y" not in header:
            raise VistrackError(f"{key} = {path}: the header needs both columns x and y, got {preview(rows[0])}")
        columns = (header.index("x"), header.index("y"))
        body = body[1:]
    points = []
    for number, row in body:
        try:
            point = [float(row[c]) for c in columns]
        except (IndexError, ValueError):
            text = ",".join(item[:81] for item in row[:81])  # enough for the preview of a huge line
            raise VistrackError(f"{key} = {path}: line {number} is not two numbers x, y: {preview(text)}") from None
        if not all(np.isfinite(point)):
            raise VistrackError(f"{key} = {path}: line {number} has a value that is not finite: {point}")
        points.append(point)
    if len(points) < 2:
        raise VistrackError(f"{key} = {path}: {len(points)} waypoint(s), at least two are needed")
    return np.array(points, dtype=float)


def write_route(points: np.ndarray, path: str | Path) -> Path:
    """An (n, 2) route as CSV with the header x,y (what :func:`read_route` reads)."""
    file = Path(path)
    file.write_text("x,y\n" + "".join(f"{x!r},{y!r}\n" for x, y in points.tolist()), encoding="utf-8")
    return file


def write_rows(rows: list[dict[str, Any]], path: str | Path) -> Path:
    """Rows of plain values (all with the keys of the first, in its order) as CSV with a header:
    numbers at full precision, booleans as true/false."""
    file = Path(path)
    columns = list(rows[0]) if rows else []

    def cell(value: Any) -> str:
        return ("true" if value else "false") if isinstance(value, bool) else repr(value)

    lines = [",".join(columns) + "\n"] + [",".join(cell(row[c]) for c in columns) + "\n" for row in rows]
    file.write_text("".join(lines), encoding="utf-8")
    return file


def write_flight(trajectory: "FlightTrajectory", path: str | Path) -> Path:
    """A flown trajectory (``vistrack.flight.FlightTrajectory``) as CSV, full double precision:
    t,x,y,psi,command,target_x,target_y,target_index,wind_east,wind_north."""
    file = Path(path)
    columns: list[list[Any]] = [
        trajectory.t.tolist(), trajectory.x.tolist(), trajectory.y.tolist(), trajectory.psi.tolist(),
        trajectory.command.tolist(), trajectory.target[:, 0].tolist(), trajectory.target[:, 1].tolist(),
        trajectory.target_index.tolist(), trajectory.wind[:, 0].tolist(), trajectory.wind[:, 1].tolist()]
    lines = ["t,x,y,psi,command,target_x,target_y,target_index,wind_east,wind_north\n"]
    for row in zip(*columns):
        lines.append(",".join(repr(v) for v in row) + "\n")
    file.write_text("".join(lines), encoding="utf-8")
    return file


def numeric_rows(path: str | Path, key: str, columns: tuple[int, ...]) -> np.ndarray:
    """The rows of a comma-separated numeric file (a header line is skipped), each with one of
    ``columns`` counts of finite numbers; VistrackError naming the key, the line and the value otherwise."""
    rows: list[list[float]] = []
    for number, line in enumerate(read_text(path, key).splitlines(), start=1):
        cells = [c.strip() for c in line.split(",")]
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        try:
            values = [float(c) for c in cells]
        except ValueError:
            if not rows and number == 1:
                continue  # a header
            raise VistrackError(f"{key} = {path}: line {number} is not numbers: {preview(line.strip())}") from None
        if len(values) not in columns:
            raise VistrackError(f"{key} = {path}: line {number} has {len(values)} values, expected "
                                f"{' or '.join(str(c) for c in columns)}")
        if not all(math.isfinite(v) for v in values):  # "nan", "inf", or one too large for a double
            raise VistrackError(f"{key} = {path}: line {number} holds a value that is not a finite number: "
                                f"{preview(line.strip())}")
        rows.append(values[: min(columns)])
    if len(rows) < 2:
        raise VistrackError(f"{key} = {path}: needs at least two rows, found {len(rows)}")
    return np.array(rows, dtype=float)


def _table_column(values: list[Any]) -> tuple[str, list[Any]]:
    """A column's type ("bool", "int", "float" or "string") and its values, None where missing;
    mixed or non-scalar values become text (JSON for lists and mappings)."""
    present = [v for v in values if v is not None]
    if present and all(isinstance(v, bool) for v in present):
        return "bool", values
    if all(isinstance(v, int) and not isinstance(v, bool) for v in present):
        return ("int", values) if present else ("string", values)
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in present):
        return "float", [None if v is None else float(v) for v in values]
    return "string", [None if v is None else v if isinstance(v, str) else json.dumps(v) for v in values]


def write_results_table(rows: list[dict[str, Any]], columns: list[str], folder: str | Path,
                        metadata: Optional[dict[str, Any]] = None) -> list[Path]:
    """A sweep's table, one row per case in the given order, as ``results.csv`` (floats written
    with every digit, missing values empty) and ``results.parquet`` (typed columns: bool, int64,
    float64 or string; ``metadata`` kept as JSON under the schema key ``vistrack.sweep``)."""
    import csv

    import pyarrow as pa
    import pyarrow.parquet as pq

    root = Path(folder)
    root.mkdir(parents=True, exist_ok=True)
    typed = {name: _table_column([row.get(name) for row in rows]) for name in columns}
    csv_file = root / "results.csv"
    with csv_file.open("w", newline="", encoding="utf-8") as stream:
        writer = csv.writer(stream)
        writer.writerow(columns)
        for i in range(len(rows)):
            writer.writerow(["" if typed[c][1][i] is None else repr(typed[c][1][i]) if typed[c][0] == "float"
                             else typed[c][1][i] for c in columns])
    arrow_types = {"bool": pa.bool_(), "int": pa.int64(), "float": pa.float64(), "string": pa.string()}
    table = pa.table({c: pa.array(typed[c][1], type=arrow_types[typed[c][0]]) for c in columns})
    if metadata is not None:
        table = table.replace_schema_metadata({"vistrack.sweep": json.dumps(metadata)})
    parquet_file = root / "results.parquet"
    pq.write_table(table, parquet_file)
    return [csv_file, parquet_file]


def read_results_table(path: str | Path) -> list[dict[str, Any]]:
    """The rows of a ``results.parquet`` written by :func:`write_results_table`, in file order."""
    import pyarrow.parquet as pq

    if not Path(path).is_file():
        raise VistrackError(f"results = {path}: no such file")
    rows: list[dict[str, Any]] = pq.read_table(path).to_pylist()
    return rows
