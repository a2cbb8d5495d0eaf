"""Federates on the gateway's host over a Unix socket (`rtig --unix PATH`, opt-in; docs/networking.md): the
figures the socket changes most, beside the same loops over TCP in this run (test_busy_poll.py,
test_large.py, test_grant.py) and against the C++ floors of both sockets (bench/tcp_floor.cpp --unix, and
--spin for the busy-polling figures).

- the 2-federate grant and lockstep and the 8 B update ping-pong with every process busy polling 50 µs,
  where the sockets' own cost is what is left of a step;
- 1 MiB and 16 MiB updates 1 → 1, where copies through the kernel are;
- the CPU per step of the 32-federate lockstep."""

from __future__ import annotations

from typing import Iterator

import pytest

from hlacore.processes import Rtig

from .floor import cpp_rtt_ns, cpp_stream_rate
from .procs import BUSY_POLL_US, unix_rtig
from .report import LARGE_SIZES, Report
from .test_busy_poll import run_ping_pong
from .test_grant import FLOOR_ROUNDS, ROUNDS, run_lockstep
from .test_large import BURST, ROUNDS as LARGE_ROUNDS, run_large

pytestmark = pytest.mark.benchmark(group="same host over a Unix socket")


@pytest.fixture
def rtig_unix() -> Iterator[tuple[Rtig, str]]:
    with unix_rtig() as server:
        yield server


@pytest.fixture
def busy_rtig_unix(monkeypatch: pytest.MonkeyPatch) -> Iterator[str]:
    """As test_busy_poll.busy_rtig: the rtig and every federate this test starts poll BUSY_POLL_US."""
    monkeypatch.setenv("HLACORE_BUSY_POLL_US", BUSY_POLL_US)
    with unix_rtig("--busy-poll", BUSY_POLL_US) as (_, address):
        yield address


@pytest.mark.parametrize("key, mode, spin", [("unix.floor.cpp", "rtt", False), ("unix.busy.floor.cpp", "rtt", True),
                                             ("unix.busy.floor.relay", "rtt-relay", True),
                                             ("unix.busy.floor.barrier", "barrier", True)])
def test_floor_cpp_rtt_unix(report: Report, tcp_floor: str, key: str, mode: str, spin: bool) -> None:
    report.add(key, [ns / 1e9 for ns in cpp_rtt_ns(tcp_floor, 8, FLOOR_ROUNDS, mode, unix=True, spin=spin)])


@pytest.mark.parametrize("size", LARGE_SIZES)
def test_floor_cpp_stream_unix(report: Report, tcp_floor: str, size: int) -> None:
    report.add(f"unix.large.floor.cpp.{size}",
               [cpp_stream_rate(tcp_floor, BURST[size], size, unix=True) * size for _ in range(LARGE_ROUNDS)])


@pytest.mark.parametrize("updates", [False, True], ids=["pure", "updates"])
def test_lockstep_busy_unix(measure, busy_rtig_unix: str, updates: bool) -> None:
    run_lockstep(measure, busy_rtig_unix, 2, f"unix.busy.grant.{'rtig' if updates else 'pure'}.2",
                 updates=updates)


@pytest.mark.parametrize("order", ["ro", "tso"])
def test_update_ping_pong_busy_unix(measure, busy_rtig_unix: str, order: str) -> None:
    run_ping_pong(measure, busy_rtig_unix, order, f"unix.busy.update.{order}.8")


@pytest.mark.parametrize("size", LARGE_SIZES)
def test_large_updates_unix(measure, rtig_unix: tuple[Rtig, str], size: int) -> None:
    run_large(measure, rtig_unix[1], size, f"unix.large.{size}")


def test_lockstep_32_unix(measure, report: Report, rtig_unix: tuple[Rtig, str]) -> None:
    server, address = rtig_unix
    run_lockstep(measure, address, 32, "unix.grant.rtig.32", rounds=ROUNDS[32], cpu=(report, server.proc.pid),
                 cpu_prefix="unix.")
