"""Federate processes killed with SIGKILL in the middle of things, against the real rtig: the others get their
grants, synchronization points and object removals, nothing they were sent is lost, and rtig gives the memory
of the dead back.

Killed while regulating: tests/rti/test_time_processes.py; while owning an object and holding up a sync point (one
victim): tests/transport/test_robustness.py::test_killed_federate_is_resigned. Here: killed during a time advance
request, and many cycles of crowds of federates that are killed holding a sync point, objects, pending TARs and
megabytes of undelivered messages, with rtig's resident memory measured before and after; and one killed with unread
data, whose last frame reaches the gateway with the connection's reset."""

from __future__ import annotations

import os
import pathlib
import signal
import time
from typing import Any, Iterator, Optional

import pytest

import hlacore.rti as rti
from hlacore.processes import Child
from hlacore.status import status

from support import (ROBOT_FED, Federate, Recorder, RtigProcess, python_subprocess, release_rtig, running_rtig,
                     share_robot_location, tick_until, vm_rss, wait_for_log, wait_until)


def read_ready(proc: Child, timeout: float = 60.0) -> list[int]:
    """The federate handles printed by crowd.py's `ready` line."""
    line = proc.read_line(timeout)
    if not line.startswith("ready "):
        proc.kill()
        raise AssertionError(f"crowd.py did not get ready: {line!r} {proc.stderr()}")
    return [int(h) for h in line.split()[1:]]


def kill(proc: Child) -> None:
    """SIGKILL by pid and reap."""
    proc.send_signal(signal.SIGKILL)
    assert proc.wait(timeout=10) in (-signal.SIGKILL, 0, 3)
    proc.close()


def federates_of(address: str, federation: str = "TestFed") -> list[dict[str, Any]]:
    for fed in status(address)["federations"]:
        if fed["name"] == federation:
            return list(fed["federates"])
    return []


@pytest.fixture
def crowd_procs() -> Iterator[list[Child]]:
    procs: list[Child] = []
    yield procs
    for proc in procs:
        kill(proc)


def test_killed_during_a_time_advance_request(rtig: RtigProcess, crowd_procs: list[Child]) -> None:
    """Two federates (one process) with a pending TAR(5) are killed: the pending requests go with them, the
    others advance to 10, and every timestamped message the dead sent before dying (updates and interactions at
    1, 2, 3) is delivered once, in timestamp order, before the grant that covers it."""
    creator = rti.RTIAmbassador(rtig.address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    conductor, amb = rti.RTIAmbassador(rtig.address), Recorder()
    conductor.joinFederationExecution("conductor", "TestFed", amb)
    bystander, by_amb = rti.RTIAmbassador(rtig.address), Recorder()
    bystander.joinFederationExecution("bystander", "TestFed", by_amb)
    try:
        robot = conductor.getObjectClassHandle("robot")
        location = conductor.getAttributeHandle("location", robot)
        command = conductor.getInteractionClassHandle("command")
        conductor.subscribeObjectClassAttributes(robot, [location])
        conductor.subscribeInteractionClass(command)
        conductor.enableTimeRegulation(0.0, 1.0)
        conductor.enableTimeConstrained()
        bystander.enableTimeConstrained()  # constrained only: it waits on the others, nobody waits on it
        tick_until(lambda: bool(amb.named("timeConstrainedEnabled")) and bool(by_amb.named("timeConstrainedEnabled")),
                   conductor, bystander)  # fmt: skip

        crowd = python_subprocess("crowd.py", rtig.address, "doomed", "2", "--updates", "3", "--payload", "8", "--tar", "5")
        crowd_procs.append(crowd)
        doomed = read_ready(crowd)
        # The conductor (regulating at 0, lookahead 1) holds the doomed federates' TAR(5).
        wait_until(lambda: all((f["pending"] or {}).get("request") == "TAR" for f in federates_of(rtig.address)
                               if f["handle"] in doomed))  # fmt: skip
        assert conductor.advance_to(2.0, timeout=10) == 2.0  # their bound is 6: no wait
        pending = {f["handle"]: f["pending"] for f in federates_of(rtig.address) if f["handle"] in doomed}
        assert all(pending[h].pop("waiting") >= 0 for h in doomed)  # seconds since the request
        assert pending == {h: {"request": "TAR", "time": 5.0} for h in doomed}, pending

        kill(crowd)
        wait_until(lambda: not any(f["handle"] in doomed for f in federates_of(rtig.address)))
        conductor.timeAdvanceRequest(10.0)
        bystander.timeAdvanceRequest(10.0)
        tick_until(lambda: len(amb.named("timeAdvanceGrant")) == 2 and len(by_amb.named("timeAdvanceGrant")) == 1,
                   conductor, bystander, timeout=10)  # fmt: skip
        assert [a[0] for a in amb.named("timeAdvanceGrant")] == [2.0, 10.0]
        assert [a[0] for a in by_amb.named("timeAdvanceGrant")] == [10.0]

        # Every TSO message of the dead, exactly once, in timestamp order, each before the grant covering it.
        events = [(n, a) for n, a in amb.calls if n in ("reflectAttributeValues", "receiveInteraction", "timeAdvanceGrant")]
        timed = [(n, a) for n, a in events if n != "timeAdvanceGrant" and len(a) > 5 and a[5] is not None]
        tso = [(n, a[5], a[6].sendingFederate) for n, a in timed]
        for kind in ("reflectAttributeValues", "receiveInteraction"):
            for h in doomed:
                assert [t for n, t, s in tso if n == kind and int(s) == h] == [1.0, 2.0, 3.0], (kind, h, tso)
        assert [t for _, t, _ in tso] == sorted(t for _, t, _ in tso)
        first_grant = events.index(next(e for e in events if e[0] == "timeAdvanceGrant"))
        assert len(tso) == 12
        before_first = [e for e in events[:first_grant] if e in timed]
        assert len(before_first) == 8 and all(a[5] <= 2.0 for _, a in before_first)  # at 1 and 2
        removed = {int(a[0]) for a in amb.named("removeObjectInstance")}
        assert len(removed) == 2
        assert len(amb.named("reflectAttributeValues")) - 6 == 6  # and the receive-order updates, 3 each
    finally:
        for fed in (conductor, bystander):
            fed.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    creator.destroyFederationExecution("TestFed")


# ---- memory ----


class Watcher(rti.FederateAmbassador):
    """Counts what it is told, without keeping the (large) values."""

    def __init__(self) -> None:
        self.discovered: dict[str, int] = {}
        self.removed: set[int] = set()
        self.announced: set[str] = set()
        self.synchronized: set[str] = set()
        self.reflections = 0
        self.interactions = 0

    def discoverObjectInstance(self, obj: Any, cls: Any, name: str) -> None:
        self.discovered[name] = int(obj)

    def removeObjectInstance(self, obj: Any, *rest: Any) -> None:
        self.removed.add(int(obj))

    def announceSynchronizationPoint(self, label: str, tag: str) -> None:
        self.announced.add(label)

    def federationSynchronized(self, label: str) -> None:
        self.synchronized.add(label)

    def reflectAttributeValues(self, *args: Any) -> None:
        self.reflections += 1

    def receiveInteraction(self, *args: Any) -> None:
        self.interactions += 1


MEMORY_CYCLES = int(os.environ.get("HLACORE_TEST_DEATH_CYCLES", "20"))
CROWD = 8
PAYLOAD = 16 << 10
UPDATES = 10
# What rtig may keep after the cycles, beyond its resident size before the first join: allocator bookkeeping
# and the high-water mark of its containers (measured: 0.2-0.5 MiB; docs/robustness.md). A cycle peaks at
# 20-50 MiB (the dead federates' undelivered messages), so keeping a tenth of one cycle would exceed it.
TOLERANCE = 4 << 20


def test_frames_read_with_the_reset_of_a_killed_sender_are_served(rtig: RtigProcess) -> None:
    """A federate killed with unread data in its socket makes the kernel reset the connection. What it sent
    before, still in the gateway's socket, comes before the reset: with the rtig stopped meanwhile, one turn of
    its read loop takes it and then the error, and it is served before the connection is closed (CI once
    counted 3183 of test_death's 3200 updates, when such frames were dropped with it). The frame is 256 KiB:
    the read of its rest is then a full one, so that the loop reads again and meets the error in that turn."""
    warm, last = 8, 256 * 1024
    creator = rti.RTIAmbassador(rtig.address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    watcher = Federate(rtig.address, "watcher")
    robot, location = share_robot_location(watcher, watcher)
    own = watcher.rtia.registerObjectInstance(robot, "watcher")

    def reflected(tag: str) -> list[bytes]:
        names = {args[0]: args[2] for args in watcher.amb.named("discoverObjectInstance")}
        return [args[1][location] for args in watcher.amb.named("reflectAttributeValues")
                if names.get(args[0]) == "sender" and args[2] == tag]

    sender = python_subprocess("dying_sender.py", rtig.address, str(warm), str(last))
    try:
        # The warm-up's megabytes grow the sockets' buffers: the last frame then fits in them whole.
        tick_until(lambda: len(reflected("warm")) == warm, watcher.rtia, timeout=60)
        assert sender.read_line(60).strip() == "ready", sender.stderr()
        for _ in range(8):  # reflected to the sender, which never reads them
            watcher.rtia.updateAttributeValues(own, {location: bytes(1024)}, "")
        watcher.rtia.registerObjectInstance(robot, "barrier")  # answered once the updates are on their way
        time.sleep(0.2)
        os.kill(rtig.child.pid, signal.SIGSTOP)
        try:
            sender.send_signal(signal.SIGUSR1)
            assert sender.read_line(30).strip() == "sent", sender.stderr()
            kill(sender)
        finally:
            os.kill(rtig.child.pid, signal.SIGCONT)
    finally:
        sender.close()
    dropped = wait_for_log(rtig, r"rtig: dropped 127\.0\.0\.1:\d+ \(federate \d+ of 'TestFed'\): [^\n]*", timeout=30)
    assert "Connection reset by peer" in dropped, dropped  # the case this test is about
    tick_until(lambda: len(reflected("last")) == 1, watcher.rtia, timeout=30)
    assert reflected("last") == [b"last" * (last // 4)]
    watcher.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    creator.destroyFederationExecution("TestFed")


def test_rtig_memory_returns_after_killed_crowds(tmp_path: pathlib.Path) -> None:
    """MEMORY_CYCLES times: 8 federates in one process join, publish, subscribe, register objects, send 16 KiB
    updates and interactions (receive order and timestamped), register a sync point, request a TAR and stop
    reading (megabytes pile up for them in rtig), then are killed. Each time the watcher gets the sync point
    synchronized and every object removed; at the end rtig's resident memory is back near its level before
    the first join."""
    with running_rtig(tmp_path, executable=release_rtig()) as server:
        address = server.address
        pid = server.proc.pid
        creator = rti.RTIAmbassador(address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        amb = Watcher()
        watcher = rti.RTIAmbassador(address)
        watcher.joinFederationExecution("watcher", "TestFed", amb)
        robot = watcher.getObjectClassHandle("robot")
        watcher.subscribeObjectClassAttributes(robot, [watcher.getAttributeHandle("location", robot)])
        watcher.subscribeInteractionClass(watcher.getInteractionClassHandle("command"))
        watcher.tick(0.1, 0.1)
        before = vm_rss(pid)
        peaks, after = [], []
        crowd: Optional[Child] = None
        try:
            for cycle in range(MEMORY_CYCLES):
                label = f"sync{cycle}"
                crowd = python_subprocess("crowd.py", address, f"c{cycle}-", str(CROWD), "--payload", str(PAYLOAD),
                                          "--updates", str(UPDATES), "--sync", label, "--tar", "100")  # fmt: skip
                handles = read_ready(crowd)
                names = [f"c{cycle}-{i}" for i in range(CROWD)]
                tick_until(lambda: label in amb.announced and all(n in amb.discovered for n in names), watcher,
                           timeout=30)  # fmt: skip
                watcher.synchronizationPointAchieved(label)
                peaks.append(vm_rss(pid))
                kill(crowd)
                crowd = None
                objects = {amb.discovered[n] for n in names}
                tick_until(lambda: label in amb.synchronized and objects <= amb.removed, watcher, timeout=30)
                wait_until(lambda: [f["name"] for f in federates_of(address)] == ["watcher"])
                after.append(vm_rss(pid))
                assert not set(handles) & {f["handle"] for f in federates_of(address)}
        finally:
            if crowd is not None:
                kill(crowd)
        assert amb.reflections >= MEMORY_CYCLES * CROWD * UPDATES * 2
        assert amb.interactions >= MEMORY_CYCLES * CROWD * UPDATES
        mib = 1 << 20
        print(f"rtig VmRSS: {before / mib:.1f} MiB before the joins, peaks "
              f"{[round(p / mib, 1) for p in peaks]}, after each cycle {[round(a / mib, 1) for a in after]} MiB")
        assert after[-1] - before < TOLERANCE, (before, peaks, after)
        # No growth from cycle to cycle: the second half stays within 1 MiB of the first half's top.
        half = len(after) // 2
        assert max(after[half:]) - max(after[:half]) < 1 << 20, (before, peaks, after)
        watcher.resignFederationExecution(rti.ResignAction.NoAction)
        creator.destroyFederationExecution("TestFed")
