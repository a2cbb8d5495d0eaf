"""Load over the real rtig: FEDERATES federate processes × UPDATES timestamped updates each, in lockstep, every
message delivered exactly once and in order (per-sender sequence numbers, checked by each peer at every step:
tests/peers/load_peer.py); then the same with 2 federates SIGKILLed midway.

The suite runs 8 × 200; `scripts/load.sh [FEDERATES [UPDATES]]` runs the full size (32 × 10 000) and prints the
figures. Sizes come from $HLACORE_LOAD_FEDERATES and $HLACORE_LOAD_UPDATES."""

from __future__ import annotations

import json
import os
import select
import signal
import subprocess
from typing import Any, Iterator

import pytest

import hlacore.rti as rti

from conftest import ROBOT_FED, Recorder, RtigProcess, python_subprocess, tick_until

FEDERATES = int(os.environ.get("HLACORE_LOAD_FEDERATES", "8"))
UPDATES = int(os.environ.get("HLACORE_LOAD_UPDATES", "200"))
# Functional bound on a whole run (not a performance assertion): generous for a loaded 2-core machine.
RUN_TIMEOUT = 120 + FEDERATES * UPDATES * 0.01


def read_json(proc: subprocess.Popen[str], timeout: float) -> dict[str, Any]:
    assert proc.stdout is not None
    ready, _, _ = select.select([proc.stdout], [], [], timeout)
    line = proc.stdout.readline() if ready else ""
    if not line:
        proc.kill()
        proc.wait()
        raise AssertionError(f"no line from pid {proc.pid} within {timeout:.0f} s: {proc.stderr.read() if proc.stderr else ''}")
    return dict(json.loads(line))


class Conductor:
    """Creates TestFed, starts the peers and releases them all at once with sync point 'start'."""

    def __init__(self, address: str) -> None:
        self.address = address
        self.rtia = rti.RTIAmbassador(address)
        self.rtia.createFederationExecution("TestFed", ROBOT_FED)
        self.amb = Recorder()
        self.rtia.joinFederationExecution("conductor", "TestFed", self.amb)
        self.peers: dict[str, subprocess.Popen[str]] = {}

    def start(self, names: list[str], *flags: str) -> None:
        for name in names:
            self.peers[name] = python_subprocess("load_peer.py", self.address, name, str(UPDATES), ",".join(names), *flags)
        for peer in self.peers.values():
            assert read_json(peer, 120) == {"ready": True}
        self.rtia.registerFederationSynchronizationPoint("start", "")
        tick_until(lambda: bool(self.amb.named("announceSynchronizationPoint")), self.rtia)
        self.rtia.synchronizationPointAchieved("start")
        tick_until(lambda: bool(self.amb.named("federationSynchronized")), self.rtia, timeout=120)

    def close(self) -> None:
        for peer in self.peers.values():
            if peer.poll() is None:
                peer.kill()
            peer.wait()
            for stream in (peer.stdout, peer.stderr):
                if stream:
                    stream.close()
        self.rtia.resignFederationExecution(rti.ResignAction.NoAction)
        self.rtia.destroyFederationExecution("TestFed")


@pytest.fixture
def conductor(rtig: RtigProcess) -> Iterator[Conductor]:
    c = Conductor(rtig.address)
    yield c
    c.close()


def check_results(conductor: Conductor, survivors: list[str], victims: list[str], die_at: int) -> None:
    results = {name: read_json(conductor.peers[name], RUN_TIMEOUT) for name in survivors}
    for name in survivors:
        peer = conductor.peers[name]
        assert peer.wait(timeout=60) == 0, peer.stderr.read() if peer.stderr else ""
    expected_last = {n: UPDATES for n in survivors} | {n: die_at for n in victims}
    for name, result in results.items():
        assert result["errors"] == [], (name, result["errors"])
        assert result["last"] == {n: k for n, k in expected_last.items() if n != name}, (name, result["last"])
        assert result["received"] == sum(k for n, k in expected_last.items() if n != name)
    delivered = sum(r["received"] for r in results.values())
    slowest = max(r["seconds"] for r in results.values())
    print(f"\n{len(survivors) + len(victims)} federates x {UPDATES} TSO updates, {len(victims)} killed at step "
          f"{die_at}: {delivered} deliveries checked, {slowest:.1f} s from the start to the last grant, "
          f"{delivered / slowest:.0f} deliveries/s")


def test_lockstep_load_every_message_once_in_order(conductor: Conductor) -> None:
    names = [f"p{i}" for i in range(FEDERATES)]
    conductor.start(names)
    check_results(conductor, names, [], 0)


def test_lockstep_load_with_two_federates_killed_midway(conductor: Conductor) -> None:
    """Two federates are SIGKILLed after the grant to UPDATES/2: the others keep stepping; from every dead
    sender they got exactly its updates 1..UPDATES/2, from every living one all UPDATES."""
    names = [f"p{i}" for i in range(FEDERATES)]
    victims, die_at = names[1:3], UPDATES // 2
    conductor.start(names, "--victims", ",".join(victims), "--die-at", str(die_at))
    for name in victims:
        assert read_json(conductor.peers[name], RUN_TIMEOUT) == {"dying": die_at}
        conductor.peers[name].send_signal(signal.SIGKILL)
    for name in victims:
        assert conductor.peers[name].wait(timeout=10) == -signal.SIGKILL
    check_results(conductor, [n for n in names if n not in victims], victims, die_at)
