"""A ROS master for one run of a scenario (paper 1 through ROS, the mirror of paper 2 §6.2):
``$ROS_MASTER_URI`` when one answers there, else ``roscore`` on a free loopback port, stopped by pid
afterwards."""

from __future__ import annotations

import contextlib
import os
import shutil
import signal
import socket
import subprocess
import tempfile
import time
import xmlrpc.client
from typing import Iterator

from .children import stop_process


def master_online(uri: str) -> bool:
    """Whether a ROS master answers at ``uri``."""
    try:
        with xmlrpc.client.ServerProxy(uri) as master:
            master.getPid("/hlacore")
        return True
    except OSError:
        return False


@contextlib.contextmanager
def ros_master(timeout: float = 30.0) -> Iterator[str]:
    """Yield the master's URI; a roscore started here gets ``ROS_HOME`` in a temporary directory (removed
    unless roscore failed: its log is kept there) and the ROS variables set for this process and its
    children. ``ROS_IP`` defaults to 127.0.0.1 (nodes would otherwise advertise another interface)."""
    if not os.environ.get("ROS_HOSTNAME"):
        os.environ.setdefault("ROS_IP", "127.0.0.1")
    uri = os.environ.get("ROS_MASTER_URI")
    if uri and master_online(uri):
        yield uri
        return
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = int(s.getsockname()[1])
    home = tempfile.mkdtemp(prefix="hlacore-ros-")
    uri = f"http://127.0.0.1:{port}"
    os.environ.update(ROS_MASTER_URI=uri, ROS_IP="127.0.0.1", ROS_HOME=home, ROS_LOG_DIR=f"{home}/log")
    with open(f"{home}/roscore.log", "wb") as log:
        proc = subprocess.Popen(["roscore", "-p", str(port)], stdout=log, stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL)
        try:
            deadline = time.monotonic() + timeout
            while not master_online(uri):
                if proc.poll() is not None or time.monotonic() > deadline:
                    raise RuntimeError(f"roscore did not start (log: {home}/roscore.log)")
                time.sleep(0.1)
            yield uri
        finally:
            stop_process(proc, signal.SIGINT)
    if proc.returncode in (0, -signal.SIGINT):
        shutil.rmtree(home, ignore_errors=True)
