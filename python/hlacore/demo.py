"""A two-federate exchange on the in-process gateway, printing what each side does.

Run with ``python -m hlacore.demo``. A "robot" federate publishes the seed FOM's ``robot`` class and
reports its location; a "monitor" federate discovers it, reflects the updates and sends a ``command``
interaction back. Both meet at a synchronization point first, as the papers' federates do.
"""

from __future__ import annotations

import struct
import sys
from importlib import resources
from typing import Any, Callable

from . import omt, rti
from .gateway import Gateway


class Narrator(rti.FederateAmbassador):
    """Prints each callback it gets, prefixed with the federate's name."""

    def __init__(self, name: str) -> None:
        self.name = name
        self.announced = False
        self.synchronized = False
        self.removed = False
        self.locations: list[tuple[float, float]] = []
        self.commands: list[str] = []

    def say(self, text: str) -> None:
        print(f"[{self.name:>7}] {text}")

    def announceSynchronizationPoint(self, label: str, tag: str) -> None:
        self.say(f"sync point '{label}' announced ({tag})")
        self.announced = True

    def federationSynchronized(self, label: str) -> None:
        self.say(f"federation synchronized at '{label}'")
        self.synchronized = True

    def startRegistrationForObjectClass(self, cls: rti.ObjectClassHandle) -> None:
        self.say(f"someone subscribes to {cls!r}: start registering")

    def turnInteractionsOn(self, cls: rti.InteractionClassHandle) -> None:
        self.say(f"someone subscribes to {cls!r}: interactions on")

    def discoverObjectInstance(self, obj: rti.ObjectHandle, cls: rti.ObjectClassHandle, name: str) -> None:
        self.say(f"discovered {name!r} ({obj!r}, {cls!r})")

    def reflectAttributeValues(self, obj: Any, attributes: dict, tag: str, order: Any, transport: Any,
                               time: Any = None, retraction: Any = None) -> None:
        x, y = struct.unpack(">dd", next(iter(attributes.values())))
        self.locations.append((x, y))
        self.say(f"reflected location ({x:.2f}, {y:.2f}) tag={tag!r}")

    def receiveInteraction(self, cls: Any, parameters: dict, tag: str, order: Any, transport: Any,
                           time: Any = None, retraction: Any = None) -> None:
        command = omt.unpack_string(next(iter(parameters.values())))
        self.commands.append(command)
        self.say(f"received command {command!r}")

    def removeObjectInstance(self, obj: rti.ObjectHandle, tag: str, time: Any = None, retraction: Any = None) -> None:
        self.say(f"{obj!r} removed ({tag!r})")
        self.removed = True


def _tick_until(done: Callable[[], bool], *ambassadors: rti.RTIAmbassador) -> None:
    for _ in range(1000):
        if done():
            return
        for rtia in ambassadors:
            rtia.tick(0.001, 0.01)
    raise RuntimeError("the demo did not make progress")


def main() -> int:
    """Run the exchange and return 0 when every message arrived."""
    fed_file = str(resources.files("hlacore") / "foms" / "robot.fed")
    with Gateway(port=0) as gateway:
        print(f"gateway listening on {gateway.address} (in-process)")
        robot_rtia, monitor_rtia = rti.RTIAmbassador(gateway.address), rti.RTIAmbassador(gateway.address)
        robot_rtia.createFederationExecution("TestFed", fed_file)
        robot, monitor = Narrator("robot"), Narrator("monitor")
        robot_rtia.joinFederationExecution("robot", "TestFed", robot)
        monitor_rtia.joinFederationExecution("monitor", "TestFed", monitor)

        robot_class = robot_rtia.getObjectClassHandle("robot")
        location = robot_rtia.getAttributeHandle("location", robot_class)
        command = robot_rtia.getInteractionClassHandle("command")
        command_name = robot_rtia.getParameterHandle("name", command)

        robot_rtia.publishObjectClass(robot_class, [location])
        robot_rtia.subscribeInteractionClass(command)
        monitor_rtia.subscribeObjectClassAttributes(robot_class, [location])
        monitor_rtia.publishInteractionClass(command)

        robot_rtia.registerFederationSynchronizationPoint("ReadyToRun", "both joined")
        _tick_until(lambda: robot.announced and monitor.announced, robot_rtia, monitor_rtia)
        robot_rtia.synchronizationPointAchieved("ReadyToRun")
        monitor_rtia.synchronizationPointAchieved("ReadyToRun")
        _tick_until(lambda: robot.synchronized and monitor.synchronized, robot_rtia, monitor_rtia)

        obj = robot_rtia.registerObjectInstance(robot_class, "robot-1")
        for step in range(3):
            robot_rtia.updateAttributeValues(obj, {location: struct.pack(">dd", 0.33 * step, 0.0)}, f"step {step}")
            _tick_until(lambda: len(monitor.locations) > step, robot_rtia, monitor_rtia)
        monitor_rtia.sendInteraction(command, {command_name: omt.pack_string("stop")}, "monitor says")
        _tick_until(lambda: bool(robot.commands), robot_rtia, monitor_rtia)

        robot_rtia.resignFederationExecution(rti.ResignAction.DeleteObjects)
        _tick_until(lambda: monitor.removed, monitor_rtia)
        monitor_rtia.resignFederationExecution(rti.ResignAction.NoAction)
        robot_rtia.destroyFederationExecution("TestFed")
    ok = len(monitor.locations) == 3 and robot.commands == ["stop"] and monitor.removed
    print("demo finished:", "every message arrived" if ok else "MESSAGES MISSING")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
