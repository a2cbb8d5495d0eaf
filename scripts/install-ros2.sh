#!/usr/bin/env bash
# Install ROS 2 Kilted (rclpy, the Fast DDS middleware, the bridge's message packages) from PyPI under .venv/ros2
# when missing, for the ROS 2 bridge and its tests (docs/ros-bridge.md, "ROS 2"). Exact pins and sha256 hashes
# (scripts/ros2-requirements.txt, which says why), --no-deps: the pinned set is the whole run-time closure.
# Under a prefix of their own, not in the venv's site-packages: ROS 2's std_msgs, geometry_msgs... would shadow
# Debian's ROS 1 packages of the same names (hlacore.federates.ros_bridge.ros2_env gives the ROS 2 processes the
# prefix). Idempotent: when every pinned version is there it only checks. Called by test.sh; the main job needs none.
source "$(dirname "$0")/env.sh"
REQUIREMENTS=scripts/ros2-requirements.txt
PREFIX=.venv/ros2
missing=build/ros2-missing.txt
mkdir -p build
# The pinned lines whose distribution is not under the prefix at that version ("# if missing" ones: at any
# version, under the prefix or in the venv).
.venv/bin/python - "$REQUIREMENTS" "$PREFIX" >"$missing" <<'PY'
import importlib.metadata as metadata
import re
import sys
import sysconfig

prefix = sysconfig.get_path("purelib", vars={"base": sys.argv[2], "platbase": sys.argv[2]})
norm = lambda name: re.sub(r"[-_.]+", "-", name).lower()
under_prefix = {norm(d.metadata["Name"]): d.version for d in metadata.distributions(path=[prefix])}
in_venv = {norm(d.metadata["Name"]) for d in metadata.distributions()}
for line in open(sys.argv[1]):
    spec = line.split("#", 1)[0].strip()
    if not spec:
        continue
    name, version = spec.split()[0].split("==")
    if "# if missing" in line:
        if norm(name) not in under_prefix and norm(name) not in in_venv:
            print(spec)
    elif under_prefix.get(norm(name)) != version:
        print(spec)
PY
if [ ! -s "$missing" ]; then
    exit 0
fi
echo "install-ros2.sh: installing $(wc -l <"$missing") pinned wheels of ROS 2 Kilted from PyPI under $PREFIX (rclpy" \
     "9.1.2, rmw_fastrtps_cpp, the message packages; about 60 MB to download, 160 MB installed), for the ROS 2 bridge and its tests" \
     "(docs/ros-bridge.md); exact versions and hashes: $REQUIREMENTS" >&2
if ! pip_install --no-deps --require-hashes --no-warn-script-location --prefix "$PREFIX" -r "$missing"; then
    [ "${CI:-}" = true ] && exit 1
    echo "install-ros2.sh: the install failed; the ROS 2 tests will skip (under CI=true they fail)" >&2
fi
