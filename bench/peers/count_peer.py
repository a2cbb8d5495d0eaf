"""A subscriber of the throughput benchmark: counts the updates it reflects.

usage: count_peer.py ADDRESS FEDERATION NAME BURST

Subscribes to robot.location, prints {"ready": true} once it has discovered the sender's object, then
prints {"received": n} each time its count reaches a multiple of BURST, and {"received": n, "stopped":
true} when it reflects b"stop" (not counted). Fails after 60 s without an update.
"""

from __future__ import annotations

import sys
import time
from typing import Any

from hlacore.processes import SyncAmbassador, tick_until
from peerlib import STOP, Joined, fail, say


class Ambassador(SyncAmbassador):
    def __init__(self, burst: int) -> None:
        super().__init__()
        self.burst = burst
        self.received = 0
        self.discovered = False
        self.stopped = False

    def discoverObjectInstance(self, obj: Any, cls: Any, name: str) -> None:
        self.discovered = True

    def reflectAttributeValues(self, obj: Any, attributes: dict, tag: str, order: Any, transport: Any,
                               time: Any = None, retraction: Any = None) -> None:
        if STOP in attributes.values():
            self.stopped = True
            return
        self.received += 1
        if self.received % self.burst == 0:
            say(received=self.received)


def main() -> None:
    address, federation, name, burst = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    amb = Ambassador(burst)
    fed = Joined(address, federation, name, amb, publish=False)
    tick_until(fed.rtia, lambda: amb.discovered)
    say(ready=True)
    last, seen = time.monotonic(), 0
    while not amb.stopped:
        fed.rtia.tick(1.0, 1.0)
        if amb.received != seen:
            last, seen = time.monotonic(), amb.received
        elif time.monotonic() - last > 60.0:
            fail(f"no update for 60 s after {seen}")
    say(received=amb.received, stopped=True)
    fed.resign()


if __name__ == "__main__":
    main()
