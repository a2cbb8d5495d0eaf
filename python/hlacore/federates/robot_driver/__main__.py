"""``python -m hlacore.federates.robot_driver``: run the Robot Federate against a simulated or real device.

Prints ``robot ready`` once it has joined, then one line per cycle; exits 0 after the last cycle.

With ``--mirror NAME`` it is instead the §6.2 robot (:mod:`.mirrored`): it joins the robot world's
federation, goes forward and avoids what the sonar of the world robot NAME sees (``--corrected`` for the
pose-correcting control), on a simulated device on an open floor (``--defective-wheel F``: the right wheel
loses F of its speed); each cycle is printed as one JSON line.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import sys
from importlib import resources
from typing import Callable, Iterator, Optional, Sequence

from .driver import TxRxDriver
from .device import SimulatedDevice, spawn_simulated_device
from .federate import RobotFederate, SyncMode
from .kinematics import CALIBRATED, MISCALIBRATED, Calibration
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
    mirror = parser.add_argument_group("paper 2 §6.2: a robot mirrored by a world robot (docs/mirror.md)")
    mirror.add_argument("--mirror", default=None, metavar="NAME", help="the world robot whose sonar this robot reads")
    mirror.add_argument("--corrected", action="store_true", help="correct heading and position every cycle")
    mirror.add_argument("--defective-wheel", type=float, default=0.0, help="simulated device: right wheel speed lost")
    mirror.add_argument("--cycle", type=float, default=0.5, help="control cycle, federation seconds")
    mirror.add_argument("--mirror-from", default="commands", choices=("commands", "odometry"),
                        help="the mirror repeats the commands (default) or the motion the odometry measured")
    args = parser.parse_args(argv)
    if args.mirror is not None:
        return _mirrored(args)

    scenario = Scenario.load(args.scenario) if args.scenario else scenario_named(args.grid)
    calibration = MISCALIBRATED if args.miscalibrated else CALIBRATED
    with _driver(args, lambda: spawn_simulated_device(scenario, calibration, args.time_scale)) as driver:
        mode = SyncMode.BEST_EFFORT if args.best_effort else SyncMode.STEPPED
        robot = RobotFederate.join(args.rtig, args.federation, args.fed_file, driver, scenario,
                                   mode=mode, lookahead=args.lookahead, on_cycle=_print)
        print("robot ready", flush=True)
        try:
            robot.setup(args.timeout)
            robot.run(args.cycles, args.timeout)
        finally:
            robot.resign()
    return 0


@contextlib.contextmanager
def _driver(args: argparse.Namespace, simulate: Callable[[], SimulatedDevice]) -> Iterator[TxRxDriver]:
    """The driver on ``--device``, or on a simulated device (``simulate()``) closed with it."""
    simulated = simulate() if args.device is None else None
    path, transport = (simulated.path, "pty") if simulated is not None else (args.device, args.transport)
    try:
        driver = TxRxDriver.open(path, transport)
        try:
            yield driver
        finally:
            driver.close()
    finally:
        if simulated is not None:
            simulated.close()


def _mirrored(args: argparse.Namespace) -> int:
    from .avoid import make_controller
    from .mirrored import MirroredRobotFederate, record_json

    floor = Scenario(1, 1)  # the start cell at the origin; the open floor has no wall and no border
    calibration = Calibration(defective_wheel=args.defective_wheel)
    with _driver(args, lambda: spawn_simulated_device(floor, calibration, args.time_scale, heading_deg=0.0,
                                                      open_floor=True)) as driver:
        robot = MirroredRobotFederate(
            driver, make_controller(args.corrected), args.mirror, address=args.rtig, cycle=args.cycle,
            lookahead=min(0.1, args.cycle), mirror_from=args.mirror_from,
            on_cycle=lambda r: print(json.dumps(record_json(r)), flush=True))
        robot.join(args.timeout)
        print("robot ready", flush=True)
        try:
            robot.run(args.cycles, args.timeout)
        finally:
            robot.resign()
    print("robot done", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
