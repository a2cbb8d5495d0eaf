"""The two federates of the flow-control case (docs/robustness.md, case 1): `python flow_peer.py ROLE ADDRESS SECONDS
ORDER`, in TestFed, ORDER "receive" or "timestamp".

ROLE "publisher": sends 1 KiB updates of one robot's location (value = sequence number, padded) as fast as
it can for SECONDS (receive order untimed; timestamp order regulating with lookahead 1 at time = sequence
number, advancing every 1024), then reports {"sent": N, "slowest_call": S} (the longest update, with its
time advance).
ROLE "paused": constrained, subscribed; reports {"ready": true}, then keeps ticking for SECONDS without asking
to advance (a federate at a breakpoint of its time loop), then asks to advance and reports
{"received": N, "in_order": BOOL, "before_advance": M} once nothing more has come for 3 s.
"""

from __future__ import annotations

import sys
import time

import hlacore.rti as rti
from peerlib import say

PAD = 1024


class Counting(rti.FederateAmbassador):
    def __init__(self) -> None:
        self.received = 0
        self.in_order = True
        self.last_at = time.monotonic()

    def reflectAttributeValues(self, obj, attributes, tag, *rest) -> None:  # type: ignore[no-untyped-def]
        value = next(iter(attributes.values()))
        if int(value[:16]) != self.received and self.in_order:
            print(f"out of order: update {int(value[:16])} came as number {self.received}", file=sys.stderr)
            self.in_order = False
        self.received += 1
        self.last_at = time.monotonic()


def publisher(rtia: rti.RTIAmbassador, seconds: float, timestamped: bool) -> None:
    robot = rtia.getObjectClassHandle("robot")
    location = rtia.getAttributeHandle("location", robot)
    rtia.publishObjectClass(robot, [location])
    obj = rtia.registerObjectInstance(robot, "flooding")
    if timestamped:
        rtia.enable_time_management(1.0, constrained=False)
    say(ready=True)
    sent, slowest = 0, 0.0
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        value = f"{sent:016d}".encode().ljust(PAD, b".")
        started = time.monotonic()
        rtia.updateAttributeValues(obj, {location: value}, "", float(sent + 1) if timestamped else None)
        sent += 1
        if timestamped and sent % 1024 == 0:
            rtia.advance_to(float(sent))  # lets its time (and the timestamps it may use) move on
        slowest = max(slowest, time.monotonic() - started)
    say(sent=sent, slowest_call=round(slowest, 3))


def paused(rtia: rti.RTIAmbassador, amb: Counting, seconds: float) -> None:
    robot = rtia.getObjectClassHandle("robot")
    rtia.subscribeObjectClassAttributes(robot, [rtia.getAttributeHandle("location", robot)])
    rtia.enable_time_management(1.0, regulating=False)
    say(ready=True)
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        rtia.tick(0.1, 0.1)
    before = amb.received
    rtia.advance_to(1e9)  # the held updates come before the grant (timestamped ones: once the publisher left)
    rtia.enableAsynchronousDelivery()  # and the later ones without waiting for another advance
    amb.last_at = time.monotonic()
    while time.monotonic() - amb.last_at < 3:
        rtia.tick(0.1, 0.1)
    say(received=amb.received, in_order=amb.in_order, before_advance=before)


def main() -> None:
    role, address, seconds, order = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
    amb = Counting()
    rtia = rti.RTIAmbassador(address)
    rtia.joinFederationExecution(role, "TestFed", amb)
    if role == "publisher":
        publisher(rtia, seconds, order == "timestamp")
    else:
        paused(rtia, amb, seconds)
    # The object stays: updates still queued for the paused federate are not dropped with it.
    rtia.resignFederationExecution(rti.ResignAction.ReleaseAttributes)


if __name__ == "__main__":
    main()
