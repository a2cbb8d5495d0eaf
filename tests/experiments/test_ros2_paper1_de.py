"""Paper 1 on ROS 2 (docs/ros-bridge.md), each process inside a loopback-only network namespace made and removed
by the test: with the controllers as an rclpy node; and paper 1's chain, the DE-engine controller federate
commanding the world as a ROS 2 node (the stageros-style stage node on rclpy) through the RTI, the bridge and
ROS 2 topics; the same checks as on ROS 1 (tests/support/paper1.py); the run's recording, the federation's
events and the bridged ROS 2 topics in one MCAP file; and the world node alone on its own clock. This process
never imports rclpy (the recording's ROS 2 messages are decoded from their schemas, as Foxglove does). Skips
without ROS 2's wheels, except under CI=true."""

from __future__ import annotations

import pathlib

import pytest
from mcap_ros2.decoder import DecoderFactory

from support import PEERS
from support.paper1 import check_de_run, check_node_run, check_recording
from support.ros import WORLD, assert_stage_on_its_own_clock, running
from support.ros2 import ros2_space


def paper1_on_ros2(tmp_path: pathlib.Path, out: pathlib.Path, *args: str) -> str:
    """``python -m hlacore.experiments.paper1.ros OUT --ros 2 ARGS`` in a loopback-only namespace: its stdout,
    once it has exited with status 0."""
    with ros2_space(tmp_path) as space:
        proc = space.popen(["-m", "hlacore.experiments.paper1.ros", str(out), "--ros", "2", *args])
        try:
            stdout, _ = proc.communicate(timeout=300)
        finally:
            if proc.poll() is None:
                proc.kill()
                proc.communicate()
    assert proc.returncode == 0, stdout
    return stdout


@pytest.mark.slow  # four processes and 300 lockstep cycles through DDS
def test_paper1_de_controller_through_ros2(tmp_path: pathlib.Path) -> None:
    """One command, paper 1's architecture on ROS 2: the paper-1 checks pass, every pose of the world node is
    bit-identical to the World alone with the DE federate's commands at their timestamps, the DE model read
    the node's poses one lookahead later; nothing is left running in the namespace. The recording
    (``--record``) opens with the mcap reader; its ROS 2 messages decode with their schemas: the world node's
    odometry at every tick and a Twist for each cmd_vel interaction the federation's events hold."""
    out = tmp_path / "out"
    summary = check_de_run(paper1_on_ros2(tmp_path, out, "--controller", "de", "--record"), out)
    assert summary["ros"] == 2

    check_recording(out, summary, DecoderFactory(), "cdr", "ros2msg")


def test_paper1_with_the_controllers_as_a_ros2_node(tmp_path: pathlib.Path) -> None:
    """One command, ``--ros 2`` with the default controllers: the world federate and the bridge in one process
    (re-executed with ROS 2's environment), the controllers as an rclpy node in another, in lockstep through
    DDS; the same checks as on ROS 1; nothing is left running in the namespace."""
    out = tmp_path / "out"
    assert check_node_run(paper1_on_ros2(tmp_path, out), out)["ros"] == 2


def test_stage_node_on_its_own_clock_on_ros2(tmp_path: pathlib.Path) -> None:
    """The world as a ROS 2 node, like stageros: with --rate it runs its own clock (/clock), applies the Twists
    of an rclpy node on /<robot>/cmd_vel and publishes odom, base_scan and range stamped with its sim time on
    interval_sim's grid; the rclpy node's clock (use_sim_time) follows it."""
    world_file, summary = tmp_path / "rover.world", tmp_path / "stage.json"
    world_file.write_text(WORLD)
    with ros2_space(tmp_path) as space:
        with running(space.popen(["-m", "hlacore.federates.ros_bridge.stage_node", str(world_file), "--ros", "2",
                                  "--rate", "5", "--summary", str(summary)])) as stage:
            stage.out.wait_for("stage_node ready", 60)
            with running(space.popen([str(PEERS / "ros2_teleop.py"), "/rover", "0.5", "0.2", "60", "--clock",
                                      "--ros-args", "-p", "use_sim_time:=true"])) as teleop:
                seen = teleop.report(90)
    assert_stage_on_its_own_clock(stage, seen, summary, stamp_tolerance=1e-9)
    odom = seen["odom"]
    assert abs(odom["node_time"] - odom["stamp"]) < 2.0 and seen["use_sim_time"] is True and seen["clock"] > 0
