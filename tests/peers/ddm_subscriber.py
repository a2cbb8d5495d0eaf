"""A subscriber through a region, in its own process (tests/rti/test_ddm.py).

usage: ddm_subscriber.py ADDRESS NAME LOW HIGH

Joins DdmFed as NAME, subscribes vehicle.position and radio through a Geo region with X in [LOW, HIGH]
(Y whole), and broadcast plainly; prints {"ready": true} once the gateway has its subscriptions. Then it
ticks until a broadcast "stop" arrives and prints what it got, in arrival order, as one JSON line:
{"discovered": [names], "reflected": [[name, position], ...], "received": [radio texts]}. It exits by
itself after 60 s as a safety net.
"""

from __future__ import annotations

import json
import sys
import time
from typing import Any

import hlacore.rti as rti
from peerlib import round_trip


class Ambassador(rti.FederateAmbassador):
    def __init__(self) -> None:
        self.names: dict[Any, str] = {}
        self.discovered: list[str] = []
        self.reflected: list[list[str]] = []
        self.received: list[str] = []
        self.stopped = False
        self.position: Any = None
        self.radio: Any = None

    def discoverObjectInstance(self, obj: Any, cls: Any, name: str) -> None:
        self.names[obj] = name
        self.discovered.append(name)

    def reflectAttributeValues(self, obj: Any, attributes: dict[Any, bytes], *rest: Any) -> None:
        self.reflected.append([self.names[obj], attributes[self.position].decode()])

    def receiveInteraction(self, cls: Any, parameters: dict[Any, bytes], *rest: Any) -> None:
        if cls == self.radio:
            self.received.extend(v.decode() for v in parameters.values())
        else:
            self.stopped = True


def main() -> None:
    address, name, low, high = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    rtia = rti.RTIAmbassador(address)
    amb = Ambassador()
    rtia.joinFederationExecution(name, "DdmFed", amb)
    geo = rtia.getRoutingSpaceHandle("Geo")
    vehicle = rtia.getObjectClassHandle("vehicle")
    amb.position = rtia.getAttributeHandle("position", vehicle)
    amb.radio = rtia.getInteractionClassHandle("radio")
    region = rtia.createRegion(geo, [(rtia.getDimensionHandle("X", geo), (low, high))])
    rtia.subscribeObjectClassAttributesWithRegion(vehicle, region, [amb.position])
    rtia.subscribeInteractionClassWithRegion(amb.radio, region)
    rtia.subscribeInteractionClass(rtia.getInteractionClassHandle("broadcast"))
    round_trip(rtia)  # the gateway has handled the subscriptions
    print(json.dumps({"ready": True}), flush=True)
    deadline = time.monotonic() + 60
    while not amb.stopped and time.monotonic() < deadline:
        rtia.tick(0.05, 0.1)
    print(json.dumps({"discovered": amb.discovered, "reflected": amb.reflected, "received": amb.received}), flush=True)
    rtia.resignFederationExecution(rti.ResignAction.NoAction)
    sys.exit(0 if amb.stopped else 3)


if __name__ == "__main__":
    main()
