"""What every bench peer does (on hlacore.processes): report as JSON lines, join the federation with the robot FOM's location
attribute published and subscribed, tick with a deadline, and become regulating and constrained."""

from __future__ import annotations

import sys

import hlacore.rti as rti
from hlacore import processes
from hlacore.processes import say

STOP = b"stop"  # the conductor's last update: peers leave their loop when they reflect it


def fail(message: str) -> None:
    say(error=message)
    sys.exit(3)


class Joined:
    """One federate joined to `federation`, with an object of class robot whose location it owns."""

    def __init__(self, address: str, federation: str, name: str, amb: rti.FederateAmbassador,
                 publish: bool = True, subscribe: bool = True) -> None:
        self.rtia = rti.RTIAmbassador(address)
        self.amb = amb
        self.rtia.joinFederationExecution(name, federation, amb)
        robot = self.rtia.getObjectClassHandle("robot")
        self.location = self.rtia.getAttributeHandle("location", robot)
        if subscribe:
            self.rtia.subscribeObjectClassAttributes(robot, [self.location])
        self.obj = None
        if publish:
            self.rtia.publishObjectClass(robot, [self.location])
            self.obj = self.rtia.registerObjectInstance(robot, name)

    def enable_time(self) -> None:
        """Regulating (lookahead 1) and constrained, waiting for both callbacks."""
        self.rtia.enable_time_management(1.0, timeout=60.0)

    def resign(self) -> None:
        self.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)


def await_start(fed: Joined, amb: processes.SyncAmbassador) -> None:
    """Wait for the conductor's synchronization point "start" and achieve it."""
    processes.synchronize(fed.rtia, amb, "start")
