"""The three-RTI benchmark (issue 19): one C++ HLA 1.3 program (bench/rtis/hla13_bench.cpp) compiled
unchanged against hlacore, OpenRTI and CERTI 3.5.1, on the same workloads as hlacore's Python federates, in
one run beside the raw TCP floor: lockstep of K = 2, 4, 8 federates with a TSO update per federate per step,
the receive-order update ping-pong (8 B), and throughput 1 → 1 (8 B updates). Each C++ figure is three runs
per RTI, the RTIs alternating; ./scripts/bench.sh builds the other two RTIs first (bench/rtis/build.sh)."""

from __future__ import annotations

import contextlib
from typing import Iterator

import pytest

from .floor import cpp_rtt_ns, cpp_stream_rate
from .pingpong import PingPong
from .report import RTI_LOCKSTEP, Report
from .test_grant import run_lockstep
from .three_rtis import RTIS, Server, run
from .throughput import Fanout

STEPS = {2: 3000, 4: 1500, 8: 600}  # lockstep steps per run: a few seconds on the slowest RTI
ROUNDS = 3000                       # ping-pong round trips per run
BURST, BURSTS = 20_000, 5           # throughput: updates per burst, bursts per run
REPETITIONS = 3

pytestmark = pytest.mark.benchmark(group="three RTIs")


@contextlib.contextmanager
def server(rti: str) -> Iterator[Server]:
    s = Server(rti)
    try:
        yield s
    finally:
        s.close()


def test_floor(report: Report, tcp_floor: str) -> None:
    """The raw C++ TCP round trip (8 B) and stream rate, the floors of this run's ratios."""
    report.add("rtis.floor.cpp", [ns / 1e9 for ns in cpp_rtt_ns(tcp_floor, 8, 5000)])
    report.add("rtis.floor.stream.cpp", [cpp_stream_rate(tcp_floor, 200_000) for _ in range(3)])


@pytest.mark.parametrize("k", RTI_LOCKSTEP)
def test_lockstep_cpp(report: Report, k: int) -> None:
    for _ in range(REPETITIONS):
        for rti in RTIS:
            with server(rti) as s:
                result = run(s, "lockstep", k, STEPS[k], STEPS[k] // 10)
            report.add(f"rtis.{rti}.lockstep.{k}", [ns / 1e9 for ns in result["samples_ns"]], extend=True)


def test_pingpong_cpp(report: Report) -> None:
    for _ in range(REPETITIONS):
        for rti in RTIS:
            with server(rti) as s:
                result = run(s, "pingpong", 2, ROUNDS, ROUNDS // 10)
            report.add(f"rtis.{rti}.pingpong", [ns / 1e9 for ns in result["samples_ns"]], extend=True)


def test_throughput_cpp(report: Report) -> None:
    for _ in range(REPETITIONS):
        for rti in RTIS:
            with server(rti) as s:
                result = run(s, "throughput", 2, BURST, BURSTS)
            report.add(f"rtis.{rti}.throughput", result["rates"], extend=True)


@pytest.mark.parametrize("k", RTI_LOCKSTEP)
def test_lockstep_python(measure, rtig, k: int) -> None:
    run_lockstep(measure, rtig.address, k, f"rtis.python.lockstep.{k}", rounds=STEPS[k])


def test_pingpong_python(measure, rtig) -> None:
    pingpong = PingPong(rtig.address, "ro", 8)
    try:
        measure("rtis.python.pingpong", pingpong.round_trip, ROUNDS)
        pingpong.finish()
    finally:
        pingpong.close()


def test_throughput_python(measure, rtig) -> None:
    fanout = Fanout(rtig.address, 1, BURST)
    try:
        measure("rtis.python.throughput", fanout.burst, BURSTS * REPETITIONS, per_round=BURST)
        fanout.finish()
    finally:
        fanout.close()
