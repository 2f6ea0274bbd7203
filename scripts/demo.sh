#!/usr/bin/env bash
# Quick start, first command: install what is needed, then run the main job on the embedded city.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install.sh
.venv/bin/vistrack demo "$@"
