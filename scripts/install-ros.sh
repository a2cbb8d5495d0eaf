#!/usr/bin/env bash
# Install ROS 1 (roscore, rospy, the message packages) from Debian's packages when missing, for the ROS
# bridge and its tests (docs/ros-bridge.md). Idempotent: a dpkg -s check, nothing else, when all are there.
# Runs apt-get update only when the install fails without it. Called by test.sh; needs root (or sudo).
set -euo pipefail
ROS_PACKAGES=(ros-core python3-rospy python3-geometry-msgs python3-nav-msgs python3-sensor-msgs python3-std-msgs)
if dpkg -s "${ROS_PACKAGES[@]}" >/dev/null 2>&1; then
    exit 0
fi
if ! command -v apt-get >/dev/null 2>&1; then
    echo "install-ros.sh: no apt-get; install ROS 1 (${ROS_PACKAGES[*]}) by hand for the ROS bridge tests" >&2
    exit 0
fi
SUDO=()
if [ "$(id -u)" != 0 ]; then
    if command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
        SUDO=(sudo -n)
    else
        echo "install-ros.sh: not root and no passwordless sudo; run as root:" >&2
        echo "  apt-get install -y --no-install-recommends ${ROS_PACKAGES[*]}" >&2
        exit 0
    fi
fi
install() {
    echo "+ apt-get install -y --no-install-recommends ${ROS_PACKAGES[*]}"
    "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
        "${ROS_PACKAGES[@]}" </dev/null
}
echo "install-ros.sh: installing ROS 1 (${ROS_PACKAGES[*]}) from Debian's packages, about 75 packages with their" \
     "dependencies and a few minutes, for the ROS bridge and its tests (docs/ros-bridge.md)"
if ! install; then
    echo "+ apt-get update"
    "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q </dev/null
    install
fi
