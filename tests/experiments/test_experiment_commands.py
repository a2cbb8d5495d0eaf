"""The experiments' commands end with one line, not a traceback, when the gateway cannot be reached or the
run is interrupted (Ctrl-C), and an interrupted main job keeps its partial trace and plot."""

from __future__ import annotations

import os
import pathlib
import signal
import socket
import subprocess
import sys

from hlacore.processes import Child, process_info

from support.ros import require_ros

MAIN_JOB = "hlacore.experiments.robot_in_the_loop"


def dead_address() -> str:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return f"127.0.0.1:{s.getsockname()[1]}"


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", *args], capture_output=True, text=True, timeout=120,
                          stdin=subprocess.DEVNULL)


def test_main_job_with_a_dead_gateway_says_so_in_one_line(tmp_path: pathlib.Path) -> None:
    address = dead_address()
    done = run(MAIN_JOB, "--rtig", address, "--out", str(tmp_path / "out"))
    assert done.returncode == 1
    assert done.stderr.strip().splitlines() == [
        f"python -m {MAIN_JOB}: cannot connect to rtig at {address}: Connection refused"]


def test_mirror_with_a_dead_gateway_says_so_in_one_line(tmp_path: pathlib.Path) -> None:
    """... and leaves no ROS process behind (roscore, stopped right after it started, once left rosmaster
    and rosout running: they have process groups of their own)."""
    require_ros()
    address = dead_address()
    done = subprocess.run([sys.executable, "-m", "hlacore.experiments.mirror", str(tmp_path / "out"), "--rtig",
                           address], capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL,
                          env={**os.environ, "TMPDIR": str(tmp_path)})
    assert done.returncode == 1, done.stderr
    assert "Traceback" not in done.stderr and f"cannot connect to rtig at {address}" in done.stderr
    processes = (process_info(int(entry.name)) for entry in pathlib.Path("/proc").iterdir() if entry.name.isdigit())
    left = [p for p in processes if p is not None and str(tmp_path) in p.command]
    assert not left, left


def test_fmu_drive_with_a_dead_gateway_says_so_in_one_line(tmp_path: pathlib.Path) -> None:
    address = dead_address()
    done = run("hlacore.experiments.fmu_drive", str(tmp_path / "out"), "--rtig", address)
    assert done.returncode == 1
    assert done.stderr.strip().splitlines() == [
        f"python -m hlacore.experiments.fmu_drive: cannot connect to rtig at {address}: Connection refused"]


def test_interrupted_main_job_keeps_its_partial_trace_and_plot(tmp_path: pathlib.Path) -> None:
    out, stderr_file = tmp_path / "out", tmp_path / "stderr"
    with Child([sys.executable, "-m", MAIN_JOB, "--out", str(out), "--cycles", "400"], stderr_path=stderr_file) as job:
        while not job.read_line(120).startswith("cycle   3"):  # interrupt once a few cycles have been checked
            pass
        job.send_signal(signal.SIGINT)
        assert job.wait(60) == 130
    stderr = stderr_file.read_text()
    assert stderr.strip().splitlines()[-1] == f"python -m {MAIN_JOB}: interrupted; what it wrote so far is in {out}"
    assert "Traceback" not in stderr
    rows = (out / "trace.csv").read_text().splitlines()
    assert len(rows) >= 1 + 4  # the header and the cycles checked before Ctrl-C
    assert (out / "trajectory.png").stat().st_size > 0
