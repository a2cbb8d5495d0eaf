"""``python -m hlacore.federates.testbench``: the testbench federate alone, for a robot started elsewhere.

Start it first (it creates the federation), then the Robot Federate (``python -m
hlacore.federates.robot_driver --rtig ... --scenario FILE``) with the same scenario, cycles and mode. It
prints a line per cycle, writes the trace, plot and delay table into ``--out``, and exits 0 when the
checker passes.
"""

from __future__ import annotations

import argparse
import pathlib
import sys
from importlib import resources
from typing import Optional, Sequence

from hlacore.federates.de import HlaDirector
from hlacore.federates.robot_driver.navigation import Scenario, scenario_named

from .bench import Testbench
from .delays import format_table
from .plotter import write_outputs


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Parse the options, run the testbench, return the exit status."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.federates.testbench", description=__doc__)
    parser.add_argument("--rtig", default=None, help="gateway address HOST:PORT (default $HLACORE_RTIG)")
    parser.add_argument("--federation", default="TestFed")
    parser.add_argument("--grid", default="5x5", help="5x5 (the paper's) or 6x6")
    parser.add_argument("--scenario", type=pathlib.Path, default=None, help="the stimulus file (overrides --grid)")
    parser.add_argument("--cycles", type=int, default=15)
    parser.add_argument("--latency", type=float, default=0.5, help="when a report is due (the robot's lookahead)")
    parser.add_argument("--precision", type=float, default=0.25)
    parser.add_argument("--pace", type=float, default=None,
                        help="wall seconds per model time unit (for a best-effort robot); default: none")
    parser.add_argument("--timeout", type=float, default=120.0)
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("testbench-out"))
    args = parser.parse_args(argv)
    scenario = Scenario.load(args.scenario) if args.scenario else scenario_named(args.grid)
    args.out.mkdir(parents=True, exist_ok=True)
    fom = str(resources.files("hlacore") / "foms" / "robot.fed")
    director = HlaDirector.join("testbench", args.federation, fom, address=args.rtig, mode="TAR", step=1.0,
                                lookahead=args.latency, grant_timeout=args.timeout)
    testbench = Testbench(director, scenario, args.cycles, args.latency, args.precision,
                          lambda line: print(line, flush=True))
    print("testbench ready", flush=True)
    try:
        result = testbench.run(pace=args.pace, discover_timeout=args.timeout)
    finally:
        director.resign()
    for line in write_outputs(args.out, result, scenario, f"{scenario.width}x{scenario.height}"):
        print(line)
    print(format_table(result.delays), end="")
    print(f"checker: {len(result.verdicts)} cycles, {len(result.value_errors)} value errors, "
          f"{len(result.time_errors)} time errors")
    return 0 if result.passed else 1


if __name__ == "__main__":
    sys.exit(main())
