"""Parameter sweeps and many routes as Dask tasks (``vt.sweep``, ``vistrack sweep``).

```python
import vistrack as vt
result = vt.sweep.run("examples/sweep_small.yaml")              # a LocalCluster, one worker per core
result = vt.sweep.run(spec, scheduler="tcp://10.0.0.5:8786")    # any Dask cluster
result = vt.sweep.run(spec, scheduler="serial")                 # one by one here, no Dask
result.rows, result.columns, result.failed, result.files        # results.csv, results.parquet, figures
```
A sweep file (:mod:`vistrack.sweep.spec`) names a base case of one kind (:mod:`vistrack.sweep.kinds`:
``tracking``, ``waypoints``, ``loiter``, ``follow``), the parameters to vary and their combination;
each case is one task, run by :func:`run_case` with the worker's shared environment and planner
(:mod:`vistrack.sweep.resources`).
"""

from __future__ import annotations

from . import follow as _follow  # noqa: F401
from . import loiter as _loiter  # noqa: F401
from . import tracking as _tracking  # noqa: F401  (registers the kinds)
from . import waypoint_nav as _waypoint_nav  # noqa: F401
from .execute import SERIAL, SweepResult, metric_columns, run, run_case, run_cases, table_columns
from .kinds import KINDS, CaseContext, CaseKind, CaseOutput, get_kind, register_kind
from .resources import Resources
from .spec import Case, SweepSpec

__all__ = [
    "KINDS", "SERIAL", "Case", "CaseContext", "CaseKind", "CaseOutput", "Resources", "SweepResult",
    "SweepSpec", "get_kind", "load", "metric_columns", "register_kind", "run", "run_case", "run_cases",
    "table_columns",
]


def load(path: str) -> SweepSpec:
    """Read and validate a sweep file (same as ``SweepSpec.load``)."""
    return SweepSpec.load(path)
