"""The Robot Federate of the paper: A* navigation driving a device, one HLA time step per control cycle.

Per cycle ``k`` (federate time ``t0 + k``):

1. **sense**: ``readSensors`` and ``readPosition`` through the Tx/Rx driver;
2. **decide**: the next cell of the A* mission (:func:`~.navigation.mission`) from the believed cell;
3. **command** the device (:func:`~.controller.commands_for_move`), then read the position again;
4. **publish** ``robot.location`` (a :class:`~.report.LocationReport`), timestamped ``t0 + k + lookahead``
   in stepped mode, in receive order in best-effort mode;
5. **advance**: stepped mode (regulating and constrained) makes a blocking ``timeAdvanceRequest(t0 + k
   + 1)``; best-effort mode (neither) only ticks for callbacks and goes on at once.

Before cycle 0 the robot waits until someone subscribes to ``robot`` (``startRegistrationForObjectClass``)
so that no report is lost, then registers its object instance.
"""

from __future__ import annotations

import enum
import itertools
import time
from typing import Any, Callable, Optional

from hlacore import rti

from .controller import commands_for_move
from .driver import TxRxDriver
from .navigation import CELL, Cell, Scenario, mission
from .report import LocationReport, encode_report

__all__ = ["SyncMode", "RobotFederate", "RobotAmbassador"]


class SyncMode(enum.Enum):
    """The paper's two ways of synchronizing the robot with the federation."""

    STEPPED = "stepped"
    """Regulating and constrained; a blocking time advance ends each cycle (lockstep)."""
    BEST_EFFORT = "best-effort"
    """Neither regulating nor constrained; the robot never waits for the federation."""


class RobotAmbassador(rti.FederateAmbassador):
    """Notes the callbacks the robot federate waits for."""

    def __init__(self) -> None:
        self.registration_started = False

    def startRegistrationForObjectClass(self, cls: rti.ObjectClassHandle) -> None:
        """Someone subscribes to the robot class."""
        self.registration_started = True


class RobotFederate:
    """The control loop of one robot, joined to a federation through ``rtia``.

    ``rtia`` must have joined with :attr:`ambassador` (see :meth:`join`). ``on_cycle`` is called with
    each report (the robot's own display).
    """

    def __init__(
        self,
        rtia: rti.RTIAmbassador,
        ambassador: RobotAmbassador,
        driver: TxRxDriver,
        scenario: Scenario,
        mode: SyncMode = SyncMode.STEPPED,
        lookahead: float = 0.5,
        instance_name: str = "robot",
        initial_heading: int = 1,
        on_cycle: Optional[Callable[[LocationReport], None]] = None,
    ) -> None:
        self.rtia = rtia
        self.ambassador = ambassador
        self.driver = driver
        self.scenario = scenario
        self.mode = mode
        self.lookahead = lookahead
        self.instance_name = instance_name
        self.heading = initial_heading
        self.on_cycle = on_cycle
        #: Every report sent, in order.
        self.reports: list[LocationReport] = []
        self.start_time = 0.0
        self._cells = mission(scenario)
        self._believed: Cell = next(self._cells)
        self._object: Optional[rti.ObjectHandle] = None
        self._location: Optional[rti.AttributeHandle] = None

    @classmethod
    def join(
        cls, address: Optional[str], federation: str, fed_file: Optional[str], driver: TxRxDriver,
        scenario: Scenario, federate_name: str = "robot", **options: Any,
    ) -> "RobotFederate":
        """Connect to the RTI at ``address``, create ``federation`` from ``fed_file`` if given and absent,
        join as ``federate_name`` and return the federate (``options`` go to the constructor)."""
        rtia = rti.RTIAmbassador(address)
        ambassador = RobotAmbassador()
        rtia.create_or_join(federate_name, federation, fed_file, ambassador)
        return cls(rtia, ambassador, driver, scenario, **options)

    def _wait(self, done: Callable[[], bool], what: str, timeout: float) -> None:
        deadline = time.monotonic() + timeout
        while not done():
            if time.monotonic() > deadline:
                raise TimeoutError(f"robot: no {what} within {timeout} s")
            self.rtia.tick(0.05, 0.05)

    def setup(self, timeout: float = 60.0) -> None:
        """Time management as the mode says, publish ``robot.location``, wait for a subscriber, register."""
        rtia, amb = self.rtia, self.ambassador
        self.driver.read_position()  # the device answers: its start-up is not counted in cycle 0
        if self.mode is SyncMode.STEPPED:
            rtia.enable_time_management(self.lookahead, timeout)
        robot_class = rtia.getObjectClassHandle("robot")
        self._location = rtia.getAttributeHandle("location", robot_class)
        rtia.publishObjectClass(robot_class, [self._location])
        self._wait(lambda: amb.registration_started, "subscriber to robot", timeout)
        self._object = rtia.registerObjectInstance(robot_class, self.instance_name)
        self.start_time = float(rtia.queryFederateTime())

    def cycle(self, k: int, grant_timeout: Optional[float] = None) -> LocationReport:
        """One control cycle (sense, decide, command, publish, advance); returns its report."""
        assert self._object is not None and self._location is not None, "setup() first"
        # Measured again when older than 10 s (a few round trips to the gateway), before the cycle's marks.
        offset, uncertainty = self.rtia.clock_offset(max_age=10.0)
        begin = time.monotonic()
        front, _, _ = self.driver.read_sensors()
        self.driver.read_position()
        here = self._believed
        there = here if k == 0 else next(self._cells)
        commands, self.heading = commands_for_move(self.heading, here, there)
        for name in commands:
            self.driver.command(name)
        x, y, heading = self.driver.read_position()
        t_action = time.monotonic()
        self._believed = there
        measured = (round(x / CELL), round(y / CELL))
        t_send = time.monotonic()
        report = LocationReport(k, measured, there, (x, y, heading), front, tuple(commands), t_action, t_send,
                                t_send - begin, offset, uncertainty)
        stamp = self.start_time + k + self.lookahead if self.mode is SyncMode.STEPPED else None
        self.rtia.updateAttributeValues(self._object, {self._location: encode_report(report)}, f"cycle {k}", stamp)
        self.reports.append(report)
        if self.on_cycle is not None:
            self.on_cycle(report)
        if self.mode is SyncMode.STEPPED:
            self.rtia.advance_to(self.start_time + k + 1, grant_timeout)
        else:
            self.rtia.tick()
        return report

    def run(self, cycles: int, grant_timeout: Optional[float] = None) -> list[LocationReport]:
        """:meth:`setup` if needed, then ``cycles`` control cycles; returns the reports."""
        if self._object is None:
            self.setup()
        for k in itertools.islice(itertools.count(len(self.reports)), cycles):
            self.cycle(k, grant_timeout)
        return self.reports

    def resign(self) -> None:
        """Resign, deleting the robot's object."""
        self.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
