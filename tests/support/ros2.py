"""ROS 2 for the tests: whether its wheels are installed (ros_bridge.install_ros2), a loopback-only network
namespace with the environment of ROS 2 processes (a domain of the test's own, logs in its tmp dir), and
processes started inside it, stopped by pid. The test process itself never imports rclpy."""

from __future__ import annotations

import contextlib
import os
import pathlib
import random
import re
import subprocess
import sys
import time
from dataclasses import dataclass
from typing import Iterator, Sequence

import pytest

from hlacore.federates.ros_bridge import ros2_env

from support.nethosts import LoopbackNamespace, namespaces_unavailable


def require_ros2() -> None:
    """Skip without ROS 2's wheels or network namespaces, except under CI, where scripts/test.sh must have
    installed the wheels and namespaces work (root)."""
    why = "" if ros2_env.installed() else f"ROS 2 is not installed under {ros2_env.prefix()} ({ros2_env.INSTALL_COMMAND})"
    why = why or namespaces_unavailable()
    if why:
        if os.environ.get("CI"):
            pytest.fail(why + "; CI=true requires it")
        pytest.skip(why)


@dataclass
class Ros2Space:
    """A loopback-only namespace and the environment of the ROS 2 processes started in it."""

    namespace: LoopbackNamespace
    env: dict[str, str]
    domain: int

    def popen(self, args: Sequence[str], extra: dict[str, str] | None = None) -> subprocess.Popen[str]:
        """``python args...`` inside the namespace, with the ROS 2 environment; stdout and stderr merged."""
        return subprocess.Popen([*self.namespace.exec_prefix(), sys.executable, *args], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, text=True,
                                env={**self.env, **(extra or {})})


@contextlib.contextmanager
def ros2_space(tmp_path: pathlib.Path, name: str = "ros2") -> Iterator[Ros2Space]:
    """A :class:`Ros2Space` for the block: the namespace is removed at the end (after killing, by pid, any
    process the test left in it: the test then fails, naming them)."""
    require_ros2()
    domain = random.randrange(1, 100)  # the namespace isolates already; a domain of its own costs nothing
    env = ros2_env.environment(domain_id=domain, log_dir=str(tmp_path / "ros2-log"))
    env.update(ROS_HOME=str(tmp_path / "ros2-home"), PYTHONUNBUFFERED="1")
    started = time.time()
    try:
        with LoopbackNamespace(name) as namespace:
            yield Ros2Space(namespace, env, domain)
    finally:
        remove_orphan_segments(since=started)
    assert not namespace.leftovers, f"processes left in the namespace {namespace.name}: {namespace.leftovers}"


def remove_orphan_segments(since: float, directory: str = "/dev/shm") -> list[str]:
    """Fast DDS's shared-memory files (``fastdds_*`` segments and their ``_el`` locks, ``sem.fastdds_*``
    semaphores) made since ``since`` that no process maps or holds open any more: Fast DDS leaves a port's
    segment and semaphore after its last user by design, and a process killed without a goodbye leaves its
    own segment; in a tmpfs, test after test. Returns the names removed."""
    used: set[str] = set()
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/maps") as maps:
                used.update(line.split(None, 5)[5].split(" (deleted)")[0].strip() for line in maps
                            if f" {directory}/" in line)
            for fd in os.listdir(f"/proc/{pid}/fd"):
                target = os.readlink(f"/proc/{pid}/fd/{fd}")
                if target.startswith(f"{directory}/"):
                    used.add(target)
        except OSError:  # a process that ended meanwhile, or one we may not read
            continue
    removed = []
    for name in os.listdir(directory):
        path = os.path.join(directory, name)
        if not name.startswith(("fastdds_", "sem.fastdds_")) or path in used:
            continue
        with contextlib.suppress(FileNotFoundError):
            if os.stat(path).st_mtime >= since - 1:
                os.unlink(path)
                removed.append(name)
    return removed


def udp_sockets_of(pid: int) -> set[int]:
    """The inodes of the UDP sockets ``pid`` holds (from its fds, matched against its namespace's tables)."""
    fds = set()
    for fd in os.listdir(f"/proc/{pid}/fd"):
        try:
            target = os.readlink(f"/proc/{pid}/fd/{fd}")
        except OSError:
            continue
        if target.startswith("socket:["):
            fds.add(int(target[8:-1]))
    udp = set()
    for table in ("udp", "udp6"):
        for line in pathlib.Path(f"/proc/{pid}/net/{table}").read_text().splitlines()[1:]:
            udp.add(int(line.split()[9]))
    return fds & udp


def root_udp_owners() -> set[int]:
    """The pids owning a UDP socket in this (the root) namespace, from ``ss -uanp``."""
    done = subprocess.run(["ss", "-uanpH"], capture_output=True, text=True, check=True)
    return {int(pid) for pid in re.findall(r"pid=(\d+)", done.stdout)}
