"""An uninvolved federate: in a federation of its own, it times queryLBTS round trips to the gateway one after
the other (1 ms apart) until STOP_FILE exists, so that its slowest round trip is the longest the gateway left it waiting.

Usage: bystander.py HOST:PORT FED STOP_FILE. Prints {"ready": true} once it is measuring, then
{"worst": s, "worst_at": t, "median": s, "calls": n} (t on the host's monotonic clock, the end of the worst
round trip). Its client timeout is 60 s, so a long stall is measured rather than raised. It stops by itself
after 120 s as a safety net.
"""

from __future__ import annotations

import os
import statistics
import sys
import time

import hlacore.rti as rti
from peerlib import say


def main() -> None:
    address, fed, stop_file = sys.argv[1:4]
    rtia = rti.RTIAmbassador(address, timeout=60.0)
    rtia.create_or_join("bystander", "Quiet", fed, rti.FederateAmbassador())
    times: list[float] = []
    worst, worst_at = 0.0, 0.0
    deadline = time.monotonic() + 120.0
    for _ in range(20):  # warmed up before it says it is measuring
        rtia.queryLBTS()
    say(ready=True)
    while not os.path.exists(stop_file) and time.monotonic() < deadline:
        start = time.monotonic()
        rtia.queryLBTS()
        end = time.monotonic()
        times.append(end - start)
        if end - start > worst:
            worst, worst_at = end - start, end
        time.sleep(0.001)  # leaves the gateway's CPU to the others (two cores), without missing a stall
    say(worst=worst, worst_at=worst_at, median=statistics.median(times), calls=len(times))
    rtia.resignFederationExecution(rti.ResignAction.NoAction)
    rtia.destroyFederationExecution("Quiet")


if __name__ == "__main__":
    main()
