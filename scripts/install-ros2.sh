#!/usr/bin/env bash
# Install ROS 2 Kilted (rclpy, the Fast DDS middleware, the bridge's message packages) from PyPI under .venv/ros2
# when missing, for the ROS 2 bridge and its tests (docs/ros-bridge.md, "ROS 2"): exact pins and sha256 hashes,
# --no-deps, by hlacore.federates.ros_bridge.install_ros2 (run from the sources: the pins are those of this
# checkout, and hlacore need not be built), which says why under a prefix of their own. Idempotent: when every
# pinned version is there it only checks. Called by test.sh; the main job needs none.
source "$(dirname "$0")/env.sh"
if ! .venv/bin/python python/hlacore/federates/ros_bridge/install_ros2.py --prefix .venv/ros2; then
    [ "${CI:-}" = true ] && exit 1
    echo "install-ros2.sh: the install failed; the ROS 2 tests will skip (under CI=true they fail)" >&2
fi
