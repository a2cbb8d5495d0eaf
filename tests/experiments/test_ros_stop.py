"""Stopping a ROS experiment (SIGTERM, Ctrl-C) ends every process it started: roscore with rosmaster and
rosout, the ROS nodes, the federates; and removes roscore's temporary ROS_HOME."""

from __future__ import annotations

import contextlib
import os
import pathlib
import signal
import subprocess
import sys
import time

import pytest

from hlacore.processes import ProcessInfo, descendants, still_running

from support.ros import require_ros

EXPERIMENTS = {
    "mirror": ["hlacore.experiments.mirror", "--cycles", "400"],
    "paper1-ros": ["hlacore.experiments.paper1.ros", "--duration", "120", "--ros", "1"],  # else ROS 2, found installed
}


def _experiment_running(processes: list[ProcessInfo]) -> bool:
    """roscore is up (rosout runs) and something of the experiment's own besides it."""
    ros = ("roscore", "rosmaster", "rosout")
    return (any("rosout" in cmd for _, _, cmd in processes)
            and any(not any(name in cmd for name in ros) for _, _, cmd in processes))


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT], ids=["SIGTERM", "SIGINT"])
@pytest.mark.parametrize("experiment", sorted(EXPERIMENTS))
def test_stopped_experiment_leaves_no_process_behind(experiment: str, signum: int, tmp_path: pathlib.Path) -> None:
    require_ros()
    env = {k: v for k, v in os.environ.items() if not k.startswith("ROS_")}  # it starts its own roscore
    env["TMPDIR"] = str(tmp_path)
    log = (tmp_path / "out.log").open("w")
    proc = subprocess.Popen([sys.executable, "-m", *EXPERIMENTS[experiment][:1], str(tmp_path / "out"),
                             *EXPERIMENTS[experiment][1:]], env=env, stdout=log, stderr=subprocess.STDOUT,
                            stdin=subprocess.DEVNULL)
    started: list[ProcessInfo] = []
    try:
        # roscore, rosmaster, rosout, then the experiment's own nodes and federates (slow on a loaded machine).
        deadline = time.monotonic() + 60
        while not _experiment_running(started := descendants(proc.pid)):
            assert proc.poll() is None, (tmp_path / "out.log").read_text()
            assert time.monotonic() < deadline, f"the experiment did not get going: {started}"
            time.sleep(0.2)
        time.sleep(1)
        started = descendants(proc.pid)
        proc.send_signal(signum)
        proc.wait(timeout=60)
    finally:
        if proc.poll() is None:  # the test failed: end what it started anyway (roscore has its own group)
            for pid in [proc.pid] + [p.pid for p in descendants(proc.pid)]:
                with contextlib.suppress(ProcessLookupError):
                    os.kill(pid, signal.SIGKILL)
            proc.wait()
        log.close()
    left = [p for p in started if still_running(p)]
    assert not left, left
    assert proc.returncode != 0  # stopped, not finished
    assert not list(tmp_path.glob("hlacore-ros-*")), "roscore's ROS_HOME was left behind"
