"""A federate of a lockstep that goes on until it is killed, at a pace a person can watch (the monitor's test).

usage: paced_federate.py ADDRESS NAME PERIOD

Joins TestFed as NAME (regulating and constrained, lookahead 1, a robot registered), prints {"ready": true},
then forever: updates its location at its time + 1 (the lookahead), advances to that time, sleeps PERIOD
seconds.
"""

import sys
import time

from peerlib import PeerAmbassador, join_lockstep, say


def main() -> None:
    address, name, period = sys.argv[1], sys.argv[2], float(sys.argv[3])
    rtia, location, obj = join_lockstep(address, name, PeerAmbassador())
    say(ready=True)
    t = rtia.queryFederateTime()  # a federate that joins a running lockstep starts where it has come to
    while True:
        t += 1.0
        rtia.updateAttributeValues(obj, {location: f"{name}:{t:g}".encode()}, "step", t)
        rtia.advance_to(t, timeout=3600.0)  # others may be paused for as long as the test wants
        time.sleep(period)


if __name__ == "__main__":
    main()
