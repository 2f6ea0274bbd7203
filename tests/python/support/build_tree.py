"""Import vistrack from this repository's python/ with the extension of a CMake build tree, when
VISTRACK_BUILD_DIR names one (development without installing).

conftest.py calls :func:`use_build_tree`; Dask workers started by the tests (LocalCluster
processes, ``dask worker`` subprocesses) load this file as a preload script
(DASK_DISTRIBUTED__WORKER__PRELOAD; --preload for `dask scheduler` and `dask worker`), so they
run the same code as the test process.
"""

from __future__ import annotations

import glob
import importlib.util
import os
import shutil
import sys
import sysconfig
from pathlib import Path

REPO = Path(__file__).resolve().parents[3]


def use_build_tree() -> None:
    build_dir = os.environ.get("VISTRACK_BUILD_DIR")
    if not build_dir or "vistrack._core" in sys.modules:
        return
    candidates = glob.glob(os.path.join(build_dir, "bindings", "_core*.so"))
    if not candidates:
        raise RuntimeError(f"VISTRACK_BUILD_DIR={build_dir}: no bindings/_core*.so there")
    sys.path.insert(0, str(REPO / "python"))
    spec = importlib.util.spec_from_file_location("vistrack._core", candidates[0])
    module = importlib.util.module_from_spec(spec)
    sys.modules["vistrack._core"] = module
    spec.loader.exec_module(module)


def preload_in_dask_workers() -> None:
    """Make Dask workers started from now on (in child processes) preload this file."""
    if os.environ.get("VISTRACK_BUILD_DIR"):
        os.environ["DASK_DISTRIBUTED__WORKER__PRELOAD"] = repr([str(Path(__file__).resolve())])


def dask_preload_arguments() -> list[str]:
    """The `dask scheduler` / `dask worker` options that preload this file (the scheduler unpickles
    the tasks too; the worker's --preload overrides the setting)."""
    return ["--preload", str(Path(__file__).resolve())] if os.environ.get("VISTRACK_BUILD_DIR") else []


def standalone_executable(name: str) -> Path | None:
    """A standalone executable (vistrack_vv, vistrack_sim, vistrack_dubins): from the CMake build
    tree given by VISTRACK_BUILD_DIR, else installed beside the ``vistrack`` command."""
    build_dir = os.environ.get("VISTRACK_BUILD_DIR")
    candidates = [Path(build_dir) / "cpp" / name] if build_dir else []
    candidates.append(Path(sysconfig.get_path("scripts")) / name)
    for candidate in candidates:
        if os.access(candidate, os.X_OK):
            return candidate
    found = shutil.which(name)
    return Path(found) if found else None


use_build_tree()  # as a Dask preload script, on import
