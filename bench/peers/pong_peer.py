"""The echoing side of the update ping-pong benchmark.

usage: pong_peer.py ADDRESS FEDERATION ro|tso

Joins as "pong" and prints {"ready": true} once it has discovered the conductor's object (so its
subscription is in place at the gateway). Every value it reflects it sends back as an update of its own
object: receive order without time management (ro), or, regulating and constrained with lookahead 1
(tso), at its grant time + 1 after nextEventRequest. Stops on b"stop", prints {"echoed": n}, resigns.
"""

from __future__ import annotations

import sys
import time
from typing import Any, Optional

from hlacore.processes import SyncAmbassador, tick_until
from peerlib import STOP, Joined, fail, say

FAR = 1e12  # nextEventRequest's bound: only the conductor's next message decides the grant


class Ambassador(SyncAmbassador):
    def __init__(self) -> None:
        super().__init__()
        self.value: Optional[bytes] = None
        self.discovered = False

    def discoverObjectInstance(self, obj: Any, cls: Any, name: str) -> None:
        self.discovered = True

    def reflectAttributeValues(self, obj: Any, attributes: dict, tag: str, order: Any, transport: Any,
                               time: Any = None, retraction: Any = None) -> None:
        (self.value,) = attributes.values()


def receive(fed: Joined, amb: Ambassador, tso: bool, requested: bool = False) -> bytes:
    """The next value reflected; in tso mode, with the federate granted to its timestamp (the
    nextEventRequest already made if `requested`)."""
    if tso and requested:
        fed.rtia.await_grant(timeout=60.0)
    elif tso:
        fed.rtia.next_event(FAR, timeout=60.0)
    deadline = time.monotonic() + 60.0
    while amb.value is None:
        if time.monotonic() > deadline:
            fail("no update within 60 s")
        fed.rtia.tick(1.0, 1.0)
    value, amb.value = amb.value, None
    return value


def main() -> None:
    address, federation, mode = sys.argv[1:4]
    tso, batched = mode != "ro", mode == "tso-batched"
    amb = Ambassador()
    fed = Joined(address, federation, "pong", amb)
    if tso:
        fed.enable_time()
    tick_until(fed.rtia, lambda: amb.discovered)
    say(ready=True)
    echoed = 0
    while (value := receive(fed, amb, tso, requested=batched and echoed > 0)) != STOP:
        time_arg = (float(fed.rtia.queryFederateTime()) + 1.0,) if tso else ()
        if batched:  # the echo and the next request in one write (RTIAmbassador.batch)
            with fed.rtia.batch():
                fed.rtia.updateAttributeValues(fed.obj, {fed.location: value}, "", *time_arg)
                fed.rtia.nextEventRequest(FAR)
        else:
            fed.rtia.updateAttributeValues(fed.obj, {fed.location: value}, "", *time_arg)
        echoed += 1
    say(echoed=echoed)
    fed.resign()


if __name__ == "__main__":
    main()
