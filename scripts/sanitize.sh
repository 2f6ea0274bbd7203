#!/usr/bin/env bash
# The GoogleTest suite and a pytest subset under AddressSanitizer + UndefinedBehaviorSanitizer
# (issue 18): a separate build of the C++ library, its tests and the Python extension in
# build/sanitize (-DVISTRACK_SANITIZE=address,undefined, cmake/VistrackSanitize.cmake), then
# ctest, then the pytest files in PYTESTS against that extension, with ASan's runtime and
# libstdc++ preloaded into Python (which links neither: without libstdc++ first, ASan cannot
# intercept C++ throws). Any finding aborts the test that triggers it.
#   bash scripts/sanitize.sh                            # build + run both (CI: .ci/run's sanitizer step)
#   VISTRACK_SANITIZE_PYTHON=0 bash scripts/sanitize.sh # the GoogleTests only, no extension
#   bash scripts/sanitize.sh -R Dubins                  # extra arguments go to ctest
# Budget: the tests listed in SLOW below run in the normal ctest only (each is a larger instance
# of what a faster test covers under the sanitizers), and the random-case tests of limits_test run
# 10^5 problems per family instead of 10^6 (VISTRACK_RANDOM_CASES).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${VISTRACK_SANITIZE_BUILD_DIR:-build/sanitize}
jobs=${VISTRACK_SANITIZE_JOBS:-2}
with_python=${VISTRACK_SANITIZE_PYTHON:-1}
python=${VISTRACK_PYTHON:-.venv/bin/python}
SLOW='^(RadialXor\.EqualsCgalOnTheSameMeshes|VisibilityVolumeData\.|RadialXor\.MeshesOnDifferentVertexRowsAreOverlappedToo|MeshXor\.PerturbationHandlesIdenticalSpheresAndStaysSmall)'
# The input-facing Python surface, the tests marked `sanitize`: every reproducer of bad input (each in
# its area's file), degenerate geometry, every fuzz seed and finding, and the Dubins, waypoint,
# loiter and follow entry points. Only the files holding such tests are collected.
mapfile -t PYTESTS < <(grep -l "pytest.mark.sanitize" tests/python/test_*.py)

start=$(date +%s)
python_args=(-DVISTRACK_BUILD_PYTHON=OFF)
if [ "$with_python" = 1 ]; then
  # The pybind11 that pyproject.toml pins (scikit-build-core's build environment is not kept).
  "$python" - <<'PY' | xargs "$python" -m pip install --quiet
import tomllib
print(next(r for r in tomllib.load(open("pyproject.toml", "rb"))["build-system"]["requires"] if r.startswith("pybind11")))
PY
  python_args=(-DVISTRACK_BUILD_PYTHON=ON -DPython_EXECUTABLE="$("$python" -c 'import sys; print(sys.executable)')"
               -Dpybind11_DIR="$("$python" -c 'import pybind11; print(pybind11.get_cmake_dir())')")
fi
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVISTRACK_SANITIZE=address,undefined \
  -DVISTRACK_BUILD_TESTS=ON -DVISTRACK_BUILD_APPS=OFF -DVISTRACK_WERROR=OFF "${python_args[@]}" >/dev/null
cmake --build "$build_dir" -j"$jobs"
built=$(date +%s)

# detect_leaks: TBB's and Embree's worker threads keep their arenas until exit (not leaks of ours).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export VISTRACK_RANDOM_CASES=${VISTRACK_RANDOM_CASES:-100000}
"$(command -v ctest || echo .venv/bin/ctest)" --test-dir "$build_dir" --output-on-failure -j"$jobs" -E "$SLOW" "$@"
tested=$(date +%s)
if [ "$with_python" = 1 ]; then
  compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build_dir/CMakeCache.txt")
  compiler=${compiler:-g++}
  # -s: a sanitizer report goes to the terminal, not into pytest's capture of a dying process.
  LD_PRELOAD="$("$compiler" -print-file-name=libasan.so) $("$compiler" -print-file-name=libstdc++.so)" \
    VISTRACK_BUILD_DIR="$build_dir" "$python" -m pytest -q -s -p no:cacheprovider -m sanitize "${PYTESTS[@]}"
fi
summary="build $((built - start)) s, ctest $((tested - built)) s"
if [ "$with_python" = 1 ]; then summary+=", pytest $(($(date +%s) - tested)) s"; fi
echo "vistrack sanitize: $summary"
