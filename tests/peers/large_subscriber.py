"""A 1516-2010 federate that counts large speeds (tests/transport/test_paused_federate.py): `python
large_subscriber.py ADDRESS COUNT`. Joins "Road" (tests/data/rti1516e/vehicles.xml) as "slow", subscribes to
Vehicle.speed, reports {"ready": true}, evokes until COUNT reflections came, reports {"received": N, "in_order":
BOOL} (each value a big-endian sequence number from 1 in its first 4 bytes) and resigns."""

from __future__ import annotations

import struct
import sys
import time

import hlacore.rti1516e as rti1516e
from peerlib import say


class Counting:
    def __init__(self) -> None:
        self.received = 0
        self.in_order = True

    def reflectAttributeValues(self, obj, values, *rest) -> None:  # type: ignore[no-untyped-def]
        (value,) = values.values()
        self.received += 1
        self.in_order = self.in_order and struct.unpack(">I", value[:4])[0] == self.received

    def __getattr__(self, name: str):  # type: ignore[no-untyped-def]
        return lambda *args: None  # the other callbacks: nothing to do


def main() -> None:
    address, count = sys.argv[1], int(sys.argv[2])
    amb = Counting()
    rtia = rti1516e.RTIambassador()
    rtia.connect(amb, "HLA_EVOKED", address)
    rtia.joinFederationExecution("slow", "large", "Road")
    vehicle = rtia.getObjectClassHandle("Vehicle")
    rtia.subscribeObjectClassAttributes(vehicle, [rtia.getAttributeHandle(vehicle, "speed")])
    say(ready=True)
    deadline = time.monotonic() + 300
    while amb.received < count and time.monotonic() < deadline:
        rtia.evokeMultipleCallbacks(0.1, 0.5)
    say(received=amb.received, in_order=amb.in_order)
    rtia.resignFederationExecution(rti1516e.NO_ACTION)
    rtia.disconnect()


if __name__ == "__main__":
    main()
