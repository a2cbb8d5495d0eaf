"""One federate of a lockstep federation (the papers' method), checking every step; prints JSON lines.

usage: lockstep.py ADDRESS NAME STEPS FEDERATES [--stall]

Joins TestFed, registers a robot named NAME, subscribes to every robot's location, becomes regulating
and constrained with lookahead 1 and prints {"ready": true}. After synchronization point "start" it runs
STEPS steps: update its location with "NAME:k" at timestamp k, then timeAdvanceRequest(k). Before each
grant it must have received exactly one update at time k from each of the other FEDERATES - 1 federates,
in timestamp order (ties by sending federate). Prints {"name", "steps", "received", "errors",
"seconds"} and resigns. With --stall it stops after synchronizing and sleeps (to be killed).
"""

import json
import sys
import time

import hlacore.rti as rti


def say(**fields):
    print(json.dumps(fields), flush=True)


class Ambassador(rti.FederateAmbassador):
    def __init__(self):
        self.announced = False
        self.synchronized = False
        self.step_reflections = []
        self.enabled = 0

    def timeRegulationEnabled(self, time):
        self.enabled += 1

    def timeConstrainedEnabled(self, time):
        self.enabled += 1

    def announceSynchronizationPoint(self, label, tag):
        self.announced = True

    def federationSynchronized(self, label):
        self.synchronized = True

    def reflectAttributeValues(self, obj, attributes, tag, order, transport, time=None, retraction=None):
        for value in attributes.values():
            self.step_reflections.append((time, retraction.sendingFederate if retraction else None, value))


def tick_until(rtia, predicate, timeout=30.0):
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            say(error="timeout")
            sys.exit(3)
        rtia.tick(0.05, 0.1)


def main():
    address, name, steps, federates = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    stall = "--stall" in sys.argv[5:]
    rtia = rti.RTIAmbassador(address)
    amb = Ambassador()
    rtia.joinFederationExecution(name, "TestFed", amb)
    robot = rtia.getObjectClassHandle("robot")
    location = rtia.getAttributeHandle("location", robot)
    rtia.publishObjectClass(robot, [location])
    rtia.subscribeObjectClassAttributes(robot, [location])
    obj = rtia.registerObjectInstance(robot, name)
    rtia.enableTimeRegulation(0.0, 1.0)
    rtia.enableTimeConstrained()
    tick_until(rtia, lambda: amb.enabled == 2)
    say(ready=True)
    tick_until(rtia, lambda: amb.announced)
    rtia.synchronizationPointAchieved("start")
    tick_until(rtia, lambda: amb.synchronized)
    if stall:
        time.sleep(120)
        return
    errors = []
    received = 0
    start = time.perf_counter()
    for k in range(1, steps + 1):
        rtia.updateAttributeValues(obj, {location: f"{name}:{k}".encode()}, "step", float(k))
        granted = rtia.advance_to(float(k), timeout=30.0)
        got = amb.step_reflections
        amb.step_reflections = []
        received += len(got)
        if granted != k:
            errors.append(f"step {k}: granted {granted}")
        if len(got) != federates - 1 or any(t != k for t, _, _ in got):
            errors.append(f"step {k}: got {[(t, v.decode()) for t, _, v in got]}")
        elif [s for _, s, _ in got] != sorted(s for _, s, _ in got):
            errors.append(f"step {k}: not in sending-federate order: {got}")
        if len(errors) > 5:
            break
    seconds = time.perf_counter() - start
    say(name=name, steps=steps, received=received, errors=errors, seconds=seconds)
    rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)


if __name__ == "__main__":
    main()
