"""Paper 1's chain (docs/ros-bridge.md): a DE-engine controller federate commands a stageros-style world node through
the RTI, the ROS bridge and ROS topics; and the bridge's other direction alone (HLA cmd_vel → Twist, the
node's state → WorldRobot reflections with federation timestamps); and the stage node on its own clock.

A real roscore is started per test (the `roscore` fixture of tests/conftest.py, ended by pid); the stage node,
the bridge and the DE federate are separate processes; the gateway is in-process or a real rtig. This process
never imports rospy. Skips without ROS, except under CI=true (see tests/federates/test_ros_bridge.py)."""

from __future__ import annotations

import contextlib
import json
import math
import pathlib
import subprocess
import sys
import time
from typing import Any, Iterator

import pytest

import hlacore.rti as rti
from hlacore import omt
from hlacore.experiments.paper1 import chain
from hlacore.link import Direction, Link
from hlacore.federates.robot_world import FEDERATION, FOM_PATH, World, codec, load_world
from hlacore.federates.ros_bridge.stage_node import last_step_at_or_before

from support import PEERS, Federate, RtigProcess
from support.nethosts import NetHosts
from support.paper1 import check_de_run, check_recording
from support.ros import (WORLD, Ros1Decoders, assert_stage_on_its_own_clock, f32, running, running_roscore,
                         start_bridge, start_teleop)

PERIOD, DT = 0.1, 0.01


def start_stage(env: dict[str, str], world_file: pathlib.Path, *args: str) -> subprocess.Popen[str]:
    return subprocess.Popen([sys.executable, "-m", "hlacore.federates.ros_bridge.stage_node", str(world_file),
                             *args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                            text=True, env=env)


def stage_files(tmp_path: pathlib.Path) -> tuple[pathlib.Path, pathlib.Path]:
    """The stage node's world file (WORLD) and where it writes its summary."""
    world_file = tmp_path / "rover.world"
    world_file.write_text(WORLD)
    return world_file, tmp_path / "stage.json"


@contextlib.contextmanager
def driver(address: str) -> Iterator[tuple[Federate, dict[Any, str], Any, dict[str, Any]]]:
    """The robot world's federation, created here, and the test's driver federate in it: it subscribes every
    attribute of the robot (handle -> name) and publishes the command interaction (its class and parameter
    handles by name). At the end the driver resigns and the federation is destroyed."""
    creator = rti.RTIAmbassador(address)
    creator.createFederationExecution(FEDERATION, str(FOM_PATH))
    try:
        fed = Federate(address, "driver", FEDERATION)
        try:
            rtia = fed.rtia
            robot_class = rtia.getObjectClassHandle(codec.OBJECT_CLASS)
            attributes = {rtia.getAttributeHandle(n, robot_class): n for n in codec.ATTRIBUTES}
            rtia.subscribeObjectClassAttributes(robot_class, list(attributes))
            cmd = rtia.getInteractionClassHandle(codec.INTERACTION)
            params = {n: rtia.getParameterHandle(n, cmd) for n in codec.PARAMETERS}
            rtia.publishInteractionClass(cmd)
            yield fed, attributes, cmd, params
        finally:
            fed.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    finally:
        creator.destroyFederationExecution(FEDERATION)


@pytest.mark.slow
def test_paper1_de_controller_through_ros(roscore: dict[str, str], gateway_address: str,
                                         tmp_path: pathlib.Path) -> None:
    """One command, paper 1's architecture: the DE controller federate, the bridge and the stage node, each
    in its own process. The paper-1 checks pass (no collision or stall, every obstacle crossed, the avatar
    held back, stopped before the wall); the node's poses at every tick are bit-identical to a World run
    alone with the DE federate's commands scheduled at their timestamps (so every command reached the node
    exactly at its federation time); the poses the DE model received are the node's, one lookahead later."""
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "hlacore.experiments.paper1.ros", str(out), "--controller",
                           "de", "--rtig", gateway_address], capture_output=True, text=True, env=roscore,
                          timeout=300, stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stdout + done.stderr
    check_de_run(done.stdout, out)


@pytest.mark.slow
def test_paper1_de_run_recorded_with_its_ros_topics(roscore: dict[str, str], tmp_path: pathlib.Path) -> None:
    """``--record`` on ROS 1: the run passes its checks, and its one MCAP file holds the federation's events and
    the bridged ROS 1 topics, which decode from their ros1msg schemas alone (tests/support/paper1.py)."""
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "hlacore.experiments.paper1.ros", str(out), "--controller", "de",
                           "--record"], capture_output=True, text=True, env=roscore, timeout=300,
                          stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stdout + done.stderr
    check_recording(out, check_de_run(done.stdout, out), Ros1Decoders(), "ros1", "ros1msg")


@pytest.mark.slow
def test_paper1_chain_with_world_bridge_and_controller_on_hosts_of_their_own(ros: None, nethosts: NetHosts,
                                                                          tmp_path: pathlib.Path) -> None:
    """Paper 1's chain across machines (test hosts, docs/networking.md): the stage node (the world) on host "world",
    the bridge and roscore on host "bridge", the DE controller federate on host "control", rtig on this one. The
    world and the bridge share a LAN for ROS (nodes connect on ports they choose); the bridge and the controller
    reach the gateway only through emulated links (2 ms each way). The paper-1 checks pass, as on one machine."""
    world, bridge, control = nethosts.add("world"), nethosts.add("bridge"), nethosts.add("control")
    world_ip, bridge_ip = nethosts.lan(world, bridge)
    two_ms = Direction(delay=0.002)
    with RtigProcess(tmp_path) as server, \
            Link((bridge.router, 0), ("127.0.0.1", server.port), up=two_ms, down=two_ms, seed=1) as bridge_link, \
            Link((control.router, 0), ("127.0.0.1", server.port), up=two_ms, down=two_ms, seed=2) as control_link, \
            running_roscore(tmp_path / "ros", ip=bridge_ip, prefix=bridge.exec_prefix(), reach=bridge.address) as env:
        master = env["ROS_MASTER_URI"]
        ros_env = {k: env[k] for k in ("ROS_HOME", "ROS_LOG_DIR")}
        result = chain.run(server.address, str(tmp_path / "out"), hosts={
            "world": chain.Placement(tuple(world.exec_prefix()), None,
                                     dict(ros_env, ROS_MASTER_URI=master, ROS_IP=world_ip)),
            "bridge": chain.Placement(tuple(bridge.exec_prefix()), bridge_link.address,
                                      dict(ros_env, ROS_MASTER_URI=master, ROS_IP=bridge_ip)),
            "controller": chain.Placement(tuple(control.exec_prefix()), control_link.address),
        })
    summary = result.summary()
    print(f"\npaper 1 across hosts: {json.dumps(summary)}")
    assert result.checks == {"no_stall": True, "no_overlap": True, "obstacles_crossed": True, "held_back": True,
                             "stopped_before_wall": True}, summary
    assert summary["grants"] == 300 and summary["late_states"] == 0 and summary["late_acks"] == 0
    assert control_link.counters["up"].bytes > 0 and bridge_link.counters["up"].bytes > 0


def test_cmd_vel_interaction_drives_stage_node_and_odometry_comes_back(
        roscore: dict[str, str], gateway_address: str, tmp_path: pathlib.Path) -> None:
    """A federate sends cmd_vel interactions; the bridge publishes them as Twist to the stage node, which
    drives its robot; the node's odometry, ground truth and scan come back as WorldRobot reflections stamped
    with federation time G + L, holding exactly the state a World alone had at G with the same commands.
    A command for a robot the node does not have, or that does not decode, is dropped by the bridge, a NaN
    one by the node (counted; both keep serving)."""
    world_file, summary = stage_files(tmp_path)
    commands: list[tuple[float, float, float]] = []
    with (driver(gateway_address) as (fed, attributes, cmd, params),
          running(start_stage(roscore, world_file, "--summary", str(summary))) as stage):
        stage.out.wait_for("stage_node ready", 60)
        rtia = fed.rtia
        fed.enable_time(lookahead=PERIOD)
        with running(start_bridge(roscore, gateway_address, "--world-node", str(world_file), "--acks", "--clock",
                                  "--await-state", "5", "--wait-connections", "60")) as bridge:
            bridge.out.wait_for("ros_bridge ready", 60)
            now = 0.0
            for k in range(20):
                linear, angular = (0.5, 0.2) if k < 15 else (0.0, 0.0)
                stamp = now + PERIOD
                rtia.sendInteraction(cmd, {params["robot"]: codec.NAME.pack("rover"),
                                           params["linear"]: codec.SPEED.pack(linear),
                                           params["angular"]: codec.SPEED.pack(angular)}, "test", stamp)
                commands.append((stamp, linear, angular))
                if k == 5:  # bad input: an unknown robot, a speed that does not decode, a NaN speed
                    for robot, bad in (("ghost", codec.SPEED.pack(0.3)), ("rover", b"\x00"),
                                       ("rover", codec.SPEED.pack(math.nan))):
                        rtia.sendInteraction(cmd, {params["robot"]: codec.NAME.pack(robot), params["linear"]: bad,
                                                   params["angular"]: codec.SPEED.pack(0.0)}, "test", stamp)
                now += PERIOD  # the bridge's grid when it serves a node: sums
                rtia.timeAdvanceRequest(now)
                assert rtia.await_grant(30) == now
    assert bridge.status == 0, bridge.lines
    assert any(line.startswith("ros_bridge stopped") and " 0 late acks" in line and " 2 ignored" in line
               for line in bridge.lines), bridge.lines
    ran = json.loads(summary.read_text())
    assert ran["rejected"] == 1 and ran["commands"] >= 20, stage.lines
    names = {args[0]: args[2] for args in fed.amb.named("discoverObjectInstance")}
    assert set(names.values()) == {"rover"}
    reflections: list[tuple[float, dict[str, Any]]] = []
    kinds: dict[str, omt.HLAdataType] = {"name": codec.NAME, "pose": codec.POSE, "odometry": codec.ODOMETRY,
                                         "ranges": codec.RANGES, "stall": codec.STALL}
    for obj, values, _tag, _order, _transport, *rest in fed.amb.named("reflectAttributeValues"):
        assert names[obj] == "rover" and rest, "every reflection is timestamped"
        reflections.append((float(rest[0]), {attributes[h]: codec.unpack(kinds[attributes[h]], v)
                                             for h, v in values.items()}))
    # stamped G + L for the bridge's grants G = 0, 0.1, 0.1 + 0.1, ... (up to the driver's last grant)
    grants = [0.0]
    while len(grants) < len(reflections):
        grants.append(grants[-1] + PERIOD)
    assert [t for t, _ in reflections] == [g + PERIOD for g in grants]
    assert len(reflections) == 20 and reflections[0][1]["name"] in (b"rover", "rover")
    alone = World(load_world(WORLD), dt=DT, watchdog=0.2)
    for stamp, linear, angular in commands:
        alone.schedule(stamp, "rover", linear, angular)
    for (stamp, values), grant in zip(reflections, grants):
        alone.advance(last_step_at_or_before(grant, DT) - alone.steps)
        r = alone.robot("rover")
        odom = values["odometry"]
        assert (odom[0], odom[1], odom[3], odom[4]) == (r.odometry.x, r.odometry.y, r.linear, r.angular), stamp
        assert odom[2] == pytest.approx(r.odometry.theta, abs=1e-12)
        assert list(values["pose"][:2]) == [r.pose.x, r.pose.y]
        assert list(values["ranges"]) == [f32(v) for v in r.ranges]
        assert not values.get("stall", False)  # Bool is unstamped: it may come with the next update
    final = reflections[-1][1]["odometry"]
    assert final[0] > 0.5 and final[1] > 0.0 and final[3] == 0.0  # it drove, turned left, and was stopped
    assert any(v["odometry"][3] == 0.5 for _, v in reflections)


def test_bridge_reticks_until_the_nodes_first_state(roscore: dict[str, str], gateway_address: str) -> None:
    """A rospy subscriber counts its connection before the node's publisher has added it, so a node's first
    state can be lost even after ``--wait-connections`` (1 run in 15 of the paper-1 chain). The bridge then
    re-publishes the first /clock until every state topic has spoken: a node deaf to its first two ticks
    costs no late state, and its state stamped 0 still comes before the grants."""
    node = subprocess.Popen([sys.executable, str(PEERS / "ros_deaf_start.py"), "/rover", "2"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, text=True,
                            env=roscore)
    with running(node) as deaf:
        deaf.out.wait_for("deaf_start ready", 60)
        with running(start_bridge(roscore, gateway_address, "--robot-node", "rover", "--sensor", "none", "--clock",
                                  "--await-state", "5", "--wait-connections", "30", "--until", "0.3")) as bridge:
            stopped = bridge.out.wait_for("ros_bridge stopped", 60)
            bridge.proc.wait(60)  # it resigns after that line
    assert bridge.status == 0 and "0 late states, 0 late acks" in stopped, bridge.lines
    seen = json.loads(deaf.lines[-1])
    assert seen["ignored"] == 2
    assert seen["published"] == pytest.approx([0.0, 0.1, 0.2, 0.3], abs=1e-9)


def test_stage_node_on_its_own_clock(roscore: dict[str, str], tmp_path: pathlib.Path) -> None:
    """Like stageros: with --rate the node runs its own clock (/clock, /use_sim_time), applies Twist on
    /<robot>/cmd_vel and publishes odom, base_scan and range stamped with sim time on interval_sim's grid."""
    world_file, summary = stage_files(tmp_path)
    with running(start_stage(roscore, world_file, "--rate", "5", "--summary", str(summary))) as stage:
        stage.out.wait_for("stage_node ready", 60)
        with running(start_teleop(roscore, "/rover", "0.5", "0.2", "60", "--clock")) as teleop:
            seen = teleop.report(90)
    assert_stage_on_its_own_clock(stage, seen, summary, stamp_tolerance=1e-8)
    assert seen["range"]["range"] == min(seen["scan"]["ranges"]) or seen["range"]["stamp"] != seen["scan"]["stamp"]
    assert seen["use_sim_time"] is True and seen["clock"] >= seen["odom"]["stamp"]


def test_untimed_bridge_to_a_free_running_node(roscore: dict[str, str], inprocess_gateway: Any,
                                               tmp_path: pathlib.Path) -> None:
    """Untimed, against a node on its own clock: cmd_vel interactions in receive order become Twists at
    once, and the node's state comes back as receive-order reflections (no timestamp), each a state the
    node had."""
    address = str(inprocess_gateway.address)
    world_file, summary = stage_files(tmp_path)
    with (driver(address) as (fed, attributes, cmd, params),
          running(start_stage(roscore, world_file, "--rate", "1", "--summary", str(summary))) as stage):
        stage.out.wait_for("stage_node ready", 60)
        rtia = fed.rtia
        with running(start_bridge(roscore, address, "--world-node", str(world_file), "--untimed",
                                  "--wait-connections", "60")) as bridge:
            bridge.out.wait_for("ros_bridge ready", 60)
            poses: list[tuple[float, float]] = []
            deadline = time.monotonic() + 60
            while not poses or poses[-1][0] <= 0.3:
                assert time.monotonic() < deadline, f"the robot did not get past x = 0.3: {poses[-3:]}"
                rtia.sendInteraction(cmd, {params["robot"]: codec.NAME.pack("rover"),
                                           params["linear"]: codec.SPEED.pack(0.5),
                                           params["angular"]: codec.SPEED.pack(0.0)}, "test")
                rtia.tick(0.05, 0.05)
                for obj, values, _tag, _order, _transport, *rest in fed.amb.named("reflectAttributeValues"):
                    assert not rest, "untimed: receive order, no timestamp"
                    for h, v in values.items():
                        if attributes[h] == "pose":
                            x, y, _theta = codec.unpack(codec.POSE, v)  # type: ignore[misc]
                            poses.append((x, y))
                fed.amb.calls.clear()
    assert bridge.status == 0, bridge.lines
    had = {(p[0], p[1]) for p in [[0.0, 0.0]] + [ps["rover"] for ps in json.loads(summary.read_text())["poses"]]}
    assert set(poses) <= had and poses[-1][0] > 0.3
