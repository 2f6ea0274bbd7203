"""Running a sweep: one Dask task per case on a LocalCluster or any scheduler (or serially in
this process), rows streamed back as cases finish, then the table, a summary and the figures.

Each case runs through :func:`run_case`, the same function serially and on a worker, with its
own seed and the worker's shared heavy objects (:mod:`vistrack.sweep.resources`), so the rows are
the same whichever way the sweep runs. A case that raises is a row with ``run_status`` "failed"
and ``run_error``; the sweep goes on.
"""

from __future__ import annotations

import fnmatch
import itertools
import logging
import math
import os
import socket
import time
import traceback
import uuid
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterator, Mapping, Optional, Sequence, Union

import numpy as np

from .._core import VistrackError
from ..io import append_json_line, write_json, write_results_table
from ..preview import preview
from ..progress import Progress
from .kinds import CaseContext, get_kind
from .resources import current_resources, current_worker, worker_stats
from .spec import Case, SweepSpec

__all__ = ["SERIAL", "SweepResult", "metric_columns", "run", "run_case", "run_cases"]

SERIAL = "serial"  # scheduler value: run the cases one by one in this process, without Dask
RUN_COLUMNS = ("run_status", "run_error", "run_worker", "run_wall_s", "run_cpu_s", "run_seed")
SUBMIT_WINDOW = 2000  # cases waiting on the scheduler at once (bounds its memory on huge sweeps)
Row = dict[str, Any]


@dataclass
class SweepResult:
    """A finished sweep: its rows in case order, the table's columns, and where it was written."""

    spec: SweepSpec
    rows: list[Row]
    columns: list[str]
    out: Path
    files: list[Path] = field(default_factory=list)
    wall_s: float = 0.0
    scheduler: str = SERIAL
    workers: dict[str, dict[str, int]] = field(default_factory=dict)  # per worker: resources built, cases

    @property
    def failed(self) -> list[Row]:
        """The rows of cases that raised."""
        return [row for row in self.rows if row["run_status"] != "ok"]

    def column(self, name: str) -> list[Any]:
        """One column's values in case order."""
        return [row.get(name) for row in self.rows]


def run_case(case: Case) -> Row:
    """Run one case and return its row: parameters, the kept metrics, ``run_`` metadata. Never
    raises for a bad case: the error goes into the row."""
    began, cpu = time.perf_counter(), time.process_time()  # CPU of every thread of the process
    resources = current_resources()
    row: Row = {"case": case.index, **case.parameters}
    try:
        kind = get_kind(case.kind)
        context = CaseContext(Path(case.folder), case.seed, resources,
                              None if case.cache_dir is None else Path(case.cache_dir))
        output = kind.run(case.data, context)
        row.update({k: _plain(v) for k, v in _select(output.metrics, case.metrics).items()})
        status, error, meta = "ok", None, {k: _plain(v) for k, v in output.meta.items()}
    except Exception as exc:  # a failed case is a row, whatever it raised
        status, error, meta = "failed", _describe(exc), {}
    row, nonfinite = finite_row(row)
    meta, more = finite_row(meta)
    resources.cases_run += 1
    row.update({"run_status": status, "run_error": error, "run_worker": _worker_name(),
                "run_wall_s": time.perf_counter() - began, "run_cpu_s": time.process_time() - cpu,
                "run_seed": case.seed})
    row.update({f"run_{key}": value for key, value in meta.items()})
    if nonfinite or more:  # why those cells are empty (JSON and CSV have no NaN)
        row["run_not_finite"] = "NaN or infinity, written empty: " + ", ".join(
            [*nonfinite, *(f"run_{k}" for k in more)])
    return row


def finite_row(row: Mapping[str, Any]) -> tuple[Row, list[str]]:
    """``row`` with every NaN or infinity (also inside lists and mappings) as None, and the keys
    that held one: the results files stay valid JSON and CSV, and the note says why a value is empty."""
    def clean(value: Any) -> tuple[Any, bool]:
        if isinstance(value, float) and not math.isfinite(value):
            return None, True
        if isinstance(value, (list, tuple)):
            items = [clean(v) for v in value]
            if any(bad for _, bad in items):
                return [v for v, _ in items], True
        elif isinstance(value, Mapping):
            pairs = {k: clean(v) for k, v in value.items()}
            if any(bad for _, bad in pairs.values()):
                return {k: v for k, (v, _) in pairs.items()}, True
        return value, False

    out: Row = {}
    bad: list[str] = []
    for key, value in row.items():
        out[key], found = clean(value)
        if found:
            bad.append(str(key))
    return out, bad


def run(spec: Union[SweepSpec, str, Path, Mapping[str, Any]], scheduler: Optional[str] = None,
        n_workers: Optional[int] = None, *, out: Union[str, Path, None] = None, quiet: bool = True,
        figures: bool = True, scheduler_checked: bool = False) -> SweepResult:
    """Run every case of a sweep and write ``results.csv``, ``results.parquet``, ``sweep.json``,
    ``rows.jsonl`` (rows as they arrived) and the summary figures into ``out`` (default: the
    spec's ``out``, else ./vistrack-out/<name>).

    ``scheduler``: None starts a LocalCluster of ``n_workers`` processes (default: one per core,
    one thread each) on 127.0.0.1; an address ("tcp://host:8786") uses that cluster;
    ``"serial"`` runs the cases one by one here, without Dask. An address is first checked to
    answer as a Dask scheduler within seconds, unless ``scheduler_checked`` says the caller did.
    """
    if not isinstance(spec, SweepSpec):
        spec = SweepSpec.load(spec) if isinstance(spec, (str, Path)) else SweepSpec.from_dict(spec)
    if n_workers is not None and (isinstance(n_workers, bool) or not isinstance(n_workers, int) or n_workers < 1):
        raise VistrackError(f"n_workers = {preview(n_workers)}: must be a positive integer")
    if n_workers is not None and scheduler is not None:
        raise VistrackError(f"n_workers = {n_workers}: only applies to a LocalCluster (scheduler=None), "
                            f"not to scheduler = {preview(scheduler)}")
    folder = Path(out) if out is not None else spec.out or Path("vistrack-out") / spec.name
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:  # a file there ([Errno 17] File exists), a folder that cannot be written
        reason = "is a file, not a folder" if folder.is_file() else f"cannot create the folder ({error.strerror})"
        raise VistrackError(f"out = {folder}: {reason}") from None
    stream = folder / "rows.jsonl"
    stream.write_text("", encoding="utf-8")
    cases = spec.cases()
    began = time.perf_counter()
    rows: list[Row] = []
    workers: dict[str, dict[str, int]] = {}
    with Progress(f"sweep {spec.name}", not quiet, unit="case", leave=True) as bar:
        bar(0, len(cases))
        failed = 0
        for row in _execute(cases, scheduler, n_workers, workers, scheduler_checked):
            rows.append(row)
            append_json_line(row, stream)
            failed += row["run_status"] != "ok"
            bar(len(rows), len(cases))
            bar.note(failed=failed)
    rows.sort(key=lambda r: r["case"])
    result = SweepResult(spec, rows, table_columns(spec, rows), folder, wall_s=time.perf_counter() - began,
                         scheduler=scheduler or "LocalCluster", workers=workers)
    _write(result, figures)
    return result


def run_cases(cases: Sequence[Case], scheduler: Optional[str] = None, n_workers: Optional[int] = None) -> list[Row]:
    """The rows of these cases in case order, without writing anything (see :func:`run`)."""
    return sorted(_execute(cases, scheduler, n_workers, {}), key=lambda r: r["case"])


def table_columns(spec: SweepSpec, rows: list[Row]) -> list[str]:
    """case, the parameters, the metrics (in the order the first rows give them), run_ columns."""
    columns = ["case", *spec.parameters]
    seen = dict.fromkeys(columns)
    metrics: dict[str, None] = {}
    extra: dict[str, None] = {}
    for row in rows:
        for key in row:
            if key in seen or key in RUN_COLUMNS:
                continue
            (extra if key.startswith("run_") else metrics)[key] = None
    return columns + list(metrics) + list(RUN_COLUMNS) + sorted(extra)


def metric_columns(result: SweepResult) -> list[str]:
    """The table's metric columns."""
    skip = {"case", *result.spec.parameters}
    return [c for c in result.columns if c not in skip and not c.startswith("run_")]


def _execute(cases: Sequence[Case], scheduler: Optional[str], n_workers: Optional[int],
             workers: dict[str, dict[str, int]], scheduler_checked: bool = False) -> Iterator[Row]:
    if scheduler == SERIAL:
        before = current_resources().stats()
        for case in cases:
            yield run_case(case)
        after = current_resources().stats()
        workers["serial"] = {k: v - before[k] if k != "cached_volumes" else v for k, v in after.items()}
        return
    from distributed import Client, LocalCluster

    from .connect import CONNECT_TIMEOUT_S, check_scheduler
    from .plugin import SweepPlugin

    cluster = None
    if scheduler is None:
        count = n_workers or os.cpu_count() or 1
        cluster = LocalCluster(n_workers=count, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address=None, silence_logs=logging.ERROR)
        address = cluster.scheduler_address
    else:
        address = scheduler
        if not scheduler_checked:  # a short timeout and a peer that speaks Dask, before Client waits on it
            check_scheduler(scheduler)
    try:
        try:
            client = Client(address, timeout=f"{CONNECT_TIMEOUT_S}s")
        except (OSError, TimeoutError, ValueError, TypeError) as error:
            # TypeError: distributed's "TLS expects a ssl_context" for tls:// without Dask's TLS settings.
            hint = "; tls:// needs distributed.comm.tls in the Dask config" if isinstance(error, TypeError) else ""
            raise VistrackError(f"scheduler = {scheduler}: cannot connect ({error}{hint})") from None
        with client:
            try:
                client.wait_for_workers(1, timeout=60)
            except TimeoutError:
                raise VistrackError(f"scheduler = {scheduler}: no worker joined within 60 s") from None
            client.register_plugin(SweepPlugin())
            yield from _stream(client, cases)
            workers.update(client.run(worker_stats))
    finally:
        if cluster is not None:
            cluster.close()


def _stream(client: Any, cases: Sequence[Case]) -> Iterator[Row]:
    """Submit the cases (at most SUBMIT_WINDOW waiting at once) and yield rows as they finish."""
    from distributed import as_completed

    token = uuid.uuid4().hex[:12]  # task keys unique to this sweep on a shared scheduler
    pending = iter(cases)
    by_key: dict[str, Case] = {}

    def submit(count: int) -> list[Any]:
        batch = list(itertools.islice(pending, count))
        if not batch:
            return []
        futures = client.map(run_case, batch, key=[f"vistrack-case-{token}-{c.index}" for c in batch], pure=False)
        by_key.update({future.key: case for future, case in zip(futures, batch)})
        return list(futures)

    finished = as_completed(submit(SUBMIT_WINDOW))
    for future in finished:
        try:
            row = future.result()
        except Exception as error:  # the task itself died (its worker lost or killed...)
            case = by_key[future.key]
            row = {"case": case.index, **case.parameters, "run_status": "failed",
                   "run_error": _describe(error), "run_worker": None, "run_wall_s": None, "run_cpu_s": None,
                   "run_seed": case.seed}
        del by_key[future.key]
        future.release()
        for more in submit(1):
            finished.add(more)
        yield row


def _write(result: SweepResult, figures: bool) -> None:
    from ..plotting.sweep import sweep_figures

    spec = result.spec
    summary = {"sweep": spec.describe(), "cases": len(result.rows), "failed": len(result.failed),
               "wall_s": result.wall_s, "scheduler": result.scheduler, "workers": result.workers,
               "columns": result.columns}
    result.files = write_results_table(result.rows, result.columns, result.out,
                                       metadata={"name": spec.name, "kind": spec.kind.name, "seed": spec.seed})
    result.files.append(write_json(finite_row(summary)[0], result.out / "sweep.json"))
    result.files.append(result.out / "rows.jsonl")
    if figures:
        chosen = spec.metrics or spec.kind.figure_metrics
        metrics = [c for c in metric_columns(result) if any(fnmatch.fnmatchcase(c, p) for p in chosen)]
        result.files += sweep_figures(result.rows, list(spec.parameters), metrics, result.out / "figures",
                                      title=spec.name)


def _select(metrics: Mapping[str, Any], patterns: tuple[str, ...]) -> dict[str, Any]:
    if not patterns:
        return dict(metrics)
    return {k: v for k, v in metrics.items() if any(fnmatch.fnmatchcase(k, p) for p in patterns)}


def _plain(value: Any) -> Any:
    """Numpy scalars as Python numbers (the table and rows.jsonl take plain data)."""
    return value.item() if isinstance(value, np.generic) else value


def _describe(error: BaseException) -> str:
    if isinstance(error, VistrackError):
        return str(error)
    last = traceback.extract_tb(error.__traceback__)[-1:] if error.__traceback__ else []
    where = f" (at {Path(last[0].filename).name}:{last[0].lineno})" if last else ""
    return f"{type(error).__name__}: {error}{where}"


def _worker_name() -> str:
    worker = current_worker()
    return str(worker.address) if worker is not None else f"{socket.gethostname()}:{os.getpid()}"
