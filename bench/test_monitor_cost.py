"""The monitor's cost on the gateway: the 2-federate lockstep through an rtig watched by
``python -m hlacore.monitor`` (its own process, a status query every 0.5 s, a page connected to it) against
the same rtig unwatched, in alternating rounds of one run."""

from __future__ import annotations

import contextlib

import pytest

from .procs import bench_rtig, watching
from .test_grant import ROUNDS as LOCKSTEP_ROUNDS
from .test_grant import run_lockstep
from .test_recording_cost import ALTERNATION, PAIRS


@pytest.mark.benchmark(group="monitor: lockstep of 2 federates")
@pytest.mark.parametrize("side", ALTERNATION)
def test_lockstep_watched(measure, side: str) -> None:
    with bench_rtig() as server, (watching(server.address) if side.startswith("on") else contextlib.nullcontext()):
        run_lockstep(measure, server.address, 2, f"monitor.grant.2.{side.split('-')[0]}", extend=True,
                     rounds=LOCKSTEP_ROUNDS[2] // PAIRS)
