"""The gateway's message trace: reading what ``rtig --trace FILE`` (or ``Gateway(trace=FILE)``) wrote.

The gateway writes one CSV row per event, stamped on the host's monotonic clock in nanoseconds (the clock
``time.monotonic()`` reads, so federates on the same host can compare their own marks with it):

``join``
    a federate joined: ``federate`` is its handle, ``name`` its name;
``update`` / ``interaction``
    an ``updateAttributeValues`` / ``sendInteraction`` of federate ``sender`` was read from its socket
    (``serial`` numbers the sender's messages, ``time`` is the timestamp, empty for receive order);
``reflect`` / ``receive``
    the reflection / interaction made of the sender's message ``serial`` was handed to the socket of federate
    ``federate`` (a timestamp-ordered one only once the receiver's grant allowed it).

:func:`hops` pairs them: for each message a sender sent, when the gateway read it and when it wrote it on to
a receiver.
"""

from __future__ import annotations

import csv
import os
from dataclasses import dataclass
from typing import Iterator, Optional

__all__ = ["TraceRow", "Hop", "read_trace", "hops"]


@dataclass(frozen=True)
class TraceRow:
    """One row of the trace; ``seconds`` is ``ns`` as ``time.monotonic()`` would give it."""

    ns: int
    event: str
    federation: str
    federate: int
    sender: Optional[int]
    serial: Optional[int]
    time: Optional[float]
    name: str

    @property
    def seconds(self) -> float:
        """``ns`` in seconds."""
        return self.ns / 1e9


@dataclass(frozen=True)
class Hop:
    """One message on its way through the gateway, in ``time.monotonic()`` seconds."""

    serial: int
    time: Optional[float]
    received: float   # the gateway read it from the sender
    forwarded: float  # the gateway handed it to the receiver's socket


def _optional(text: str, kind: type) -> Optional[int | float]:
    return kind(text) if text else None


def read_trace(path: str | os.PathLike[str]) -> Iterator[TraceRow]:
    """The rows of a trace file, in the order written (a trailing partial line, from a gateway still
    writing, is skipped)."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader, None)
        if header != ["ns", "event", "federation", "federate", "sender", "serial", "time", "name"]:
            raise ValueError(f"{os.fspath(path)} is not an hlacore message trace (header {header!r})")
        for fields in reader:
            if len(fields) != 8:
                continue
            ns, event, federation, federate, sender, serial, time, name = fields
            yield TraceRow(int(ns), event, federation, int(federate), _optional(sender, int),  # type: ignore[arg-type]
                           _optional(serial, int), _optional(time, float), name)  # type: ignore[arg-type]


def hops(path: str | os.PathLike[str], sender: str, receiver: str, federation: Optional[str] = None) -> list[Hop]:
    """Each message federate ``sender`` sent that reached federate ``receiver`` (both by name; the last
    federates of those names to join), in the order sent. A message split into several reflections (per
    order and transport) counts from its first."""
    rows = list(read_trace(path))
    handles: dict[tuple[str, str], int] = {}
    for row in rows:
        if row.event == "join" and (federation is None or row.federation == federation):
            handles[(row.federation, row.name)] = row.federate
    senders = {fed: h for (fed, name), h in handles.items() if name == sender}
    receivers = {fed: h for (fed, name), h in handles.items() if name == receiver}
    if not senders or not receivers:
        missing = sender if not senders else receiver
        raise KeyError(f"no federate named {missing!r} joined in the trace {os.fspath(path)}")
    received: dict[tuple[str, int], TraceRow] = {}
    forwarded: dict[tuple[str, int], TraceRow] = {}
    for row in rows:
        if row.serial is None or senders.get(row.federation) != row.sender:
            continue
        key = (row.federation, row.serial)
        if row.event in ("update", "interaction"):
            received.setdefault(key, row)
        elif row.event in ("reflect", "receive") and receivers.get(row.federation) == row.federate:
            forwarded.setdefault(key, row)
    return [Hop(key[1], row.time, row.seconds, forwarded[key].seconds)
            for key, row in sorted(received.items(), key=lambda item: item[1].ns) if key in forwarded]
