"""Save and restore of a federation with N objects: two federates in this process, `a` registering N
robots that `b` discovers; one round is a whole requestFederationSave -> federationSaved (or
requestFederationRestore -> federationRestored) at both, ticking included."""

from __future__ import annotations

import time
from typing import Any, Callable

import hlacore.rti as rti

from .federation import FOM, create


class Answering(rti.FederateAmbassador):
    """Answers initiateFederateSave / initiateFederateRestore at once and counts the outcomes."""

    def __init__(self) -> None:
        self.rtia: Any = None
        self.discovered = 0
        self.saved = 0
        self.restored = 0

    def discoverObjectInstance(self, obj: Any, cls: Any, name: str) -> None:
        self.discovered += 1

    def initiateFederateSave(self, label: str) -> None:
        self.rtia.federateSaveComplete()

    def federationSaved(self) -> None:
        self.saved += 1

    def initiateFederateRestore(self, label: str, handle: Any) -> None:
        self.rtia.federateRestoreComplete()

    def federationRestored(self) -> None:
        self.restored += 1


class SaveRestore:
    def __init__(self, address: str, objects: int) -> None:
        self.federation = create(address)
        self.feds: list[tuple[rti.RTIAmbassador, Answering]] = []
        for name in ("a", "b"):
            rtia, amb = rti.RTIAmbassador(address), Answering()
            amb.rtia = rtia
            rtia.joinFederationExecution(name, self.federation, amb)
            self.feds.append((rtia, amb))
        (a, _), (b, b_amb) = self.feds
        robot = a.getObjectClassHandle("robot")
        attributes = [a.getAttributeHandle(n, robot) for n in ("location", "battery")]
        a.publishObjectClass(robot, attributes)
        b.subscribeObjectClassAttributes(robot, attributes)
        for _ in range(objects):
            a.registerObjectInstance(robot)
        self._tick_until(lambda: b_amb.discovered == objects)
        a.requestFederationSave("bench")
        self._tick_until(lambda: all(amb.saved for _, amb in self.feds))

    def _tick_until(self, done: Callable[[], bool], timeout: float = 120.0) -> None:
        deadline = time.monotonic() + timeout
        while not done():
            if time.monotonic() > deadline:
                raise TimeoutError("save/restore bench: no progress")
            for rtia, _ in self.feds:
                rtia.tick()

    def save(self) -> None:
        target = self.feds[0][1].saved + 1
        self.feds[0][0].requestFederationSave("bench")
        self._tick_until(lambda: all(amb.saved == target for _, amb in self.feds))

    def restore(self) -> None:
        target = self.feds[0][1].restored + 1
        self.feds[0][0].requestFederationRestore("bench")
        self._tick_until(lambda: all(amb.restored == target for _, amb in self.feds))

    def close(self) -> None:
        for rtia, _ in self.feds:
            rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        self.feds[0][0].destroyFederationExecution(self.federation)


__all__ = ["SaveRestore", "FOM"]
