"""Fixtures of the bench run: a fresh Release rtig per benchmark, the C++ floor program, and `measure`,
which times a call with pytest-benchmark and keeps its samples in the run's Report. At the end the
report's table is printed and written (bench/outputs.py)."""

from __future__ import annotations

import os
import pathlib
import sys
from typing import Any, Callable, Iterator, Optional

import pytest
from hlacore.processes import Rtig

from .machine import describe
from .outputs import ROOT, write
from .procs import bench_rtig
from .report import Report

_REPORT = Report()
_LOAD_AT_START = os.getloadavg()

Measure = Callable[..., list[float]]


@pytest.fixture(scope="session")
def report() -> Report:
    return _REPORT


@pytest.fixture
def rtig() -> Iterator[Rtig]:
    with bench_rtig() as server:
        yield server


@pytest.fixture(scope="session")
def tcp_floor() -> str:
    """The C++ floor program: $HLACORE_TCP_FLOOR, else build/bench/tcp_floor (built by scripts/bench.sh)."""
    path = pathlib.Path(os.environ.get("HLACORE_TCP_FLOOR") or ROOT / "build" / "bench" / "tcp_floor")
    if not path.exists():
        pytest.fail(f"{path} is missing: ./scripts/bench.sh builds it (cmake -DHLACORE_BENCH=ON)")
    return str(path)


@pytest.fixture
def measure(benchmark: Any, report: Report) -> Measure:
    """measure(key, fn, rounds, group=None, per_round=None, extend=False): run fn `rounds` times (after
    rounds // 10 unrecorded warm-up calls) timed one call each, and record the seconds per call under `key`, or
    per_round / seconds (a rate) when per_round is given; `extend` adds them to what the key has already
    (alternating A/B rounds)."""

    def run(key: str, fn: Callable[[], None], rounds: int, group: Optional[str] = None,
            per_round: Optional[int] = None, extend: bool = False) -> list[float]:
        if group:
            benchmark.group = group
        benchmark.pedantic(fn, rounds=rounds, warmup_rounds=rounds // 10, iterations=1)
        seconds = list(benchmark.stats.stats.data)
        report.add(key, [per_round / s for s in seconds] if per_round else seconds, extend=extend)
        return seconds

    return run


def pytest_terminal_summary(terminalreporter: Any) -> None:
    if not _REPORT.samples:
        return
    command = os.environ.get("HLACORE_BENCH_COMMAND") or " ".join(["python -m pytest", *sys.argv[1:]])
    paths = write(_REPORT, describe(_LOAD_AT_START), command)
    terminalreporter.section("hlacore figures and ratios to the raw TCP floors")
    terminalreporter.write_line(_REPORT.markdown())
    terminalreporter.write_line("written: " + ", ".join(str(p.relative_to(ROOT)) for p in paths))
    if not _REPORT.complete():
        terminalreporter.write_line("(a partial run: docs/ left unchanged)")
