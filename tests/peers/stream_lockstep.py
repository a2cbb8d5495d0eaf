"""A lockstep federate (as lockstep.py, two federates) that also streams best-effort `reply` interactions at
RATE Hz from a second thread while it steps, and counts the other federate's; prints JSON lines.

usage: stream_lockstep.py ADDRESS NAME STEPS RATE

Prints {"ready": true} once joined, regulating and constrained; after synchronization point "start", STEPS
TSO steps with asynchronous delivery (an update of its robot's location at timestamp k, then timeAdvanceRequest(k), checking that the
other federate's update for k came before the grant) while the stream runs (RATE 0: no stream). Then it
takes what is still on the way for a second and prints {"name", "errors", "step_ms": [median, p99],
"sent", "received", "latency_ms": [median, p99] (send to receive, one clock on one machine), "datagrams":
RTIAmbassador.datagram_status(), "gateway": the gateway's counts for this federate} and resigns.
"""

import json
import statistics
import sys
import threading
import time

import hlacore.rti as rti
from peerlib import PeerAmbassador, join_lockstep, say, synchronize


class Ambassador(PeerAmbassador):
    def __init__(self, name):
        super().__init__()
        self.name = name
        self.step_reflections = []
        self.latencies = []

    def reflectAttributeValues(self, obj, attributes, tag, order, transport, time=None, retraction=None):
        self.step_reflections.extend((time, value) for value in attributes.values())

    def receiveInteraction(self, cls, parameters, tag, *rest):
        sender, _, sent_at = next(iter(parameters.values())).decode().split(":")
        if sender != self.name:
            self.latencies.append(time.monotonic() - float(sent_at))


def percentile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))] if ordered else None


def main():
    address, name, steps, rate = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4])
    amb = Ambassador(name)
    rtia, location, obj = join_lockstep(address, name, amb)
    rtia.enableAsynchronousDelivery()  # the stream comes as it comes, not held for the next time advance
    reply = rtia.getInteractionClassHandle("reply")
    value = rtia.getParameterHandle("value", reply)
    rtia.publishInteractionClass(reply)
    rtia.subscribeInteractionClass(reply)
    say(ready=True)
    synchronize(rtia, amb)

    stop = threading.Event()
    sent = 0

    def stream():
        nonlocal sent
        period, next_at = 1.0 / rate, time.monotonic()
        while not stop.is_set():
            rtia.sendInteraction(reply, {value: f"{name}:{sent}:{time.monotonic()!r}".encode()}, "stream")
            sent += 1
            next_at += period
            stop.wait(max(0.0, next_at - time.monotonic()))

    streamer = threading.Thread(target=stream) if rate > 0 else None
    if streamer:
        streamer.start()
    errors, step_seconds = [], []
    try:
        for k in range(1, steps + 1):
            began = time.monotonic()
            rtia.updateAttributeValues(obj, {location: f"{name}:{k}".encode()}, "step", float(k))
            granted = rtia.advance_to(float(k), timeout=30.0)
            step_seconds.append(time.monotonic() - began)
            got, amb.step_reflections = amb.step_reflections, []
            if granted != k or len(got) != 1 or got[0][0] != k:
                errors.append(f"step {k}: granted {granted}, got {[(t, v.decode()) for t, v in got]}")
            if len(errors) > 5:
                break
    finally:
        stop.set()
        if streamer:
            streamer.join()
    # What the other federate streamed last is still on its way: take it (the other keeps granting nothing
    # new, so only receive-order messages come).
    end = time.monotonic() + 1.0
    while time.monotonic() < end:
        rtia.tick(0.05, 0.1)
    median_step = statistics.median(step_seconds) if step_seconds else None
    # The gateway's counts of this federate's datagrams, while it is still joined.
    report = json.loads(rtia._status())
    handle = next(f["handle"] for fed in report["federations"] for f in fed["federates"] if f["name"] == name)
    gateway = next(f["counts"] for f in report["datagrams"]["federates"] if f["federate"] == handle)
    say(name=name, errors=errors, sent=sent, received=len(amb.latencies), gateway=gateway,
        step_ms=[round(median_step * 1e3, 3) if median_step else None,
                 round(percentile(step_seconds, 0.99) * 1e3, 3) if step_seconds else None],
        latency_ms=[round(percentile(amb.latencies, q) * 1e3, 3) if amb.latencies else None for q in (0.5, 0.99)],
        datagrams=rtia.datagram_status())
    rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)


if __name__ == "__main__":
    main()
