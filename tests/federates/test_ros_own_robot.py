"""docs/own-robot.md runs as written: a robot that is a ROS node (docs/own-robot/my_robot.py, standing in
for a real one) bridged with ``--robot-node NAME --sensor range --untimed``, and the HLA federate
docs/own-robot/drive.py driving it through the federation until its range sensor reads 0.5 m."""

from __future__ import annotations

import os
import pathlib
import sys
from typing import Iterator

import pytest

from hlacore.processes import still_running

from support import RtigProcess
from support.own_robot import EXAMPLE, run_walkthrough
from support.ros import require_ros, running_roscore

pytestmark = pytest.mark.slow  # roscore, the robot node, the bridge and a federate, as the walkthrough runs them

@pytest.fixture
def ros_env(tmp_path: pathlib.Path) -> Iterator[dict[str, str]]:
    require_ros()
    with running_roscore(tmp_path / "ros") as env:
        yield env


def test_the_walkthrough_drives_a_ros_robot_from_an_hla_federate(ros_env: dict[str, str],
                                                                 rtig: RtigProcess) -> None:
    python = sys.executable
    _, family = run_walkthrough(
        [python, str(EXAMPLE / "my_robot.py"), "myrobot", "--wall", "2.0"],
        [python, "-m", "hlacore.federates.ros_bridge", "--rtig", rtig.address, "--robot-node", "myrobot", "--sensor",
         "range", "--untimed"], rtig.address, ros_env, dict(os.environ, PYTHONUNBUFFERED="1"))
    assert not [p for p in family if still_running(p)], family
