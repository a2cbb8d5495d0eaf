"""One side of the two-process exchange of test_two_processes.py, printing what it saw as JSON lines.

usage: robot_pair.py ADDRESS sender|receiver
The receiver joins first and prints {"joined": true}; the sender then registers sync point "start" for the
whole federation; after both are synchronized the sender registers a robot, updates its location with
exact bytes and sends a command; the receiver answers the command with a reply carrying the same value.
"""

import sys

import hlacore.rti as rti
from peerlib import PeerAmbassador, say, synchronize, tick_until

LOCATION = bytes(range(256)) + b"\x00tail"
COMMAND = b"go\x00\xff\xfe"


class Ambassador(PeerAmbassador):
    def __init__(self):
        super().__init__()
        self.discovered = []
        self.reflected = []
        self.interactions = []
        self.removed = []

    def discoverObjectInstance(self, obj, cls, name):
        self.discovered.append((obj, cls, name))

    def reflectAttributeValues(self, obj, attributes, tag, order, transport, time=None, retraction=None):
        self.reflected.append((obj, attributes, tag))

    def receiveInteraction(self, cls, parameters, tag, order, transport, time=None, retraction=None):
        self.interactions.append((cls, parameters, tag))

    def removeObjectInstance(self, obj, tag, time=None, retraction=None):
        self.removed.append(obj)


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
        synchronize(rtia, amb)
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
        synchronize(rtia, amb)
        obj = rtia.registerObjectInstance(robot, "robot-1")
        rtia.updateAttributeValues(obj, {location: LOCATION}, "first fix")
        rtia.sendInteraction(command, {name: b"move", value: COMMAND}, "cmd")
        tick_until(rtia, lambda: amb.interactions)
        _, params, tag = amb.interactions[0]
        say(reply=params[reply_value].hex(), reply_tag=tag, synchronized=sorted(amb.synchronized))
        rtia.resignFederationExecution(rti.ResignAction.DeleteObjects)


if __name__ == "__main__":
    main()
