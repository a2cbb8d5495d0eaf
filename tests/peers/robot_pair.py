"""One side of the two-process exchange of test_two_processes.py, printing what it saw as JSON lines.

usage: robot_pair.py ADDRESS sender|receiver
The receiver joins first and prints {"joined": true}; the sender then registers sync point "start" for the
whole federation; after both are synchronized the sender registers a robot, updates its location with
exact bytes and sends a command; the receiver answers the command with a reply carrying the same value.
"""

import json
import sys
import time

import hlacore.rti as rti

LOCATION = bytes(range(256)) + b"\x00tail"
COMMAND = b"go\x00\xff\xfe"


def say(**fields):
    print(json.dumps(fields), flush=True)


class Ambassador(rti.FederateAmbassador):
    def __init__(self):
        self.announced = set()
        self.synchronized = set()
        self.discovered = []
        self.reflected = []
        self.interactions = []
        self.removed = []

    def announceSynchronizationPoint(self, label, tag):
        self.announced.add(label)

    def federationSynchronized(self, label):
        self.synchronized.add(label)

    def discoverObjectInstance(self, obj, cls, name):
        self.discovered.append((obj, cls, name))

    def reflectAttributeValues(self, obj, attributes, tag, order, transport, time=None, retraction=None):
        self.reflected.append((obj, attributes, tag))

    def receiveInteraction(self, cls, parameters, tag, order, transport, time=None, retraction=None):
        self.interactions.append((cls, parameters, tag))

    def removeObjectInstance(self, obj, tag, time=None, retraction=None):
        self.removed.append(obj)


def tick_until(rtia, predicate, timeout=10.0):
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            say(error="timeout")
            sys.exit(3)
        rtia.tick(0.05, 0.1)


def main():
    address, role = sys.argv[1], sys.argv[2]
    rtia = rti.RTIAmbassador(address)
    amb = Ambassador()
    rtia.joinFederationExecution(role, "TestFed", amb)
    robot = rtia.getObjectClassHandle("ObjectRoot.robot")
    location = rtia.getAttributeHandle("location", robot)
    command = rtia.getInteractionClassHandle("command")
    name, value = rtia.getParameterHandle("name", command), rtia.getParameterHandle("value", command)
    reply = rtia.getInteractionClassHandle("reply")
    reply_value = rtia.getParameterHandle("value", reply)

    if role == "receiver":
        rtia.subscribeObjectClassAttributes(robot, [location])
        rtia.subscribeInteractionClass(command)
        rtia.publishInteractionClass(reply)
        say(joined=True)
        tick_until(rtia, lambda: "start" in amb.announced)
        rtia.synchronizationPointAchieved("start")
        tick_until(rtia, lambda: "start" in amb.synchronized)
        tick_until(rtia, lambda: amb.reflected and amb.interactions)
        _, params, _ = amb.interactions[0]
        rtia.sendInteraction(reply, {reply_value: params[value]}, "reply")
        tick_until(rtia, lambda: amb.removed)
        obj, cls, obj_name = amb.discovered[0]
        _, attributes, tag = amb.reflected[0]
        say(
            discovered_class=rtia.getObjectClassName(cls),
            discovered_name=obj_name,
            reflected={rtia.getAttributeName(a, cls): v.hex() for a, v in attributes.items()},
            reflect_tag=tag,
            interaction={rtia.getParameterName(p, command): v.hex() for p, v in params.items()},
            removed=obj == amb.removed[0],
            synchronized=sorted(amb.synchronized),
        )
        rtia.resignFederationExecution(rti.ResignAction.NoAction)
    else:
        rtia.publishObjectClass(robot, [location])
        rtia.publishInteractionClass(command)
        rtia.subscribeInteractionClass(reply)
        rtia.registerFederationSynchronizationPoint("start", "both joined")
        tick_until(rtia, lambda: "start" in amb.announced)
        rtia.synchronizationPointAchieved("start")
        tick_until(rtia, lambda: "start" in amb.synchronized)
        obj = rtia.registerObjectInstance(robot, "robot-1")
        rtia.updateAttributeValues(obj, {location: LOCATION}, "first fix")
        rtia.sendInteraction(command, {name: b"move", value: COMMAND}, "cmd")
        tick_until(rtia, lambda: amb.interactions)
        _, params, tag = amb.interactions[0]
        say(reply=params[reply_value].hex(), reply_tag=tag, synchronized=sorted(amb.synchronized))
        rtia.resignFederationExecution(rti.ResignAction.DeleteObjects)


if __name__ == "__main__":
    main()
