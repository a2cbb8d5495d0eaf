"""The paper's robot-in-the-loop A* experiment end to end: the main job's body.

:func:`run_experiment` writes the stimulus (scenario) file into the output folder, starts a gateway (the
in-process one unless ``rtig`` gives an address), joins the testbench, starts the Robot Federate as its
own process (``python -m hlacore.federates.robot_driver``, which starts the simulated device on a pty),
runs the testbench, waits for the robot, and writes into the folder:

- ``scenario.txt``: the stimulus file; ``robot.log``: the robot process's output;
- ``trace.csv``: one row per cycle (:data:`hlacore.federates.testbench.plotter.TRACE_COLUMNS`);
- ``trajectory.png``: robot vs reference (when matplotlib is installed);
- ``delays.md``: the delay decomposition in Table 1's form;
- ``gateway-trace.csv``: the in-process gateway's message trace, whose marks split the communication delay
  (with ``rtig``, pass the file it writes with ``--trace`` as ``gateway_trace`` for the same).
"""

from __future__ import annotations

import contextlib
import dataclasses
import pathlib
import subprocess
import sys
from dataclasses import dataclass
from importlib import resources
from typing import Callable, Iterator, Optional

from hlacore.exceptions import FederatesCurrentlyJoined
from hlacore.trace import hops
from hlacore.federates.de import HlaDirector
from hlacore.federates.robot_driver.navigation import Scenario, scenario_named

from hlacore.federates.testbench.bench import Testbench, TestbenchResult
from hlacore.federates.testbench.delays import cycle_hops, delay_table
from hlacore.federates.testbench.plotter import write_outputs

__all__ = ["ExperimentOptions", "Experiment", "run_experiment", "write_outputs"]


@dataclass
class ExperimentOptions:
    """The experiment's knobs; the defaults are the main job's (the paper's calibrated 5x5 run)."""

    out: pathlib.Path
    rtig: Optional[str] = None
    grid: str = "5x5"
    scenario_file: Optional[pathlib.Path] = None
    miscalibrated: bool = False
    best_effort: bool = False
    cycles: int = 15
    time_scale: float = 0.05
    latency: float = 0.5
    precision: float = 0.25
    federation: str = "TestFed"
    timeout: float = 60.0
    gateway_trace: Optional[pathlib.Path] = None  # what `rtig --trace` writes, when rtig is given
    # The Robot Federate on "another machine" (docs/networking.md): the address it reaches the gateway at (a
    # link emulator's, say) and what its command runs through (["ip", "netns", "exec", NAME]).
    robot_rtig: Optional[str] = None
    robot_prefix: tuple[str, ...] = ()
    # Record the run (MCAP, docs/record-replay.md) with the in-process gateway; with rtig, use its --record.
    record: Optional[pathlib.Path] = None
    # Replay the Robot Federate from this recording instead of running it (no robot process, no device).
    replay_robot: Optional[pathlib.Path] = None
    # Serve the live web view of the gateway (hlacore.monitor) on this (host, port) during the run.
    monitor: Optional[tuple[str, int]] = None


@dataclass
class Experiment:
    """A finished run: the checker's result and the files written."""

    result: TestbenchResult
    out: pathlib.Path
    robot_status: int
    messages: list[str]


@contextlib.contextmanager
def _gateway(address: Optional[str], trace: pathlib.Path, record: Optional[pathlib.Path]) -> Iterator[str]:
    if address is not None:
        if record is not None:
            raise ValueError("record a run through rtig with its --record option")
        yield address
        return
    from hlacore.gateway import Gateway

    with Gateway(port=0, trace=trace, record=record) as gateway:
        yield str(gateway.address)


def _robot_command(options: ExperimentOptions, address: str, scenario_path: pathlib.Path) -> list[str]:
    if options.replay_robot is not None:
        return [*options.robot_prefix, sys.executable, "-m", "hlacore.replay", str(options.replay_robot),
                "--as", "robot", "--rtig", options.robot_rtig or address, "--federation", options.federation,
                "--timeout", repr(options.timeout)]
    command = [
        *options.robot_prefix, sys.executable, "-m", "hlacore.federates.robot_driver",
        "--rtig", options.robot_rtig or address,
        "--federation", options.federation, "--scenario", str(scenario_path), "--cycles", str(options.cycles),
        "--lookahead", repr(options.latency), "--time-scale", repr(options.time_scale),
        "--timeout", repr(options.timeout),
    ]
    if options.best_effort:
        command.append("--best-effort")
    if options.miscalibrated:
        command.append("--miscalibrated")
    return command


def run_experiment(options: ExperimentOptions, write: Callable[[str], None] = print) -> Experiment:
    """Run the experiment (see the module docstring); ``write`` gets the progress lines."""
    out = options.out
    out.mkdir(parents=True, exist_ok=True)
    scenario = Scenario.load(options.scenario_file) if options.scenario_file else scenario_named(options.grid)
    stimulus = out / "scenario.txt"
    stimulus.write_text(scenario.to_text())
    fom = str(resources.files("hlacore") / "foms" / "robot.fed")
    mode = "best-effort" if options.best_effort else "stepped"
    calibration = "miscalibrated" if options.miscalibrated else "calibrated"
    title = f"{scenario.width}x{scenario.height}, {calibration}, {mode}"
    # Best effort: the model keeps the pace of a straight cell (2 simulated seconds per cycle).
    pace = max(2.0 * options.time_scale, 0.01) if options.best_effort else None
    trace = out / "gateway-trace.csv" if options.rtig is None else options.gateway_trace
    if options.replay_robot is not None:
        calibration = f"replayed from {options.replay_robot}"
    with _gateway(options.rtig, out / "gateway-trace.csv", options.record) as address, \
            contextlib.ExitStack() as monitoring:
        write(f"gateway {address} ({'in-process' if options.rtig is None else 'rtig'}); "
              f"{calibration} robot, {mode} mode, {options.cycles} cycles; output in {out}"
              + (f"; recording {options.record}" if options.record else ""))
        if options.monitor is not None:
            from hlacore.monitor import Monitor

            host, port = options.monitor
            monitor = monitoring.enter_context(Monitor(address, host=host, port=port))
            write(f"monitor: {monitor.url}")
        director = HlaDirector.join("testbench", options.federation, fom, address=address, mode="TAR",
                                    step=1.0, lookahead=options.latency, grant_timeout=options.timeout)
        testbench = Testbench(director, Scenario.load(stimulus), options.cycles, options.latency,
                              options.precision, write)
        with open(out / "robot.log", "w") as log:
            robot = subprocess.Popen(_robot_command(options, address, stimulus), stdout=log,
                                     stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
            try:
                result = testbench.run(pace=pace, discover_timeout=options.timeout)
                robot_status = robot.wait(timeout=options.timeout)
            except KeyboardInterrupt:  # keep what the run has shown so far: its trace and plot
                write_outputs(out, testbench.result(), scenario, f"{title}, interrupted")
                raise
            finally:
                if robot.poll() is None:
                    robot.terminate()
                    try:
                        robot.wait(timeout=10)
                    except subprocess.TimeoutExpired:
                        robot.kill()
                        robot.wait()
        director.resign()
        try:
            director.rtia.destroyFederationExecution(options.federation)
        except FederatesCurrentlyJoined:
            pass
    if trace is not None:
        # The gateway's marks split the robot -> testbench delay into its three hops.
        by_cycle = cycle_hops(hops(trace, "robot", "testbench", options.federation))
        result = dataclasses.replace(result, delays=delay_table(result.verdicts, result.reflected_at, by_cycle,
                                                                   result.bench_clock))
    messages = write_outputs(out, result, scenario, title)
    return Experiment(result, out, int(robot.returncode), messages)

