"""A best-effort stream through rtig, run inside a network namespace whose firewall drops packets of the
gateway's port (bench/lossy_stream.py sets it up): `python lossy_stream.py RTIG PORT COUNT RATE DATAGRAMS`.

Starts RTIG on 127.0.0.1:PORT, joins a sender and a receiver (the receiver not time-constrained, so that
receive-order messages come as they come), sends COUNT `reply` interactions (best effort in the FOM) at RATE
per second from a thread, each stamped with time.monotonic(), over UDP when DATAGRAMS is 1 and over TCP when
0; the receiver ticks until all came or 5 s passed after the last was sent. Prints one JSON line:
{"sent", "latencies" (seconds, in arrival order), "path" (the receiver's datagram path)}.
"""

import json
import sys
import threading
import time
from importlib import resources

import hlacore.rti as rti
from hlacore.processes import Rtig

FED = str(resources.files("hlacore") / "foms" / "robot.fed")


class Receiver(rti.FederateAmbassador):
    def __init__(self):
        self.latencies = []

    def receiveInteraction(self, cls, parameters, tag, *rest):
        self.latencies.append(time.monotonic() - float(next(iter(parameters.values()))))


def main():
    executable, port, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    rate, datagrams = float(sys.argv[4]), sys.argv[5] == "1"
    with Rtig("--port", str(port), executable=executable) as server:
        address = f"127.0.0.1:{server.port}"
        creator = rti.RTIAmbassador(address, timeout=30)
        creator.createFederationExecution("LossyFed", FED)
        sender = rti.RTIAmbassador(address, timeout=30, datagrams=datagrams)
        receiver = rti.RTIAmbassador(address, timeout=30, datagrams=datagrams)
        amb = Receiver()
        sender.joinFederationExecution("sender", "LossyFed", rti.FederateAmbassador())
        receiver.joinFederationExecution("receiver", "LossyFed", amb)
        reply = sender.getInteractionClassHandle("reply")
        value = sender.getParameterHandle("value", reply)
        sender.publishInteractionClass(reply)
        receiver.subscribeInteractionClass(reply)
        for fed in (sender, receiver):  # a round trip each: the gateway has the publication and subscription
            fed.queryLBTS()
        done = threading.Event()

        def stream():
            next_at = time.monotonic()
            for _ in range(count):
                sender.sendInteraction(reply, {value: repr(time.monotonic()).encode()}, "")
                next_at += 1.0 / rate
                time.sleep(max(0.0, next_at - time.monotonic()))
            done.set()

        streamer = threading.Thread(target=stream)
        streamer.start()
        deadline = None
        while len(amb.latencies) < count:
            if done.is_set() and deadline is None:
                deadline = time.monotonic() + 5.0
            if deadline is not None and time.monotonic() > deadline:
                break
            receiver.tick(0.01, 0.05)
        streamer.join()
        print(json.dumps({"sent": count, "latencies": amb.latencies, "path": receiver.datagram_status()["path"]}),
              flush=True)
        for fed in (sender, receiver):
            fed.resignFederationExecution(rti.ResignAction.NoAction)
        creator.destroyFederationExecution("LossyFed")


if __name__ == "__main__":
    main()
