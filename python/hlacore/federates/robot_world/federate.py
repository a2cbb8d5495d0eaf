"""The robot world as an HLA federate: time-regulating and constrained, stepped exactly to each grant.

Each cycle the federate requests ``timeAdvanceRequest(k * period)`` (k = 1, 2, ...: computed by
multiplication, never by accumulating sums). Commands (``cmd_vel`` interactions, TSO) delivered with the
grant are scheduled in the world at their timestamps (from the first physics step starting at or after
the timestamp); then the world runs whole steps of ``dt`` up to the grant time ``G``; then every robot's
pose, odometry, ranges and stall flag are published with timestamp ``G + lookahead`` (the earliest the
sending rule allows after a grant to ``G``). The period must be a whole number of steps, and so must every
grant: a grant off the grid raises :class:`~.world.GridError` rather than integrating a partial step.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional

import hlacore.rti as rti

from . import codec
from .world import Pose, World, steps_at

# exported by hlacore.rti at import time (from the C++ module), so invisible to type checkers


@dataclass(frozen=True)
class Command:
    """A received cmd_vel: its timestamp (None for receive order), the robot and the velocities."""

    time: Optional[float]
    robot: str
    linear: float
    angular: float


class _Ambassador(rti.FederateAmbassador):
    def __init__(self) -> None:
        self.commands: list[Command] = []
        self.params: dict[Any, str] = {}

    def receiveInteraction(self, cls: Any, parameters: dict[Any, bytes], tag: Any, order: Any, transport: Any,
                           time: Optional[float] = None, retraction: Any = None) -> None:
        """Queue a complete command as a :class:`Command` (an incomplete one is ignored)."""
        values = {self.params[h]: v for h, v in parameters.items() if h in self.params}
        if set(values) != set(codec.PARAMETERS):
            return  # an incomplete command is ignored
        self.commands.append(Command(
            None if time is None else float(time),
            codec.unpack_name(values["robot"]),
            float(codec.unpack(codec.SPEED, values["linear"])),  # type: ignore[arg-type]
            float(codec.unpack(codec.SPEED, values["angular"])),  # type: ignore[arg-type]
        ))


class WorldFederate:
    """A :class:`World` joined to a federation (see the module docstring for the cycle).

    Use :meth:`join`; then :meth:`advance` (blocking), or :meth:`request` and :meth:`poll` to run beside
    other federates on the same thread. ``history`` holds ``(grant time, poses)`` for every grant;
    ``ignored`` the commands that named no robot of the world."""

    def __init__(self, world: World, rtia: rti.RTIAmbassador, ambassador: _Ambassador, period: float,
                 lookahead: float) -> None:
        self.world = world
        self.rtia = rtia
        self._amb = ambassador
        self.period = float(period)
        self.lookahead = float(lookahead)
        self.cycle = 0
        self.history: list[tuple[float, dict[str, Pose]]] = []
        self.ignored: list[Command] = []
        self._pending = False
        rob = rtia.getObjectClassHandle(codec.OBJECT_CLASS)
        self._attr = {name: rtia.getAttributeHandle(name, rob) for name in codec.ATTRIBUTES}
        rtia.publishObjectClass(rob, list(self._attr.values()))
        cmd = rtia.getInteractionClassHandle(codec.INTERACTION)
        ambassador.params = {rtia.getParameterHandle(name, cmd): name for name in codec.PARAMETERS}
        rtia.subscribeInteractionClass(cmd)
        self._objects = {r.name: rtia.registerObjectInstance(rob, r.name) for r in world.robots}

    @classmethod
    def join(cls, world: World, address: Optional[str] = None, federation: str = codec.FEDERATION,
             name: str = "world", period: float = 0.1, lookahead: Optional[float] = None,
             create: bool = True, timeout: float = 10.0) -> "WorldFederate":
        """Join ``federation`` (created from the robot-world FOM when ``create`` and missing), enable time
        regulation (``lookahead``, default ``period``) and constraint, and publish the initial state.

        ``period`` must be a whole number of ``world.dt`` steps and ``lookahead`` positive."""
        steps = steps_at(period, world.dt)
        if steps < 1:
            raise ValueError("period must be at least one step")
        lookahead = period if lookahead is None else float(lookahead)
        if not lookahead > 0:
            raise ValueError("lookahead must be positive (published states are stamped grant + lookahead)")
        rtia = rti.RTIAmbassador(address)
        amb = _Ambassador()
        rtia.create_or_join(name, federation, str(codec.FOM_PATH) if create else None, amb)
        try:
            fed = cls(world, rtia, amb, period, lookahead)
            start = rtia.enable_time_management(lookahead, timeout)
            world.advance_to(start)
            fed.cycle = steps_at(start, period) if start else 0
            fed._publish(start)
        except BaseException:
            rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
            raise
        return fed

    @property
    def time(self) -> float:
        """The federate's logical time (the last grant)."""
        return float(self.rtia.queryFederateTime())

    def request(self) -> float:
        """Request the next grid point (``timeAdvanceRequest``); returns it."""
        if self._pending:
            raise RuntimeError("a time advance is already pending")
        target = (self.cycle + 1) * self.period
        self.rtia.timeAdvanceRequest(target)
        self._pending = True
        return target

    def poll(self) -> bool:
        """Deliver what has arrived without blocking; once granted, step the world to the grant and publish.

        Returns True when the pending advance has completed (then call :meth:`request` again)."""
        if not self._pending:
            raise RuntimeError("no time advance is pending")
        if not self.rtia.deliver_until_granted():
            return False
        self._complete()
        return True

    def advance(self, timeout: Optional[float] = None) -> float:
        """Request the next grid point, wait for the grant, step and publish; returns the grant time."""
        self.request()
        self.rtia.await_grant(timeout)
        return self._complete()

    def run_until(self, end: float, timeout: Optional[float] = None) -> None:
        """Advance until the federate's time reaches ``end`` (bounded by ``end / period`` cycles)."""
        for _ in range(steps_at(end, self.period) - self.cycle):
            self.advance(timeout)

    def resign(self) -> None:
        """Resign, deleting the robot objects."""
        self.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)

    # ---- internals ----

    def _complete(self) -> float:
        self._pending = False
        granted = self.time
        commands, self._amb.commands = self._amb.commands, []
        names = {robot.name for robot in self.world.robots}
        for command in commands:
            if command.robot not in names:
                self.ignored.append(command)
                continue
            at = self.world.time if command.time is None else command.time
            self.world.schedule(at, command.robot, command.linear, command.angular)
        self.world.advance_to(granted)
        self.cycle = steps_at(granted, self.period)
        self._publish(granted)
        return granted

    def _publish(self, granted: float) -> None:
        self.history.append((granted, self.world.poses()))
        stamp = granted + self.lookahead
        a = self._attr
        for robot in self.world.robots:
            pose, odom = robot.pose, robot.odometry
            values = {
                a["name"]: codec.NAME.pack(robot.name),
                a["pose"]: codec.POSE.pack([pose.x, pose.y, pose.theta]),
                a["odometry"]: codec.ODOMETRY.pack([odom.x, odom.y, odom.theta, robot.linear, robot.angular]),
                a["ranges"]: codec.RANGES.pack(robot.ranges),
                a["stall"]: codec.STALL.pack(robot.stall),
            }
            self.rtia.updateAttributeValues(self._objects[robot.name], values, "world", stamp)
