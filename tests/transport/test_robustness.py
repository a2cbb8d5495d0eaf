"""Hostile and dying clients against the real `rtig`: each is dropped with a clear log line, sees EOF,
and the federates joined beside it keep working."""

from __future__ import annotations

import math
import os
import pathlib
import random
import re
import signal
import socket
import struct
import threading
import time
from typing import Any, Optional

import pytest

from hlacore import rti
from hlacore.processes import Child

from support import ROBOT_FED, Federate, RtigProcess, python_subprocess, running_rtig, settle, tick_until, wait_for_log
from support.federations import Legit, legit_federation
from support.wire import (MAGIC, MAX_FRAME, T, VERSION, Cursor, boolean, closed_and_dropped, dropped_line, f64, frame,
                          handles, hello, joined_raw_client, optional_time, raw_client, send_interaction, string, u8,
                          u16, u32, u64)


# ---- 1. garbage ----


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_random_garbage_is_a_protocol_error(rtig: RtigProcess, legit: Legit, seed: int) -> None:
    """Seeded random bytes of several sizes each get their connection dropped with a protocol error."""
    rng = random.Random(seed)
    for size in (6, 7, 64, 1000, 65536, 1 << 20):
        data = rng.randbytes(size)
        (length,) = struct.unpack_from("<I", data)
        if 2 <= length <= min(MAX_FRAME, size - 4):
            # A plausible length: make the type unknown so the frame cannot decode by luck.
            data = data[:4] + u16(0xFFFF) + data[6:]
        elif 2 <= length <= MAX_FRAME:
            # The header promises more than we send: make the length impossible instead.
            data = u32(MAX_FRAME + 1 + rng.randrange(1 << 20)) + data[4:]
        with raw_client(rtig.address) as hostile:
            hostile.send(data, tolerate_drop=True)
            line = closed_and_dropped(rtig, hostile)
        assert "protocol error" in line, line
    legit.check_working()


def test_garbage_after_a_valid_join_resigns_the_federate(rtig: RtigProcess, legit: Legit) -> None:
    """Garbage from a joined federate drops it, names it in the log and frees its federate name."""
    with joined_raw_client(rtig.address, "garbler") as (hostile, handle):
        hostile.send(random.Random(7).randbytes(4096), tolerate_drop=True)
        line = closed_and_dropped(rtig, hostile)
    assert f"(federate {handle} of 'TestFed')" in line and "protocol error" in line, line
    again = Federate(rtig.address, "garbler")
    again.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    legit.check_working()


# ---- 2. impossible lengths ----


@pytest.mark.parametrize(
    "length, why",
    [
        (0xFFFFFFF0, "frame length 4294967280 exceeds the limit of 67108864 bytes"),
        (MAX_FRAME + 1, "frame length 67108865 exceeds the limit of 67108864 bytes"),
        (1, "frame length 1 is shorter than its type field"),
        (0, "frame length 0 is shorter than its type field"),
    ],
)
def test_impossible_frame_length_is_refused_at_once(rtig: RtigProcess, legit: Legit, length: int, why: str) -> None:
    """A header with a huge (or too small) length is dropped at once, without waiting for the body."""
    with raw_client(rtig.address) as hostile:
        hostile.send(u32(length) + u16(T["Hello"]))
        line = closed_and_dropped(rtig, hostile)
    assert f"protocol error: {why}" in line, line
    legit.check_working()


def test_huge_length_after_joining(rtig: RtigProcess, legit: Legit) -> None:
    """A joined federate announcing a 4 GiB frame is dropped (exceeds the limit) and resigned."""
    with joined_raw_client(rtig.address, "bragger") as (hostile, handle):
        hostile.send(u32(0xFFFFFFF0) + u16(T["UpdateAttributes"]) + b"\0" * 100)
        line = closed_and_dropped(rtig, hostile)
    assert f"(federate {handle} of 'TestFed')" in line and "exceeds the limit" in line, line
    legit.check_working()


# ---- 3. truncated frame, then close ----


@pytest.mark.parametrize("sent", [3, 6, 11])
def test_truncated_frame_then_close(rtig: RtigProcess, legit: Legit, sent: int) -> None:
    """A peer closing after part of a frame (header or body) is dropped `in the middle of a frame`."""
    with raw_client(rtig.address) as hostile:
        hostile.send(hello()[:sent])
        hostile.sock.shutdown(socket.SHUT_WR)
        line = closed_and_dropped(rtig, hostile)
    assert f"connection closed in the middle of a frame ({sent} bytes pending)" in line, line
    legit.check_working()


def test_truncated_frame_then_close_after_joining(rtig: RtigProcess, legit: Legit) -> None:
    """A joined federate dying mid-frame is dropped and resigned: its object is removed at the subscriber."""
    with joined_raw_client(rtig.address, "halfway") as (hostile, handle):
        robot, battery, _ = legit.handles()
        hostile.send(frame("PublishObjectClass", u32(robot) + handles([battery])))
        reply = hostile.call("RegisterObject", u32(robot) + string("halfway-object"))
        assert reply.error == 0, reply.message
        tick_until(lambda: any(a[2] == "halfway-object" for a in legit.bob.amb.named("discoverObjectInstance")), legit.bob.rtia)
        update = frame("UpdateAttributes", u32(reply.handle) + u32(1) + u32(battery) + string(b"x" * 100))
        hostile.send(update[:50])
        hostile.sock.shutdown(socket.SHUT_WR)
        line = closed_and_dropped(rtig, hostile)
    assert f"(federate {handle} of 'TestFed'): connection closed in the middle of a frame (50 bytes pending)" in line
    tick_until(lambda: any(int(a[0]) == reply.handle for a in legit.bob.amb.named("removeObjectInstance")), legit.bob.rtia)
    legit.check_working()


# ---- 4. truncated frame, then silence ----


def test_truncated_frame_then_silence_times_out(tmp_path: pathlib.Path) -> None:
    """A partial frame left alone is dropped after --frame-timeout (0.5 s), not before; idle peers stay."""
    with running_rtig(tmp_path, "--frame-timeout", "0.5") as server, legit_federation(server.address) as legit:
        with raw_client(server.address) as slow, raw_client(server.address) as stalled:
            # A peer that completes its frame in time and then idles is not dropped.
            slow.send(hello()[:5])
            start = time.monotonic()
            stalled.send(hello()[:7])
            time.sleep(0.2)  # deliberately less than the timeout: the frame completes in time
            slow.send(hello()[5:])
            code, _ = slow.recv_frame()
            assert code == T["Welcome"]
            stalled.wait_eof(timeout=5)
            elapsed = time.monotonic() - start
            line = dropped_line(server, stalled)
            assert "incomplete frame for too long" in line, line
            assert 0.45 <= elapsed < 5, elapsed
            # The idle legit federates and the slow peer outlive the timeout.
            legit.check_working()
            slow.ping()
            assert slow.local not in server.log()


def test_a_connection_that_never_says_hello_times_out(tmp_path: pathlib.Path) -> None:
    """A client that connects and sends nothing is dropped after --frame-timeout (0.5 s), not before; one
    that completed its handshake may idle."""
    with running_rtig(tmp_path, "--frame-timeout", "0.5") as server:
        with raw_client(server.address) as silent, raw_client(server.address) as greeted:
            start = time.monotonic()
            greeted.handshake()
            silent.wait_eof(timeout=5)
            elapsed = time.monotonic() - start
            assert "no handshake within the frame timeout" in dropped_line(server, silent)
            assert 0.45 <= elapsed < 5, elapsed
            time.sleep(0.6)
            greeted.ping()
            assert greeted.local not in server.log()


# ---- 5. wrong handshakes ----


@pytest.mark.parametrize(
    "first, why",
    [
        (hello(magic=0xDEADBEEF), "expected a Hello handshake, got Hello"),
        (hello(version=99), f"protocol version 99 is not supported (gateway speaks {VERSION})"),
        (frame("JoinFederation", u32(1) + string("sneaky") + string("TestFed") + string("") + string("") + string("")),
         "expected a Hello handshake, got JoinFederation"),
        (frame("Welcome", u16(1) + string("me") + u32(64) + string("") + struct.pack("<QI", 0, 0) + string("")),
         "expected a Hello handshake, got Welcome"),
        (frame("Hello", u32(MAGIC) + u16(VERSION) + b"extra"), "trailing bytes in Hello message"),
        (frame("Hello", u32(MAGIC)), "truncated field in Hello message"),
        (frame(0x7777, b""), "unknown message type 30583"),
    ],
    ids=["bad-magic", "version-99", "join-first", "welcome-first", "trailing-bytes", "short-hello", "unknown-type"],
)
def test_wrong_handshake_is_a_protocol_error(rtig: RtigProcess, legit: Legit, first: bytes, why: str) -> None:
    """Anything but a well-formed Hello of version 1 first gets the connection dropped with a protocol error."""
    with raw_client(rtig.address) as hostile:
        hostile.send(first)
        line = closed_and_dropped(rtig, hostile)
    assert f"protocol error: {why}" in line, line
    # The JoinFederation sent without a handshake was never handled: the name is free.
    again = Federate(rtig.address, "sneaky")
    again.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    legit.check_working()


def test_welcome_names_the_gateway(rtig: RtigProcess) -> None:
    """The Welcome answering a Hello carries the protocol version, the server name and its frame limit."""
    with raw_client(rtig.address) as client:
        assert client.handshake() == (VERSION, b"hlacore rtig", 64 << 20)
        client.ping()


# ---- 6. services before joining ----


@pytest.mark.parametrize(
    "message, payload",
    [
        ("PublishObjectClass", u32(1) + handles([])),
        ("SubscribeInteractionClass", u32(1) + boolean(True)),
        ("SyncPointAchieved", string("x")),
        ("Hello", u32(MAGIC) + u16(VERSION)),
    ],
)
def test_service_before_join_is_a_protocol_error(rtig: RtigProcess, legit: Legit, message: str, payload: bytes) -> None:
    """After the handshake, a federation service sent before joining drops the connection (`sent before joining`)."""
    with raw_client(rtig.address) as hostile:
        hostile.handshake()
        hostile.send(frame(message, payload))
        line = closed_and_dropped(rtig, hostile)
    assert f"protocol error: {message} sent before joining a federation" in line, line
    legit.check_working()


def test_request_before_join_gets_an_error_reply(rtig: RtigProcess) -> None:
    """RegisterObject and ResignFederation before joining are answered with an error Reply, not a drop."""
    with raw_client(rtig.address) as client:
        client.handshake()
        assert client.call("RegisterObject", u32(1) + string("")).error != 0
        assert client.call("ResignFederation", u8(3)).error != 0
        assert client.call("RequestFederationSave", string("s") + boolean(False)).error != 0
        assert client.call("RequestFederationRestore", string("s")).error != 0
        client.ping()
    assert "dropped" not in rtig.log()


# ---- 7. handles of nothing ----


@pytest.mark.parametrize(
    "message, payload, why",
    [
        ("PublishObjectClass", u32(999) + handles([]), "object class handle 999 is not defined in the FOM"),
        ("SubscribeObjectClass", u32(999) + handles([]) + boolean(True), "object class handle 999 is not defined in the FOM"),
        ("SubscribeInteractionClass", u32(999) + boolean(True), "interaction class handle 999 is not defined in the FOM"),
        ("PublishObjectClass", None, "attribute handle 999 is not defined for class"),
    ],
    ids=["publish-class-999", "subscribe-class-999", "subscribe-interaction-999", "publish-attribute-999"],
)
def test_undefined_handles_drop_and_resign_the_federate(
    rtig: RtigProcess, legit: Legit, message: str, payload: Optional[bytes], why: str
) -> None:
    """A joined federate naming a handle the FOM lacks is dropped (`not defined`) and resigned: its object is
    removed, a sync point does not wait for it, and its name is free again."""
    robot, battery, _ = legit.handles()
    with joined_raw_client(rtig.address, "hostile") as (hostile, handle):
        hostile.send(frame("PublishObjectClass", u32(robot) + handles([battery])))
        reply = hostile.call("RegisterObject", u32(robot) + string("hostile-object"))
        assert reply.error == 0, reply.message
        bob = legit.bob
        tick_until(lambda: any(a[2] == "hostile-object" for a in bob.amb.named("discoverObjectInstance")), bob.rtia)
        if payload is None:
            payload = u32(robot) + handles([battery, 999])
        hostile.send(frame(message, payload))
        line = closed_and_dropped(rtig, hostile)
    assert f"(federate {handle} of 'TestFed'): protocol error: " in line and why in line, line
    tick_until(lambda: any(int(a[0]) == reply.handle for a in bob.amb.named("removeObjectInstance")), bob.rtia)
    # A whole-federation sync point now involves alice and bob only.
    alice = legit.alice
    alice.rtia.registerFederationSynchronizationPoint("after-hostile", "")
    for fed in (alice, bob):
        tick_until(lambda: ("after-hostile", "") in fed.amb.named("announceSynchronizationPoint"), alice.rtia, bob.rtia)
        fed.rtia.synchronizationPointAchieved("after-hostile")
    tick_until(
        lambda: all(("after-hostile",) in f.amb.named("federationSynchronized") for f in (alice, bob)), alice.rtia, bob.rtia
    )
    again = Federate(rtig.address, "hostile")
    again.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    legit.check_working()


@pytest.mark.parametrize(
    "message, payload, why",
    [
        ("Reply", u32(1) + u16(0) + string(""), "Reply is not a federation service message"),
        ("ObjectRegistered", u32(1) + u32(7) + string("o"), "ObjectRegistered is not a federation service message"),
        ("Hello", u32(MAGIC) + u16(VERSION), "Hello is not a federation service message"),
        ("InitiateFederateSave", string("s"), "InitiateFederateSave is not a federation service message"),
        ("SetAdvisorySwitch", u8(77) + boolean(True), "unknown advisory switch 77"),
        ("SubscribeInteractionClass", u32(1) + u8(2), "bad boolean in SubscribeInteractionClass message"),
        ("SubscribeObjectClass", u32(1) + u32(0x40000000) + boolean(True), "element count exceeds frame in SubscribeObjectClass"),
    ],
    ids=["reply", "typed-answer", "second-hello", "initiate-save", "advisory-77", "bad-bool", "huge-count"],
)
def test_joined_federate_sending_nonsense_is_dropped(
    rtig: RtigProcess, legit: Legit, message: str, payload: bytes, why: str
) -> None:
    """A joined federate sending a gateway-only or malformed message is dropped and resigned, with a reason."""
    with joined_raw_client(rtig.address, "nonsense") as (hostile, handle):
        hostile.send(frame(message, payload))
        line = closed_and_dropped(rtig, hostile)
    assert f"(federate {handle} of 'TestFed'): protocol error: " in line and why in line, line
    again = Federate(rtig.address, "nonsense")
    again.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    legit.check_working()


# ---- 8. a client that never reads ----


class Counter(rti.FederateAmbassador):
    """Counts reflections without keeping their (large) values."""

    def __init__(self) -> None:
        self.discovered: list[str] = []
        self.reflected = 0
        self.last_size = 0

    def discoverObjectInstance(self, obj: Any, cls: Any, name: str) -> None:
        self.discovered.append(name)

    def reflectAttributeValues(self, obj: Any, attributes: dict[Any, bytes], *rest: Any) -> None:
        self.reflected += 1
        self.last_size = sum(len(v) for v in attributes.values())


def test_client_that_never_reads_holds_back_its_publisher_then_is_dropped(tmp_path: pathlib.Path) -> None:
    """Without spilling (--disk-budget 0; tests/transport/test_paused_federate.py spills), a subscriber that
    never reads: once 8 MiB (--client-budget) are held for it the publisher is no longer
    read (its updates wait in its socket, its calls block), and after 2 s (--stall-timeout) in which the
    subscriber took nothing it is dropped (`not reading: ...`); then the publisher goes on and a reading
    subscriber gets every update. Nobody else is dropped."""
    budget = 8 << 20
    with running_rtig(tmp_path, "--client-budget", str(budget), "--stall-timeout", "2", "--disk-budget", "0") as server, \
            legit_federation(server.address) as legit:
        robot, _, location = legit.handles()
        with raw_client(server.address, rcvbuf=4096) as sloth:
            sloth_handle = sloth.join("sloth")
            sloth.send(frame("SubscribeObjectClass", u32(robot) + handles([location]) + boolean(True)))
            sloth.ping()  # the subscription is in place; from here on the sloth never reads

            carol_amb = Counter()
            carol = rti.RTIAmbassador(server.address)
            carol.joinFederationExecution("carol", "TestFed", carol_amb)
            try:
                carol.subscribeObjectClassAttributes(legit.robot, [legit.location])
                alice = legit.alice.rtia
                obj = alice.registerObjectInstance(legit.robot, "heavy")
                tick_until(lambda: "heavy" in carol_amb.discovered, carol, alice)
                value = bytes(64 << 10)
                updates = 300  # 19 MiB: beyond the budget even with a few MiB in kernel buffers
                slowest = 0.0
                for i in range(updates):
                    sent = time.monotonic()
                    alice.updateAttributeValues(obj, {legit.location: value}, "heavy")
                    tick_until(lambda: carol_amb.reflected > i - 32, carol, alice)
                    slowest = max(slowest, time.monotonic() - sent)
                line = dropped_line(server, sloth, timeout=10)
                tick_until(lambda: carol_amb.reflected == updates, carol, alice, timeout=10)
                assert carol_amb.last_size == len(value)
            finally:
                carol.resignFederationExecution(rti.ResignAction.NoAction)
            print(f"\nslowest update (until carol reflected it) while held back: {slowest:.2f} s; {line.strip()}")
            assert f"(federate {sloth_handle} of 'TestFed'): not reading: " in line, line
            queued = int(re.search(r"not reading: (\d+) bytes queued, none taken for \d+ s \(budget (\d+)\)", line).group(1))  # type: ignore[union-attr]
            assert budget // 2 < queued < budget + MAX_FRAME
            assert f"(budget {budget})" in line
            assert slowest > 1.5  # alice's updates waited until the sloth was dropped
            assert "carol" not in server.log() and "alice" not in server.log()
            sloth.wait_eof(timeout=10)
        legit.check_working()


# ---- 9. a federate killed with SIGKILL ----


@pytest.mark.parametrize("achieve_before_kill", [True, False], ids=["achieved-before", "achieved-after"])
def test_killed_federate_is_resigned(rtig: RtigProcess, achieve_before_kill: bool) -> None:
    """A federate killed with SIGKILL while owning an object and holding up a sync point is resigned: its
    object is removed and the sync point completes without it."""
    creator = rti.RTIAmbassador(rtig.address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    watcher = Federate(rtig.address, "watcher")
    victim: Optional[Child] = None
    try:
        robot = watcher.rtia.getObjectClassHandle("robot")
        location = watcher.rtia.getAttributeHandle("location", robot)
        watcher.rtia.subscribeObjectClassAttributes(robot, [location])
        victim = python_subprocess("victim_federate.py", rtig.address)
        line = victim.read_line(timeout=15)
        assert line.startswith("ready "), (line, victim.stderr())
        _, victim_handle, victim_object = line.split()
        tick_until(lambda: any(a[2] == "victim" for a in watcher.amb.named("discoverObjectInstance")), watcher.rtia)
        (obj, _, _) = next(a for a in watcher.amb.named("discoverObjectInstance") if a[2] == "victim")
        assert int(obj) == int(victim_object)
        tick_until(lambda: any(a[0] == obj for a in watcher.amb.named("reflectAttributeValues")), watcher.rtia)

        watcher.rtia.registerFederationSynchronizationPoint("checkpoint", "tag")
        tick_until(lambda: ("checkpoint", "tag") in watcher.amb.named("announceSynchronizationPoint"), watcher.rtia)
        assert ("checkpoint",) in watcher.amb.named("synchronizationPointRegistrationSucceeded")
        if achieve_before_kill:
            watcher.rtia.synchronizationPointAchieved("checkpoint")
            settle(watcher.rtia, seconds=0.3)
            assert not watcher.amb.named("federationSynchronized"), "the victim has not achieved the point"

        victim.send_signal(signal.SIGKILL)
        assert victim.wait(timeout=10) == -signal.SIGKILL
        tick_until(lambda: any(a[0] == obj for a in watcher.amb.named("removeObjectInstance")), watcher.rtia)
        if not achieve_before_kill:
            watcher.rtia.synchronizationPointAchieved("checkpoint")
        tick_until(lambda: ("checkpoint",) in watcher.amb.named("federationSynchronized"), watcher.rtia)
        dropped = wait_for_log(rtig, rf"rtig: dropped 127\.0\.0\.1:\d+ \(federate {victim_handle} of 'TestFed'\): [^\n]*")
        assert "connection closed by peer" in dropped or "Connection reset by peer" in dropped, dropped
        # The dead federate's name is free again and the federation can be destroyed once the rest resign.
        again = Federate(rtig.address, "victim")
        again.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    finally:
        if victim is not None:
            victim.close()
        watcher.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    creator.destroyFederationExecution("TestFed")


# ---- a FED name that is not a regular file ----


def test_fed_name_naming_a_fifo_does_not_freeze_the_gateway(
    tmp_path: pathlib.Path, rtig: RtigProcess, legit: Legit
) -> None:
    """CreateFederation naming (by absolute path, outside any --fom-path) a FIFO nobody writes to is answered
    promptly with an error, and the gateway keeps serving everyone else meanwhile."""
    fifo = tmp_path / "trap.fed"
    os.mkfifo(fifo)
    try:
        with raw_client(rtig.address) as hostile, raw_client(rtig.address) as bystander:
            hostile.handshake()
            hostile.send(frame("CreateFederation", u32(1) + string("Trap") + string(str(fifo)) + string("") + string("") + u8(0) + u8(0)))
            # Another client must still get its handshake answered...
            try:
                bystander.handshake()
                responsive = True
            except (AssertionError, socket.timeout):
                responsive = False
            assert responsive, "the gateway froze: it blocks opening the FIFO named by a client"
            # ... and the creator gets an error reply, not silence.
            code, payload = hostile.recv_frame()
            assert code == T["Reply"] and Cursor(payload[4:]).take("<H") != 0
    finally:
        # Unfreeze the gateway (if it is blocked opening the FIFO for reading) so that it can stop.
        try:
            os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))
        except OSError:  # ENXIO: nobody has it open for reading
            pass
    legit.check_working()


# ---- 10. time management rules the client checks first ----

TAR = 1  # TimeAdvance kinds (AdvanceKind)


def interaction_time(payload: bytes) -> tuple[bytes, Optional[float]]:
    """(the first parameter's value, the timestamp) of a ReceiveInteraction payload."""
    c = Cursor(payload)
    c.take("<I")
    n = c.take("<I")
    values = []
    for _ in range(n):
        c.take("<I")
        values.append(c.string())
    c.string()
    c.take("<B"), c.take("<B")
    ts = c.take("<d") if c.take("<B") else None
    return values[0], ts


@pytest.mark.parametrize("message", ["interaction", "update", "delete"])
def test_timestamp_below_the_senders_bound_is_a_protocol_error(rtig: RtigProcess, legit: Legit, message: str) -> None:
    """A regulating federate (lookahead 1 at time 0) sending at 0.5, below its bound 1, is dropped and resigned;
    at 1 itself it was fine. Its early message reaches nobody."""
    robot, battery, _ = legit.handles()
    command, value = int(legit.command), int(legit.value)
    bob = legit.bob
    with joined_raw_client(rtig.address, "hasty") as (hasty, handle):
        hasty.send(frame("PublishObjectClass", u32(robot) + handles([battery])))
        hasty.send(frame("PublishInteractionClass", u32(command)))
        reply = hasty.call("RegisterObject", u32(robot) + string("hasty-object"))
        assert reply.error == 0, reply.message
        hasty.send(frame("EnableTimeRegulation", f64(0.0) + f64(1.0)))
        _, enabled = hasty.frames_until("TimeRegulationEnabled")
        assert Cursor(enabled).take("<d") == 0.0
        hasty.send(send_interaction(hasty, command, value, b"on-time", 1.0, 0))
        tick_until(lambda: any(a[1].get(legit.value) == b"on-time" for a in bob.amb.named("receiveInteraction")), bob.rtia)
        early = {
            "interaction": send_interaction(hasty, command, value, b"early", 0.5, 1),
            "update": frame(
                "UpdateAttributes",
                u32(reply.handle) + u32(1) + u32(battery) + string(b"early") + string("raw") + optional_time(0.5) + u64(1),
            ),
            "delete": frame("DeleteObject", u32(reply.handle) + string("early") + optional_time(0.5) + u64(1)),
        }[message]
        hasty.send(early, tolerate_drop=True)
        line = closed_and_dropped(rtig, hasty)
    what = {"interaction": "interaction", "update": "attribute update", "delete": "object deletion"}[message]
    assert f"(federate {handle} of 'TestFed'): protocol error: {what} at timestamp 0.5 is below the sender's " in line
    assert "output bound 1 " in line, line
    # removed by the resign (empty tag), not by the early deletion
    tick_until(lambda: any(int(a[0]) == reply.handle for a in bob.amb.named("removeObjectInstance")), bob.rtia)
    assert [a[1] for a in bob.amb.named("removeObjectInstance") if int(a[0]) == reply.handle] == [""]
    assert not any(a[1].get(legit.value) == b"early" for a in bob.amb.named("receiveInteraction"))
    assert not any(a[1].get(legit.battery) == b"early" for a in bob.amb.named("reflectAttributeValues"))
    again = Federate(rtig.address, "hasty")
    again.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    legit.check_working()


@pytest.mark.parametrize("message, payload, reason", [
    ("EnableTimeRegulation", f64(0.0) + f64(math.inf), "enable time regulation: the time and lookahead must be finite"),
    ("EnableTimeRegulation", f64(math.inf) + f64(1.0), "enable time regulation: the time and lookahead must be finite"),
    ("ModifyLookahead", f64(math.inf), "invalid lookahead (finite, >= 0)"),
    ("TimeAdvance", u8(TAR) + f64(math.inf), "invalid time advance request (kind 1-5, a finite time)"),
    ("interaction", math.inf, "interaction at a timestamp that is not finite"),
    ("interaction", -math.inf, "interaction at a timestamp that is not finite"),
], ids=["lookahead-inf", "regulation-time-inf", "modify-lookahead-inf", "advance-to-inf", "timestamp-inf",
        "timestamp-minus-inf"])
def test_non_finite_times_are_refused_by_the_gateway(rtig: RtigProcess, legit: Legit, message: str, payload: Any,
                                                     reason: str) -> None:
    """Non-finite times (docs/robustness.md, case 7): the client refuses these (InvalidLookahead,
    InvalidFederationTime); a client that sends them anyway is dropped with the reason, before a federate granted
    +inf could make every later regulating federate start at +inf."""
    command, value = int(legit.command), int(legit.value)
    with joined_raw_client(rtig.address, "infinite") as (client, handle):
        if message == "interaction":
            client.send(frame("PublishInteractionClass", u32(command)))
            client.send(send_interaction(client, command, value, b"never", payload, 0), tolerate_drop=True)
        else:
            if message == "ModifyLookahead":
                client.send(frame("EnableTimeRegulation", f64(0.0) + f64(1.0)))
                client.frames_until("TimeRegulationEnabled")
            client.send(frame(message, payload), tolerate_drop=True)
        line = closed_and_dropped(rtig, client)
    assert f"(federate {handle} of 'TestFed'): protocol error: {reason}" in line, line
    assert not any(a[1].get(legit.value) == b"never" for a in legit.bob.amb.named("receiveInteraction"))
    legit.check_working()


@pytest.mark.parametrize("then", ["advance-others", "enable-again", "advance-self"])
def test_pending_regulation_enable_over_the_wire(rtig: RtigProcess, legit: Legit, then: str) -> None:
    """A constrained federate enabling regulation ahead of its LBTS gets the TSO messages below t0 first, then
    timeRegulationEnabled(t0); enabling again or asking to advance meanwhile is a protocol error."""
    command, value = int(legit.command), int(legit.value)
    with raw_client(rtig.address) as pacer, raw_client(rtig.address) as newcomer:
        pacer.join("pacer")
        pacer.send(frame("PublishInteractionClass", u32(command)))
        pacer.send(frame("EnableTimeRegulation", f64(0.0) + f64(1.0)))
        pacer.frames_until("TimeRegulationEnabled")
        handle = newcomer.join("newcomer")
        newcomer.send(frame("SubscribeInteractionClass", u32(command) + boolean(True)))
        newcomer.send(frame("EnableTimeConstrained"))
        _, enabled = newcomer.frames_until("TimeConstrainedEnabled")
        assert Cursor(enabled).take("<d") == 0.0
        pacer.send(send_interaction(pacer, command, value, b"at-2", 2.0, 0))
        pacer.send(send_interaction(pacer, command, value, b"at-6", 6.0, 1))
        pacer.ping()
        newcomer.skipped.clear()
        newcomer.send(frame("EnableTimeRegulation", f64(5.0) + f64(1.0)))  # t0 = 5 > LBTS = 1
        newcomer.ping()
        assert not newcomer.skipped and not newcomer.buffer, "nothing may come before the pacer moves"
        if then == "advance-others":
            pacer.send(frame("TimeAdvance", u8(TAR) + f64(10.0)))
            _, granted = pacer.frames_until("TimeAdvanceGrant")
            assert Cursor(granted).take("<d") == 10.0
            before, enabled = newcomer.frames_until("TimeRegulationEnabled")
            assert Cursor(enabled).take("<d") == 5.0
            assert [interaction_time(p) for code, p in before if code == T["ReceiveInteraction"]] == [(b"at-2", 2.0)]
            newcomer.send(frame("TimeAdvance", u8(TAR) + f64(7.0)))
            before, granted = newcomer.frames_until("TimeAdvanceGrant")
            assert Cursor(granted).take("<d") == 7.0
            assert [interaction_time(p) for code, p in before if code == T["ReceiveInteraction"]] == [(b"at-6", 6.0)]
            newcomer.ping()
        else:
            again = frame("EnableTimeRegulation", f64(5.0) + f64(1.0))
            advance = frame("TimeAdvance", u8(TAR) + f64(7.0))
            newcomer.send(again if then == "enable-again" else advance, tolerate_drop=True)
            line = closed_and_dropped(rtig, newcomer)
            why = {
                "enable-again": "enable time regulation while an enable is pending",
                "advance-self": "time advance request while a regulation enable is pending",
            }[then]
            assert f"(federate {handle} of 'TestFed'): protocol error: {why}" in line, line
    legit.check_working()


# ---- 11. a gateway answering a request with the wrong message ----


def test_an_answer_of_the_wrong_type_is_a_protocol_error() -> None:
    """A gateway answering a join with a bare Reply instead of FederationJoined breaks the protocol: the client
    closes the connection and the call says why."""
    with socket.create_server(("127.0.0.1", 0)) as listener:

        def gateway() -> None:
            conn, _ = listener.accept()
            with conn, conn.makefile("rb") as incoming:
                def read() -> tuple[int, bytes]:
                    length, code = struct.unpack("<IH", incoming.read(6))
                    return code, incoming.read(length - 2)

                assert read()[0] == T["Hello"]
                conn.sendall(frame("Welcome", u16(VERSION) + string("fake") + u32(MAX_FRAME) + string("") + u64(0)
                                   + u32(0) + string("")))
                code, join = read()
                assert code == T["JoinFederation"]
                conn.sendall(frame("Reply", join[:4] + u16(0) + string("")))
                incoming.read()  # until the client closes

        thread = threading.Thread(target=gateway, daemon=True)
        thread.start()
        amb = rti.RTIAmbassador("127.0.0.1:%d" % listener.getsockname()[1])
        with pytest.raises(rti.RTIinternalError,
                           match=r"protocol error from the gateway: Reply answered request \d+ \(FederationJoined expected\)"):
            amb.joinFederationExecution("wrong", "TestFed", rti.FederateAmbassador())
        thread.join(5)
        assert not thread.is_alive(), "the client did not close the connection"
