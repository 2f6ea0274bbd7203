#!/usr/bin/env bash
# Coverage-guided fuzzing (atheris) of every loader and the array entry points (tests/fuzz): each
# target for a fixed time; any crash, hang, NaN/inf result or exception other than VistrackError
# fails (the failing input is left in build/fuzz/<target>/: copy it to
# tests/fuzz/regressions/<target>/, which tests/python/test_fuzz_regressions.py replays).
#   bash scripts/fuzz.sh                 # every target, VISTRACK_FUZZ_SECONDS (default 20) each (CI)
#   VISTRACK_FUZZ_SEED=7 bash scripts/fuzz.sh   # libFuzzer's seed (default 1: CI's run is repeatable;
#                                               # a fresh build/fuzz corpus reproduces it)
#   VISTRACK_FUZZ_SECONDS=3600 bash scripts/fuzz.sh geojson   # a longer run of one target
# Installs the `fuzz` extra's packages (pyproject.toml) into .venv first, without rebuilding
# vistrack; uses the installed vistrack, or $VISTRACK_BUILD_DIR's extension when set.
set -euo pipefail
cd "$(dirname "$0")/.."
python=${VISTRACK_PYTHON:-.venv/bin/python}
seconds=${VISTRACK_FUZZ_SECONDS:-20}
seed=${VISTRACK_FUZZ_SEED:-1}
"$python" - <<'PY' | xargs -r "$python" -m pip install --quiet
import tomllib
print("\n".join(tomllib.load(open("pyproject.toml", "rb"))["project"]["optional-dependencies"]["fuzz"]))
PY
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  listed=$("$python" tests/fuzz/fuzz.py --list)  # a failing import stops the script here (set -e)
  read -r -a targets <<<"${listed#targets: }"
fi
[ ${#targets[@]} -gt 0 ] || { echo "vistrack fuzz: no targets"; exit 1; }
failed=()
for target in "${targets[@]}"; do
  log=build/fuzz/$target.log
  mkdir -p build/fuzz
  start=$(date +%s)
  if "$python" tests/fuzz/fuzz.py "$target" -max_total_time="$seconds" -seed="$seed" -timeout=20 -print_final_stats=1 >"$log" 2>&1; then
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
    echo "vistrack fuzz: $target: $runs inputs in $(($(date +%s) - start)) s, no finding"
  else
    echo "vistrack fuzz: $target: FAILED (log: $log)"; tail -n 30 "$log"; failed+=("$target")
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "vistrack fuzz: findings in: ${failed[*]}"; exit 1
fi
