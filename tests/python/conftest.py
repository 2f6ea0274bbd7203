"""Shared fixtures. Tests read real data from ../shared/data and skip when it is absent.

For development against a CMake build tree instead of the installed package, set
VISTRACK_BUILD_DIR to the build folder holding bindings/_core*.so: the package is then
imported from python/ with that extension.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))  # the support package
from support.build_tree import preload_in_dask_workers, use_build_tree
from support.paths import SHARED_DATA

use_build_tree()
preload_in_dask_workers()


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "sanitize: in the pytest subset scripts/sanitize.sh runs under ASan + UBSan "
                                       "(the input-facing surface: bad input, degenerate geometry, fuzz findings)")


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
