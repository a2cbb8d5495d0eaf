"""The cost of recording: the 2-federate lockstep and the 1 → 1 throughput through an rtig that
records everything (``rtig --record``) against the same rtig without, in alternating rounds of one run."""

from __future__ import annotations

import pathlib

import pytest

from hlacore.processes import Rtig

from .procs import bench_rtig
from .test_grant import ROUNDS as LOCKSTEP_ROUNDS
from .test_grant import run_lockstep
from .test_throughput import BURST
from .throughput import Fanout

# off, on, off, on...: each key gathers all of its runs (report.add extends); six pairs, since one run's median
# moves by up to 2× from the next on this 2-core machine.
PAIRS = 6
ALTERNATION = [f"{side}-{i}" for i in range(1, PAIRS + 1) for side in ("off", "on")]


def recording_rtig(side: str, tmp_path: pathlib.Path) -> Rtig:
    return bench_rtig("--record", str(tmp_path / "run.mcap")) if side.startswith("on") else bench_rtig()


@pytest.mark.benchmark(group="recording: lockstep of 2 federates")
@pytest.mark.parametrize("side", ALTERNATION)
def test_lockstep_recorded(measure, tmp_path: pathlib.Path, side: str) -> None:
    with recording_rtig(side, tmp_path) as server:
        run_lockstep(measure, server.address, 2, f"record.grant.2.{side.split('-')[0]}", extend=True,
                     rounds=LOCKSTEP_ROUNDS[2] // PAIRS)


@pytest.mark.benchmark(group="recording: throughput 1 → 1")
@pytest.mark.parametrize("side", ALTERNATION)
def test_throughput_recorded(measure, tmp_path: pathlib.Path, side: str) -> None:
    with recording_rtig(side, tmp_path) as server:
        fanout = Fanout(server.address, 1, BURST[1])
        try:
            measure(f"record.throughput.1.{side.split('-')[0]}", fanout.burst, 3, per_round=BURST[1], extend=True)
            fanout.finish()
        finally:
            fanout.close()
