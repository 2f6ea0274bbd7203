#!/usr/bin/env bash
# Regenerates the extension's type stubs (python/vistrack/_core/*.pyi) from a build tree:
#   bash scripts/stubs.sh [build/dev]
# tests/python/test_stubs.py fails while they are stale.
set -euo pipefail
cd "$(dirname "$0")/.."
export VISTRACK_BUILD_DIR=${1:-build/dev}
"${PYTHON:-.venv/bin/python}" - <<'PY'
import sys

sys.path.insert(0, "tests/python")
import conftest  # noqa: F401  (loads the build tree's extension as vistrack._core)
import pybind11_stubgen

import vistrack  # noqa: F401  (attaches the methods written in Python: to_mission, Environment.from_geojson)

sys.argv = ["pybind11-stubgen", "vistrack._core", "-o", "python", "--ignore-all-errors"]
pybind11_stubgen.main()
PY
