"""Coalescing of the federate's writes (cpp/rti/client/writer.cpp): a message sent soon after a wait (a lone
update, or an update and its time advance request) is written by the caller at once; a longer run of sends
goes to the writer thread, many messages per system call, in the order sent; RTIAmbassador.batch() holds
them for one write at its end or before a wait. Both gateways."""

from __future__ import annotations

import gc
import os
import pathlib
import signal
import socket
import time
import weakref
from typing import Any

import pytest

import hlacore.rti as rti
from hlacore.status import status

from support import ROBOT_FED, RtigProcess, barrier, python_subprocess, share_robot_location, tick_until

RUN = 5000  # messages sent without a wait in between
DIRECT = 4  # the first messages after a wait, written by the caller (kDirectSends)
LARGE = bytes(16 << 20)
LARGE_EVERY = 250  # a large interaction after every this many updates of the run (see below)


def counts(fed: Any) -> tuple[int, int]:
    """(messages sent, write system calls) of a federate's connection so far."""
    messages, writes = fed.rtia._send_counts()
    return int(messages), int(writes)


def test_a_message_after_a_wait_is_written_by_the_caller_at_once(federation: Any) -> None:
    pub, sub = federation("pub"), federation("sub")
    robot, location = share_robot_location(pub, sub)
    obj = pub.rtia.registerObjectInstance(robot, "r")
    for n in range(3):
        pub.rtia.tick()  # a wait: the next sends are lone ones
        before = counts(pub)
        pub.rtia.updateAttributeValues(obj, {location: b"lone %d" % n}, "")
        # Written before the call returned, in a system call of its own.
        assert counts(pub) == (before[0] + 1, before[1] + 1)
    tick_until(lambda: len(sub.amb.named("reflectAttributeValues")) == 3, sub.rtia)


def test_a_long_run_of_sends_is_coalesced_and_keeps_its_order(federation: Any) -> None:
    pub, sub = federation("pub"), federation("sub")
    robot, location = share_robot_location(pub, sub)
    obj = pub.rtia.registerObjectInstance(robot, "r")
    barrier(sub.rtia)
    pub.rtia.tick()
    # Large interactions nobody subscribes to: the gateway reads them and forwards nothing.
    command = pub.rtia.getInteractionClassHandle("command")
    pub.rtia.publishInteractionClass(command)
    large = {pub.rtia.getParameterHandle("value", command): LARGE}
    before = counts(pub)
    for i in range(RUN):
        pub.rtia.updateAttributeValues(obj, {location: i.to_bytes(4, "big")}, "")
        if i % LARGE_EVERY == DIRECT:
            # How many small messages share a write depends on how far the sender gets ahead of the writer
            # thread (1.5 on average in one CI run, 4 and more in others). A large message keeps the writer
            # busy for a while (the faster the gateway reads it, the shorter), so that the run behind it is
            # sure to pile up: one at the start of every LARGE_EVERY.
            pub.rtia.sendInteraction(command, large, "")
    barrier(pub.rtia)  # a request behind the run: answered once all of it was written and served
    messages, writes = counts(pub)
    assert messages - before[0] == RUN + RUN // LARGE_EVERY + 1
    assert writes - before[1] < RUN // 4, (messages, writes)  # many messages per write
    tick_until(lambda: len(sub.amb.named("reflectAttributeValues")) == RUN, sub.rtia, timeout=30)
    values = [args[1][location] for args in sub.amb.named("reflectAttributeValues")]
    assert [int.from_bytes(v, "big") for v in values] == list(range(RUN))


def test_a_run_then_a_resign_loses_nothing(federation: Any) -> None:
    """The resign goes behind the queued updates: the subscriber reflects all of them before the removal."""
    pub, sub = federation("pub"), federation("sub")
    robot, location = share_robot_location(pub, sub)
    obj = pub.rtia.registerObjectInstance(robot, "r")
    barrier(sub.rtia)
    for i in range(RUN):
        pub.rtia.updateAttributeValues(obj, {location: i.to_bytes(4, "big")}, "")
    pub.rtia.resignFederationExecution(rti.ResignAction.DeleteObjects)
    tick_until(lambda: bool(sub.amb.named("removeObjectInstance")), sub.rtia, timeout=30)
    names = [name for name, _ in sub.amb.calls if name in ("reflectAttributeValues", "removeObjectInstance")]
    assert names == ["reflectAttributeValues"] * RUN + ["removeObjectInstance"]


def test_ctrl_c_ends_a_wait_for_room_in_the_pending_buffer(rtig: RtigProcess, tmp_path: pathlib.Path) -> None:
    """A federate floods a gateway that stopped reading (SIGSTOP): the kernel's buffers fill, then the writer
    thread's 1 MiB, and the caller waits for room; SIGINT ends that wait with KeyboardInterrupt at the call."""
    rti.RTIAmbassador(rtig.address).createFederationExecution("TestFed", ROBOT_FED)
    go = tmp_path / "go"
    with python_subprocess("flood_peer.py", rtig.address, str(go)) as flood:
        assert flood.read_json(30) == {"ready": True}
        os.kill(rtig.proc.pid, signal.SIGSTOP)
        try:
            go.touch()
            time.sleep(1.0)  # long enough to fill a few MiB of buffers, short of the 5 s liveness timeout
            os.kill(flood.pid, signal.SIGINT)
            report = flood.read_json(10)
        finally:
            os.kill(rtig.proc.pid, signal.SIGCONT)
        assert report["interrupted"] is True and report["sent"] > 1024, report  # more than 1 MiB was queued
        assert flood.wait(10) == 0, flood.stderr()
    assert status(rtig.address)["connections"] >= 1  # the gateway serves on


def test_a_gateway_that_dies_during_a_run_makes_the_next_call_raise(tmp_path: pathlib.Path) -> None:
    """The writer thread's write fails: it closes the connection, and the sender's next call raises instead of
    queueing into a connection nobody writes any more."""
    server = RtigProcess(tmp_path)
    try:
        rti.RTIAmbassador(server.address).createFederationExecution("TestFed", ROBOT_FED)
        go = tmp_path / "go"
        with python_subprocess("flood_peer.py", server.address, str(go)) as flood:
            assert flood.read_json(30) == {"ready": True}
            go.touch()
            time.sleep(0.5)  # the run is under way
            os.kill(server.proc.pid, signal.SIGKILL)
            report = flood.read_json(15)
            assert report["raised"] in ("RTIinternalError", "GatewayNotResponding"), report
            assert report["sent"] > 1024, report
            assert flood.wait(10) == 0, flood.stderr()
    finally:
        server.stop()  # killed: its status is the signal's


def test_a_batch_is_written_in_one_call_at_its_end(federation: Any) -> None:
    pub, sub = federation("pub"), federation("sub")
    robot, location = share_robot_location(pub, sub)
    obj = pub.rtia.registerObjectInstance(robot, "r")
    pub.rtia.tick()  # a wait: without the batch each update would be written at once
    before = counts(pub)
    with pub.rtia.batch():
        for n in range(3):
            pub.rtia.updateAttributeValues(obj, {location: b"held %d" % n}, "")
        assert counts(pub) == before  # nothing written yet
    assert counts(pub) == (before[0] + 3, before[1] + 1)
    tick_until(lambda: len(sub.amb.named("reflectAttributeValues")) == 3, sub.rtia)
    assert [args[1][location] for args in sub.amb.named("reflectAttributeValues")] == [b"held 0", b"held 1", b"held 2"]


def test_a_wait_inside_a_batch_writes_what_it_holds_first(federation: Any) -> None:
    """A service with an answer and a time advance inside a batch: what the batch held goes out before each
    wait, in the order sent, so neither waits for what it holds."""
    pub, sub = federation("pub"), federation("sub")
    robot, location = share_robot_location(pub, sub)
    pub.enable_time(1.0, constrained=False)  # the only regulating federate: its grants wait for nobody
    pub.rtia.tick()
    before = counts(pub)
    with pub.rtia.batch():
        obj = pub.rtia.registerObjectInstance(robot, "r")  # waits for the gateway's answer
        assert counts(pub) == (before[0] + 1, before[1] + 1)
        pub.rtia.updateAttributeValues(obj, {location: b"at 1.5"}, "", 1.5)
        assert pub.rtia.advance_to(1.0, timeout=10.0) == 1.0  # the update and the request: one write
        assert counts(pub) == (before[0] + 3, before[1] + 2)
        pub.rtia.updateAttributeValues(obj, {location: b"after the grant"}, "")
    assert counts(pub) == (before[0] + 4, before[1] + 3)
    tick_until(lambda: len(sub.amb.named("reflectAttributeValues")) == 2, sub.rtia)
    assert [args[1][location] for args in sub.amb.named("reflectAttributeValues")] == [b"at 1.5", b"after the grant"]


def test_a_large_batch_is_written_before_it_grows_further(federation: Any) -> None:
    """Held messages past 64 KiB (Client::kMaxHeldBytes) are written at once: memory stays bounded."""
    pub, sub = federation("pub"), federation("sub")
    robot, location = share_robot_location(pub, sub)
    obj = pub.rtia.registerObjectInstance(robot, "r")
    pub.rtia.tick()
    before = counts(pub)
    value = bytes(16 << 10)
    with pub.rtia.batch():
        for _ in range(4):
            pub.rtia.updateAttributeValues(obj, {location: value}, "")
        assert counts(pub)[1] == before[1] + 1  # the fourth took the batch past 64 KiB
        pub.rtia.updateAttributeValues(obj, {location: b"last"}, "")
    assert counts(pub) == (before[0] + 5, before[1] + 2)
    tick_until(lambda: len(sub.amb.named("reflectAttributeValues")) == 5, sub.rtia)
    assert [args[1][location] for args in sub.amb.named("reflectAttributeValues")] == [value] * 4 + [b"last"]


def test_a_batch_keeps_its_ambassador_and_raises_a_failed_write_typed_at_its_end(inprocess_gateway: Any) -> None:
    """The block's object holds the ambassador it was made from (which lives as long as the block does), and a
    write that fails at the block's end (the socket shut for writing under the client) raises the client's own
    error there."""
    rtia = rti.RTIAmbassador(inprocess_gateway.address)
    rtia.createFederationExecution("Batched", ROBOT_FED)
    rtia.joinFederationExecution("f", "Batched", rti.FederateAmbassador())
    held = weakref.ref(rtia)
    batch, fileno = rtia.batch(), rtia.fileno()
    del rtia
    gc.collect()
    ambassador = held()
    assert ambassador is not None
    with pytest.raises(rti.RTIinternalError, match="lost"):
        with batch:
            ambassador.enableAsynchronousDelivery()  # held until the block ends
            with socket.socket(fileno=os.dup(fileno)) as s:
                s.shutdown(socket.SHUT_WR)
    del ambassador, batch
    gc.collect()
    assert held() is None
