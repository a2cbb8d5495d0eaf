"""The ROS 2 bridge with real rclpy nodes, each in a process of its own, inside a network namespace that has
only loopback (Fast DDS binds UDP sockets on every interface it sees; there it sees only ``lo``), made and
removed by the test. The gateway and the world federate run in this process, outside the namespace: the
bridge reaches the gateway through a Unix socket (a path, which no network namespace separates). This process
never imports rclpy.

The tests run whenever ROS 2's wheels are installed (hlacore.federates.ros_bridge.install_ros2, run by scripts/test.sh);
without them they skip, except under CI=true, where that is a failure."""

from __future__ import annotations

import math
import os
import pathlib
import re
import signal
import subprocess
import sys
import time
from typing import Iterator

import pytest

import hlacore

from support import PEERS, running_rtig
from support.ros import (MAX_CYCLES, PERIOD, Running, assert_seen_timed, assert_seen_untimed, drive_untimed, running,
                         state, world_federate)
from support.nethosts import LoopbackNamespace
from support.ros2 import Ros2Space, root_udp_owners, ros2_space, udp_sockets_of


@pytest.fixture
def space(tmp_path: pathlib.Path) -> Iterator[Ros2Space]:
    """A loopback-only namespace for the test's ROS 2 processes (removed after; none may be left in it)."""
    with ros2_space(tmp_path) as s:
        yield s


@pytest.fixture(params=["in-process", "rtig"])
def unix_gateway(request: pytest.FixtureRequest, tmp_path: pathlib.Path) -> Iterator[str]:
    """A gateway listening on a Unix socket too, both kinds (the in-process one, the rtig executable): its
    ``unix:PATH`` address, which reaches it from inside the namespace."""
    path = tmp_path / "rtig.sock"
    if request.param == "in-process":
        with hlacore.Gateway(port=0, unix=path) as gateway:
            yield str(gateway.unix_address)
    else:
        with running_rtig(tmp_path, "--unix", str(path)) as server:
            yield str(server.unix_address)


def bridge_args(address: str, *args: str) -> list[str]:
    return ["-m", "hlacore.federates.ros_bridge", "--ros", "2", "--rtig", address, *args]


def teleop_args(*args: str, sim_time: bool = True) -> list[str]:
    """tests/peers/ros2_teleop.py on /rover; ``sim_time``: its node's clock on /clock (``use_sim_time``)."""
    return [str(PEERS / "ros2_teleop.py"), "/rover", *args, "--ros-args", "-p",
            f"use_sim_time:={'true' if sim_time else 'false'}"]


def test_dds_stays_in_the_namespace(space: Ros2Space) -> None:
    """Two rclpy processes in the namespace exchange Twists over DDS; every UDP socket they hold is in the
    namespace (which has no interface but ``lo``) and none in the root namespace; DDS's discovery ports of
    the test's domain are among them. A listener of the same domain and topic in another namespace hears
    nothing meanwhile (Fast DDS's shared memory crosses no namespace either: without discovery over the
    network, nothing flows)."""
    assert space.namespace.links() == ["lo"]
    listen = [str(PEERS / "ros2_echo.py"), "listen", "/probe/cmd_vel", "100"]
    with LoopbackNamespace("outside") as outside, \
            running(subprocess.Popen([*outside.exec_prefix(), sys.executable, *listen], stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, text=True,
                                     env=space.env)) as outsider:
        outsider.out.wait_for("listen ready", 30)
        with running(space.popen(listen)) as listener, \
                running(space.popen([str(PEERS / "ros2_echo.py"), "talk", "/probe/cmd_vel"])) as talker:
            listener.out.wait_for("listen ready", 30)
            listener.out.wait_for("listen got 100", 30)
            pids = [listener.proc.pid, talker.proc.pid]
            inside = space.namespace.inode()
            assert all(os.stat(f"/proc/{pid}/ns/net").st_ino == inside for pid in pids)
            sockets = {pid: udp_sockets_of(pid) for pid in pids}
            assert all(sockets.values()), sockets  # DDS did open UDP sockets ...
            assert not set(pids) & root_udp_owners()  # ... and none of them is in the root namespace
            ports = {int(line.split()[1].split(":")[1], 16) for table in ("udp", "udp6")
                     for line in pathlib.Path(f"/proc/{pids[0]}/net/{table}").read_text().splitlines()[1:]}
            discovery = 7400 + 250 * space.domain  # the RTPS well-known multicast discovery port of the domain
            assert discovery in ports, (discovery, sorted(ports))
    assert listener.status == 0 and talker.status == 0, (listener.lines, talker.lines)
    assert outsider.status == 0 and "listen heard 0\n" in outsider.lines, outsider.lines
    assert outside.leftovers == []


def test_timed_bridge_round_trip(space: Ros2Space, unix_gateway: str, tmp_path: pathlib.Path) -> None:
    """A Twist from an rclpy node → cmd_vel → the world moves the robot → Odometry, LaserScan, Range and
    /clock on ROS 2, stamped with federation time and equal to the world's state at the grant they were
    taken; the rclpy node's own clock (``use_sim_time``) is federation time."""
    with world_federate(unix_gateway, tmp_path) as (world, world_file):
        states = {0: state(world)}
        with running(space.popen(bridge_args(unix_gateway, "--world", str(world_file), "--clock", "--rate",
                                             "20"))) as bridge:
            bridge.out.wait_for("ros_bridge ready", 60)
            with running(space.popen(teleop_args("0.5", "0.2", "60", "--clock"))) as teleop:
                for _ in range(MAX_CYCLES):
                    granted = world.advance(timeout=30)
                    states[round(granted / PERIOD)] = state(world)
                    if teleop.proc.poll() is not None:
                        break
                seen = teleop.report(30)
        assert bridge.status == 0, bridge.lines
        assert any(line.startswith("ros_bridge stopped at") and "ROS 2" in line for line in bridge.lines)

    assert_seen_timed(states, seen, stamp_tolerance=1e-9)
    odom = seen["odom"]
    # the node runs in federation time: when the odometry came, its clock was a /clock tick (a grant), not
    # the wall clock's 1.7e9 s; ticks and Odometry travel on different topics, so one may overtake the other
    node_time = odom["node_time"]
    assert node_time > 0 and round(node_time / PERIOD) * PERIOD == pytest.approx(node_time, abs=1e-9), odom
    assert abs(node_time - odom["stamp"]) < 2.0, odom
    # /clock carries grants (on the bridge's grid); the node took use_sim_time
    assert seen["clock"] > 0 and round(seen["clock"] / PERIOD) * PERIOD == pytest.approx(seen["clock"], abs=1e-9)
    assert seen["use_sim_time"] is True


def test_untimed_bridge_round_trip(space: Ros2Space, tmp_path: pathlib.Path) -> None:
    """Untimed (neither regulating nor constrained): the Twist goes into the federation in receive order, the
    reflections come back as they arrive, stamped with the wall clock (ROS time without /clock); the node's
    Odometry and LaserScan are states the world had."""
    with hlacore.Gateway(port=0, unix=tmp_path / "rtig.sock") as gateway:
        address = str(gateway.unix_address)
        with world_federate(address, tmp_path) as (world, world_file):
            states = [state(world)]
            with running(space.popen(bridge_args(address, "--world", str(world_file), "--untimed"))) as bridge:
                bridge.out.wait_for("ros_bridge ready", 60)
                started = time.time()
                with running(space.popen(teleop_args("0.5", "0.2", "60", sim_time=False))) as teleop:
                    seen = drive_untimed(world, teleop, states)
            assert bridge.status == 0, bridge.lines
    assert_seen_untimed(states, seen)
    assert started <= seen["odom"]["stamp"] <= time.time() and seen["use_sim_time"] is False  # wall time


def drain(run: Running) -> list[str]:
    """Every line the process has printed so far (without waiting)."""
    while not run.out.lines.empty():
        run.out.seen.append(run.out.lines.get())
    return run.out.seen


@pytest.mark.slow  # four rclpy nodes, a killed one seen gone after its 3 s lease, 20 more grants
def test_bad_input_is_said_once_and_the_federation_goes_on(space: Ros2Space, unix_gateway: str,
                                                           tmp_path: pathlib.Path) -> None:
    """NaN Twists on a bridged cmd_vel, a std_msgs/String publisher and a best-effort Odometry publisher on a
    bridged (reliable) Odometry topic, and the robot node publishing that Odometry killed: the bridge says
    each once, sends no NaN into the federation, and the world federate keeps being granted; nothing is left
    running."""
    with world_federate(unix_gateway, tmp_path) as (world, world_file):
        with running(space.popen(bridge_args(unix_gateway, "--world", str(world_file), "--robot-node", "bot",
                                             "--sensor", "none", "--rate", "20"))) as bridge:
            bridge.out.wait_for("ros_bridge ready", 60)
            with running(space.popen([str(PEERS / "ros2_bad.py"), "nan", "/rover/cmd_vel"])) as nan, \
                    running(space.popen([str(PEERS / "ros2_bad.py"), "wrong", "/bot/odom"])) as wrong, \
                    running(space.popen([str(PEERS / "ros2_bad.py"), "besteffort", "/bot/odom"])) as sensor, \
                    running(space.popen([str(PEERS / "ros2_bad.py"), "odom", "/bot/odom"])) as robot:
                for peer in (nan, wrong, sensor, robot):
                    peer.out.wait_for(f"{peer.proc.args[-2]} ready", 30)  # type: ignore[index]
                robot.out.wait_for("odom matched", 30)  # the bridge hears the robot before it dies
                killed_at, after_death = None, 0
                for _ in range(MAX_CYCLES):
                    world.advance(timeout=30)
                    assert math.isfinite(world.world.robot("rover").linear)
                    said = [line for line in drain(bridge) if line.startswith("ros_bridge: ")]
                    if killed_at is None and any("non-finite" in line for line in said) \
                            and any("std_msgs/msg/String" in line for line in said) \
                            and any("QoS does not match" in line for line in said):
                        robot.proc.send_signal(signal.SIGKILL)  # the robot node dies, without a goodbye
                        killed_at = time.monotonic()
                    if any("no publisher left on /bot/odom" in line for line in said):
                        after_death += 1
                        if after_death == 20:  # the federation went on: 20 more grants
                            break
                dead_after = time.monotonic() - (killed_at or math.inf)
        assert bridge.status == 0, bridge.lines
    said = [line for line in bridge.lines if line.startswith("ros_bridge: ")]
    assert after_death == 20, "".join(bridge.lines)
    assert len([line for line in said if "non-finite" in line]) == 1, said  # said once, for many NaN Twists
    assert len([line for line in said if "std_msgs/msg/String" in line]) == 1, said
    assert len([line for line in said if "/bot/odom: a publisher whose QoS does not match "
                "(RMW_QOS_POLICY_RELIABILITY" in line]) == 1, said
    assert len([line for line in said if "no publisher left on /bot/odom" in line]) == 1, said
    stopped = next(line for line in bridge.lines if line.startswith("ros_bridge stopped"))
    assert int(re.search(r"(\d+) rejected", stopped)[1]) > 1, stopped  # type: ignore[index]
    # the robot's odometry went into the federation before it died
    assert int(re.search(r"(\d+) updates", stopped)[1]) > 1, stopped  # type: ignore[index]
    print(f"the killed node was said gone after {dead_after:.1f} s")
