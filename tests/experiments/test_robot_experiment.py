"""The paper's A* experiment end to end, its acceptance runs (docs/robot.md):
`python -m hlacore.experiments.robot_in_the_loop` in its own process, the Robot Federate in another, the simulated
device in a third, over the real rtig or the in-process gateway."""

from __future__ import annotations

import csv
import pathlib
import re
import subprocess
import sys

from hlacore.federates.robot_driver import MISCALIBRATED, PAPER_5X5, Body, commands_for_move

from support import PAPER_PATH, running_rtig


def run_demo(tmp_path: pathlib.Path, *args: str) -> tuple[subprocess.CompletedProcess[str], list[dict[str, str]]]:
    """Run the main job into tmp_path/out; returns the process and the trace rows."""
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "hlacore.experiments.robot_in_the_loop", "--out", str(out), *args],
                          capture_output=True, text=True, timeout=110, stdin=subprocess.DEVNULL)
    assert "experiment finished:" in done.stdout, done.stdout + done.stderr
    assert (out / "delays.md").exists() and (out / "scenario.txt").exists()
    with open(out / "trace.csv", newline="") as stream:
        rows = list(csv.DictReader(stream))
    return done, rows


def robot_cells(rows: list[dict[str, str]]) -> list[tuple[int, int]]:
    return [(int(r["robot_a"]), int(r["robot_b"])) for r in rows if r["robot_a"] != ""]


def first_divergence_of_the_device() -> int:
    """The first cycle at which the miscalibrated body, driven along the paper's path, is in another cell."""
    body, heading = Body(PAPER_5X5, MISCALIBRATED), 1
    moves = {"goFront": (body.drive, 1, 2.0), "goBack": (body.drive, -1, 2.0),
             "turnLeft": (body.turn, 1, 1.0), "turnRight": (body.turn, -1, 1.0)}
    for k, (here, there) in enumerate(zip(PAPER_PATH, PAPER_PATH[1:]), 1):
        commands, heading = commands_for_move(heading, here, there)
        for name in commands:
            method, direction, seconds = moves[name]
            method(direction, seconds)
        if body.cell != there:
            return k
    raise AssertionError("the miscalibrated body never diverges")


def test_calibrated_robot_follows_the_papers_path_over_the_real_rtig(tmp_path):
    trace = tmp_path / "rtig-trace.csv"
    with running_rtig(tmp_path, "--trace", str(trace)) as rtig:
        done, rows = run_demo(tmp_path, "--rtig", rtig.address, "--gateway-trace", str(trace), "--time-scale", "0")
    assert done.returncode == 0, done.stdout + done.stderr
    assert robot_cells(rows) == PAPER_PATH
    assert [(int(r["ref_a"]), int(r["ref_b"])) for r in rows] == PAPER_PATH
    assert all(r["value_error"] == "0" and r["time_error"] == "0" for r in rows)
    assert "checker: 15 cycles, 0 value errors, 0 time errors" in done.stdout
    assert done.stdout.rstrip().endswith("experiment finished: checker passed")
    # rtig's trace splits the robot -> testbench delay of every cycle into its three hops.
    table = (tmp_path / "out" / "delays.md").read_text()
    for row in ("C_RTI^emb", "t_cycle^RTI", "C_PT^RTI"):
        assert re.search(rf"^\| {re.escape(row)} \|", table, re.M), table
    assert "| delay (15 cycles, ms) |" in table


def test_miscalibrated_robot_has_value_errors_from_the_first_diverging_cycle(tmp_path):
    done, rows = run_demo(tmp_path, "--miscalibrated", "--time-scale", "0")
    assert done.returncode == 1
    first = first_divergence_of_the_device()
    errors = [int(r["cycle"]) for r in rows if r["value_error"] == "1"]
    assert errors[0] == first
    assert all(r["value_error"] == "0" for r in rows[:first])
    assert f"value errors (first at cycle {first})" in done.stdout
    assert all(r["time_error"] == "0" for r in rows)  # lockstep: on time, just in the wrong place


def test_best_effort_robot_has_time_errors_and_the_run_completes(tmp_path):
    done, rows = run_demo(tmp_path, "--best-effort", "--time-scale", "0.02")
    assert done.returncode == 1
    assert [int(r["cycle"]) for r in rows] == list(range(15))
    # Receive-order reports land on the testbench's TAR grid points, never on the due times k + 0.5.
    assert all(r["time_error"] == "1" for r in rows)
    assert all(r["value_error"] == "0" for r in rows)
    assert robot_cells(rows) == PAPER_PATH[: len(robot_cells(rows))]
    assert "experiment finished: CHECKER FOUND ERRORS" in done.stdout


def test_the_6x6_scenario_runs_calibrated_with_the_monitor_watching(tmp_path):
    done, rows = run_demo(tmp_path, "--grid", "6x6", "--cycles", "12", "--time-scale", "0", "--monitor", "127.0.0.1:0")
    assert done.returncode == 0, done.stdout + done.stderr
    assert len(rows) == 12 and robot_cells(rows)[-1] == (5, 4)
    assert re.search(r"^monitor: http://127\.0\.0\.1:[1-9]\d*/$", done.stdout, re.M), done.stdout  # port 0: a free one


def test_testbench_and_robot_as_two_commands_over_the_real_rtig(rtig, tmp_path):
    """The two federates started separately, as on two machines: python -m ...testbench and ...robot_driver."""
    commands = [
        [sys.executable, "-m", "hlacore.federates.testbench", "--rtig", rtig.address, "--out", str(tmp_path / "tb"),
         "--cycles", "15", "--timeout", "60"],
        [sys.executable, "-m", "hlacore.federates.robot_driver", "--rtig", rtig.address, "--cycles", "15",
         "--timeout", "60"],
    ]
    processes = [subprocess.Popen(c, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                  text=True) for c in commands]
    try:
        outputs = [p.communicate(timeout=100)[0] for p in processes]
    finally:
        for p in processes:
            if p.poll() is None:
                p.kill()
                p.wait()
    testbench, robot = outputs
    assert [p.returncode for p in processes] == [0, 0], testbench + robot
    assert "checker: 15 cycles, 0 value errors, 0 time errors" in testbench
    assert robot.count("robot cycle") == 15
    with open(tmp_path / "tb" / "trace.csv", newline="") as stream:
        assert robot_cells(list(csv.DictReader(stream))) == PAPER_PATH
