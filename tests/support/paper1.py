"""Paper 1 through ROS (``python -m hlacore.experiments.paper1.ros OUT``, the controllers as a ROS node, and
``--controller de``, paper 1's chain), checked the same whichever ROS carries it, and its recording
(``--record``): tests/federates/test_ros_bridge.py and tests/experiments/test_ros_paper1_de.py (ROS 1),
test_ros2_paper1_de.py (ROS 2)."""

from __future__ import annotations

import json
import pathlib
from typing import Any

import pytest
from mcap.decoder import DecoderFactory
from mcap.reader import make_reader

from hlacore.experiments.paper1 import scenario as paper1
from hlacore.federates.robot_world import World
from hlacore.recording import read

PERIOD, DT = 0.1, 0.01


def check_node_run(stdout: str, out: pathlib.Path) -> dict[str, Any]:
    """The checks of a run with the controllers as a ROS node, given its output and OUTDIR: the paper-1 checks
    pass (the avatar never collides, passes once the obstacles have gone, stops before the wall), 301 grants to
    30 s, every cycle's commands sent; trace and snapshot written. Returns the run's JSON summary."""
    summary = json.loads(stdout.strip().splitlines()[-1])
    assert summary["checks"] == {"no_stall": True, "no_overlap": True, "obstacles_crossed": True,
                                 "held_back": True, "stopped_before_wall": True}
    assert summary["grants"] == 301 and summary["end"] == pytest.approx(30.0)
    assert 0.0 < summary["wall_gap"] <= 0.5 and summary["sent"] > 4 * 250
    assert (out / "paper1-ros-trace.csv").read_text().count("\n") == 302
    assert (out / "paper1-ros-snapshot.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    return summary


def check_de_run(stdout: str, out: pathlib.Path) -> dict[str, Any]:
    """The run's checks, given its output and OUTDIR: the paper-1 checks pass (no collision or stall, every
    obstacle crossed, the avatar held back, stopped before the wall), no late state or acknowledgement; the
    node's poses at every tick are bit-identical to a World run alone with the DE federate's commands
    scheduled at their timestamps (every command reached the node exactly at its federation time); the poses
    the DE model received are the node's, one lookahead later; the avatar's speeds follow the paper-1 rule;
    trace and snapshot written. Returns the run's JSON summary."""
    summary = json.loads(stdout.strip().splitlines()[-1])
    assert summary["checks"] == {"no_stall": True, "no_overlap": True, "obstacles_crossed": True,
                                 "held_back": True, "stopped_before_wall": True}
    assert summary["controller"] == "de" and summary["grants"] == 300 and summary["end"] == pytest.approx(30.0)
    assert summary["late_states"] == 0 and summary["late_acks"] == 0 and 0.0 < summary["wall_gap"] <= 0.5
    assert summary["avatar_commands"] == 299 and summary["sent"] == 299 + 3 * 299

    stage = json.loads((out / "stage-node.json").read_text())
    de = json.loads((out / "de-federate.json").read_text())
    assert all(v == 0 for v in stage["stall_steps"].values())
    # every command, stamped DE time + lookahead, acted from exactly that step in the node
    alone = World(paper1.world_spec(), dt=DT, watchdog=0.2)
    for t, robot, linear in de["commands"]:
        alone.schedule(t + PERIOD, robot, linear, 0.0)
    for t, poses in zip(stage["times"], stage["poses"]):
        alone.advance_to(t)
        assert {n: [p.x, p.y, p.theta] for n, p in alone.poses().items()} == poses, t
    # the DE model saw the node's state of G at G + L (x, y exact through nav_msgs/Odometry)
    by_tick = {round(t / PERIOD): poses for t, poses in zip(stage["times"], stage["poses"])}
    assert len(de["poses"]) == 4 * 299  # states of 0 .. 29.8 s (that of 29.9 s is stamped past the end)
    for t, robot, pose in de["poses"][4:]:  # the first four are the initial state (time 0)
        node = by_tick[round(t / PERIOD) - 1][robot]
        assert pose[:2] == node[:2] and pose[2] == pytest.approx(node[2], abs=1e-12)
    # the avatar was commanded go, slow and stop by the paper-1 rule on the distance it read
    rule = paper1.Controller()
    assert {speed for _t, _d, speed in de["control"]} == {rule.go, rule.slow, 0.0}
    assert all(speed == rule(d) for _t, d, speed in de["control"])
    lines = (out / "paper1-de-trace.csv").read_text().splitlines()
    assert len(lines) == 301 and lines[0].startswith("time,distance,avatar_speed,avatar_x")
    assert (out / "paper1-de-snapshot.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    return summary


def check_recording(out: pathlib.Path, summary: dict[str, Any], decoders: DecoderFactory, encoding: str,
                    schema_encoding: str) -> None:
    """The ``--record`` run's file OUTDIR/paper1-de.mcap: the bridged topics are channels of ``encoding`` with
    schemas of ``schema_encoding`` named after their message types, and decode with ``decoders``: the world
    node's odometry at every tick (published at its header's stamp) is the pose the node reported, and there is
    one Twist for each cmd_vel interaction the federation's events in the same file hold for the avatar."""
    recording = out / "paper1-de.mcap"
    with open(recording, "rb") as f:
        reader = make_reader(f, decoder_factories=[decoders])
        summary_section = reader.get_summary()
        assert summary_section is not None
        schemas = {c.topic: summary_section.schemas[c.schema_id] for c in summary_section.channels.values()
                   if c.message_encoding == encoding}
        odom: dict[int, tuple[float, float]] = {}
        twists: list[float] = []
        clocks = 0
        for _schema, channel, message, decoded in reader.iter_decoded_messages(
                topics=["/avatar/odom", "/avatar/cmd_vel", "/clock"]):
            if channel.topic == "/avatar/odom":
                stamp = decoded.header.stamp
                nanoseconds = (stamp.sec * 10**9 + stamp.nanosec if hasattr(stamp, "nanosec")  # ROS 2
                               else stamp.secs * 10**9 + stamp.nsecs)  # ROS 1
                odom[round(nanoseconds * 1e-9 / PERIOD)] = (decoded.pose.pose.position.x,
                                                            decoded.pose.pose.position.y)
                assert message.publish_time == nanoseconds
            elif channel.topic == "/avatar/cmd_vel":
                twists.append(decoded.linear.x)
            else:
                clocks += 1
    assert {topic: (s.name, s.encoding) for topic, s in schemas.items()
            if topic in ("/avatar/odom", "/avatar/cmd_vel", "/avatar/base_scan", "/clock")} == {
        "/avatar/odom": ("nav_msgs/Odometry", schema_encoding), "/avatar/cmd_vel": ("geometry_msgs/Twist", schema_encoding),
        "/avatar/base_scan": ("sensor_msgs/LaserScan", schema_encoding), "/clock": ("rosgraph_msgs/Clock", schema_encoding)}
    stage = json.loads((out / "stage-node.json").read_text())
    for t, poses in zip(stage["times"], stage["poses"]):  # the node's odometry of every tick, decoded
        assert odom[round(t / PERIOD)] == pytest.approx(tuple(poses["avatar"][:2]), abs=0.0), t
    assert clocks >= 300
    commands = [e for e in read(recording) if e.kind == "interaction" and e.class_name == "cmd_vel"
                and b"avatar" in e.values()["robot"]]
    assert len(commands) == len(twists) == summary["avatar_commands"]
