"""Grant latency (TAR → TAG) of 2 to 32 federates in lockstep, each its own process, against the raw TCP
round trip; and the in-process gateway against the standalone rtig for the 2-federate loop."""

from __future__ import annotations

from typing import Optional

import pytest

import hlacore

from .floor import PyEcho, cpp_rtt_ns
from .lockstep import Lockstep
from .procs import cpu_seconds
from .report import FEDERATES, Report

# Rounds per federate count: more for the fast loops, so that each takes a few seconds at most.
ROUNDS = {2: 5000, 4: 3000, 8: 2000, 16: 1000, 32: 500}
FLOOR_ROUNDS = 5000

pytestmark = pytest.mark.benchmark(group="grant latency")


def test_floor_python_rtt(measure) -> None:
    echo = PyEcho(8)
    try:
        measure("grant.floor.py", echo.round_trip, FLOOR_ROUNDS)
    finally:
        echo.close()


def test_floor_cpp_rtt(report: Report, tcp_floor: str) -> None:
    report.add("grant.floor.cpp", [ns / 1e9 for ns in cpp_rtt_ns(tcp_floor, 8, FLOOR_ROUNDS)])


def test_floor_cpp_barrier(report: Report, tcp_floor: str) -> None:
    """The C++ floor of a 2-federate grant: a server answers two clients once both have sent."""
    report.add("grant.floor.barrier", [ns / 1e9 for ns in cpp_rtt_ns(tcp_floor, 8, FLOOR_ROUNDS, "barrier")])


def run_lockstep(measure, address: str, federates: int, key: str, updates: bool = True, extend: bool = False,
                 rounds: Optional[int] = None, cpu: Optional[tuple[Report, int]] = None, cpu_prefix: str = "",
                 batched: bool = False) -> None:
    """`cpu` = (report, the rtig's pid): also record the CPU time per step of the rtig and of each peer
    federate process (PREFIXcpu.K.rtig, PREFIXcpu.K.federate: their mean)."""
    rounds = rounds or ROUNDS[federates]
    federation = Lockstep(address, federates, max_steps=rounds + rounds // 10 + 10,  # warm-up, stop, margin
                          updates=updates, batched=batched)
    try:
        pids = [cpu[1], *(peer.pid for peer in federation.peers)] if cpu else []  # the rtig's first
        spent, steps = [cpu_seconds(pid) for pid in pids], federation.time
        measure(key, federation.step, rounds, extend=extend)
        if cpu:
            steps = federation.time - steps
            per_step = [(cpu_seconds(pid) - before) / steps for pid, before in zip(pids, spent)]
            cpu[0].add(f"{cpu_prefix}cpu.{federates}.rtig", per_step[:1])
            cpu[0].add(f"{cpu_prefix}cpu.{federates}.federate", per_step[1:])
        federation.finish()
    finally:
        federation.close()


@pytest.mark.parametrize("federates", FEDERATES)
def test_lockstep_rtig(measure, report: Report, rtig, federates: int) -> None:
    run_lockstep(measure, rtig.address, federates, f"grant.rtig.{federates}",
                 cpu=(report, rtig.proc.pid) if federates == max(FEDERATES) else None)


@pytest.mark.parametrize("federates", FEDERATES)
def test_pure_grant_rtig(measure, rtig, federates: int) -> None:
    run_lockstep(measure, rtig.address, federates, f"grant.pure.{federates}", updates=False)


def test_lockstep_inprocess_gateway(measure) -> None:
    with hlacore.Gateway(port=0) as gateway:
        run_lockstep(measure, gateway.address, 2, "grant.inprocess.2")
