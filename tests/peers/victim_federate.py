"""A federate that joins TestFed, owns a robot named 'victim' and then only sleeps, waiting to be killed.

Usage: victim_federate.py HOST:PORT. Prints `ready <federate handle> <object handle>` once registered.
It never ticks, so it never achieves a synchronization point. It exits by itself after 60 s as a safety net.
"""

from __future__ import annotations

import sys
import time

import hlacore.rti as rti


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
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        time.sleep(0.2)


if __name__ == "__main__":
    main()
