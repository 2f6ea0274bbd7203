"""Heavy objects built once per worker: environments (and their Embree scenes) and orbit planners
(their VV caches), kept for every case the worker runs.

An environment is keyed by its map file's content hash (SHA-256; the demo city by name), so two
paths to the same file share one environment and an edited file gets a new one. A planner (its
Embree scene, 2-20 ms to build on the demo city and Charlotte, and its VV cache) is keyed by the
map, the sensor, the VV cache folder and what places the VVs (see :meth:`Resources.planner`):
cases that differ only in the UAV, the control or the simulation share one per worker thread (one
thread per worker by default). On a Dask worker the
worker plugin :class:`vistrack.sweep.plugin.SweepPlugin` holds them; a serial sweep uses one
:class:`Resources` in the calling process.
"""

from __future__ import annotations

import hashlib
import sys
import threading
from pathlib import Path
from typing import Any, Callable, Hashable, Optional

from .._core import Environment, OrbitPlanner, Sensor

__all__ = ["PLANNER_VOLUME_LIMIT", "PLUGIN_NAME", "Resources", "current_resources", "current_worker",
           "worker_stats"]

PLUGIN_NAME = "vistrack-sweep"

# A planner holding more VVs than this is replaced by a fresh one on the same environment, and a
# worker keeps at most MAX_PLANNERS of them: this bounds its memory (a 1-degree VV holds a few MB).
PLANNER_VOLUME_LIMIT = 600
MAX_PLANNERS = 4


def file_hash(path: str | Path) -> str:
    """SHA-256 of a file's bytes, hex."""
    digest = hashlib.sha256()
    with Path(path).open("rb") as stream:
        for block in iter(lambda: stream.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


class Resources:
    """Environments and planners of one process, built on first use and counted."""

    def __init__(self) -> None:
        self._lock = threading.Lock()  # a worker may run cases on several threads
        self._hashes: dict[tuple[str, int, int], str] = {}
        self._environments: dict[tuple[str, ...], Environment] = {}
        self._planners: dict[tuple[Any, ...], OrbitPlanner] = {}
        self.environments_built = 0
        self.planners_built = 0
        self.cases_run = 0

    def map_key(self, kind: str, path: Optional[Path], *options: str) -> tuple[str, ...]:
        """The key of a map: its kind, its file's content hash (memoised by path, size and
        modification time) and loader options such as the up axis."""
        if path is None:
            return (kind, *options)
        stat = Path(path).stat()
        memo = (str(path), stat.st_size, stat.st_mtime_ns)
        with self._lock:
            digest = self._hashes.get(memo)
        if digest is None:
            digest = file_hash(path)
            with self._lock:
                self._hashes[memo] = digest
        return (kind, digest, *options)

    def environment(self, key: tuple[str, ...], load: Callable[[], Environment]) -> Environment:
        """The environment of that map key, loaded by ``load()`` the first time."""
        with self._lock:
            env = self._environments.get(key)
            if env is None:
                env = load()
                self._environments[key] = env
                self.environments_built += 1
            return env

    def planner(self, key: tuple[str, ...], env: Environment, sensor: Sensor, cache_dir: Optional[Path] = None,
                share: Hashable = None) -> OrbitPlanner:
        """The orbit planner on ``env`` (map ``key``) for this sensor, VV cache folder and ``share``
        key, one per thread (a planner takes calls from one thread at a time).

        A planner's in-memory VV cache finds a VV by its POI position to the micrometre, so a VV
        left by another case at a position a rounding error away would be used as is, and the
        case's numbers would depend on which cases ran before it on this worker (in the last
        digits). Cases share a planner only when ``share`` is equal: the caller makes it name
        everything that places the VVs (the POI path, the discretization), so shared VVs sit at
        bit-identical positions and every case gets exactly what it would get alone. At most
        ``MAX_PLANNERS`` planners are kept (least recently used dropped).
        """
        band = sensor.altitude_band
        planner_key = (key, sensor.d_max, None if band is None else tuple(band), str(cache_dir or ""),
                       threading.get_ident(), share)
        with self._lock:
            planner = self._planners.pop(planner_key, None)
            if planner is None or planner.cached_volumes > PLANNER_VOLUME_LIMIT:
                planner = OrbitPlanner(env, sensor, "" if cache_dir is None else str(cache_dir))
                self.planners_built += 1
            self._planners[planner_key] = planner  # most recently used last
            while len(self._planners) > MAX_PLANNERS:
                self._planners.pop(next(iter(self._planners)))
            return planner

    def stats(self) -> dict[str, int]:
        """Counts: environments and planners built, cases run, and VVs held now."""
        with self._lock:
            return {"environments_built": self.environments_built, "planners_built": self.planners_built,
                    "cases_run": self.cases_run,
                    "cached_volumes": sum(p.cached_volumes for p in self._planners.values())}


_LOCAL = Resources()


def current_worker() -> Any:
    """The Dask worker running this task, or None (no Dask here, or not inside a task)."""
    if "distributed" not in sys.modules:  # a task on a worker has imported it; elsewhere, keep it unloaded
        return None
    from distributed import get_worker

    try:
        return get_worker()
    except ValueError:
        return None


def current_resources() -> Resources:
    """The resources of the Dask worker running this task (its SweepPlugin's), else the process's own."""
    worker = current_worker()
    plugin = None if worker is None else worker.plugins.get(PLUGIN_NAME)
    resources = getattr(plugin, "resources", None)
    return resources if isinstance(resources, Resources) else _LOCAL


def worker_stats(dask_worker: Any = None) -> dict[str, int]:
    """The resource counts of a worker (``Client.run`` passes ``dask_worker``)."""
    plugin = None if dask_worker is None else dask_worker.plugins.get(PLUGIN_NAME)
    resources = getattr(plugin, "resources", None)
    return resources.stats() if isinstance(resources, Resources) else _LOCAL.stats()
