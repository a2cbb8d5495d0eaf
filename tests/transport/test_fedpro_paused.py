"""A Federate Protocol federate paused in a debugger stalls nobody: its process stopped (SIGSTOP) while a native
federate publishes 96 MiB to it, more than the door keeps for a session (64 MiB): the door's kept messages stop at
their budget, its federate stops reading the gateway, and the gateway spills the rest beyond its 8 MiB budget to
disk (docs/robustness.md).
The publisher sends everything at full speed; continued, the paused federate gets every update, in order."""

from __future__ import annotations

import contextlib
import os
import pathlib
import signal
import struct
import time
from typing import Any, Iterator

import pytest

from hlacore.processes import python_peer

from support import PEERS
from support.fedpro import door as fedpro_door
from support.rti1516e import VEHICLES, Federate

MIB = 1 << 20
UPDATES = 96  # of 1 MiB: values the gateway forwards by reference to the sender's read blocks


@pytest.fixture
def door(tmp_path: pathlib.Path) -> Iterator[Any]:
    with fedpro_door(tmp_path, "--spill-dir", str(tmp_path), "--client-budget", str(8 * MIB)) as server:
        yield server


@pytest.mark.slow
def test_a_paused_fedpro_federate_stalls_nobody(door: Any) -> None:
    publisher = Federate(door.address)
    publisher.rtia.createFederationExecution("Road", [VEHICLES])
    publisher.rtia.joinFederationExecution("fast", "1516e", "Road")
    slow = python_peer(PEERS / "fedpro_subscriber.py", door.fedpro_address, UPDATES)
    try:
        assert slow.read_json(timeout=30) == {"ready": True}
        vehicle = publisher.rtia.getObjectClassHandle("Vehicle")
        speed = publisher.rtia.getAttributeHandle(vehicle, "speed")
        publisher.rtia.publishObjectClassAttributes(vehicle, [speed])
        obj = publisher.rtia.registerObjectInstance(vehicle)
        os.kill(slow.pid, signal.SIGSTOP)
        slowest = 0.0
        for n in range(1, UPDATES + 1):
            before = time.monotonic()
            publisher.rtia.updateAttributeValues(obj, {speed: struct.pack(">I", n) + bytes(MIB - 4)}, b"")
            slowest = max(slowest, time.monotonic() - before)
        time.sleep(2)  # what was sent reaches the door, its budget, and the gateway's spill
        os.kill(slow.pid, signal.SIGCONT)
        assert slow.read_json(timeout=120) == {"received": UPDATES, "in_order": True}
        assert slow.wait(timeout=30) == 0, slow.stderr()
        # Nobody waited for the stopped federate: no call took anything like a stall (which would last until it
        # was continued).
        assert slowest < 5.0, slowest
    finally:
        with contextlib.suppress(ProcessLookupError):  # continued, whatever failed, so that it can end
            os.kill(slow.pid, signal.SIGCONT)
        slow.close()
        publisher.close()


def test_a_fedpro_federate_that_does_not_evoke_queues_within_its_bound(door: Any) -> None:
    """hlacore.fedpro's session stops reading once its queued callbacks pass `max_queued` (here 1 MiB): a federate
    that never evokes holds about that much, the rest waits at the door and the gateway; a call still gets its
    answer meanwhile; evoked at last, every update comes, in order."""
    from hlacore import fedpro

    from support.fedpro import Calls, until

    from hlacore.fedpro.session import split_address

    rtia = fedpro.RTIambassador(fedpro.Session.connect(*split_address(door.fedpro_address), max_queued=MIB))
    amb = Calls()
    publisher = Federate(door.address)
    try:
        rtia.connect(amb)
        rtia.createFederationExecutionWithModules(federationName="Road", fomModules=[VEHICLES])
        rtia.joinFederationExecution(federateName="idle", federateType="fedpro", federationName="Road")
        vehicle = rtia.getObjectClassHandle(objectClassName="Vehicle")
        rtia.subscribeObjectClassAttributes(objectClass=vehicle,
                                            attributes=[rtia.getAttributeHandle(objectClass=vehicle, attributeName="speed")])
        publisher.rtia.joinFederationExecution("fast", "1516e", "Road")
        p_vehicle = publisher.rtia.getObjectClassHandle("Vehicle")
        speed = publisher.rtia.getAttributeHandle(p_vehicle, "speed")
        publisher.rtia.publishObjectClassAttributes(p_vehicle, [speed])
        obj = publisher.rtia.registerObjectInstance(p_vehicle)
        count, size = 24, 256 << 10
        for n in range(1, count + 1):
            publisher.rtia.updateAttributeValues(obj, {speed: struct.pack(">I", n) + bytes(size - 4)}, b"")
        deadline = time.monotonic() + 10
        while rtia.session.queued_bytes <= MIB and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(1.0)  # had it gone on reading, the rest would be here by now
        assert MIB < rtia.session.queued_bytes <= MIB + size + 4096, rtia.session.queued_bytes
        assert rtia.getObjectClassName(objectClass=vehicle) == "Vehicle"  # answered while the queue is full
        until(rtia, lambda: len(amb.named("reflectAttributeValues")) == count, seconds=30)
        values = [fedpro.handle_values(m.attributeValues) for m in amb.named("reflectAttributeValues")]
        assert [struct.unpack(">I", list(v.values())[0][:4])[0] for v in values] == list(range(1, count + 1))
    finally:
        publisher.close()
        rtia.resignFederationExecution(resignAction="CANCEL_THEN_DELETE_THEN_DIVEST")
        rtia.destroyFederationExecution(federationName="Road")
        rtia.close()
