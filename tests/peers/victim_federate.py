"""A federate that joins TestFed, owns a robot named 'victim' and then only sleeps, waiting to be killed.

Usage: victim_federate.py HOST:PORT. Prints `ready <federate handle> <object handle>` once registered.
It never ticks, so it never achieves a synchronization point. It exits by itself after 60 s as a safety net.
"""

from __future__ import annotations

import sys

import hlacore.rti as rti
from peerlib import linger


class Silent(rti.FederateAmbassador):
    pass


def main() -> None:
    rtia = rti.RTIAmbassador(sys.argv[1])
    handle = rtia.joinFederationExecution("victim", "TestFed", Silent())
    robot = rtia.getObjectClassHandle("robot")
    location = rtia.getAttributeHandle("location", robot)
    rtia.publishObjectClass(robot, [location])
    obj = rtia.registerObjectInstance(robot, "victim")
    rtia.updateAttributeValues(obj, {location: b"here"}, "alive")
    print(f"ready {int(handle)} {int(obj)}", flush=True)
    linger(60)


if __name__ == "__main__":
    main()
