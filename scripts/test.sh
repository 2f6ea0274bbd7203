#!/usr/bin/env bash
# Quick start, second command: install what is needed, then run every test (GoogleTest through
# ctest, ruff on the package, tests and benchmarks, mypy on the package, the docs site, then
# pytest). Exits non-zero when any check fails.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=build/test
bash scripts/install.sh -Cbuild-dir="$build_dir" -Ccmake.define.VISTRACK_BUILD_TESTS=ON \
  -Ccmake.define.VISTRACK_WERROR=ON
ctest_bin=$(command -v ctest || echo .venv/bin/ctest)
"$ctest_bin" --test-dir "$build_dir" --output-on-failure -j2
.venv/bin/ruff check python tests/python tests/fuzz bench
.venv/bin/mypy python/vistrack
NO_MKDOCS_2_WARNING=1 .venv/bin/mkdocs build --strict --quiet --site-dir build/site
.venv/bin/python -m pytest tests/python "$@"
