"""What the standalone test peers share beyond hlacore.processes (JSON-line reports, bounded ticking,
synchronization points, a round trip to the gateway, waiting to be killed, re-exported here): the
time-enabling callbacks and joining a lockstep. Each peer runs as `python tests/peers/X.py`, so this directory is
on its path."""

from __future__ import annotations

import hlacore.rti as rti
from hlacore.processes import SyncAmbassador, linger, round_trip, say, serve, synchronize, tick_until

__all__ = ["PeerAmbassador", "SavingAmbassador", "enable_time", "join_lockstep", "join_publisher", "linger",
           "round_trip", "say", "serve", "synchronize", "tick_until"]


class PeerAmbassador(SyncAmbassador):
    """Counts timeRegulationEnabled/timeConstrainedEnabled, and keeps the synchronization points."""

    def __init__(self) -> None:
        super().__init__()
        self.enabled = 0

    def timeRegulationEnabled(self, time: float) -> None:
        self.enabled += 1

    def timeConstrainedEnabled(self, time: float) -> None:
        self.enabled += 1


class SavingAmbassador(rti.FederateAmbassador):
    """For the save/restore peers: keeps the names of the objects discovered, prints initiateFederateSave
    and federationSaved as JSON lines ({"event": ...}) and answers the save with answer_save()."""

    def __init__(self, rtia: rti.RTIAmbassador | None = None) -> None:
        self.rtia = rtia
        self.names: dict = {}

    def discoverObjectInstance(self, obj, cls, name) -> None:
        self.names[obj] = name

    def initiateFederateSave(self, label: str) -> None:
        say(event="initiateFederateSave", label=label)
        self.answer_save()

    def answer_save(self) -> None:
        self.rtia.federateSaveBegun()
        self.rtia.federateSaveComplete()

    def federationSaved(self) -> None:
        say(event="federationSaved")


def enable_time(rtia: rti.RTIAmbassador, amb: PeerAmbassador, lookahead: float = 1.0) -> None:
    """Regulating (from time 0, `lookahead`) and constrained, waiting for both callbacks."""
    rtia.enable_time_management(lookahead, timeout=30.0)


def join_publisher(address: str, name: str):
    """Join TestFed as `name`, publish robot.location and register a robot named `name` (no time management).
    Returns (rtia, location attribute, object)."""
    rtia = rti.RTIAmbassador(address)
    rtia.joinFederationExecution(name, "TestFed", rti.FederateAmbassador())
    robot = rtia.getObjectClassHandle("robot")
    location = rtia.getAttributeHandle("location", robot)
    rtia.publishObjectClass(robot, [location])
    return rtia, location, rtia.registerObjectInstance(robot, name)


def join_lockstep(address: str, name: str, amb: PeerAmbassador, timeout: float = 60.0):
    """Join TestFed as `name`, publish and subscribe robot.location, register a robot named `name`, become
    regulating (lookahead 1) and constrained. Returns (rtia, location attribute, object)."""
    rtia = rti.RTIAmbassador(address)
    rtia.joinFederationExecution(name, "TestFed", amb)
    robot = rtia.getObjectClassHandle("robot")
    location = rtia.getAttributeHandle("location", robot)
    rtia.publishObjectClass(robot, [location])
    rtia.subscribeObjectClassAttributes(robot, [location])
    obj = rtia.registerObjectInstance(robot, name)
    rtia.enable_time_management(1.0, timeout)
    return rtia, location, obj
