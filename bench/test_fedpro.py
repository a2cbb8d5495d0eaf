"""The HLA 4 Federate Protocol beside hlacore's own, in alternating rounds of one run through one rtig (--fedpro):
the 2-federate lockstep and the 8 B update ping-pong in receive order, the measuring federate on hlacore.rti
(off) or on hlacore.fedpro, pure Python over the Federate Protocol (on); the peer processes are the same."""

from __future__ import annotations

from typing import Iterator

import pytest

from hlacore.processes import Rtig

from .fedpro import FedproLockstep, FedproPingPong
from .procs import bench_rtig
from .test_grant import ROUNDS as LOCKSTEP_ROUNDS
from .test_grant import run_lockstep
from .test_recording_cost import ALTERNATION, PAIRS
from .test_busy_poll import run_ping_pong
from .test_update import ROUNDS as UPDATE_ROUNDS


@pytest.fixture(scope="module")
def door() -> Iterator[Rtig]:
    with bench_rtig("--fedpro", "127.0.0.1:0") as server:
        assert server.fedpro_address
        yield server


@pytest.mark.benchmark(group="Federate Protocol: lockstep of 2 federates")
@pytest.mark.parametrize("side", ALTERNATION)
def test_lockstep_over_the_federate_protocol(measure, door: Rtig, side: str) -> None:
    rounds = LOCKSTEP_ROUNDS[2] // PAIRS
    if side.startswith("off"):
        run_lockstep(measure, door.address, 2, "fedpro.grant.2.off", extend=True, rounds=rounds)
        return
    federation = FedproLockstep(door.address, door.fedpro_address, max_steps=rounds + rounds // 10 + 10)
    try:
        measure("fedpro.grant.2.on", federation.step, rounds, extend=True)
        federation.finish()
    finally:
        federation.close()


@pytest.mark.benchmark(group="Federate Protocol: update ping-pong, 8 B, receive order")
@pytest.mark.parametrize("side", ALTERNATION)
def test_ping_pong_over_the_federate_protocol(measure, door: Rtig, side: str) -> None:
    rounds = UPDATE_ROUNDS[8] // PAIRS
    if side.startswith("off"):
        run_ping_pong(measure, door.address, "ro", "fedpro.update.ro.8.off", rounds=rounds, extend=True)
        return
    pingpong = FedproPingPong(door.address, door.fedpro_address, 8)
    try:
        measure("fedpro.update.ro.8.on", pingpong.round_trip, rounds, extend=True)
        pingpong.finish()
    finally:
        pingpong.close()
