"""Paper 2 §6.2 end to end: ``python -m hlacore.experiments.mirror`` against a real rtig and a real roscore
(both started here, ended by pid). The command runs the world federate and the ROS bridge; the robot
federate (with its simulated device process on a pty) and the ROS robot's rospy node are processes of
their own. The checks read the command's JSON summary, its CSV trace and its PNG. Last, a robot whose
mirror never appears (in-process gateway, no ROS).

Figures (ours, docs/mirror.md): a 0.4 m box 1.6 m ahead; a robot clears it when its centre stays more than
its half diagonal (0.233 m) from the box; the defective wheel is the right wheel 5 % slow.
"""

from __future__ import annotations

import csv
import json
import pathlib
import subprocess
import sys
from typing import Any, Iterator

import pytest

from support.ros import require_ros, running_roscore

CLEAR = 0.33 / 2 * 2 ** 0.5  # the robot's half diagonal
CYCLES = 50


@pytest.fixture(scope="module")
def roscore(tmp_path_factory: pytest.TempPathFactory) -> Iterator[dict[str, str]]:
    """A real roscore for the module; yields the environment for the runs."""
    require_ros()
    with running_roscore(tmp_path_factory.mktemp("ros")) as env:
        yield env


def run_mirror(env: dict[str, str], address: str, out: pathlib.Path, *options: str) -> dict[str, Any]:
    """Run the command; its exit status must be 0; returns the JSON summary (its last line)."""
    done = subprocess.run([sys.executable, "-m", "hlacore.experiments.mirror", str(out), "--rtig", address,
                           "--cycles", str(CYCLES), *options], capture_output=True, text=True, env=env,
                          timeout=300, stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stdout + done.stderr
    summary: dict[str, Any] = json.loads(done.stdout.strip().splitlines()[-1])
    assert summary["cycles"] == CYCLES and summary["stall_steps"] == {"mirror": 0, "rosbot": 0}
    return summary


def assert_ros_robot_drove_around_its_box(summary: dict[str, Any]) -> None:
    ros = summary["rosbot"]
    assert ros["avoidances"] == 1 and ros["passed_box"] and ros["box_clearance"] > CLEAR
    assert ros["end"][0] > 2.5 and ros["vs_reference"] < 0.1  # on its own lane, moved onto the reference's


def test_calibrated_real_robot_follows_the_reference(roscore: dict[str, str], rtig: Any,
                                                     tmp_path: pathlib.Path) -> None:
    """Calibrated: the real robot's odometry follows the reference path within 5 cm and clears the box it
    only knows through its mirror's sonar; the mirror repeats its commands exactly; the ROS robot does the
    same on its lane."""
    summary = run_mirror(roscore, str(rtig.address), tmp_path)
    real = summary["real"]
    assert real["avoidances"] == 1 and real["passed_box"] and real["box_clearance"] > CLEAR
    assert real["vs_reference"] < 0.05 and summary["mirror"]["vs_real"] < 0.05
    assert_ros_robot_drove_around_its_box(summary)
    with open(tmp_path / "mirror-trace.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == CYCLES
    assert all((r["linear"], r["angular"]) == (r["mirror_linear"], r["mirror_angular"]) for r in rows)
    assert [r["mode"] for r in rows].count("turn-left") == 4 and rows[-1]["mode"] == "forward"
    assert (tmp_path / "mirror-trajectories.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_defective_wheel_diverges_from_the_reference(roscore: dict[str, str], rtig: Any,
                                                     tmp_path: pathlib.Path) -> None:
    """The right wheel 5 % slow, open-loop control: the real robot drifts far from the reference and runs
    through the (virtual) box. Its mirror repeats the commands on an ideal body, so the mirror stays on the
    reference and its sonar never sees the box again: no re-detection with this mirror."""
    summary = run_mirror(roscore, str(rtig.address), tmp_path, "--defective-wheel", "0.05")
    real = summary["real"]
    assert real["vs_reference"] > 0.5 and real["box_clearance"] < 0.0
    assert real["avoidances"] == 1 and summary["mirror"]["vs_reference"] < 0.05
    assert_ros_robot_drove_around_its_box(summary)


def test_corrected_control_brings_the_defective_robot_back(roscore: dict[str, str], rtig: Any,
                                                           tmp_path: pathlib.Path) -> None:
    """Defective wheel, corrected control: the real robot is back within 10 cm of the reference path and
    clears the box; the mirror, fed the compensating commands on an ideal body, drifts away instead."""
    summary = run_mirror(roscore, str(rtig.address), tmp_path, "--defective-wheel", "0.05", "--corrected")
    real = summary["real"]
    assert real["vs_reference"] < 0.1 and real["passed_box"] and real["box_clearance"] > CLEAR
    assert real["avoidances"] == 1 and summary["mirror"]["vs_reference"] > 0.5
    assert_ros_robot_drove_around_its_box(summary)


def test_mirror_of_the_odometry_redetects_the_box(roscore: dict[str, str], rtig: Any,
                                                  tmp_path: pathlib.Path) -> None:
    """Defective wheel, open loop, the mirror repeating the motion the odometry measured: the mirror goes
    where the real robot goes, so its sonar sees the box again after the side step and the robot turns
    again (the paper's re-detection)."""
    summary = run_mirror(roscore, str(rtig.address), tmp_path, "--defective-wheel", "0.05", "--mirror-from",
                         "odometry")
    real = summary["real"]
    assert real["avoidances"] >= 2 and real["vs_reference"] > 0.5
    assert summary["mirror"]["vs_real"] < 0.05
    with open(tmp_path / "mirror-trace.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert any((r["linear"], r["angular"]) != (r["mirror_linear"], r["mirror_angular"]) for r in rows)


def test_robot_without_its_mirror_times_out_and_leaves(inprocess_gateway: Any) -> None:
    """No world robot of that name in the federation: joining raises a TimeoutError naming it, and the
    robot has resigned (the federation can be destroyed at once)."""
    import hlacore.rti as rti
    from hlacore.federates.robot_driver.avoid import OpenLoopAvoid
    from hlacore.federates.robot_driver.mirrored import MirroredRobotFederate
    from hlacore.federates.robot_world import FEDERATION

    address = str(inprocess_gateway.address)
    robot = MirroredRobotFederate(None, OpenLoopAvoid(), mirror="nobody", address=address)  # type: ignore[arg-type]
    with pytest.raises(TimeoutError, match="the mirror robot 'nobody'"):
        robot.join(timeout=0.5)
    assert robot.rtia is None
    rti.RTIAmbassador(address).destroyFederationExecution(FEDERATION)
