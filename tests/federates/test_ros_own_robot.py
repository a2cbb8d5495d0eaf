"""docs/own-robot.md runs as written: a robot that is a ROS node (docs/own-robot/my_robot.py, standing in
for a real one) bridged with ``--robot-node NAME --sensor range --untimed``, and the HLA federate
docs/own-robot/drive.py driving it through the federation until its range sensor reads 0.5 m."""

from __future__ import annotations

import os
import pathlib
import re
import signal
import sys
from typing import Iterator

import pytest

from hlacore.processes import Child, descendants, still_running

from support import ROOT, RtigProcess
from support.ros import require_ros, running_roscore

pytestmark = pytest.mark.slow  # roscore, the robot node, the bridge and a federate, as the walkthrough runs them

EXAMPLE = ROOT / "docs" / "own-robot"


@pytest.fixture
def ros_env(tmp_path: pathlib.Path) -> Iterator[dict[str, str]]:
    require_ros()
    with running_roscore(tmp_path / "ros") as env:
        yield env


def read_until(child: Child, prefix: str, timeout: float) -> str:
    line = child.read_line(timeout)
    while not line.startswith(prefix):
        line = child.read_line(timeout)
    return line


def test_the_walkthrough_drives_a_ros_robot_from_an_hla_federate(ros_env: dict[str, str],
                                                                 rtig: RtigProcess) -> None:
    python = sys.executable
    with Child([python, str(EXAMPLE / "my_robot.py"), "myrobot", "--wall", "2.0"], env=ros_env) as robot, \
            Child([python, "-m", "hlacore.federates.ros_bridge", "--rtig", rtig.address, "--robot-node", "myrobot",
                   "--sensor", "range", "--untimed"], env=ros_env) as bridge:
        read_until(robot, "my_robot ready", 30)
        read_until(bridge, "ros_bridge ready", 30)
        with Child([python, str(EXAMPLE / "drive.py"), "myrobot", "--rtig", rtig.address, "--timeout", "60"],
                   env=dict(os.environ, PYTHONUNBUFFERED="1")) as drive:
            line = read_until(drive, "drive:", 90)
            assert drive.wait(30) == 0, drive.stderr()
        found = re.fullmatch(r"drive: myrobot stopped ([0-9.]+) m from the obstacle, at x=([0-9.]+) m", line)
        assert found, line
        # 20 Hz sensing at 0.3 m/s: each reading is at most ~2 cm old, plus the bridge's and the federate's
        # ticks; the stop is taken at or below 0.5 m, and the robot rolled on for at most a few cycles. The x
        # printed is the latest odometry, which may be one reading (1.5 cm) older than the range that
        # stopped it: 1.48 m at 0.50 m (seen once in CI).
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
    assert not [p for p in family if still_running(p)], family
