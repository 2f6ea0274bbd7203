"""Shared fixtures. Tests read real data from ../shared/data and skip when it is absent.

For development against a CMake build tree instead of the installed package, set
VISTRACK_BUILD_DIR to the build folder holding bindings/_core*.so: the package is then
imported from python/ with that extension.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
SHARED_DATA = Path(os.environ.get("VISTRACK_DATA", REPO.parent / "shared" / "data"))


sys.path.insert(0, str(Path(__file__).resolve().parent))
from build_tree import preload_in_dask_workers, use_build_tree  # noqa: E402

use_build_tree()
preload_in_dask_workers()


def ticks_during(call) -> tuple[int, float]:
    """Run ``call()`` while another Python thread ticks every millisecond; return the ticks that
    fell inside the call and its duration. Zero ticks over a long call means it held the GIL."""
    import threading
    import time

    ticks: list[float] = []
    stop = threading.Event()

    def ticker() -> None:
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    thread = threading.Thread(target=ticker)
    thread.start()
    time.sleep(0.01)  # the ticker is running before the call starts
    try:
        start = time.perf_counter()
        call()
        end = time.perf_counter()
    finally:
        stop.set()
        thread.join()
    return sum(start < t < end for t in ticks), end - start


def standalone_executable(name: str) -> Path | None:
    """A standalone executable (vistrack_vv, vistrack_sim, vistrack_dubins): from the CMake build
    tree given by VISTRACK_BUILD_DIR, else installed beside the ``vistrack`` command."""
    import shutil
    import sysconfig

    build_dir = os.environ.get("VISTRACK_BUILD_DIR")
    candidates = [Path(build_dir) / "cpp" / name] if build_dir else []
    candidates.append(Path(sysconfig.get_path("scripts")) / name)
    for candidate in candidates:
        if os.access(candidate, os.X_OK):
            return candidate
    found = shutil.which(name)
    return Path(found) if found else None


@pytest.fixture(scope="session")
def shared_data() -> Path:
    """The real data folder; the test is skipped with a clear message when it is absent."""
    if not SHARED_DATA.is_dir():
        pytest.skip(f"real data not found at {SHARED_DATA} (set VISTRACK_DATA or place ../shared/data)")
    return SHARED_DATA


@pytest.fixture(scope="session")
def charlotte(shared_data: Path) -> Path:
    return shared_data / "charlotte"


@pytest.fixture(scope="session")
def campus(shared_data: Path) -> Path:
    return shared_data / "campus"
