"""The measuring federate's side shared by the benchmarks: a fresh federation on the robot FOM that the
pytest process creates and joins, and the synchronization point that releases the peers together."""

from __future__ import annotations

import itertools
import pathlib
from typing import Any

import hlacore
import hlacore.rti as rti
from hlacore.processes import SyncAmbassador, tick_until

from .peers.peerlib import Joined

FOM = str(pathlib.Path(hlacore.__file__).parent / "foms" / "robot.fed")
_names = itertools.count(1)


class Counting(SyncAmbassador):
    """Counts reflections and keeps the last value reflected."""

    def __init__(self) -> None:
        super().__init__()
        self.reflected = 0
        self.last: Any = None

    def reflectAttributeValues(self, obj: Any, attributes: dict, tag: str, order: Any, transport: Any,
                               time: Any = None, retraction: Any = None) -> None:
        self.reflected += 1
        self.last = attributes


def create(address: str) -> str:
    """A new federation execution on the robot FOM; returns its name (unique in this process)."""
    name = f"bench-{next(_names)}"
    rti.RTIAmbassador(address).createFederationExecution(name, FOM)
    return name


def join(address: str, federation: str, name: str, **kwargs: bool) -> tuple[Joined, Counting]:
    amb = Counting()
    return Joined(address, federation, name, amb, **kwargs), amb


def release_peers(fed: Joined, amb: Counting) -> None:
    """Register "start", achieve it, and wait until every joined federate has."""
    fed.rtia.registerFederationSynchronizationPoint("start", "")
    tick_until(fed.rtia, lambda: amb.announced)
    fed.rtia.synchronizationPointAchieved("start")
    tick_until(fed.rtia, lambda: amb.synchronized)


def leave(fed: Joined, federation: str) -> None:
    """Resign and destroy the federation (the peers have resigned by then)."""
    fed.resign()
    fed.rtia.destroyFederationExecution(federation)
