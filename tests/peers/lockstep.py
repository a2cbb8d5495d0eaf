"""One federate of a lockstep federation (the papers' method), checking every step; prints JSON lines.

usage: lockstep.py ADDRESS NAME STEPS FEDERATES [--stall]

Joins TestFed, registers a robot named NAME, subscribes to every robot's location, becomes regulating
and constrained with lookahead 1 and prints {"ready": true}. After synchronization point "start" it runs
STEPS steps: update its location with "NAME:k" at timestamp k, then timeAdvanceRequest(k). Before each
grant it must have received exactly one update at time k from each of the other FEDERATES - 1 federates,
in timestamp order (ties by sending federate). Prints {"name", "steps", "received", "errors",
"seconds"} and resigns. With --stall it stops after synchronizing and sleeps (to be killed).
"""

import sys
import time

import hlacore.rti as rti
from peerlib import PeerAmbassador, join_lockstep, say, synchronize


class Ambassador(PeerAmbassador):
    def __init__(self):
        super().__init__()
        self.step_reflections = []

    def reflectAttributeValues(self, obj, attributes, tag, order, transport, time=None, retraction=None):
        for value in attributes.values():
            self.step_reflections.append((time, retraction.sendingFederate if retraction else None, value))


def main():
    address, name, steps, federates = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    stall = "--stall" in sys.argv[5:]
    amb = Ambassador()
    rtia, location, obj = join_lockstep(address, name, amb)
    say(ready=True)
    synchronize(rtia, amb)
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
