"""The ROS 1 bridge against a real roscore (started here on a free port, ended by pid), in separate
processes: the world federate runs in this process, the bridge (``python -m hlacore.federates.ros_bridge``)
and a plain rospy node (tests/peers/ros_teleop.py) in their own. The node's Twist moves the world robot
through the federation; its Odometry, LaserScan and Range come back on ROS carrying the federation
timestamps and exactly the values the world had at those times.

The tests run whenever ROS is installed (scripts/install-ros.sh, called by scripts/test.sh, installs it);
without ROS they skip, except under CI=true where missing ROS is a failure. This process never imports
rospy: the ROS side lives in the subprocesses."""

from __future__ import annotations

import json
import os
import pathlib
import subprocess
import sys
import threading
import xmlrpc.server

import pytest

from hlacore.federates.ros_bridge.master import free_master_port, master_online

from support.paper1 import check_node_run
from support.ros import (DIST, MAX_CYCLES, PERIOD, assert_seen_timed, assert_seen_untimed, drive_untimed, running,
                         start_bridge, start_teleop, state, world_federate)


def test_timed_bridge_round_trip(roscore: dict[str, str], gateway_address: str, tmp_path: pathlib.Path) -> None:
    """Twist from a ROS node → cmd_vel → the world moves the robot → Odometry, LaserScan, Range and /clock
    on ROS, stamped with federation time, equal to the world's state at the grant they were taken."""
    with world_federate(gateway_address, tmp_path) as (world, world_file):
        states = {0: state(world)}
        with running(start_bridge(roscore, gateway_address, "--world", str(world_file), "--clock", "--rate",
                                  "20")) as bridge:
            bridge.out.wait_for("ros_bridge ready", 60)
            with running(start_teleop(roscore, "/rover", "0.5", "0.2", "60", "--clock")) as teleop:
                for _ in range(MAX_CYCLES):
                    granted = world.advance(timeout=30)
                    states[round(granted / PERIOD)] = state(world)
                    if teleop.proc.poll() is not None:
                        break
                seen = teleop.report(30)
        assert bridge.status == 0, bridge.lines
        assert any(line.startswith("ros_bridge stopped at") for line in bridge.lines), bridge.lines

    assert_seen_timed(states, seen, stamp_tolerance=1e-6)
    odom = seen["odom"]
    # /clock follows the grants; /use_sim_time is set
    assert seen["clock"] >= odom["stamp"] - PERIOD and seen["use_sim_time"] is True


def test_untimed_bridge_round_trip(roscore: dict[str, str], inprocess_gateway: object,
                                   tmp_path: pathlib.Path) -> None:
    """Untimed (neither regulating nor constrained): the Twist goes in receive order from rospy's thread,
    the reflections come back as they arrive; the node's Odometry and LaserScan are states the world had."""
    address = str(inprocess_gateway.address)  # type: ignore[attr-defined]
    with world_federate(address, tmp_path) as (world, world_file):
        states = [state(world)]
        with running(start_bridge(roscore, address, "--world", str(world_file), "--untimed")) as bridge:
            bridge.out.wait_for("ros_bridge ready", 60)
            with running(start_teleop(roscore, "/rover", "0.5", "0.2", "60")) as teleop:
                seen = drive_untimed(world, teleop, states)
        assert bridge.status == 0, bridge.lines
    assert_seen_untimed(states, seen)


def test_ros1_without_ros_names_the_packages(tmp_path: pathlib.Path) -> None:
    """With no rospy to be found, the package still imports (it serves ROS 2 too), and choosing ROS 1 is an
    ImportError that says what to install."""
    env = dict(os.environ, HLACORE_ROS_DIST_PACKAGES=str(tmp_path))
    done = subprocess.run([sys.executable, "-c", "import hlacore.federates.ros_bridge as b; b.select(1)"],
                          capture_output=True, text=True, env=env, timeout=60, stdin=subprocess.DEVNULL)
    assert done.returncode == 1
    assert "ImportError: the ROS bridge needs ROS 1" in done.stderr, done.stderr
    assert "apt-get install -y --no-install-recommends ros-core python3-rospy" in done.stderr


def test_a_roscore_port_is_one_no_ros_process_can_be_handed_and_another_server_is_no_master() -> None:
    """roscore's port lies below the ephemeral range (roslaunch and rosout bind port 0; a CI run once had
    roslaunch's own server answer on the port picked for the master), and an XML-RPC server that is not a
    ROS master is not taken for one."""
    low = int(pathlib.Path("/proc/sys/net/ipv4/ip_local_port_range").read_text().split()[0])
    assert all(1024 <= free_master_port() < low for _ in range(20))
    server = xmlrpc.server.SimpleXMLRPCServer(("127.0.0.1", 0), logRequests=False)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        assert master_online(f"http://127.0.0.1:{server.server_address[1]}") is False
    finally:
        server.shutdown()
        server.server_close()
        thread.join(10)


CHECK_FINDER = """
import importlib.util, json, sys
import hlacore.federates.ros_bridge as bridge
bridge.import_rospy()
import rospy, std_msgs.msg
print(json.dumps({"rospy": rospy.__file__, "std_msgs": std_msgs.msg.__file__,
                  "dist_on_path": any(p.rstrip("/") == sys.argv[1].rstrip("/") for p in sys.path),
                  "paramiko": importlib.util.find_spec("paramiko") is not None}))
"""


def test_only_ros_modules_come_from_dist_packages(ros: None) -> None:
    """rospy and the messages load from Debian's dist-packages without putting it on sys.path: another
    Debian package in the same directory (paramiko, a dependency of ROS's) stays invisible."""
    assert os.path.isdir(os.path.join(DIST, "paramiko"))
    done = subprocess.run([sys.executable, "-c", CHECK_FINDER, DIST], capture_output=True, text=True,
                          timeout=60, stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stderr
    seen = json.loads(done.stdout)
    assert seen["rospy"].startswith(DIST) and seen["std_msgs"].startswith(DIST)
    assert seen["dist_on_path"] is False and seen["paramiko"] is False


def test_paper1_through_ros(roscore: dict[str, str], gateway_address: str, tmp_path: pathlib.Path) -> None:
    """Paper 1 through ROS, one command: the world federate and the bridge in one process, the controllers
    as a ROS node in another; the avatar never collides, passes once the obstacles have gone, stops
    before the wall (the checks of hlacore.experiments.paper1.checks.check)."""
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "hlacore.experiments.paper1.ros", str(out), "--rtig",
                           gateway_address], capture_output=True, text=True, env=roscore, timeout=300,
                          stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stdout + done.stderr
    assert check_node_run(done.stdout, out)["ros"] == 1
