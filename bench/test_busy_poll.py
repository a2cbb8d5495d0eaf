"""Busy polling (opt-in): the 2-federate grant and lockstep and the 8 B update ping-pong with every process
polling 50 µs before it sleeps (`rtig --busy-poll 50`, $HLACORE_BUSY_POLL_US=50 for the federates), beside the
same loops without it (test_grant.py, test_update.py) and the floors of the same run."""

from __future__ import annotations

from typing import Iterator

import pytest

from hlacore.processes import Rtig

from .pingpong import PingPong
from .procs import bench_rtig
from .test_grant import run_lockstep
from .test_update import ROUNDS as UPDATE_ROUNDS

BUSY_POLL_US = "50"

pytestmark = pytest.mark.benchmark(group="busy polling")


@pytest.fixture
def busy_rtig(monkeypatch: pytest.MonkeyPatch) -> Iterator[Rtig]:
    """The rtig polling BUSY_POLL_US, and the same for every federate this test starts, here or in a peer."""
    monkeypatch.setenv("HLACORE_BUSY_POLL_US", BUSY_POLL_US)
    with bench_rtig("--busy-poll", BUSY_POLL_US) as server:
        yield server


@pytest.mark.parametrize("updates", [False, True], ids=["pure", "updates"])
def test_lockstep_busy(measure, busy_rtig: Rtig, updates: bool) -> None:
    run_lockstep(measure, busy_rtig.address, 2, f"busy.grant.{'rtig' if updates else 'pure'}.2", updates=updates)


@pytest.mark.parametrize("order", ["ro", "tso"])
def test_update_ping_pong_busy(measure, busy_rtig: Rtig, order: str) -> None:
    pingpong = PingPong(busy_rtig.address, order, 8)
    try:
        measure(f"busy.update.{order}.8", pingpong.round_trip, UPDATE_ROUNDS[8])
        pingpong.finish()
    finally:
        pingpong.close()
