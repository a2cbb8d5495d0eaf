"""The ROS 1 bridge against a real roscore (started here on a free port, ended by pid), in separate
processes: the world federate runs in this process, the bridge (``python -m hlacore.federates.ros_bridge``)
and a plain rospy node (tests/peers/ros_teleop.py) in their own. The node's Twist moves the world robot
through the federation; its Odometry, LaserScan and Range come back on ROS carrying the federation
timestamps and exactly the values the world had at those times.

The tests run whenever ROS is installed (scripts/install-ros.sh, called by scripts/test.sh, installs it);
without ROS they skip, except under CI=true where missing ROS is a failure. This process never imports
rospy: the ROS side lives in the subprocesses."""

from __future__ import annotations

import contextlib
import json
import os
import pathlib
import queue
import signal
import subprocess
import sys
import threading
import time
import xmlrpc.client
import xmlrpc.server
from typing import Any, Iterator, Optional, Sequence

import pytest

import hlacore.rti as rti
from hlacore.federates.robot_world import FEDERATION, FOM_PATH, World, WorldFederate, load_world
from hlacore.federates.robot_world.federate import Pose
from hlacore.federates.ros_bridge.children import stop_process
from hlacore.federates.ros_bridge.master import free_master_port, master_online

from conftest import ROVER_MODEL

PEERS = pathlib.Path(__file__).parent / "peers"
DIST = os.environ.get("HLACORE_ROS_DIST_PACKAGES", "/usr/lib/python3/dist-packages")
WORLD = ROVER_MODEL + """
bot( pose [ 0 0 0 0 ] name "rover" )
model( pose [ 3 0 0 0 ] size [ 0.2 3 0.5 ] )
"""
DT, PERIOD = 0.01, 0.1
MAX_CYCLES = 4000  # bounds each run: 400 s of federation time


def ros_installed() -> bool:
    return os.path.exists("/usr/bin/roscore") and os.path.isdir(os.path.join(DIST, "rospy"))


def require_ros() -> None:
    """Skip without ROS, except under CI where scripts/test.sh must have installed it."""
    if not ros_installed():
        message = "ROS 1 is not installed (./scripts/install-ros.sh installs it from Debian)"
        if os.environ.get("CI"):
            pytest.fail(message + "; CI=true requires it")
        pytest.skip(message)


@pytest.fixture
def ros() -> None:
    require_ros()


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


@pytest.fixture
def roscore(ros: None, tmp_path: pathlib.Path) -> Iterator[dict[str, str]]:
    """A real roscore for the test (running_roscore)."""
    with running_roscore(tmp_path / "ros") as env:
        yield env


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


def state(fed: WorldFederate) -> tuple[Pose, tuple[float, ...], list[float]]:
    r = fed.world.robot("rover")
    return r.pose, (r.odometry.x, r.odometry.y, r.odometry.theta, r.linear, r.angular), list(r.ranges)


def f32(x: float) -> float:
    import struct

    return float(struct.unpack("f", struct.pack("f", x))[0])


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

    # the Twist reached the world: the robot drove at the commanded speed
    assert any(odom[3] == 0.5 for _pose, odom, _ranges in states.values())
    # Odometry: stamped G + L with the world's odometry at G (float64: exact)
    odom = seen["odom"]
    k = round(odom["stamp"] / PERIOD) - 1
    assert odom["stamp"] == pytest.approx((k + 1) * PERIOD, abs=1e-6)
    _pose, o, _ranges = states[k]
    assert (odom["x"], odom["y"], odom["v"]) == (o[0], o[1], o[3])
    assert odom["x"] > 0.2 and odom["frame"] == "rover/odom" and odom["child"] == "base_footprint"
    # LaserScan and Range: the world's beams at G (float32 on the wire), the sonar's 40° fan
    scan = seen["scan"]
    k = round(scan["stamp"] / PERIOD) - 1
    assert scan["ranges"] == [f32(r) for r in states[k][2]]
    assert scan["angle_min"] == pytest.approx(-0.349066, abs=1e-5) and scan["range_max"] == pytest.approx(4.0)
    rng = seen["range"]
    k = round(rng["stamp"] / PERIOD) - 1
    assert rng["range"] == f32(min(states[k][2])) and rng["radiation_type"] == 0
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
                for _ in range(MAX_CYCLES):
                    world.advance(timeout=30)  # the world alone regulates: the test paces it
                    states.append(state(world))
                    if teleop.proc.poll() is not None:
                        break
                    time.sleep(0.005)
                seen = teleop.report(30)
        assert bridge.status == 0, bridge.lines
    odometries = {(o[0], o[1]) for _pose, o, _ranges in states}
    assert (seen["odom"]["x"], seen["odom"]["y"]) in odometries and seen["odom"]["x"] > 0.2
    assert seen["scan"]["ranges"] in [[f32(r) for r in ranges] for _pose, _o, ranges in states]
    assert any(o[3] == 0.5 for _pose, o, _ranges in states)


def test_import_without_ros_names_the_packages(tmp_path: pathlib.Path) -> None:
    """With no rospy to be found, importing the bridge is an ImportError that says what to install."""
    env = dict(os.environ, HLACORE_ROS_DIST_PACKAGES=str(tmp_path))
    done = subprocess.run([sys.executable, "-c", "import hlacore.federates.ros_bridge"], capture_output=True,
                          text=True, env=env, timeout=60, stdin=subprocess.DEVNULL)
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
    summary = json.loads(done.stdout.strip().splitlines()[-1])
    assert summary["checks"] == {"no_stall": True, "no_overlap": True, "obstacles_crossed": True,
                                 "held_back": True, "stopped_before_wall": True}
    assert summary["grants"] == 301 and summary["end"] == pytest.approx(30.0)
    assert 0.0 < summary["wall_gap"] <= 0.5 and summary["sent"] > 4 * 250
    assert (out / "paper1-ros-trace.csv").read_text().count("\n") == 302
    assert (out / "paper1-ros-snapshot.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
