"""The main job: the robot-in-the-loop A* experiment of testing-rtes-hla-2016 §6, end to end.

Run with ``python -m hlacore.experiments.robot_in_the_loop`` (or ``./scripts/run.sh``; the old
``python -m hlacore.demo`` still works for one release). With no option it runs the paper's calibrated
robot on the 5x5 grid on an in-process gateway: the testbench federate (sequencer, reference model,
checker, display) here, the Robot Federate in its own process, the simulated device behind a pty. It prints
a line per cycle, writes the trace, the trajectory plot and the delay table into the output folder it
names, and exits 0 when the checker passes (1 when it found value or time errors).
"""

from __future__ import annotations

import argparse
import datetime
import pathlib
import sys
from typing import Optional, Sequence

from hlacore.federates.testbench.delays import format_table

from ...monitor.__main__ import listen_address
from ..cli import run_command
from .experiment import ExperimentOptions, run_experiment


def _grid(text: str) -> str:
    if text not in ("5x5", "6x6"):
        raise argparse.ArgumentTypeError("the grids are 5x5 (the paper's) and 6x6 (ours); use --scenario FILE")
    return text


def parse_args(argv: Optional[Sequence[str]] = None) -> ExperimentOptions:
    """The command line as :class:`ExperimentOptions`."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.experiments.robot_in_the_loop", description=__doc__.splitlines()[0])
    parser.add_argument("--rtig", metavar="HOST:PORT", default=None,
                        help="a running rtig instead of the in-process gateway")
    parser.add_argument("--gateway-trace", metavar="FILE", type=pathlib.Path, default=None,
                        help="with --rtig: the message trace it writes (rtig --trace FILE), to split the "
                             "communication delay into its hops")
    parser.add_argument("--miscalibrated", action="store_true", help="the device's motors are miscalibrated")
    parser.add_argument("--grid", type=_grid, default="5x5", help="5x5 (the paper's, default) or 6x6 (ours)")
    parser.add_argument("--scenario", type=pathlib.Path, default=None, help="a scenario file (overrides --grid)")
    parser.add_argument("--best-effort", action="store_true",
                        help="the robot is neither regulating nor constrained (never waits)")
    parser.add_argument("--cycles", type=int, default=15, help="control cycles (default 15: the whole path)")
    parser.add_argument("--time-scale", type=float, default=0.05,
                        help="wall seconds per simulated device second (default 0.05; 1 = real time)")
    parser.add_argument("--precision", type=float, default=0.25, help="checker's time precision, model time")
    parser.add_argument("--federation", default="TestFed")
    parser.add_argument("--robot-rtig", metavar="HOST:PORT", default=None,
                        help="where the Robot Federate reaches the gateway, when not where the testbench does "
                             "(a link emulator's address: docs/networking.md)")
    parser.add_argument("--robot-netns", metavar="NAME", default=None,
                        help="run the Robot Federate in this network namespace (ip netns exec NAME)")
    parser.add_argument("--record", metavar="FILE", type=pathlib.Path, default=None,
                        help="record the run into FILE (MCAP; with --rtig, give rtig --record instead): "
                             "docs/record-replay.md")
    parser.add_argument("--replay-robot", metavar="FILE", type=pathlib.Path, default=None,
                        help="replay the Robot Federate from the recording FILE instead of running it")
    parser.add_argument("--monitor", metavar="HOST:PORT", type=listen_address, nargs="?", const=("127.0.0.1", 8470),
                        default=None, help="serve the live web view of the gateway during the run "
                                           "(hlacore.monitor; default 127.0.0.1:8470)")
    parser.add_argument("--out", type=pathlib.Path, default=None,
                        help="output folder (default ./robot-experiment-<UTC time>)")
    args = parser.parse_args(argv)
    if args.gateway_trace is not None and args.rtig is None:
        parser.error("--gateway-trace goes with --rtig (the in-process gateway writes its own trace)")
    if args.record is not None and args.rtig is not None:
        parser.error("--record goes with the in-process gateway: start rtig with --record FILE instead")
    if args.replay_robot is not None and (args.miscalibrated or args.best_effort):
        parser.error("--replay-robot replays the recorded robot: its calibration and mode are the recording's")
    if args.cycles < 1:
        parser.error("--cycles must be at least 1")
    out = args.out or pathlib.Path(f"robot-experiment-{datetime.datetime.now(datetime.timezone.utc):%Y%m%d-%H%M%S}")
    return ExperimentOptions(out=out, rtig=args.rtig, grid=args.grid, scenario_file=args.scenario,
                             miscalibrated=args.miscalibrated, best_effort=args.best_effort, cycles=args.cycles,
                             time_scale=args.time_scale, precision=args.precision, federation=args.federation,
                             gateway_trace=args.gateway_trace, robot_rtig=args.robot_rtig,
                             robot_prefix=("ip", "netns", "exec", args.robot_netns) if args.robot_netns else (),
                             record=args.record, replay_robot=args.replay_robot, monitor=args.monitor)


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Run the experiment; 0 when the checker passes, 1 when it found errors (or the gateway cannot be
    reached), 130 after Ctrl-C."""
    options = parse_args(argv)
    return run_command("python -m hlacore.experiments.robot_in_the_loop", lambda: _run(options),
                       lambda: str(options.out))


def _run(options: ExperimentOptions) -> int:
    experiment = run_experiment(options, lambda line: print(line, flush=True))
    result = experiment.result
    for message in experiment.messages:
        print(message)
    print(format_table(result.delays), end="")
    value, late = result.value_errors, result.time_errors
    first = f" (first at cycle {value[0].cycle})" if value else ""
    print(f"checker: {len(result.verdicts)} cycles, {len(value)} value errors{first}, {len(late)} time errors")
    if experiment.robot_status != 0:
        print(f"robot federate exited with {experiment.robot_status}: see {experiment.out / 'robot.log'}")
    passed = result.passed and experiment.robot_status == 0
    print("experiment finished:", "checker passed" if passed else "CHECKER FOUND ERRORS")
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
