"""Spilling: the subscriber stopped (SIGSTOP) while a burst of 1 KiB updates goes to it, then continued, until
it has counted all of them: the backlog held in memory (the default 64 MiB budget) against the same burst
spilled to disk beyond a 1 MiB budget (docs/robustness.md), in alternating rounds of one run."""

from __future__ import annotations

import signal

import pytest

from .procs import bench_rtig
from .throughput import Fanout

PAIRS = 3
ALTERNATION = [f"{side}-{i}" for i in range(1, PAIRS + 1) for side in ("off", "on")]  # off: memory, on: disk
BURST = 20_000  # 20 MiB
ROUNDS = 3


@pytest.mark.benchmark(group="spilling: a stopped subscriber catching up")
@pytest.mark.parametrize("side", ALTERNATION)
def test_catching_up(measure, side: str) -> None:
    args = ("--client-budget", str(1 << 20)) if side.startswith("on") else ()
    with bench_rtig(*args) as server:
        fanout = Fanout(server.address, 1, BURST, payload=bytes(1024))
        subscriber = fanout.peers[0]

        def stopped_burst() -> None:
            subscriber.send_signal(signal.SIGSTOP)
            try:
                fanout.send()
            finally:
                subscriber.send_signal(signal.SIGCONT)
            fanout.wait_counted()

        try:
            measure(f"spill.throughput.1.{side.split('-')[0]}", stopped_burst, ROUNDS, per_round=BURST, extend=True)
            fanout.finish()
        finally:
            fanout.close()
