"""The federates of the paused-subscriber case (docs/robustness.md, spilling): `python paused_peer.py ROLE ADDRESS
SECONDS ORDER`, in TestFed, ORDER "receive" or "timestamp".

ROLE "publisher": sends a 1 KiB update of one robot's location every millisecond for SECONDS (value = sequence
number, padded), then one with the value END; reports {"sent": N, "slowest_call": S}. In timestamp order it is
regulating and constrained with lookahead 1, stamps each update one unit after its time and advances to it, in
lockstep with the watcher (one grant per update).
ROLE "watcher" and "paused": subscribed (in timestamp order: the watcher regulating and constrained, the paused
one constrained, asking to advance as it goes); they report {"ready": true}, then receive until END and report
{"received": N, "in_order": BOOL, "max_gap": S} (the longest time between two updates). The test stops and
continues "paused" from outside (SIGSTOP, SIGCONT).
"""

from __future__ import annotations

import sys
import time

import hlacore.rti as rti
from peerlib import say

PAD = 1024
END = b"END"
PERIOD = 0.001  # s between updates
STEP = 1.0      # federation time between updates (whole numbers: exact in floating point)


class Counting(rti.FederateAmbassador):
    def __init__(self) -> None:
        self.received = 0
        self.in_order = True
        self.ended = False
        self.last_at: float | None = None
        self.max_gap = 0.0

    def reflectAttributeValues(self, obj, attributes, tag, *rest) -> None:  # type: ignore[no-untyped-def]
        value = next(iter(attributes.values()))
        now = time.monotonic()
        if self.last_at is not None:
            self.max_gap = max(self.max_gap, now - self.last_at)
        self.last_at = now
        if value == END:
            self.ended = True
            return
        if int(value[:16]) != self.received and self.in_order:
            print(f"out of order: update {int(value[:16])} came as number {self.received}", file=sys.stderr)
            self.in_order = False
        self.received += 1


def publisher(rtia: rti.RTIAmbassador, seconds: float, timestamped: bool) -> None:
    robot = rtia.getObjectClassHandle("robot")
    location = rtia.getAttributeHandle("location", robot)
    rtia.publishObjectClass(robot, [location])
    obj = rtia.registerObjectInstance(robot, "publisher")
    base = rtia.enable_time_management(STEP) if timestamped else 0.0  # where the others' times let it start
    say(ready=True)
    sent, slowest = 0, 0.0
    start = time.monotonic()
    while time.monotonic() < start + seconds:
        value = f"{sent:016d}".encode().ljust(PAD, b".")
        started = time.monotonic()
        stamp = base + (sent + 1) * STEP
        rtia.updateAttributeValues(obj, {location: value}, "", stamp if timestamped else None)
        slowest = max(slowest, time.monotonic() - started)
        sent += 1
        if timestamped:
            rtia.advance_to(stamp, timeout=30.0)  # the grant waits for the watcher: the lockstep
        pause = start + sent * PERIOD - time.monotonic()
        if pause > 0:
            time.sleep(pause)
    rtia.updateAttributeValues(obj, {location: END}, "", base + (sent + 1) * STEP if timestamped else None)
    if timestamped:
        rtia.disableTimeRegulation()  # the others advance past the end without it
    say(sent=sent, slowest_call=round(slowest, 4))


def subscriber(rtia: rti.RTIAmbassador, amb: Counting, timestamped: bool, regulating: bool) -> None:
    robot = rtia.getObjectClassHandle("robot")
    rtia.subscribeObjectClassAttributes(robot, [rtia.getAttributeHandle("location", robot)])
    now = rtia.enable_time_management(STEP, regulating=regulating) if timestamped else 0.0
    say(ready=True)
    while not amb.ended:
        if timestamped:
            now += STEP
            rtia.advance_to(now, timeout=600.0)  # each grant delivers what is stamped up to it
        else:
            rtia.tick(0.01, 0.1)
    say(received=amb.received, in_order=amb.in_order, max_gap=round(amb.max_gap, 4))


def main() -> None:
    role, address, seconds, order = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
    timestamped = order == "timestamp"
    amb = Counting()
    rtia = rti.RTIAmbassador(address)
    rtia.joinFederationExecution(role, "TestFed", amb)
    if role == "publisher":
        publisher(rtia, seconds, timestamped)
    else:
        subscriber(rtia, amb, timestamped, regulating=role == "watcher")
    rtia.resignFederationExecution(rti.ResignAction.ReleaseAttributes)


if __name__ == "__main__":
    main()
