"""ROS 1 for the tests: whether it is installed, a real roscore on a free port, the bridge and tests/peers'
ROS nodes started as processes and stopped by pid; and, for the ROS 1 and ROS 2 bridge tests alike, the rover
world they drive (its federate in the test's process) and reading a process's output."""

from __future__ import annotations

import contextlib
import json
import math
import os
import pathlib
import queue
import signal
import struct
import subprocess
import sys
import threading
import time
import xmlrpc.client
from typing import Any, Callable, Iterator, Optional, Sequence

import pytest
from mcap.decoder import DecoderFactory as McapDecoderFactory
from mcap.records import Schema

import hlacore.rti as rti
from hlacore.federates.robot_world import FEDERATION, FOM_PATH, World, WorldFederate, load_world
from hlacore.federates.robot_world.federate import Pose
from hlacore.federates.ros_bridge import ros_import
from hlacore.federates.ros_bridge.children import stop_process
from hlacore.federates.ros_bridge.master import free_master_port

from support import PEERS, ROVER_MODEL

DT, PERIOD = 0.01, 0.1  # the rover world's physics step and the federates' period
MAX_CYCLES = 4000  # bounds each round-trip run: 400 s of federation time
DIST = os.environ.get("HLACORE_ROS_DIST_PACKAGES", "/usr/lib/python3/dist-packages")
WORLD = ROVER_MODEL + """
bot( pose [ 0 0 0 0 ] name "rover" )
model( pose [ 3 0 0 0 ] size [ 0.2 3 0.5 ] )
"""


def ros_installed() -> bool:
    return os.path.exists("/usr/bin/roscore") and os.path.isdir(os.path.join(DIST, "rospy"))


def require_ros() -> None:
    """Skip without ROS, except under CI where scripts/test.sh must have installed it."""
    if not ros_installed():
        message = "ROS 1 is not installed (./scripts/install-ros.sh installs it from Debian)"
        if os.environ.get("CI"):
            pytest.fail(message + "; CI=true requires it")
        pytest.skip(message)


class Lines:
    """A subprocess's stdout read line by line on a thread, for bounded waits."""

    def __init__(self, proc: subprocess.Popen[str]) -> None:
        self.proc = proc
        self.lines: "queue.Queue[str]" = queue.Queue()
        self.seen: list[str] = []
        assert proc.stdout is not None
        stdout = proc.stdout
        self._thread = threading.Thread(target=lambda: [self.lines.put(line) for line in stdout], daemon=True)
        self._thread.start()

    def wait_for(self, prefix: str, timeout: float) -> str:
        deadline = time.monotonic() + timeout
        while True:
            try:
                line = self.lines.get(timeout=max(0.0, min(0.1, deadline - time.monotonic())))
            except queue.Empty:
                if time.monotonic() > deadline or self.proc.poll() is not None and self.lines.empty():
                    raise AssertionError(f"no {prefix!r} line (exit {self.proc.poll()}); saw {self.seen}")
                continue
            self.seen.append(line)
            if line.startswith(prefix):
                return line

    def rest(self, timeout: float = 5.0) -> list[str]:
        """Once the process has ended: every line not read yet appended to those seen; closes the pipe."""
        self._thread.join(timeout)
        while not self.lines.empty():
            self.seen.append(self.lines.get())
        if not self._thread.is_alive() and self.proc.stdout is not None:
            self.proc.stdout.close()
        return self.seen


@contextlib.contextmanager
def running_roscore(home: pathlib.Path, ip: str = "127.0.0.1", prefix: Sequence[str] = (),
                    reach: str = "127.0.0.1") -> Iterator[dict[str, str]]:
    """A real roscore on a free port, its ROS_HOME (and log) in `home`, stopped by pid at the end; yields
    the environment for ROS processes. On another host: `prefix` runs it there, `ip` is its address there
    (the master's URI), `reach` where this process reaches it to see it up."""
    home.mkdir(parents=True, exist_ok=True)
    port = free_master_port()
    env = dict(os.environ, ROS_MASTER_URI=f"http://{ip}:{port}", ROS_IP=ip, ROS_HOME=str(home),
               ROS_LOG_DIR=str(home / "log"), PYTHONUNBUFFERED="1")
    env.pop("ROS_HOSTNAME", None)
    with open(home / "roscore.log", "wb") as log:
        proc = subprocess.Popen([*prefix, "roscore", "-p", str(port)], stdout=log, stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL, env=env)
        try:
            deadline = time.monotonic() + 30
            while True:
                try:
                    with xmlrpc.client.ServerProxy(f"http://{reach}:{port}") as master:
                        master.getPid("/hlacore_test")
                    break
                except OSError:
                    if proc.poll() is not None or time.monotonic() > deadline:
                        raise AssertionError("roscore did not start: "
                                             + (home / "roscore.log").read_text(errors="replace"))
                    time.sleep(0.1)
            yield env
        finally:
            stop_process(proc, signal.SIGINT)


def start_bridge(env: dict[str, str], address: str, *args: str) -> subprocess.Popen[str]:
    return subprocess.Popen([sys.executable, "-m", "hlacore.federates.ros_bridge", "--rtig", address, *args],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                            text=True, env=env)


def start_teleop(env: dict[str, str], *args: str) -> subprocess.Popen[str]:
    return subprocess.Popen([sys.executable, str(PEERS / "ros_teleop.py"), *args], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, text=True, env=env)


class Running:
    """A started process and its output (Lines); once `running` has stopped it, its exit status and every
    line it printed."""

    def __init__(self, proc: subprocess.Popen[str]) -> None:
        self.proc, self.out = proc, Lines(proc)
        self.status: Optional[int] = None
        self.lines: list[str] = []

    def report(self, timeout: float) -> Any:
        """For a node that ends by itself (tests/peers/ros_teleop.py): it exits 0 within `timeout` s; the JSON
        line it printed last."""
        assert self.proc.wait(timeout) == 0, self.out.rest()
        return json.loads(self.out.wait_for("{", 5))


@contextlib.contextmanager
def running(proc: subprocess.Popen[str]) -> Iterator[Running]:
    """`proc` (one of the start_* above) for the block; at the end, even on failure, it is stopped by pid
    (stop_process; a process that has exited is only reaped) and the rest of its output is read."""
    run = Running(proc)
    try:
        yield run
    finally:
        run.status = stop_process(proc)
        run.lines = run.out.rest()


def f32(x: float) -> float:
    """x rounded to a float32, as a ROS message carries it."""
    return float(struct.unpack("f", struct.pack("f", x))[0])


@contextlib.contextmanager
def world_federate(address: str, tmp_path: pathlib.Path) -> Iterator[tuple[WorldFederate, pathlib.Path]]:
    creator = rti.RTIAmbassador(address)
    creator.createFederationExecution(FEDERATION, str(FOM_PATH))
    world_file = tmp_path / "rover.world"
    world_file.write_text(WORLD)
    fed = WorldFederate.join(World(load_world(WORLD), dt=DT, watchdog=None), address, period=PERIOD,
                             lookahead=PERIOD)
    try:
        yield fed, world_file
    finally:
        fed.resign()
        creator.destroyFederationExecution(FEDERATION)


State = tuple[Pose, tuple[float, ...], list[float]]  # the robot's pose, odometry and speeds, ranges


def state(fed: WorldFederate) -> State:
    r = fed.world.robot("rover")
    return r.pose, (r.odometry.x, r.odometry.y, r.odometry.theta, r.linear, r.angular), list(r.ranges)


def drive_untimed(world: WorldFederate, teleop: Running, states: list[State]) -> Any:
    """Paces the world, which alone regulates, appending its state at each step, until the teleop node (0.5 m/s)
    ends; the node's report."""
    for _ in range(MAX_CYCLES):
        world.advance(timeout=30)
        states.append(state(world))
        if teleop.proc.poll() is not None:
            break
        time.sleep(0.005)
    return teleop.report(30)


def assert_seen_untimed(states: list[State], seen: Any) -> None:
    """The odometry and scan the node saw are the world's at one of its steps, and the robot moved at its speed."""
    odometries = {(o[0], o[1]) for _pose, o, _ranges in states}
    assert (seen["odom"]["x"], seen["odom"]["y"]) in odometries and seen["odom"]["x"] > 0.2
    assert seen["scan"]["ranges"] in [[f32(r) for r in ranges] for _pose, _o, ranges in states]
    assert any(o[3] == 0.5 for _pose, o, _ranges in states)


def assert_seen_timed(states: dict[int, State], seen: Any, stamp_tolerance: float) -> None:
    """What the teleop node saw in a timed round trip (``states`` by grant index): the robot drove at the commanded
    0.5 m/s; the Odometry was stamped G + L with the world's odometry at G (float64: exact) and the node's frames;
    the LaserScan and Range were the world's beams at G (float32 on the wire), the sonar's 40° fan."""
    assert any(odom[3] == 0.5 for _pose, odom, _ranges in states.values())
    odom = seen["odom"]
    k = round(odom["stamp"] / PERIOD) - 1
    assert odom["stamp"] == pytest.approx((k + 1) * PERIOD, abs=stamp_tolerance)
    _pose, o, _ranges = states[k]
    assert (odom["x"], odom["y"], odom["v"]) == (o[0], o[1], o[3])
    assert odom["x"] > 0.2 and odom["frame"] == "rover/odom" and odom["child"] == "base_footprint"
    scan = seen["scan"]
    k = round(scan["stamp"] / PERIOD) - 1
    assert scan["ranges"] == [f32(r) for r in states[k][2]]
    assert scan["angle_min"] == pytest.approx(-0.349066, abs=1e-5) and scan["range_max"] == pytest.approx(4.0)
    rng = seen["range"]
    k = round(rng["stamp"] / PERIOD) - 1
    assert rng["range"] == f32(min(states[k][2])) and rng["radiation_type"] == 0


def assert_stage_on_its_own_clock(stage: Running, seen: Any, summary: pathlib.Path, stamp_tolerance: float) -> None:
    """A stage node that ran on its own clock (``--rate``) for the teleop node (0.5 m/s): it stopped cleanly; the
    Odometry came at the speed, stamped on interval_sim's grid; the LaserScan after it, with the world file's 5
    beams over 40°; its ``--summary`` counts commands and one tick per time."""
    assert stage.status == 0 and any(line.startswith("stage_node stopped at") for line in stage.lines), stage.lines
    odom = seen["odom"]
    assert odom["v"] == 0.5 and odom["x"] > 0.2 and odom["frame"] == "rover/odom"
    assert odom["stamp"] == pytest.approx(round(odom["stamp"] / PERIOD) * PERIOD, abs=stamp_tolerance)
    assert seen["scan"]["stamp"] >= odom["stamp"] and len(seen["scan"]["ranges"]) == 5
    assert seen["scan"]["angle_min"] == pytest.approx(-math.radians(20), abs=1e-6)
    ran = json.loads(summary.read_text())
    assert ran["commands"] > 0 and ran["ticks"] == len(ran["times"]) > 0


class Ros1Decoders(McapDecoderFactory):
    """Decodes the ROS 1 messages of an MCAP file from their ``ros1msg`` schemas alone, with genpy's dynamic
    message classes (Debian's ROS 1, through hlacore's ROS import), as ROS 1's own tools read a bag."""

    def decoder_for(self, message_encoding: str, schema: Optional[Schema]) -> Optional[Callable[[bytes], Any]]:
        """A decoder for ``ros1`` messages of a ``ros1msg`` schema; None for anything else."""
        if message_encoding != "ros1" or schema is None or schema.encoding != "ros1msg":
            return None
        ros_import.enable()
        import genpy.dynamic

        kind = genpy.dynamic.generate_dynamic(schema.name, schema.data.decode())[schema.name]
        return lambda data: kind().deserialize(data)
