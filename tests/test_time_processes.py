"""Time management end to end over the real rtig, one federate per process."""

from __future__ import annotations

import json
import signal
import subprocess
import time
from typing import Iterator

import pytest

import hlacore.rti as rti

from conftest import ROBOT_FED, Recorder, RtigProcess, python_subprocess, tick_until


def read_json_line(proc: subprocess.Popen[str]) -> dict:
    line = proc.stdout.readline() if proc.stdout else ""
    assert line, f"peer exited early: {proc.stderr.read() if proc.stderr else ''}"
    return json.loads(line)


class Lockstep:
    """The test's own federate: creates TestFed, starts peers, and releases them with sync point 'start'."""

    def __init__(self, address: str) -> None:
        self.address = address
        self.rtia = rti.RTIAmbassador(address)
        self.rtia.createFederationExecution("TestFed", ROBOT_FED)
        self.amb = Recorder()
        self.rtia.joinFederationExecution("conductor", "TestFed", self.amb)
        self.peers: list[subprocess.Popen[str]] = []

    def start_peers(self, steps: int, count: int, *flags: str) -> None:
        for i in range(count):
            self.peers.append(python_subprocess("lockstep.py", self.address, f"p{i}", str(steps), str(count), *flags))
        for peer in self.peers:
            assert read_json_line(peer) == {"ready": True}

    def synchronize(self) -> None:
        self.rtia.registerFederationSynchronizationPoint("start", "")
        tick_until(lambda: bool(self.amb.named("announceSynchronizationPoint")), self.rtia)
        self.rtia.synchronizationPointAchieved("start")
        tick_until(lambda: bool(self.amb.named("federationSynchronized")), self.rtia, timeout=30)

    def close(self) -> None:
        for peer in self.peers:
            if peer.poll() is None:
                peer.kill()
            peer.wait()
            for stream in (peer.stdout, peer.stderr):
                if stream:
                    stream.close()
        self.rtia.resignFederationExecution(rti.ResignAction.NoAction)
        self.rtia.destroyFederationExecution("TestFed")


@pytest.fixture
def lockstep(rtig: RtigProcess) -> Iterator[Lockstep]:
    conductor = Lockstep(rtig.address)
    yield conductor
    conductor.close()


def test_two_processes_in_lockstep_for_1000_steps(lockstep: Lockstep) -> None:
    """Paper 2's lockstep: every timestamped update arrives before the grant to its time, none lost."""
    lockstep.start_peers(1000, 2)
    lockstep.synchronize()
    results = [read_json_line(peer) for peer in lockstep.peers]
    for peer in lockstep.peers:
        assert peer.wait(timeout=60) == 0, peer.stderr.read() if peer.stderr else ""
    for result in results:
        assert result["errors"] == []
        assert result["received"] == 1000


def test_a_killed_regulating_federate_unblocks_the_others_within_a_second(lockstep: Lockstep) -> None:
    lockstep.start_peers(0, 1, "--stall")
    me = lockstep.rtia
    me.enableTimeRegulation(0.0, 1.0)
    me.enableTimeConstrained()
    tick_until(lambda: bool(lockstep.amb.named("timeConstrainedEnabled")), me)
    lockstep.synchronize()
    me.timeAdvanceRequest(10.0)
    with pytest.raises(TimeoutError):
        me.await_grant(timeout=0.5)  # the stalled peer (lookahead 1, at time 0) holds LBTS at 1
    lockstep.peers[0].send_signal(signal.SIGKILL)
    killed = time.monotonic()
    assert me.await_grant(timeout=1.0) == 10.0
    print(f"granted {time.monotonic() - killed:.4f} s after SIGKILL")
