"""The Robot Federate and its device (testing-rtes-hla-2016 §5-6), in Python.

- :mod:`.navigation` — scenarios (grid, walls, start, goal) and 4-connected A*;
- :mod:`.protocol` — the command protocol (goFront, goBack, turnLeft, turnRight, readSensors, readPosition);
- :mod:`.kinematics` — the simulated differential-drive body, with miscalibration;
- :mod:`.device` — the simulated device process on a pty;
- :mod:`.driver` — the Tx/Rx driver (serial port through pyserial, or a pty);
- :mod:`.controller` — from a planned move to motor commands;
- :mod:`.report` — the per-cycle ``location`` report;
- :mod:`.federate` — the control loop as a federate (stepped or best-effort).

``python -m hlacore.federates.robot_driver --help`` runs the federate. See ``docs/robot.md``. The §6.2 robot
(:mod:`.mirrored`, with the :mod:`.avoid` controllers) is a federate too, parameterised by its mirror; the
scenario that uses it is :mod:`hlacore.experiments.mirror`.

Federates layer: imports the core and :mod:`hlacore.federates.robot_world` (the world's FOM codec).
"""

from .controller import commands_for_move
from .device import DeviceServer, SimulatedDevice, spawn_simulated_device
from .driver import TxRxDriver
from .federate import RobotAmbassador, RobotFederate, SyncMode
from .kinematics import CALIBRATED, MISCALIBRATED, Body, Calibration
from .navigation import CELL, PAPER_5X5, SCENARIO_6X6, Scenario, astar, mission, scenario_named
from .protocol import COMMANDS, ProtocolError
from .report import REPORT_CODEC, LocationReport, decode_report, encode_report

__all__ = [
    "Body",
    "CALIBRATED",
    "CELL",
    "COMMANDS",
    "Calibration",
    "DeviceServer",
    "LocationReport",
    "MISCALIBRATED",
    "PAPER_5X5",
    "ProtocolError",
    "REPORT_CODEC",
    "RobotAmbassador",
    "RobotFederate",
    "SCENARIO_6X6",
    "Scenario",
    "SimulatedDevice",
    "SyncMode",
    "TxRxDriver",
    "astar",
    "commands_for_move",
    "decode_report",
    "encode_report",
    "mission",
    "scenario_named",
    "spawn_simulated_device",
]
