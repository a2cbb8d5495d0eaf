"""Throughput: the pytest process sends bursts of small receive-order updates as fast as it can through
one gateway to N subscriber processes; a burst ends when every subscriber has counted all of it, so the
rate is of updates delivered, none lost."""

from __future__ import annotations

from hlacore.processes import Child

from .federation import create, join, leave
from .peers.peerlib import STOP
from .procs import close_all, start_peer

PAYLOAD = b"\x00\x01\x02\x03\x04\x05\x06\x07"  # 8 bytes: a small update


class Fanout:
    """One sender (this process) and `subscribers` count_peer.py processes; each burst sends `burst` updates of
    `payload`."""

    def __init__(self, address: str, subscribers: int, burst: int, payload: bytes = PAYLOAD) -> None:
        self.burst_size = burst
        self.payload = payload
        self.sent = 0
        self.federation = create(address)
        self.fed, self.amb = join(address, self.federation, "sender", subscribe=False)
        self.peers: list[Child] = []
        try:
            self.peers = [
                start_peer("count_peer.py", address, self.federation, f"s{i}", burst) for i in range(subscribers)
            ]
            for peer in self.peers:
                assert peer.read_json(timeout=60.0) == {"ready": True}
        except BaseException:
            close_all(self.peers)
            raise

    def burst(self) -> None:
        """Send `burst` updates, then wait until every subscriber has reflected all of them."""
        self.send()
        self.wait_counted()

    def send(self) -> None:
        update, obj, values = self.fed.rtia.updateAttributeValues, self.fed.obj, {self.fed.location: self.payload}
        for _ in range(self.burst_size):
            update(obj, values, "")
        self.sent += self.burst_size

    def wait_counted(self) -> None:
        for peer in self.peers:
            got = peer.read_json(timeout=60.0)
            assert got == {"received": self.sent}, (got, self.sent)

    def finish(self) -> None:
        """Stop the subscribers, check their final counts equal what was sent, and leave."""
        try:
            self.fed.rtia.updateAttributeValues(self.fed.obj, {self.fed.location: STOP}, "")
            results = [peer.read_json(timeout=60.0) for peer in self.peers]
            for peer in self.peers:
                assert peer.wait(timeout=30.0) == 0, peer.stderr()
        finally:
            close_all(self.peers)
        assert results == [{"received": self.sent, "stopped": True}] * len(self.peers), results
        leave(self.fed, self.federation)

    def close(self) -> None:
        close_all(self.peers)
