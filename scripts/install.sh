#!/usr/bin/env bash
# Installs everything vistrack needs on Debian 12 (system packages through apt-get, through sudo
# when not root), makes the virtual environment .venv and builds and installs vistrack into it.
# Extra arguments go to pip (for example -Ccmake.define.VISTRACK_BUILD_TESTS=ON).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ make cmake ninja-build ccache python3-dev python3-venv
          libembree-dev libcgal-dev libeigen3-dev libgtest-dev libtbb-dev libboost-dev nlohmann-json3-dev)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "vistrack: installing Debian packages: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

python=${PYTHON:-python3}
[ -x .venv/bin/python ] || "$python" -m venv .venv
.venv/bin/python -m pip install --quiet --upgrade pip
.venv/bin/python -m pip install --quiet ".[test]" "$@"
