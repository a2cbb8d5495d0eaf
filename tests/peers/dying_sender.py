"""A federate that subscribes to robot.location without ever ticking (what it is sent stays unread in its
socket) and registers the robot 'sender'. It first updates it WARM times with 1 MiB values (the connection's
socket buffers grow to hold megabytes), prints `ready`, and on SIGUSR1 updates it once with LAST bytes (b"last"
repeated, tag "last"); it waits a second for its writes to reach the kernel, prints `sent` and waits to be
killed: its death then resets the connection. Usage: dying_sender.py HOST:PORT WARM LAST. Exits by itself
after 60 s."""

from __future__ import annotations

import signal
import sys
import threading
import time

import hlacore.rti as rti
from peerlib import linger


def main() -> None:
    address, warm, last = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    go = threading.Event()
    signal.signal(signal.SIGUSR1, lambda *_: go.set())
    rtia = rti.RTIAmbassador(address)
    rtia.joinFederationExecution("sender", "TestFed", rti.FederateAmbassador())
    robot = rtia.getObjectClassHandle("robot")
    location = rtia.getAttributeHandle("location", robot)
    rtia.subscribeObjectClassAttributes(robot, [location])
    rtia.publishObjectClass(robot, [location])
    obj = rtia.registerObjectInstance(robot, "sender")
    for _ in range(warm):
        rtia.updateAttributeValues(obj, {location: bytes(1 << 20)}, "warm")
    print("ready", flush=True)
    if not go.wait(60):
        return
    rtia.updateAttributeValues(obj, {location: b"last" * (last // 4)}, "last")
    time.sleep(1.0)  # the client's writer thread hands the last of them to the kernel meanwhile
    print("sent", flush=True)
    linger(60)


if __name__ == "__main__":
    main()
