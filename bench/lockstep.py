"""Grant latency: a federation of regulating + constrained federates in lockstep, each its own process,
the pytest process being one of them. One step (the benchmarked call) is what every federate does:
update at t+1 (TSO), timeAdvanceRequest(t+1), tick to the grant; or, `updates=False`, only the
timeAdvanceRequest and the grant (pure TAR → TAG); `batched=True`: the update and the request inside
RTIAmbassador.batch() (one write). Lookahead 1."""

from __future__ import annotations

from hlacore.processes import Child

from .federation import create, join, leave, release_peers
from .peers.peerlib import STOP
from .procs import close_all, start_peer


class Lockstep:
    """`federates` federates in lockstep on the gateway at `address`; `federates - 1` are peer processes,
    which stop by themselves after `max_steps` (the stop step included) should this process be killed."""

    def __init__(self, address: str, federates: int, max_steps: int, updates: bool = True,
                 batched: bool = False) -> None:
        self.federates = federates
        self.updates = updates
        self.batched = batched
        self.max_steps = max_steps
        self.time = 0
        self.federation = create(address)
        self.fed, self.amb = join(address, self.federation, "conductor")
        self.fed.enable_time()
        self.peers: list[Child] = []
        try:
            self.peers = [
                start_peer("lockstep_peer.py", address, self.federation, f"p{i}", federates, max_steps,
                            *(["pure"] if not updates else ["batched"] if batched else []))
                for i in range(federates - 1)
            ]
            for peer in self.peers:
                assert peer.read_json(timeout=60.0) == {"ready": True}
            release_peers(self.fed, self.amb)
        except BaseException:
            close_all(self.peers)
            raise

    def step(self, value: bytes = b"conductor") -> None:
        """One lockstep step of the whole federation, seen from this federate."""
        t, rtia = float(self.time + 1), self.fed.rtia
        if self.batched:
            with rtia.batch():
                rtia.updateAttributeValues(self.fed.obj, {self.fed.location: value}, "", t)
                rtia.timeAdvanceRequest(t)
            rtia.await_grant(timeout=60.0)
        else:
            if self.updates:
                rtia.updateAttributeValues(self.fed.obj, {self.fed.location: value}, "", t)
            rtia.advance_to(t, timeout=60.0)
        self.time += 1

    def finish(self) -> None:
        """Stop the peers with one last step, check that every step of every federate got every update,
        and leave; raises AssertionError naming what went wrong. Pure peers run to max_steps by themselves
        once this federate has left."""
        if not self.updates:
            self._finish_pure()
            return
        try:
            self.step(STOP)
            results = [peer.read_json(timeout=60.0) for peer in self.peers]
            for peer in self.peers:
                assert peer.wait(timeout=30.0) == 0, peer.stderr()
        finally:
            close_all(self.peers)
        others = self.federates - 1
        for result in results:
            assert result["errors"] == [], result
            assert result == {"steps": self.time, "received": others * self.time, "errors": []}, result
        assert self.amb.reflected == others * self.time, (self.amb.reflected, others, self.time)
        leave(self.fed, self.federation)

    def _finish_pure(self) -> None:
        leave_time = self.time
        self.fed.resign()
        try:
            results = [peer.read_json(timeout=60.0) for peer in self.peers]
            for peer in self.peers:
                assert peer.wait(timeout=30.0) == 0, peer.stderr()
        finally:
            close_all(self.peers)
        for result in results:
            assert result == {"steps": self.max_steps, "received": 0, "errors": []}, result
        assert leave_time <= self.max_steps
        self.fed.rtia.destroyFederationExecution(self.federation)

    def close(self) -> None:
        """Kill whatever is left (after a failure); finish() has already cleaned up otherwise."""
        close_all(self.peers)
