#!/usr/bin/env bash
# Install ROS 2 Kilted (rclpy, the Fast DDS middleware, the bridge's message packages) from PyPI into .venv when
# missing, for the ROS 2 bridge and its tests (docs/ros-bridge.md, "ROS 2"). Exact pins and sha256 hashes
# (scripts/ros2-requirements.txt, which says why), --no-deps: the pinned set is the whole run-time closure.
# Idempotent: when every pinned version is installed it only checks. Called by test.sh; the main job needs none.
source "$(dirname "$0")/env.sh"
REQUIREMENTS=scripts/ros2-requirements.txt
missing=build/ros2-missing.txt
mkdir -p build
# The pinned lines whose distribution is not installed at that version ("# if missing" ones: at any version).
.venv/bin/python - "$REQUIREMENTS" >"$missing" <<'PY'
import importlib.metadata as metadata
import sys

for line in open(sys.argv[1]):
    spec = line.split("#", 1)[0].strip()
    if not spec:
        continue
    name, version = spec.split()[0].split("==")
    try:
        have = metadata.version(name)
    except metadata.PackageNotFoundError:
        have = None
    if have is None or (have != version and "# if missing" not in line):
        print(spec)
PY
if [ ! -s "$missing" ]; then
    exit 0
fi
echo "install-ros2.sh: installing $(wc -l <"$missing") pinned wheels of ROS 2 Kilted from PyPI into .venv (rclpy" \
     "9.1.2, rmw_fastrtps_cpp, the message packages; about 60 MB), for the ROS 2 bridge and its tests" \
     "(docs/ros-bridge.md); exact versions and hashes: $REQUIREMENTS" >&2
pip_install --no-deps --require-hashes -r "$missing"
