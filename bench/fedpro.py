"""The Federate Protocol's figures: the lockstep of lockstep.py and the update ping-pong of pingpong.py with the
measuring federate speaking the HLA 4 Federate Protocol (hlacore.fedpro, pure Python, through rtig --fedpro)
instead of hlacore's own (hlacore.rti); the peers are the same processes, on hlacore's own protocol."""

from __future__ import annotations

import time
from typing import Any, Callable

from hlacore import fedpro
from hlacore.processes import Child

from .federation import create
from .peers.peerlib import STOP
from .procs import close_all, start_peer


class _Counting(fedpro.FederateAmbassador):
    """Counts the callbacks that the loops wait for."""

    def __init__(self) -> None:
        self.reflected = 0
        self.last: Any = None
        self.grants = 0
        self.seen: set[str] = set()

    def reflectAttributeValues(self, msg: Any) -> None:
        self.reflected += 1
        self.last = fedpro.handle_values(msg.attributeValues)

    reflectAttributeValuesWithTime = reflectAttributeValues

    def timeAdvanceGrant(self, msg: Any) -> None:
        self.grants += 1

    def __getattr__(self, name: str) -> Callable[[Any], None]:  # the others: noted
        if name.startswith("_") or name not in fedpro.CALLBACKS:
            raise AttributeError(name)
        return lambda msg: self.seen.add(name)


class FedproFederate:
    """A FedPro federate joined to `federation` (the robot FOM's) with a robot whose location it publishes and
    subscribes; regulating (lookahead 1) and constrained when `timed`."""

    def __init__(self, fedpro_address: str, federation: str, name: str, timed: bool) -> None:
        self.amb = _Counting()
        self.rtia = fedpro.RTIambassador(fedpro_address)
        self.rtia.connect(self.amb)
        self.rtia.joinFederationExecution(federateName=name, federateType="bench", federationName=federation)
        robot = self.rtia.getObjectClassHandle(objectClassName="robot")
        self.location = self.rtia.getAttributeHandle(objectClass=robot, attributeName="location").data
        self.rtia.subscribeObjectClassAttributes(objectClass=robot, attributes=[self.location])
        self.rtia.publishObjectClassAttributes(objectClass=robot, attributes=[self.location])
        self.obj = self.rtia.registerObjectInstance(objectClass=robot)
        if timed:
            self.rtia.enableTimeRegulation(lookahead=fedpro.float64_interval(1.0))
            self.rtia.enableTimeConstrained()
            self.until(lambda: {"timeRegulationEnabled", "timeConstrainedEnabled"} <= self.amb.seen)

    def until(self, done: Callable[[], bool], seconds: float = 60.0) -> None:
        deadline = time.monotonic() + seconds
        while not done():
            if time.monotonic() > deadline:
                raise TimeoutError(f"not done within {seconds} s")
            self.rtia.evokeCallback(1.0)  # wakes as soon as one comes

    def update(self, value: bytes, at: float | None = None) -> None:
        if at is None:
            self.rtia.updateAttributeValues(objectInstance=self.obj, attributeValues={self.location: value},
                                            userSuppliedTag=b"")
        else:
            self.rtia.updateAttributeValues(objectInstance=self.obj, attributeValues={self.location: value},
                                            userSuppliedTag=b"", time=fedpro.float64_time(at))

    def leave(self, federation: str) -> None:
        self.rtia.resignFederationExecution(resignAction="DELETE_OBJECTS_THEN_DIVEST")
        self.rtia.destroyFederationExecution(federationName=federation)
        self.rtia.close()


class FedproLockstep:
    """lockstep.Lockstep with this federate over the Federate Protocol: 2 federates (it and one peer), each
    step an update at t+1, timeAdvanceRequest(t+1) and the grant."""

    def __init__(self, address: str, fedpro_address: str, max_steps: int) -> None:
        self.time = 0
        self.federation = create(address)
        self.fed = FedproFederate(fedpro_address, self.federation, "conductor", timed=True)
        self.peers: list[Child] = []
        try:
            self.peers = [start_peer("lockstep_peer.py", address, self.federation, "p0", 2, max_steps)]
            assert self.peers[0].read_json(timeout=60.0) == {"ready": True}
            rtia = self.fed.rtia
            rtia.registerFederationSynchronizationPoint(synchronizationPointLabel="start", userSuppliedTag=b"")
            self.fed.until(lambda: "announceSynchronizationPoint" in self.fed.amb.seen)
            rtia.synchronizationPointAchieved(synchronizationPointLabel="start", successfully=True)
            self.fed.until(lambda: "federationSynchronized" in self.fed.amb.seen)
        except BaseException:
            close_all(self.peers)
            raise

    def step(self, value: bytes = b"conductor") -> None:
        t = float(self.time + 1)
        self.fed.update(value, t)
        self.fed.rtia.timeAdvanceRequest(time=fedpro.float64_time(t))
        grants = self.time + 1
        self.fed.until(lambda: self.fed.amb.grants == grants)
        self.time += 1

    def finish(self) -> None:
        """Stop the peer with one last step; check that each step of both federates got the other's update."""
        try:
            self.step(STOP)
            result = self.peers[0].read_json(timeout=60.0)
            assert self.peers[0].wait(timeout=30.0) == 0, self.peers[0].stderr()
        finally:
            close_all(self.peers)
        assert result == {"steps": self.time, "received": self.time, "errors": []}, result
        assert self.fed.amb.reflected == self.time, (self.fed.amb.reflected, self.time)
        self.fed.leave(self.federation)

    def close(self) -> None:
        close_all(self.peers)


class FedproPingPong:
    """pingpong.PingPong in receive order with this federate over the Federate Protocol."""

    def __init__(self, address: str, fedpro_address: str, size: int) -> None:
        self.payload = bytes(i % 251 for i in range(size))
        self.round_trips = 0
        self.federation = create(address)
        self.fed = FedproFederate(fedpro_address, self.federation, "ping", timed=False)
        self.peer: Child = start_peer("pong_peer.py", address, self.federation, "ro")
        try:
            assert self.peer.read_json(timeout=60.0) == {"ready": True}
        except BaseException:
            self.peer.close()
            raise

    def round_trip(self) -> None:
        before = self.fed.amb.reflected
        self.fed.update(self.payload)
        self.fed.until(lambda: self.fed.amb.reflected != before)
        self.round_trips += 1

    def finish(self) -> None:
        try:
            self.fed.update(STOP)
            result = self.peer.read_json(timeout=60.0)
            assert self.peer.wait(timeout=30.0) == 0, self.peer.stderr()
        finally:
            self.peer.close()
        assert result == {"echoed": self.round_trips}, result
        assert self.fed.amb.reflected == self.round_trips
        if self.round_trips:
            assert self.fed.amb.last == {self.fed.location: self.payload}
        self.fed.leave(self.federation)

    def close(self) -> None:
        self.peer.close()
