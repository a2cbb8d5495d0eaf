"""Large updates: camera-frame and point-cloud sizes, 1 MiB and 16 MiB, sent 1 → 1 through one
rtig as fast as the receiver takes them, every one counted; against a raw TCP stream of the same sizes (C++
and Python, one send() per record), and the same C++ stream through a relay process (what any design that
routes through a server cannot beat). Figures in bytes per second."""

from __future__ import annotations

import pytest

from .floor import PySink, cpp_stream_rate
from .report import LARGE_SIZES, Report
from .throughput import Fanout

ROUNDS = 10  # the first of ours is a warm-up (conftest.measure: rounds // 10), as in the other groups
BURST = {1 << 20: 64, 16 << 20: 4}  # updates per round: 64 MiB each

pytestmark = pytest.mark.benchmark(group="large updates 1 → 1 (one round = 64 MiB)")


@pytest.mark.parametrize("size", LARGE_SIZES)
def test_floor_python_stream(measure, size: int) -> None:
    sink = PySink(BURST[size], record=size)
    try:
        measure(f"large.floor.py.{size}", sink.burst, ROUNDS, per_round=BURST[size] * size)
    finally:
        sink.close()


@pytest.mark.parametrize("size", LARGE_SIZES)
def test_floor_cpp_stream(report: Report, tcp_floor: str, size: int) -> None:
    report.add(f"large.floor.cpp.{size}", [cpp_stream_rate(tcp_floor, BURST[size], size) * size for _ in range(ROUNDS)])


@pytest.mark.parametrize("size", LARGE_SIZES)
def test_floor_cpp_relay(report: Report, tcp_floor: str, size: int) -> None:
    report.add(f"large.floor.relay.{size}",
               [cpp_stream_rate(tcp_floor, BURST[size], size, mode="relay") * size for _ in range(ROUNDS)])


def run_large(measure, address: str, size: int, key: str) -> None:
    """ROUNDS rounds of BURST[size] updates of `size` bytes 1 → 1 through the gateway at `address`, in bytes
    per second under `key`."""
    fanout = Fanout(address, 1, BURST[size], payload=bytes(size))
    try:
        measure(key, fanout.burst, ROUNDS, per_round=BURST[size] * size)
        fanout.finish()
    finally:
        fanout.close()


@pytest.mark.parametrize("size", LARGE_SIZES)
def test_large_updates(measure, rtig, size: int) -> None:
    run_large(measure, rtig.address, size, f"large.{size}")
