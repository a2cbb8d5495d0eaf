"""What the standalone test peers share: JSON-line reports, bounded ticking, the time-enabling and
synchronization-point callbacks, and waiting to be killed. Each peer runs as `python tests/peers/X.py`,
so this directory is on its path."""

from __future__ import annotations

import json
import sys
import time
from typing import Any, Callable

import hlacore.rti as rti


def say(**fields: Any) -> None:
    """One JSON line on stdout, flushed: how peers talk to the test that started them."""
    print(json.dumps(fields), flush=True)


def tick_until(rtia: rti.RTIAmbassador, predicate: Callable[[], bool], timeout: float = 30.0) -> None:
    """Tick until predicate() holds; after `timeout` seconds report {"error": "timeout"} and exit 3."""
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            say(error="timeout")
            sys.exit(3)
        rtia.tick(0.05, 0.1)


def round_trip(rtia: rti.RTIAmbassador) -> None:
    """A request answered by the gateway: whatever this federate sent before has been handled once it returns
    (asks to destroy a federation that does not exist)."""
    try:
        rtia.destroyFederationExecution("peerlib-round-trip")
    except rti.FederationExecutionDoesNotExist:
        pass


def linger(seconds: float) -> None:
    """Do nothing (never tick) until killed; exit by ourselves after `seconds` as a safety net."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        time.sleep(0.2)


class PeerAmbassador(rti.FederateAmbassador):
    """Counts timeRegulationEnabled/timeConstrainedEnabled and keeps the announced and synchronized labels."""

    def __init__(self) -> None:
        self.enabled = 0
        self.announced: set[str] = set()
        self.synchronized: set[str] = set()

    def timeRegulationEnabled(self, time: float) -> None:
        self.enabled += 1

    def timeConstrainedEnabled(self, time: float) -> None:
        self.enabled += 1

    def announceSynchronizationPoint(self, label: str, tag: str) -> None:
        self.announced.add(label)

    def federationSynchronized(self, label: str) -> None:
        self.synchronized.add(label)


def enable_time(rtia: rti.RTIAmbassador, amb: PeerAmbassador, lookahead: float = 1.0) -> None:
    """Regulating (from time 0, `lookahead`) and constrained, waiting for both callbacks."""
    rtia.enable_time_management(lookahead, timeout=30.0)


def synchronize(rtia: rti.RTIAmbassador, amb: PeerAmbassador, label: str = "start") -> None:
    """Wait for `label` to be announced, achieve it and wait until the federation is synchronized on it."""
    tick_until(rtia, lambda: label in amb.announced)
    rtia.synchronizationPointAchieved(label)
    tick_until(rtia, lambda: label in amb.synchronized)


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
