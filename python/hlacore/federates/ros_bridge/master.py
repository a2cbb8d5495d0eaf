"""A ROS master for one run of a scenario (paper 1 through ROS, the mirror of paper 2 §6.2):
``$ROS_MASTER_URI`` when one answers there, else ``roscore`` on a free loopback port, stopped by pid
afterwards."""

from __future__ import annotations

import contextlib
import os
import pathlib
import random
import shutil
import signal
import socket
import subprocess
import tempfile
import threading
import time
import xmlrpc.client
from typing import Iterator

from hlacore.processes import ProcessInfo, descendants, still_running



def master_online(uri: str, with_rosout: bool = False) -> bool:
    """Whether a ROS master answers at ``uri`` (and, ``with_rosout``, has rosout registered: roscore has
    started everything it starts)."""
    try:
        with xmlrpc.client.ServerProxy(uri) as master:
            master.getPid("/hlacore")
            if not with_rosout:
                return True
            found = master.lookupNode("/hlacore", "/rosout")  # [code, message, URI]; code 1: registered
            return isinstance(found, list) and found[0] == 1
    except (OSError, xmlrpc.client.Fault):  # nothing there, or a server that is not a ROS master
        return False


def free_master_port(host: str = "127.0.0.1") -> int:
    """A free port for a roscore, below the kernel's ephemeral range: roslaunch and rosout bind port 0,
    so a port the kernel handed out that way could go to one of them before rosmaster binds it."""
    low = int(pathlib.Path("/proc/sys/net/ipv4/ip_local_port_range").read_text().split()[0])
    for port in random.sample(range(max(1024, low - 12000), low), 200):
        with socket.socket() as s:
            try:
                s.bind((host, port))
            except OSError:
                continue
            return port
    raise RuntimeError(f"no free port for a ROS master below the ephemeral range (ports from {low})")


@contextlib.contextmanager
def ros_master(timeout: float = 30.0) -> Iterator[str]:
    """Yield the master's URI; a roscore started here gets ``ROS_HOME`` in a temporary directory (removed
    at the end, however the run ends, unless roscore failed to start: its log is kept there) and the ROS variables set for this process and its
    children. ``ROS_IP`` defaults to 127.0.0.1 (nodes would otherwise advertise another interface).

    roscore runs in a process group of its own, ended as a whole (rosmaster and rosout with it). While it
    runs, SIGTERM to this process raises SystemExit in the main thread, so that the caller's clean-up (and
    this one) runs as on Ctrl-C instead of the process vanishing with its children left behind."""
    if not os.environ.get("ROS_HOSTNAME"):
        os.environ.setdefault("ROS_IP", "127.0.0.1")
    uri = os.environ.get("ROS_MASTER_URI")
    if uri and master_online(uri):
        yield uri
        return
    port = free_master_port()
    home = tempfile.mkdtemp(prefix="hlacore-ros-")
    uri = f"http://127.0.0.1:{port}"
    os.environ.update(ROS_MASTER_URI=uri, ROS_IP="127.0.0.1", ROS_HOME=home, ROS_LOG_DIR=f"{home}/log")
    with open(f"{home}/roscore.log", "wb") as log, _sigterm_as_exit():
        proc = subprocess.Popen(["roscore", "-p", str(port)], stdout=log, stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL, start_new_session=True)
        started = False
        try:
            deadline = time.monotonic() + timeout
            # Until rosout is up too: roscore stopped while still launching leaves what it launched behind.
            while not master_online(uri, with_rosout=True):
                if proc.poll() is not None or time.monotonic() > deadline:
                    raise RuntimeError(f"roscore did not start (log: {home}/roscore.log)")
                time.sleep(0.1)
            started = True
            yield uri
        finally:
            stop_group(proc, signal.SIGINT)
            if started:  # its log is worth keeping only when it did not start
                shutil.rmtree(home, ignore_errors=True)


def stop_group(proc: "subprocess.Popen[bytes]", sig: int, timeout: float = 15.0) -> None:
    """End the process group `proc` leads (started with start_new_session): `sig` to the group once, then
    SIGKILL to what is left of it after `timeout` s. roscore puts rosmaster and rosout in groups of their own
    and ends them itself; those of its descendants seen meanwhile that outlive it are ended by pid too."""
    family = set(descendants(proc.pid))
    with contextlib.suppress(ProcessLookupError):
        os.killpg(proc.pid, sig)
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        family |= set(descendants(proc.pid))
        proc.poll()  # reap the leader, or the group would never look empty
        try:
            os.killpg(proc.pid, 0)  # members of the group remain?
        except ProcessLookupError:
            break
        time.sleep(0.05)
    else:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    _end_survivors(family, timeout)


def _end_survivors(family: set[ProcessInfo], timeout: float) -> None:
    """SIGTERM, then SIGKILL after `timeout` s, to those of `family` still alive."""
    def alive() -> list[ProcessInfo]:
        return [p for p in family if still_running(p)]

    for sig in (signal.SIGTERM, signal.SIGKILL):
        for process in alive():
            with contextlib.suppress(ProcessLookupError):
                os.kill(process.pid, sig)
        deadline = time.monotonic() + timeout
        while alive() and time.monotonic() < deadline:
            time.sleep(0.05)
        if not alive():
            return


@contextlib.contextmanager
def _sigterm_as_exit() -> Iterator[None]:
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def leave(signum: int, frame: object) -> None:
        raise SystemExit(128 + signum)

    previous = signal.signal(signal.SIGTERM, leave)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)
