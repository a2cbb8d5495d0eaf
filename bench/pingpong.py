"""Update latency: the pytest process updates its robot's location, a peer process reflects it and sends
the same bytes back; one round trip is the benchmarked call (one-way = half of it).

Receive order: neither federate uses time management; the conductor ticks until the echo is reflected.
TSO: both are regulating (lookahead 1) and constrained; the conductor updates at t+1 and waits in
nextEventRequest, which grants it t+2 together with the echo (the peer answers at its grant + 1).
TSO batched: the same, each side's update and the nextEventRequest after it in RTIAmbassador.batch()
(one write)."""

from __future__ import annotations

import time

from hlacore.processes import Child

from .federation import create, join, leave
from .peers.peerlib import STOP
from .procs import start_peer

FAR = 1e12


class PingPong:
    def __init__(self, address: str, mode: str, size: int) -> None:
        assert mode in ("ro", "tso", "tso-batched")
        self.tso, self.batched = mode != "ro", mode == "tso-batched"
        self.payload = bytes(i % 251 for i in range(size))
        self.round_trips = 0
        self.time = 0.0  # the conductor's logical time (TSO)
        self.federation = create(address)
        self.fed, self.amb = join(address, self.federation, "ping")
        if self.tso:
            self.fed.enable_time()
        self.peer: Child = start_peer("pong_peer.py", address, self.federation, mode)
        try:
            assert self.peer.read_json(timeout=60.0) == {"ready": True}
        except BaseException:
            self.peer.close()
            raise

    def _send(self, value: bytes) -> None:
        rtia = self.fed.rtia
        if self.tso:
            rtia.updateAttributeValues(self.fed.obj, {self.fed.location: value}, "", self.time + 1)
        else:
            rtia.updateAttributeValues(self.fed.obj, {self.fed.location: value}, "")

    def round_trip(self) -> None:
        """Send the payload and return once its echo has been reflected here."""
        before, rtia = self.amb.reflected, self.fed.rtia
        if self.batched:
            with rtia.batch():
                self._send(self.payload)
                rtia.nextEventRequest(FAR)
            self.time = rtia.await_grant(timeout=60.0)
        else:
            self._send(self.payload)
            if self.tso:
                self.time = rtia.next_event(FAR, timeout=60.0)
        deadline = time.monotonic() + 60.0
        while self.amb.reflected == before:
            if time.monotonic() > deadline:
                raise TimeoutError("no echo within 60 s")
            self.fed.rtia.tick(1.0, 1.0)
        self.round_trips += 1

    def finish(self) -> None:
        """Stop the peer, check that it echoed every round trip unchanged, and leave."""
        try:
            self._send(STOP)
            if self.tso:
                self.fed.rtia.disableTimeRegulation()  # lets the peer be granted to the stop's timestamp
            result = self.peer.read_json(timeout=60.0)
            assert self.peer.wait(timeout=30.0) == 0, self.peer.stderr()
        finally:
            self.peer.close()
        assert result == {"echoed": self.round_trips}, result
        assert self.amb.reflected == self.round_trips
        if self.round_trips:
            assert self.amb.last == {self.fed.location: self.payload}
        leave(self.fed, self.federation)

    def close(self) -> None:
        self.peer.close()
