"""Busy polling (opt-in): the 2-federate grant and lockstep and the 8 B update ping-pong with every process
polling 50 µs before it sleeps (`rtig --busy-poll 50`, $HLACORE_BUSY_POLL_US=50 for the federates), beside the
same loops without it (test_grant.py, test_update.py), the floors of the same run and the C++ round trips with
every process polling: direct, through a relay, and the barrier of two clients (the floors of processes that
do not sleep)."""

from __future__ import annotations

from typing import Iterator

import pytest

from hlacore.processes import Rtig

from .floor import cpp_rtt_ns
from .pingpong import PingPong
from .procs import bench_rtig
from .report import Report
from .test_grant import FLOOR_ROUNDS, run_lockstep
from .test_update import ROUNDS as UPDATE_ROUNDS

BUSY_POLL_US = "50"

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


def run_ping_pong(measure, address: str, order: str, key: str) -> None:
    """The 8 B update ping-pong of test_update.py through the gateway at `address`, timed under `key`."""
    pingpong = PingPong(address, order, 8)
    try:
        measure(key, pingpong.round_trip, UPDATE_ROUNDS[8])
        pingpong.finish()
    finally:
        pingpong.close()


@pytest.mark.parametrize("order", ["ro", "tso", "tso-batched"])
def test_update_ping_pong_busy(measure, busy_rtig: Rtig, order: str) -> None:
    run_ping_pong(measure, busy_rtig.address, order, f"busy.update.{order}.8")
