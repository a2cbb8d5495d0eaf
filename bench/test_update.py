"""Update latency: an update ping-pong between two processes, receive order and TSO, for 8 B, 1 KiB and
64 KiB payloads, against raw TCP round trips of the same size (one-way = round trip / 2 for both), and the
C++ round trip through a relay process (four hops, as through a gateway: what no routed design can beat)."""

from __future__ import annotations

import pytest

from .floor import PyEcho, cpp_rtt_ns
from .pingpong import PingPong
from .report import PAYLOADS, Report, size_name

ROUNDS = {8: 3000, 1024: 3000, 65536: 1000}


@pytest.mark.parametrize("size", PAYLOADS)
def test_floor_python_rtt(measure, size: int) -> None:
    echo = PyEcho(size)
    try:
        measure(f"update.floor.py.{size}", echo.round_trip, ROUNDS[size], group=f"update {size_name(size)}")
    finally:
        echo.close()


@pytest.mark.parametrize("size", PAYLOADS)
def test_floor_cpp_rtt(report: Report, tcp_floor: str, size: int) -> None:
    report.add(f"update.floor.cpp.{size}", [ns / 1e9 for ns in cpp_rtt_ns(tcp_floor, size, ROUNDS[size])])


@pytest.mark.parametrize("size", PAYLOADS)
def test_floor_cpp_relay_rtt(report: Report, tcp_floor: str, size: int) -> None:
    report.add(f"update.floor.relay.{size}", [ns / 1e9 for ns in cpp_rtt_ns(tcp_floor, size, ROUNDS[size], "rtt-relay")])


@pytest.mark.parametrize("order", ["ro", "tso"])
@pytest.mark.parametrize("size", PAYLOADS)
def test_update_ping_pong(measure, rtig, size: int, order: str) -> None:
    pingpong = PingPong(rtig.address, order, size)
    try:
        measure(f"update.{order}.{size}", pingpong.round_trip, ROUNDS[size], group=f"update {size_name(size)}")
        pingpong.finish()
    finally:
        pingpong.close()
