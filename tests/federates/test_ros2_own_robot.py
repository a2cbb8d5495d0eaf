"""docs/own-robot.md's ROS 2 walkthrough runs as written: a robot that is an rclpy node (docs/own-robot/my_robot2.py,
standing in for a real one, started through ``hlacore.federates.ros_bridge.ros2_env``) bridged with ``--ros 2
--robot-node NAME --sensor range --untimed``, and the HLA federate docs/own-robot/drive.py driving it through the
federation until its range sensor reads 0.5 m. Every command, rtig included, runs inside a loopback-only network
namespace made and removed by the test."""

from __future__ import annotations

import os
import pathlib
import re
import signal
import sys

import pytest

from hlacore.processes import Child, descendants, still_running

from support import ROOT, RtigProcess
from support.ros2 import ros2_space

pytestmark = pytest.mark.slow  # rtig, the robot node, the bridge and a federate, as the walkthrough runs them

EXAMPLE = ROOT / "docs" / "own-robot"


def read_until(child: Child, prefix: str, timeout: float) -> str:
    line = child.read_line(timeout)
    while not line.startswith(prefix):
        line = child.read_line(timeout)
    return line


def test_the_ros2_walkthrough_drives_a_ros2_robot_from_an_hla_federate(tmp_path: pathlib.Path) -> None:
    python = sys.executable
    with ros2_space(tmp_path) as space:
        inside = space.namespace.exec_prefix()
        # the walkthrough's shell: no ROS 2 variables but a domain of the test's own and its log directory
        env = dict(os.environ, ROS_DOMAIN_ID=str(space.domain), ROS_LOG_DIR=str(tmp_path / "ros2-log"),
                   PYTHONUNBUFFERED="1")
        rtig = RtigProcess(tmp_path, prefix=inside)
        try:
            with Child([*inside, python, "-m", "hlacore.federates.ros_bridge.ros2_env", "python",
                        str(EXAMPLE / "my_robot2.py"), "myrobot", "--wall", "2.0"], env=env) as robot, \
                    Child([*inside, python, "-m", "hlacore.federates.ros_bridge", "--ros", "2", "--rtig",
                           rtig.address, "--robot-node", "myrobot", "--sensor", "range", "--untimed"],
                          env=env) as bridge:
                read_until(robot, "my_robot ready", 30)
                read_until(bridge, "ros_bridge ready", 30)
                with Child([*inside, python, str(EXAMPLE / "drive.py"), "myrobot", "--rtig", rtig.address,
                            "--timeout", "60"], env=env) as drive:
                    line = read_until(drive, "drive:", 90)
                    assert drive.wait(30) == 0, drive.stderr()
                found = re.fullmatch(r"drive: myrobot stopped ([0-9.]+) m from the obstacle, at x=([0-9.]+) m", line)
                assert found, line
                # as on ROS 1 (tests/federates/test_ros_own_robot.py): 20 Hz sensing at 0.3 m/s
                assert 0.35 <= float(found[1]) <= 0.5 and 1.48 <= float(found[2]) <= 1.65
                family = descendants(robot.pid) + descendants(bridge.pid)
                for child in (robot, bridge):
                    child.send_signal(signal.SIGINT)
                assert robot.wait(30) == 0, robot.stderr()
                assert bridge.wait(30) == 0, bridge.stderr()
                stopped = read_until(robot, "my_robot stopped at x=", 5)
                assert 1.5 <= float(stopped.split("x=")[1].split()[0]) <= 1.7
                summary = read_until(bridge, "ros_bridge stopped", 5)
                assert int(re.search(r"(\d+) Twists out", summary)[1]) > 0  # type: ignore[index]
                assert "ROS 2" in summary
        finally:
            assert rtig.stop() == 0, rtig.log()
    assert not [p for p in family if still_running(p)], family
