"""One federate of the load test: lockstep with timestamped updates, every message checked by its sender's
sequence number. Prints JSON lines.

usage: load_peer.py ADDRESS NAME STEPS NAMES [--victims V1,V2 --die-at K]

NAMES is the comma-separated list of every federate of the run (NAME among them); those listed after
--victims stop after step K. Joins TestFed, registers a robot named NAME, subscribes to every robot's location,
becomes regulating and constrained (lookahead 1), prints {"ready": true} and achieves sync point "start".
Step k: update location with "NAME:k" at timestamp k, then timeAdvanceRequest(k). Before the grant to k it must
have received exactly one update at time k from each other federate alive at k, carrying that sender's sequence
number k (so from each sender 1, 2, 3, ... with no gap, duplicate or reordering), in timestamp order, ties by
sending federate. A victim (listed in --victims) prints {"dying": K} after the grant to K and waits to be killed.
Prints {"name", "steps", "received", "last": {sender: last sequence number}, "errors", "seconds"} and resigns.
"""

import argparse
import time

import hlacore.rti as rti
from peerlib import PeerAmbassador, join_lockstep, say, tick_until


class Ambassador(PeerAmbassador):
    def __init__(self):
        super().__init__()
        self.step = []  # (time, sending federate handle, value) since the last grant

    def reflectAttributeValues(self, obj, attributes, tag, order, transport, time=None, retraction=None):
        for value in attributes.values():
            self.step.append((time, int(retraction.sendingFederate) if retraction else None, bytes(value)))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("address")
    parser.add_argument("name")
    parser.add_argument("steps", type=int)
    parser.add_argument("names")
    parser.add_argument("--victims", default="")
    parser.add_argument("--die-at", type=int, default=0)
    args = parser.parse_args()
    names = args.names.split(",")
    victims = set(filter(None, args.victims.split(",")))
    others = [n for n in names if n != args.name]

    amb = Ambassador()
    rtia, location, obj = join_lockstep(args.address, args.name, amb)
    say(ready=True)
    tick_until(rtia, lambda: "start" in amb.announced, 120)
    rtia.synchronizationPointAchieved("start")
    tick_until(rtia, lambda: "start" in amb.synchronized, 120)

    errors = []
    last = {n: 0 for n in others}
    received = 0
    start = time.perf_counter()
    for k in range(1, args.steps + 1):
        if args.name in victims and k > args.die_at:
            say(dying=args.die_at)
            time.sleep(120)
            return
        rtia.updateAttributeValues(obj, {location: f"{args.name}:{k}".encode()}, "load", float(k))
        granted = rtia.advance_to(float(k), timeout=60.0)
        got, amb.step = amb.step, []
        received += len(got)
        if granted != k:
            errors.append(f"step {k}: granted {granted}")
        expected = {n for n in others if n not in victims or k <= args.die_at}
        senders = []
        for t, handle, value in got:
            sender, _, seq = value.decode().partition(":")
            if sender not in last:
                errors.append(f"step {k}: unknown sender in {value!r}")
                continue
            if int(seq) != last[sender] + 1 or t != k or int(seq) != k:
                errors.append(f"step {k}: {value!r} at {t} after {sender}:{last[sender]}")
            last[sender] = int(seq)
            senders.append((handle, sender))
        if sorted(s for _, s in senders) != sorted(expected):
            errors.append(f"step {k}: from {sorted(s for _, s in senders)}, expected {sorted(expected)}")
        if [h for h, _ in senders] != sorted(h for h, _ in senders):
            errors.append(f"step {k}: not in sending-federate order")
        if len(errors) > 5:
            break
    seconds = time.perf_counter() - start
    say(name=args.name, steps=args.steps, received=received, last=last, errors=errors, seconds=seconds)
    rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)


if __name__ == "__main__":
    main()
