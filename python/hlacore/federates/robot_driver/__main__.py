"""``python -m hlacore.federates.robot_driver``: run the Robot Federate against a simulated or real device.

Prints ``robot ready`` once it has joined, then one line per cycle; exits 0 after the last cycle.
"""

from __future__ import annotations

import argparse
import sys
from importlib import resources
from typing import Optional, Sequence

from .driver import TxRxDriver
from .device import SimulatedDevice, spawn_simulated_device
from .federate import RobotFederate, SyncMode
from .kinematics import CALIBRATED, MISCALIBRATED
from .navigation import Scenario, scenario_named
from .report import LocationReport


def _print(report: LocationReport) -> None:
    print(f"robot cycle {report.cycle}: {' '.join(report.commands) or '-'} -> cell {report.cell} "
          f"(believed {report.believed})", flush=True)


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Parse the options, run the robot, return the exit status."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.federates.robot_driver", description=__doc__)
    parser.add_argument("--rtig", default=None, help="gateway address HOST:PORT (default $HLACORE_RTIG)")
    parser.add_argument("--federation", default="TestFed")
    parser.add_argument("--fed-file", default=str(resources.files("hlacore") / "foms" / "robot.fed"))
    parser.add_argument("--grid", default="5x5", help="5x5 (the paper's) or 6x6")
    parser.add_argument("--scenario", default=None, help="a scenario file (overrides --grid)")
    parser.add_argument("--cycles", type=int, default=15)
    parser.add_argument("--best-effort", action="store_true", help="neither regulating nor constrained")
    parser.add_argument("--lookahead", type=float, default=0.5)
    parser.add_argument("--miscalibrated", action="store_true", help="simulated device: the demo's miscalibration")
    parser.add_argument("--time-scale", type=float, default=0.0, help="simulated device: wall s per simulated s")
    parser.add_argument("--device", default=None, help="a real device (serial port path) instead of the simulation")
    parser.add_argument("--transport", default="auto", choices=("auto", "pty", "serial"))
    parser.add_argument("--timeout", type=float, default=60.0, help="bound on each wait for the RTI, seconds")
    args = parser.parse_args(argv)

    scenario = Scenario.load(args.scenario) if args.scenario else scenario_named(args.grid)
    simulated: Optional[SimulatedDevice] = None
    if args.device is None:
        calibration = MISCALIBRATED if args.miscalibrated else CALIBRATED
        simulated = spawn_simulated_device(scenario, calibration, args.time_scale)
        path, transport = simulated.path, "pty"
    else:
        path, transport = args.device, args.transport
    try:
        driver = TxRxDriver.open(path, transport)
        try:
            mode = SyncMode.BEST_EFFORT if args.best_effort else SyncMode.STEPPED
            robot = RobotFederate.join(args.rtig, args.federation, args.fed_file, driver, scenario,
                                       mode=mode, lookahead=args.lookahead, on_cycle=_print)
            print("robot ready", flush=True)
            try:
                robot.setup(args.timeout)
                robot.run(args.cycles, args.timeout)
            finally:
                robot.resign()
        finally:
            driver.close()
    finally:
        if simulated is not None:
            simulated.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
