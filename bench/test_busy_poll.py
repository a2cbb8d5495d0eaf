"""Busy polling (opt-in): the 2-federate grant and lockstep and the 8 B update ping-pong with every process
polling 50 µs before it sleeps (`rtig --busy-poll 50`, $HLACORE_BUSY_POLL_US=50 for the federates), beside the
same loops without it (test_grant.py, test_update.py), the floors of the same run and the C++ round trips with
every process polling: direct, through a relay, and the barrier of two clients (the floors of processes that
do not sleep); and the lockstep and the receive-order ping-pong of bench/rtis's C++ program, polling too: the
same client library and rtig without Python."""

from __future__ import annotations

from typing import Iterator, Optional

import pytest

from hlacore.processes import Rtig

from .floor import cpp_rtt_ns
from .pingpong import PingPong
from .procs import BUSY_POLL_US, bench_rtig
from .report import Report
from .test_grant import FLOOR_ROUNDS, ROUNDS as GRANT_ROUNDS, run_lockstep
from .test_update import ROUNDS as UPDATE_ROUNDS
from .three_rtis import Server, run

pytestmark = pytest.mark.benchmark(group="busy polling")


@pytest.fixture
def busy_rtig(monkeypatch: pytest.MonkeyPatch) -> Iterator[Rtig]:
    """The rtig polling BUSY_POLL_US, and the same for every federate this test starts, here or in a peer."""
    monkeypatch.setenv("HLACORE_BUSY_POLL_US", BUSY_POLL_US)
    with bench_rtig("--busy-poll", BUSY_POLL_US) as server:
        yield server


@pytest.mark.parametrize("key, mode", [("busy.floor.cpp", "rtt"), ("busy.floor.relay", "rtt-relay"),
                                       ("busy.floor.barrier", "barrier")])
def test_floor_cpp_rtt_polling(report: Report, tcp_floor: str, key: str, mode: str) -> None:
    report.add(key, [ns / 1e9 for ns in cpp_rtt_ns(tcp_floor, 8, FLOOR_ROUNDS, mode, spin=True)])


@pytest.mark.parametrize("updates", [False, True], ids=["pure", "updates"])
def test_lockstep_busy(measure, busy_rtig: Rtig, updates: bool) -> None:
    run_lockstep(measure, busy_rtig.address, 2, f"busy.grant.{'rtig' if updates else 'pure'}.2", updates=updates)


def test_lockstep_busy_batched(measure, busy_rtig: Rtig) -> None:
    """The lockstep with updates, each federate's update and request in one write (RTIAmbassador.batch())."""
    run_lockstep(measure, busy_rtig.address, 2, "busy.grant.batched.2", batched=True)


@pytest.mark.parametrize("key, workload, rounds", [("busy.grant.cpp.2", "lockstep", GRANT_ROUNDS[2]),
                                                   ("busy.update.ro-cpp.8", "pingpong", UPDATE_ROUNDS[8])])
def test_cpp_program_busy(report: Report, monkeypatch: pytest.MonkeyPatch, key: str, workload: str,
                          rounds: int) -> None:
    """bench/rtis's C++ program (hlacore's HLA 1.3 API) as both federates, every process polling: the lockstep
    (its update and request in two writes) and the receive-order ping-pong of 8 B, timed by the program."""
    monkeypatch.setenv("HLACORE_BUSY_POLL_US", BUSY_POLL_US)
    server = Server("hlacore", "--busy-poll", BUSY_POLL_US)
    try:
        samples = run(server, workload, 2, rounds, rounds // 10)["samples_ns"]
    finally:
        server.close()
    report.add(key, [ns / 1e9 for ns in samples])


def run_ping_pong(measure, address: str, order: str, key: str, rounds: Optional[int] = None, extend: bool = False) -> None:
    """The 8 B update ping-pong of test_update.py through the gateway at `address`, timed under `key`."""
    pingpong = PingPong(address, order, 8)
    try:
        measure(key, pingpong.round_trip, rounds or UPDATE_ROUNDS[8], extend=extend)
        pingpong.finish()
    finally:
        pingpong.close()


@pytest.mark.parametrize("order", ["ro", "tso", "tso-batched"])
def test_update_ping_pong_busy(measure, busy_rtig: Rtig, order: str) -> None:
    run_ping_pong(measure, busy_rtig.address, order, f"busy.update.{order}.8")
