"""The gateway's message trace (`rtig --trace`, `Gateway(trace=)`, hlacore.trace): every update and
interaction is stamped when read from its sender and when written on to each receiver, on the clock
time.monotonic() reads, and a timestamp-ordered one only leaves once the receiver's grant allows it."""

from __future__ import annotations

import contextlib
import pathlib
import subprocess
import time
from typing import Iterator

import pytest

import hlacore
import hlacore.rti as rti
from hlacore.trace import hops, read_trace

from support import ROBOT_FED, Federate, barrier, rtig_executable, running_rtig, tick_until


@pytest.fixture(params=["in-process", "rtig"])
def traced(request: pytest.FixtureRequest, tmp_path: pathlib.Path) -> Iterator[tuple[str, pathlib.Path]]:
    """(address, trace file) of a gateway writing its message trace."""
    trace = tmp_path / "trace.csv"
    if request.param == "in-process":
        with hlacore.Gateway(port=0, trace=trace) as gateway:
            yield gateway.address, trace
    else:
        with running_rtig(tmp_path, "--trace", str(trace)) as server:
            yield server.address, trace


@contextlib.contextmanager
def sender_and_receiver(address: str) -> Iterator[tuple[Federate, Federate]]:
    """Federates "sender" and "receiver" in TraceFed; on exit they leave and the trace has been flushed."""
    creator = rti.RTIAmbassador(address)
    creator.createFederationExecution("TraceFed", ROBOT_FED)
    pair = Federate(address, "sender", "TraceFed"), Federate(address, "receiver", "TraceFed")
    yield pair
    for fed in pair:
        fed.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    creator.destroyFederationExecution("TraceFed")
    time.sleep(0.1)  # the gateway flushes its trace once per turn of its loop


def robot_location(a: Federate, b: Federate) -> tuple[rti.ObjectHandle, rti.AttributeHandle]:
    """a registers a robot whose location b subscribes to and has discovered."""
    robot = a.rtia.getObjectClassHandle("robot")
    location = a.rtia.getAttributeHandle("location", robot)
    a.rtia.publishObjectClass(robot, [location])
    b.rtia.subscribeObjectClassAttributes(robot, [location])
    barrier(b.rtia)
    obj = a.rtia.registerObjectInstance(robot, "r1")
    tick_until(lambda: bool(b.amb.named("discoverObjectInstance")), b.rtia)
    return obj, location


def test_each_message_is_stamped_in_and_out_in_order(traced: tuple[str, pathlib.Path]) -> None:
    address, trace = traced
    with sender_and_receiver(address) as (a, b):
        obj, location = robot_location(a, b)
        before = time.monotonic()
        for k in range(5):
            a.rtia.updateAttributeValues(obj, {location: str(k).encode()}, "ro")
        tick_until(lambda: len(b.amb.named("reflectAttributeValues")) == 5, b.rtia)
        after = time.monotonic()

    events = [row.event for row in read_trace(trace)]
    assert events.count("join") == 2 and events.count("update") == 5 and events.count("reflect") == 5
    seen = hops(trace, "sender", "receiver", "TraceFed")
    assert len(seen) == 5
    assert [h.serial for h in seen] == sorted(h.serial for h in seen)
    for hop in seen:
        assert before <= hop.received <= hop.forwarded <= after
        assert hop.time is None


def test_a_timestamped_update_leaves_when_the_receivers_grant_allows(traced: tuple[str, pathlib.Path]) -> None:
    address, trace = traced
    with sender_and_receiver(address) as (a, b):
        obj, location = robot_location(a, b)
        a.enable_time(lookahead=1.0, constrained=False)
        b.enable_time(lookahead=None)
        a.rtia.updateAttributeValues(obj, {location: b"at 5"}, "tso", 5.0)
        barrier(a.rtia)  # the gateway has the update queued for b
        requested = time.monotonic()
        b.rtia.timeAdvanceRequest(10.0)
        a.rtia.timeAdvanceRequest(20.0)  # lets b's LBTS pass 5
        tick_until(lambda: bool(b.amb.named("reflectAttributeValues")), b.rtia, a.rtia)

    (hop,) = hops(trace, "sender", "receiver", "TraceFed")
    assert hop.time == 5.0
    assert hop.received < requested < hop.forwarded


def test_interactions_are_traced_too(traced: tuple[str, pathlib.Path]) -> None:
    address, trace = traced
    with sender_and_receiver(address) as (a, b):
        reply = a.rtia.getInteractionClassHandle("reply")
        a.rtia.publishInteractionClass(reply)
        b.rtia.subscribeInteractionClass(reply)
        barrier(b.rtia)
        a.rtia.sendInteraction(reply, {}, "hello")
        tick_until(lambda: bool(b.amb.named("receiveInteraction")), b.rtia)

    events = [row.event for row in read_trace(trace)]
    assert events.count("interaction") == 1 and events.count("receive") == 1
    assert len(hops(trace, "sender", "receiver")) == 1


def test_unwritable_trace_is_a_clear_error(tmp_path: pathlib.Path) -> None:
    missing = tmp_path / "no-such-dir" / "trace.csv"
    with pytest.raises(RuntimeError, match="cannot write the trace file"):
        hlacore.Gateway(port=0, trace=missing)
    proc = subprocess.run([rtig_executable(), "--port", "0", "--trace", str(missing)], capture_output=True,
                          text=True, timeout=10, stdin=subprocess.DEVNULL)
    assert proc.returncode == 1 and "cannot write the trace file" in proc.stderr


def test_hops_names_a_missing_federate(tmp_path: pathlib.Path) -> None:
    trace = tmp_path / "trace.csv"
    with hlacore.Gateway(port=0, trace=trace):
        pass
    with pytest.raises(KeyError, match="'robot'"):
        hops(trace, "robot", "testbench")
    (tmp_path / "other.csv").write_text("a,b\n")
    with pytest.raises(ValueError, match="not an hlacore message trace"):
        list(read_trace(tmp_path / "other.csv"))
