"""docs/own-robot.md's ROS 2 walkthrough runs as written: a robot that is an rclpy node (docs/own-robot/my_robot2.py,
standing in for a real one, started through ``hlacore.federates.ros_bridge.ros2_env``) bridged with ``--ros 2
--robot-node NAME --sensor range --untimed``, and the HLA federate docs/own-robot/drive.py driving it through the
federation until its range sensor reads 0.5 m. Every command, rtig included, runs inside a loopback-only network
namespace made and removed by the test."""

from __future__ import annotations

import os
import pathlib
import sys

import pytest

from hlacore.processes import still_running

from support import RtigProcess
from support.own_robot import EXAMPLE, run_walkthrough
from support.ros2 import ros2_space

pytestmark = pytest.mark.slow  # rtig, the robot node, the bridge and a federate, as the walkthrough runs them


def test_the_ros2_walkthrough_drives_a_ros2_robot_from_an_hla_federate(tmp_path: pathlib.Path) -> None:
    python = sys.executable
    with ros2_space(tmp_path) as space:
        inside = space.namespace.exec_prefix()
        # the walkthrough's shell: no ROS 2 variables but a domain of the test's own and its log directory
        env = dict(os.environ, ROS_DOMAIN_ID=str(space.domain), ROS_LOG_DIR=str(tmp_path / "ros2-log"),
                   PYTHONUNBUFFERED="1")
        rtig = RtigProcess(tmp_path, prefix=inside)
        try:
            summary, family = run_walkthrough(
                [python, "-m", "hlacore.federates.ros_bridge.ros2_env", "python", str(EXAMPLE / "my_robot2.py"),
                 "myrobot", "--wall", "2.0"],
                [python, "-m", "hlacore.federates.ros_bridge", "--ros", "2", "--rtig", rtig.address, "--robot-node",
                 "myrobot", "--sensor", "range", "--untimed"], rtig.address, env, env, prefix=inside)
            assert "ROS 2" in summary
        finally:
            assert rtig.stop() == 0, rtig.log()
    assert not [p for p in family if still_running(p)], family
