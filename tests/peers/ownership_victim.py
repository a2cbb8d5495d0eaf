"""A federate that acquires the unowned location and battery of robot 'r1', then waits to be killed.

Usage: ownership_victim.py HOST:PORT. Joins TestFed as 'victim', publishes robot location and battery,
discovers r1, takes both with attributeOwnershipAcquisitionIfAvailable, updates location with b"victim"
and prints `owner <federate handle>`. Then it only sleeps (never ticks, so it never answers a release
request); it exits by itself after 60 s as a safety net.
"""

import sys

import hlacore.rti as rti
from peerlib import linger, tick_until


class Ambassador(rti.FederateAmbassador):
    def __init__(self):
        self.discovered = {}
        self.acquired = set()

    def discoverObjectInstance(self, obj, cls, name):
        self.discovered[name] = obj

    def attributeOwnershipAcquisitionNotification(self, obj, attributes):
        self.acquired.update(attributes)


def main():
    rtia = rti.RTIAmbassador(sys.argv[1])
    amb = Ambassador()
    handle = rtia.joinFederationExecution("victim", "TestFed", amb)
    robot = rtia.getObjectClassHandle("robot")
    location = rtia.getAttributeHandle("location", robot)
    battery = rtia.getAttributeHandle("battery", robot)
    rtia.publishObjectClass(robot, [location, battery])
    rtia.subscribeObjectClassAttributes(robot, [location])
    tick_until(rtia, lambda: "r1" in amb.discovered)
    obj = amb.discovered["r1"]
    rtia.attributeOwnershipAcquisitionIfAvailable(obj, [location, battery])
    tick_until(rtia, lambda: amb.acquired == {location, battery})
    rtia.updateAttributeValues(obj, {location: b"victim"}, "alive")
    print(f"owner {int(handle)}", flush=True)
    linger(60)


if __name__ == "__main__":
    main()
