"""A lockstep federate for the grant-latency benchmark.

usage: lockstep_peer.py ADDRESS FEDERATION NAME FEDERATES MAX_STEPS [pure]

Regulating (lookahead 1) and constrained; prints {"ready": true}, waits for sync point "start", then for
k = 1, 2, ... updates its location at timestamp k and advances to k, until MAX_STEPS or until it
reflects the conductor's b"stop". Each step must bring FEDERATES - 1 reflections at time k. Prints
{"steps", "received", "errors"} and resigns. With `pure`, there are no updates: each step is only
timeAdvanceRequest(k) and the grant, and the peer runs exactly MAX_STEPS steps.
"""

from __future__ import annotations

import sys
from typing import Any

from hlacore.processes import SyncAmbassador
from peerlib import STOP, Joined, await_start, say


class Ambassador(SyncAmbassador):
    def __init__(self) -> None:
        super().__init__()
        self.times: list[float] = []
        self.stop = False

    def reflectAttributeValues(self, obj: Any, attributes: dict, tag: str, order: Any, transport: Any,
                               time: Any = None, retraction: Any = None) -> None:
        self.times.append(time)
        if STOP in attributes.values():
            self.stop = True


def main() -> None:
    address, federation, name = sys.argv[1:4]
    federates, max_steps = int(sys.argv[4]), int(sys.argv[5])
    pure, batched = sys.argv[6:] == ["pure"], sys.argv[6:] == ["batched"]
    amb = Ambassador()
    fed = Joined(address, federation, name, amb)
    fed.enable_time()
    say(ready=True)
    await_start(fed, amb)
    payload = name.encode()
    errors: list[str] = []
    received = steps = 0
    for k in range(1, max_steps + 1):
        if batched:  # the update and the request in one write (RTIAmbassador.batch)
            with fed.rtia.batch():
                fed.rtia.updateAttributeValues(fed.obj, {fed.location: payload}, "", float(k))
                fed.rtia.timeAdvanceRequest(float(k))
            granted = fed.rtia.await_grant(timeout=60.0)
        else:
            if not pure:
                fed.rtia.updateAttributeValues(fed.obj, {fed.location: payload}, "", float(k))
            granted = fed.rtia.advance_to(float(k), timeout=60.0)
        steps = k
        got, amb.times = amb.times, []
        received += len(got)
        expected = 0 if pure else federates - 1
        if (granted != k or len(got) != expected or any(t != k for t in got)) and len(errors) < 5:
            errors.append(f"step {k}: granted {granted}, reflections at {got}")
        if amb.stop:
            break
    say(steps=steps, received=received, errors=errors)
    fed.resign()


if __name__ == "__main__":
    main()
