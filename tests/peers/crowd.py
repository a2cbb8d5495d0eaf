"""Several federates in one process that do a bit of everything, then freeze waiting to be killed.

usage: crowd.py ADDRESS PREFIX COUNT [--payload BYTES] [--updates K] [--tar TIME] [--sync LABEL]

Joins COUNT federates PREFIX0..PREFIX{COUNT-1} to TestFed, one connection each. Each publishes and subscribes
robot.location and the command interaction, registers a robot named after itself, becomes regulating
(lookahead 1) and constrained, then sends K receive-order updates of BYTES bytes, K timestamped updates (times
1..K) and K timestamped interactions, then waits for each federate's queryLBTS (the gateway then has all it
sent). With --sync, federate 0 registers LABEL and every federate sees it announced (none achieves it). With --tar, every federate requests a time advance to TIME. Then it prints
`ready H0 H1 ...` (the federate handles) and stops ticking: messages for it pile up in the gateway until the
process is killed. It exits by itself after 120 s as a safety net.
"""

from __future__ import annotations

import argparse
import sys
import time

import hlacore.rti as rti
from peerlib import linger


class Ambassador(rti.FederateAmbassador):
    def __init__(self) -> None:
        self.enabled = 0
        self.announced = False

    def timeRegulationEnabled(self, t: float) -> None:
        self.enabled += 1

    def timeConstrainedEnabled(self, t: float) -> None:
        self.enabled += 1

    def announceSynchronizationPoint(self, label: str, tag: str) -> None:
        self.announced = True


def tick_until(feds, predicate, timeout: float = 30.0) -> None:
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            print("timeout", flush=True)
            sys.exit(3)
        for rtia, _ in feds:
            rtia.tick(0.0, 0.01)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("address")
    parser.add_argument("prefix")
    parser.add_argument("count", type=int)
    parser.add_argument("--payload", type=int, default=1024)
    parser.add_argument("--updates", type=int, default=10)
    parser.add_argument("--tar", type=float)
    parser.add_argument("--sync")
    args = parser.parse_args()

    feds = []
    handles = []
    for i in range(args.count):
        rtia, amb = rti.RTIAmbassador(args.address), Ambassador()
        handles.append(int(rtia.joinFederationExecution(f"{args.prefix}{i}", "TestFed", amb)))
        feds.append((rtia, amb))
    rtia0 = feds[0][0]
    robot = rtia0.getObjectClassHandle("robot")
    location = rtia0.getAttributeHandle("location", robot)
    command = rtia0.getInteractionClassHandle("command")
    value = rtia0.getParameterHandle("value", command)
    objects = []
    for i, (rtia, amb) in enumerate(feds):
        rtia.publishObjectClass(robot, [location])
        rtia.subscribeObjectClassAttributes(robot, [location])
        rtia.publishInteractionClass(command)
        rtia.subscribeInteractionClass(command)
        objects.append(rtia.registerObjectInstance(robot, f"{args.prefix}{i}"))
        rtia.enableTimeRegulation(0.0, 1.0)
        rtia.enableTimeConstrained()
    tick_until(feds, lambda: all(amb.enabled == 2 for _, amb in feds))
    payload = bytes(args.payload)
    for (rtia, _), obj in zip(feds, objects):
        for k in range(1, args.updates + 1):
            rtia.updateAttributeValues(obj, {location: payload}, "ro")
            rtia.updateAttributeValues(obj, {location: payload}, "tso", float(k))
            rtia.sendInteraction(command, {value: payload}, "tso", float(k))
    # A query the gateway answers after everything sent before it: nothing is left in a writer thread or a
    # socket buffer of this process when the test kills it.
    for rtia, _ in feds:
        rtia.queryLBTS()
    if args.sync:
        rtia0.registerFederationSynchronizationPoint(args.sync, "")
        tick_until(feds, lambda: all(amb.announced for _, amb in feds))
    if args.tar is not None:
        for rtia, _ in feds:
            rtia.timeAdvanceRequest(args.tar)
    print("ready " + " ".join(map(str, handles)), flush=True)
    linger(120)


if __name__ == "__main__":
    main()
