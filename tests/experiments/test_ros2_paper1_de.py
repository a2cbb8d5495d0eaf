"""Paper 1's chain on ROS 2 (docs/ros-bridge.md): the DE-engine controller federate commands the world as a
ROS 2 node (the stageros-style stage node on rclpy) through the RTI, the bridge and ROS 2 topics, each a
process of its own, all inside a loopback-only network namespace made and removed by the test; the same
checks as on ROS 1 (tests/support/paper1.py). This process never imports rclpy. Skips without ROS 2's wheels,
except under CI=true."""

from __future__ import annotations

import pathlib
import subprocess

import pytest

from support.paper1 import check_de_run
from support.ros2 import ros2_space

pytestmark = pytest.mark.slow  # four processes and 300 lockstep cycles through DDS


def test_paper1_de_controller_through_ros2(tmp_path: pathlib.Path) -> None:
    """One command, paper 1's architecture on ROS 2: the paper-1 checks pass, every pose of the world node is
    bit-identical to the World alone with the DE federate's commands at their timestamps, the DE model read
    the node's poses one lookahead later; nothing is left running in the namespace."""
    out = tmp_path / "out"
    with ros2_space(tmp_path) as space:
        proc = space.popen(["-m", "hlacore.experiments.paper1.ros", str(out), "--controller", "de", "--ros", "2"])
        try:
            stdout, _ = proc.communicate(timeout=300)
        finally:
            if proc.poll() is None:
                proc.kill()
                proc.communicate()
    assert proc.returncode == 0, stdout
    summary = check_de_run(stdout, out)
    assert summary["ros"] == 2
