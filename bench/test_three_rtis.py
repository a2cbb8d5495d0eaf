"""The three-RTI benchmark: one C++ HLA 1.3 program (bench/rtis/hla13_bench.cpp) compiled unchanged against
hlacore, OpenRTI and CERTI 3.5.1, and its IEEE 1516-2010 twin (bench/rtis/rti1516e_bench.cpp) against hlacore
and OpenRTI, on the same workloads as hlacore's Python federates, in one run beside the raw TCP floor: lockstep of K = 2, 4, 8 federates with a TSO update per federate per step, the receive-order update
ping-pong (8 B), and throughput 1 → 1 (8 B updates). Each figure is REPETITIONS runs per RTI and API, the RTIs,
their APIs and the Python federates alternating, each on a fresh server (the machine's noise then falls on all alike); the samples
time themselves (the C++ program with steady_clock, the Python federates with perf_counter), and the C++ floors
are measured in each round too.

OpenRTI and CERTI are existing installs, not built here: point the bench at them with
HLACORE_BENCH_OPENRTI=PREFIX and HLACORE_BENCH_CERTI=PREFIX (what each prefix must hold: bench/three_rtis.py).
Without either, hlacore's rows (its two C++ programs and its Python federates) are measured alone and
test_other_rtis is skipped with the line that says so."""

from __future__ import annotations

import contextlib
import time
from typing import Callable, Iterator

import pytest

from .floor import cpp_rtt_ns, cpp_stream_rate
from .lockstep import Lockstep
from .pingpong import PingPong
from .report import RTI_LOCKSTEP, Report
from .three_rtis import NOT_INSTALLED, Server, bench_binary, column, installed, programs, run
from .throughput import Fanout

STEPS = {2: 3000, 4: 1500, 8: 600}  # lockstep steps per run: a few seconds on the slowest RTI
ROUNDS = 3000                       # ping-pong round trips per run
BURST, BURSTS = 20_000, 5           # throughput: updates per burst, bursts per run
REPETITIONS = 5


@pytest.fixture(scope="module", autouse=True)
def binaries() -> None:
    """The programs compiled against hlacore and each other RTI installed, before anything is timed."""
    for rti, api in programs():
        bench_binary(rti, api)


def test_other_rtis() -> None:
    """Each other RTI given by its prefix variable starts its server, with the programs compiled against it;
    skipped, saying how to give them, when none is."""
    if not installed():
        pytest.skip(NOT_INSTALLED)
    for rti in installed():
        with server(rti) as s:
            assert s.pid > 0


@contextlib.contextmanager
def server(rti: str) -> Iterator[Server]:
    s = Server(rti)
    try:
        yield s
    finally:
        s.close()


def timed(call: Callable[[], object], count: int, warmup: int) -> list[float]:
    """Seconds per call of `call`, `count` times after `warmup` untimed calls."""
    for _ in range(warmup):
        call()
    samples = []
    for _ in range(count):
        start = time.perf_counter()
        call()
        samples.append(time.perf_counter() - start)
    return samples


def python_lockstep(address: str, k: int) -> list[float]:
    federation = Lockstep(address, k, max_steps=STEPS[k] + STEPS[k] // 10 + 10)
    try:
        samples = timed(federation.step, STEPS[k], STEPS[k] // 10)
        federation.finish()  # every federate got every update of every step
    finally:
        federation.close()
    return samples


def python_pingpong(address: str) -> list[float]:
    pingpong = PingPong(address, "ro", 8)
    try:
        samples = timed(pingpong.round_trip, ROUNDS, ROUNDS // 10)
        pingpong.finish()
    finally:
        pingpong.close()
    return samples


def python_throughput(address: str) -> list[float]:
    fanout = Fanout(address, 1, BURST)
    try:
        rates = [BURST / s for s in timed(fanout.burst, BURSTS, 0)]
        fanout.finish()
    finally:
        fanout.close()
    return rates


def alternate(report: Report, tcp_floor: str, key: str, cpp: Callable[[Server, str], list[float]],
              python: Callable[[str], list[float]]) -> None:
    """REPETITIONS rounds, each measuring the C++ floors (rtis.floor.cpp: TCP round trips of 8 B;
    rtis.floor.stream.cpp: the stream rate), then running the C++ programs on hlacore and each other RTI
    installed (`cpp(server, api)`), and hlacore's Python federates, each on a fresh server; the samples go
    under rtis.<column>.<key> (three_rtis.column: hlacore, hlacore-1516e, ..., python)."""
    for _ in range(REPETITIONS):
        report.add("rtis.floor.cpp", [ns / 1e9 for ns in cpp_rtt_ns(tcp_floor, 8, 1000)], extend=True)
        report.add("rtis.floor.stream.cpp", [cpp_stream_rate(tcp_floor, 200_000)], extend=True)
        for rti, api in (*programs(), ("python", "")):
            with server("hlacore" if rti == "python" else rti) as s:
                samples = python(s.address) if rti == "python" else cpp(s, api)
            report.add(f"rtis.{column(rti, api) if api else rti}.{key}", samples, extend=True)


@pytest.mark.parametrize("k", RTI_LOCKSTEP)
def test_lockstep(report: Report, tcp_floor: str, k: int) -> None:
    alternate(report, tcp_floor, f"lockstep.{k}",
              lambda s, api: [ns / 1e9 for ns in run(s, "lockstep", k, STEPS[k], STEPS[k] // 10, api=api)["samples_ns"]],
              lambda address: python_lockstep(address, k))


def test_pingpong(report: Report, tcp_floor: str) -> None:
    alternate(report, tcp_floor, "pingpong",
              lambda s, api: [ns / 1e9 for ns in run(s, "pingpong", 2, ROUNDS, ROUNDS // 10, api=api)["samples_ns"]],
              python_pingpong)


def test_throughput(report: Report, tcp_floor: str) -> None:
    alternate(report, tcp_floor, "throughput", lambda s, api: list(run(s, "throughput", 2, BURST, BURSTS, api=api)["rates"]),
              python_throughput)
