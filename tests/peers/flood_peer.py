"""A federate that floods a gateway that does not read (the test stops it) until Ctrl-C (the coalescing test).

usage: flood_peer.py ADDRESS GO_FILE

Joins TestFed, publishes a robot's location and registers it, prints {"ready": true}, waits for GO_FILE to
exist (at most 30 s), then sends 1 KiB updates without end. Its sends queue behind the writer thread until
the pending buffer is full and then wait: SIGINT must end that wait with KeyboardInterrupt, which it reports
as {"interrupted": true, "sent": N}; a gateway that dies must make a call raise, reported as {"raised": NAME,
"message": TEXT, "sent": N}.
"""

import os
import sys
import time

import hlacore.rti as rti
from peerlib import join_publisher, say


def main() -> None:
    address, go = sys.argv[1], sys.argv[2]
    rtia, location, obj = join_publisher(address, "flood")
    say(ready=True)
    deadline = time.monotonic() + 30
    while not os.path.exists(go):
        if time.monotonic() > deadline:
            sys.exit("the go file never came")
        time.sleep(0.01)
    sent, value = 0, bytes(1024)
    try:
        while True:
            rtia.updateAttributeValues(obj, {location: value}, "")
            sent += 1
    except KeyboardInterrupt:
        say(interrupted=True, sent=sent)
    except rti.RTIexception as e:  # the gateway is gone
        say(raised=type(e).__name__, message=str(e), sent=sent)


if __name__ == "__main__":
    main()
