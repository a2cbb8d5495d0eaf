"""What the Federate Protocol tests share: an rtig with the door open, a federate ambassador of hlacore.fedpro
that records every callback, evoking until a condition holds, and a FedPro federate with a native one set up
for a lockstep."""

from __future__ import annotations

import contextlib
import pathlib
import struct
import time
from typing import Any, Callable, Iterator

from hlacore import fedpro

from . import RtigProcess, running_rtig
from .rti1516e import Federate


@contextlib.contextmanager
def door(tmp_path: pathlib.Path, *args: str, address: str = "127.0.0.1:0") -> Iterator[RtigProcess]:
    """The rtig under test with the Federate Protocol's door at `address`, by default on a free loopback port
    (`fedpro_address`)."""
    with running_rtig(tmp_path, "--fedpro", address, *args) as server:
        yield server


class Calls(fedpro.FederateAmbassador):
    """Records every callback's message by name."""

    def __init__(self) -> None:
        self.calls: list[tuple[str, Any]] = []

    def __getattr__(self, name: str) -> Callable[[Any], None]:
        if name.startswith("_") or name not in fedpro.CALLBACKS:
            raise AttributeError(name)
        return lambda msg: self.calls.append((name, msg))

    def named(self, name: str) -> list[Any]:
        return [m for n, m in self.calls if n == name]


def until(rtia: fedpro.RTIambassador, done: Callable[[], bool], seconds: float = 10.0) -> None:
    """Evoke callbacks (each wait ends as one comes) until `done()`; AssertionError after `seconds`."""
    deadline = time.monotonic() + seconds
    while not done():
        assert time.monotonic() < deadline, f"not done in {seconds} s"
        rtia.evokeCallback(0.1)


class Pair:
    """A joined FedPro federate and ``other``, a 1516-2010 federate of hlacore's own that joins "Road" through
    the gateway at `address` as "native": each with a Vehicle whose position it publishes and subscribes
    (tests/data/rti1516e/vehicles.xml), regulating (lookahead 1) and constrained, each having discovered the
    other's vehicle; ready for a timestamped lockstep. ``other.close()`` is the caller's."""

    def __init__(self, rtia: fedpro.RTIambassador, amb: Calls, address: str) -> None:
        self.other = other = Federate(address)
        other.rtia.joinFederationExecution("native", "1516e", "Road")
        vehicle = rtia.getObjectClassHandle(objectClassName="Vehicle")
        self.position = rtia.getAttributeHandle(objectClass=vehicle, attributeName="position")
        rtia.publishObjectClassAttributes(objectClass=vehicle, attributes=[self.position])
        rtia.subscribeObjectClassAttributes(objectClass=vehicle, attributes=[self.position])
        o_vehicle = other.rtia.getObjectClassHandle("Vehicle")
        self.o_position = other.rtia.getAttributeHandle(o_vehicle, "position")
        other.rtia.publishObjectClassAttributes(o_vehicle, [self.o_position])
        other.rtia.subscribeObjectClassAttributes(o_vehicle, [self.o_position])
        rtia.enableTimeRegulation(lookahead=fedpro.float64_interval(1.0))
        rtia.enableTimeConstrained()
        other.rtia.enableTimeRegulation(1.0)
        other.rtia.enableTimeConstrained()
        until(rtia, lambda: bool(amb.named("timeRegulationEnabled")) and bool(amb.named("timeConstrainedEnabled")))
        other.until(lambda: bool(other.amb.named("timeRegulationEnabled")) and bool(other.amb.named("timeConstrainedEnabled")))
        self.mine = rtia.registerObjectInstance(objectClass=vehicle)
        self.theirs = other.rtia.registerObjectInstance(o_vehicle)
        until(rtia, lambda: bool(amb.named("discoverObjectInstance")))
        other.until(lambda: bool(other.amb.named("discoverObjectInstance")))

    def lockstep(self, rtia: fedpro.RTIambassador, amb: Calls, steps: int,
                 between: Callable[[int], None] = lambda step: None) -> None:
        """`steps` timestamped steps: at each, both update their vehicle's position (the step number) at the step's
        time and ask to advance to it; `between(step)` runs after the native federate's request and before the
        FedPro federate's (to cut its connection there). Then checks that the FedPro federate got each grant and
        each of the other's updates once, in order, each at its time, and the other each of its updates once."""
        other = self.other
        for step in range(1, steps + 1):
            rtia.updateAttributeValues(objectInstance=self.mine, attributeValues={self.position.data: struct.pack(">I", step)},
                                       userSuppliedTag=b"", time=float(step))
            other.rtia.updateAttributeValues(self.theirs, {self.o_position: struct.pack(">I", step)}, b"", float(step))
            other.rtia.timeAdvanceRequest(float(step))
            between(step)
            rtia.timeAdvanceRequest(time=float(step))
            until(rtia, lambda: len(amb.named("timeAdvanceGrant")) >= step)
            other.until(lambda: len(other.amb.named("timeAdvanceGrant")) == step)
        grants = [fedpro.time_value(m.time) for m in amb.named("timeAdvanceGrant")]
        assert grants == [float(s) for s in range(1, steps + 1)], "each grant once"
        reflected = amb.named("reflectAttributeValuesWithTime")
        assert [struct.unpack(">I", fedpro.handle_values(m.attributeValues)[self.position.data])[0] for m in reflected] == \
            list(range(1, steps + 1)), "each of the other's updates once, in order"
        assert [fedpro.time_value(m.time) for m in reflected] == [float(s) for s in range(1, steps + 1)], "at its time"
        theirs_seen = [struct.unpack(">I", list(args[1].values())[0])[0] for args in other.amb.named("reflectAttributeValues")]
        assert theirs_seen == list(range(1, steps + 1)), "each of the FedPro federate's updates once"
