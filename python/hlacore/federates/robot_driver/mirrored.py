"""The Robot Federate of testing-rtes-hla-2016 §6.2: a "real" robot (its device, odometry on) in the robot
world's federation, sensing through the sonar of its mirror, a world robot that repeats its motion.

Per cycle ``k = 1 .. cycles`` (federation time ``k * cycle``):

1. **advance**: a blocking ``timeAdvanceRequest(k * cycle)`` (regulating and constrained, lookahead ``L``);
   the grant delivers the mirror's ``WorldRobot`` state stamped up to ``k * cycle``;
2. **sense**: the front range is the nearest beam of the mirror's ``ranges`` (the virtual sonar); the pose
   is the device's odometry (``readPosition``);
3. **decide**: an :mod:`.avoid` controller (open loop, or corrected from the pose);
4. **act**: ``drive linear angular cycle`` on the device, then ``readPosition`` again;
5. **mirror**: a ``cmd_vel(mirror, ...)`` stamped ``k * cycle + L``: with ``mirror_from="commands"`` the
   velocities just commanded (the paper's mirror: the same commands), with ``"odometry"`` the velocities the
   device actually achieved over the cycle (the arc between the two odometry readings);
6. **report**: the robot's own ``WorldRobot`` instance (``real``) gets its odometry (``pose`` and
   ``odometry``) stamped ``k * cycle + L``, as if it were one more robot of the world.
"""

from __future__ import annotations

import math
import time
from dataclasses import asdict, dataclass, field
from typing import Any, Callable, Optional

from hlacore import rti
from hlacore.federates.robot_world import codec

from .avoid import CorrectedAvoid, OpenLoopAvoid, wrap
from .driver import TxRxDriver

__all__ = ["MirroredRobotFederate", "CycleRecord", "executed_velocity", "record_json", "MIRROR_SOURCES"]

#: What the mirror is sent: the commanded velocities, or those the odometry measured.
MIRROR_SOURCES = ("commands", "odometry")


@dataclass(frozen=True)
class CycleRecord:
    """One control cycle: federation time, odometry before and after, the sonar's front range, the command,
    what the mirror was sent and the controller's mode."""

    cycle: int
    time: float
    pose: tuple[float, float, float]
    after: tuple[float, float, float]
    front: float
    command: tuple[float, float]
    mirrored: tuple[float, float]
    mode: str
    avoidances: int


def executed_velocity(before: tuple[float, float, float], after: tuple[float, float, float],
                      seconds: float) -> tuple[float, float]:
    """The constant (linear, angular) velocity whose arc takes ``before`` to ``after`` in ``seconds``
    (poses in m and rad): the motion the device really made, whatever it was told."""
    turn = wrap(after[2] - before[2])
    dx, dy = after[0] - before[0], after[1] - before[1]
    chord = math.hypot(dx, dy)
    arc = chord if abs(turn) < 1e-9 else chord * (turn / 2) / math.sin(turn / 2)
    forward = dx * math.cos(before[2] + turn / 2) + dy * math.sin(before[2] + turn / 2)
    return math.copysign(arc, forward) / seconds, turn / seconds


class _Ambassador(rti.FederateAmbassador):
    def __init__(self) -> None:
        self.names: dict[Any, str] = {}
        self.ranges: dict[str, list[float]] = {}
        self.ranges_handle: Any = None

    def discoverObjectInstance(self, obj: Any, cls: Any, name: str) -> None:
        """Note the discovered robot's name."""
        self.names[obj] = str(name)

    def reflectAttributeValues(self, obj: Any, attributes: dict[Any, bytes], tag: Any, order: Any,
                               transport: Any, time: Optional[float] = None, retraction: Any = None) -> None:
        """Keep the ranges reflected for a known robot, as floats."""
        name = self.names.get(obj)
        data = attributes.get(self.ranges_handle)
        if name is not None and data is not None:
            ranges = codec.unpack(codec.RANGES, data)
            assert isinstance(ranges, (list, tuple)), ranges
            self.ranges[name] = [float(r) for r in ranges]


@dataclass(eq=False, repr=False)  # the constructor only: a federate compares and prints as an object
class MirroredRobotFederate:
    """The robot's control loop in the ``RobotWorld`` federation (see the module docstring).

    ``controller`` is an :class:`~.avoid.OpenLoopAvoid` or :class:`~.avoid.CorrectedAvoid`; ``mirror`` names
    the world robot that mirrors this one; ``on_cycle`` sees each :class:`CycleRecord`."""

    driver: TxRxDriver
    controller: "OpenLoopAvoid | CorrectedAvoid"
    mirror: str = "mirror"
    name: str = "real"
    address: Optional[str] = None
    cycle: float = 0.5
    lookahead: float = 0.1
    mirror_from: str = "commands"
    on_cycle: Optional[Callable[[CycleRecord], None]] = None
    records: list[CycleRecord] = field(init=False, default_factory=list)
    rtia: Optional[rti.RTIAmbassador] = field(init=False, default=None)
    _amb: _Ambassador = field(init=False, default_factory=_Ambassador)

    def __post_init__(self) -> None:
        if self.mirror_from not in MIRROR_SOURCES:
            raise ValueError(f"mirror_from must be one of {MIRROR_SOURCES}, not {self.mirror_from!r}")
        if not 0 < self.lookahead <= self.cycle:
            raise ValueError("the lookahead must be positive and at most one cycle")
        self.cycle = float(self.cycle)
        self.lookahead = float(self.lookahead)

    def join(self, timeout: float = 30.0) -> None:
        """Join ``RobotWorld`` (created from its FOM if missing), enable regulation and constraint, publish
        cmd_vel and this robot's ``WorldRobot`` instance, and wait until the mirror is discovered."""
        rtia = rti.RTIAmbassador(self.address)
        rtia.create_or_join(f"robot_{self.name}", codec.FEDERATION, str(codec.FOM_PATH), self._amb)
        self.rtia = rtia
        try:
            self._declare_and_enable(timeout)
        except BaseException:
            self.resign()
            raise

    def _declare_and_enable(self, timeout: float) -> None:
        rtia = self._rtia()
        amb = self._amb
        robot = rtia.getObjectClassHandle(codec.OBJECT_CLASS)
        self._attrs = {n: rtia.getAttributeHandle(n, robot) for n in codec.ATTRIBUTES}
        amb.ranges_handle = self._attrs["ranges"]
        rtia.subscribeObjectClassAttributes(robot, [self._attrs["ranges"]])
        rtia.publishObjectClass(robot, [self._attrs[n] for n in ("name", "pose", "odometry")])
        self._cmd = rtia.getInteractionClassHandle(codec.INTERACTION)
        self._params = {n: rtia.getParameterHandle(n, self._cmd) for n in codec.PARAMETERS}
        rtia.publishInteractionClass(self._cmd)
        self._object = rtia.registerObjectInstance(robot, self.name)
        rtia.enable_time_management(self.lookahead, timeout)
        self._tick_until(lambda: self.mirror in amb.names.values(), f"the mirror robot {self.mirror!r}", timeout)
        self.start = float(rtia.queryFederateTime())

    def run(self, cycles: int, grant_timeout: Optional[float] = 60.0) -> list[CycleRecord]:
        """``cycles`` control cycles (see the module docstring); returns their records."""
        rtia = self._rtia()
        for k in range(1, cycles + 1):
            now = self.start + k * self.cycle
            rtia.advance_to(now, grant_timeout)
            ranges = self._amb.ranges.get(self.mirror)
            if not ranges:
                raise RuntimeError(f"no sonar reading from the mirror {self.mirror!r} by time {now}")
            front = min(ranges)
            pose = self._odometry()
            linear, angular = self.controller.decide(pose, front)
            self.driver.drive(linear, angular, self.cycle)
            after = self._odometry()
            sent = (linear, angular) if self.mirror_from == "commands" else executed_velocity(pose, after, self.cycle)
            stamp = now + self.lookahead
            self._send_cmd_vel(sent, stamp)
            self._report(pose, (linear, angular), stamp)
            record = CycleRecord(k, now, pose, after, front, (linear, angular), sent, self.controller.mode,
                                 self.controller.avoidances)
            self.records.append(record)
            if self.on_cycle is not None:
                self.on_cycle(record)
        return self.records

    def resign(self) -> None:
        """Resign, deleting this robot's object."""
        if self.rtia is not None:
            self.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
            self.rtia = None

    # ---- internals ----

    def _odometry(self) -> tuple[float, float, float]:
        x, y, heading = self.driver.read_position()
        return x, y, math.radians(heading)

    def _send_cmd_vel(self, velocity: tuple[float, float], stamp: float) -> None:
        p = self._params
        values = {p["robot"]: codec.NAME.pack(self.mirror), p["linear"]: codec.SPEED.pack(velocity[0]),
                  p["angular"]: codec.SPEED.pack(velocity[1])}
        self._rtia().sendInteraction(self._cmd, values, f"{self.name} mirror", stamp)

    def _report(self, pose: tuple[float, float, float], velocity: tuple[float, float], stamp: float) -> None:
        a = self._attrs
        values = {a["name"]: codec.NAME.pack(self.name), a["pose"]: codec.POSE.pack(list(pose)),
                  a["odometry"]: codec.ODOMETRY.pack([*pose, *velocity])}
        self._rtia().updateAttributeValues(self._object, values, "odometry", stamp)

    def _rtia(self) -> rti.RTIAmbassador:
        if self.rtia is None:
            raise RuntimeError("join() first")
        return self.rtia

    def _tick_until(self, done: Callable[[], bool], what: str, timeout: float) -> None:
        deadline = time.monotonic() + timeout
        while not done():
            if time.monotonic() > deadline:
                raise TimeoutError(f"robot {self.name}: no {what} within {timeout} s")
            self._rtia().tick(0.01, 0.05)


def record_json(record: CycleRecord) -> dict[str, Any]:
    """A record as a JSON-able dict."""
    return asdict(record)
