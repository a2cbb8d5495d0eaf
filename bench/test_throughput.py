"""Throughput: bursts of small updates through one rtig to 1 and 8 subscriber processes, every update
counted by every subscriber; against raw TCP messages of about the same size, one send() each."""

from __future__ import annotations

import pytest

from .floor import PySink, cpp_stream_rate
from .report import SUBSCRIBERS, Report
from .throughput import Fanout

ROUNDS = 5
BURST = {1: 100_000, 8: 25_000}  # updates per round: about a second each
FLOOR_BURST = 200_000

pytestmark = pytest.mark.benchmark(group="throughput (one round = one burst)")


def test_floor_python_stream(measure) -> None:
    sink = PySink(FLOOR_BURST)
    try:
        measure("throughput.floor.py", sink.burst, ROUNDS, per_round=FLOOR_BURST)
    finally:
        sink.close()


def test_floor_cpp_stream(report: Report, tcp_floor: str) -> None:
    report.add("throughput.floor.cpp", [cpp_stream_rate(tcp_floor, FLOOR_BURST) for _ in range(ROUNDS)])


@pytest.mark.parametrize("subscribers", SUBSCRIBERS)
def test_fanout(measure, rtig, subscribers: int) -> None:
    fanout = Fanout(rtig.address, subscribers, BURST[subscribers])
    try:
        measure(f"throughput.{subscribers}", fanout.burst, ROUNDS, per_round=BURST[subscribers])
        fanout.finish()
    finally:
        fanout.close()
