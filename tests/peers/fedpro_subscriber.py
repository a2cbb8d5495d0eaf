"""A Federate Protocol federate that counts the speeds of vehicles (tests/transport/test_fedpro_paused.py):
`python fedpro_subscriber.py FEDPRO_ADDRESS COUNT`. Joins "Road" as "slow" through hlacore.fedpro, subscribes to
Vehicle.speed, reports {"ready": true}, then evokes until COUNT reflections came and reports {"received": N,
"in_order": BOOL} (each value a big-endian sequence number from 1 in its first 4 bytes), and resigns."""

from __future__ import annotations

import struct
import sys
import time
from typing import Any

from hlacore import fedpro
from peerlib import say


class Counting(fedpro.NullFederateAmbassador):
    def __init__(self) -> None:
        self.received = 0
        self.in_order = True

    def reflectAttributeValues(self, msg: Any) -> None:
        (value,) = fedpro.handle_values(msg.attributeValues).values()
        self.received += 1
        self.in_order = self.in_order and struct.unpack(">I", value[:4])[0] == self.received


def main() -> None:
    address, count = sys.argv[1], int(sys.argv[2])
    amb = Counting()
    with fedpro.RTIambassador(address) as rtia:
        rtia.connect(amb)
        rtia.joinFederationExecution(federateName="slow", federateType="fedpro", federationName="Road")
        vehicle = rtia.getObjectClassHandle(objectClassName="Vehicle")
        speed = rtia.getAttributeHandle(objectClass=vehicle, attributeName="speed")
        rtia.subscribeObjectClassAttributes(objectClass=vehicle, attributes=[speed])
        say(ready=True)
        deadline = time.monotonic() + 300
        while amb.received < count and time.monotonic() < deadline:
            rtia.evokeCallback(0.5)
        say(received=amb.received, in_order=amb.in_order)
        rtia.resignFederationExecution(resignAction="NO_ACTION")


if __name__ == "__main__":
    main()
