"""A 200 Hz best-effort stream with 1 % of the gateway port's packets lost each way (nftables in a network
namespace, bench/lossy_stream.py): its latency over datagrams and over TCP, the same stream, the same loss."""

from __future__ import annotations

import os

import pytest
from hlacore.processes import rtig_beside_python

from .lossy_stream import stream_through_loss
from .report import Report

COUNT, RATE, LOSS = 4000, 200.0, 0.01


@pytest.mark.parametrize("path", ["udp", "tcp"])
def test_best_effort_stream_under_loss(report: Report, path: str) -> None:
    rtig = os.environ.get("HLACORE_BENCH_RTIG") or rtig_beside_python()
    result = stream_through_loss(rtig, LOSS, COUNT, RATE, datagrams=path == "udp")
    assert result["path"] == (path == "udp")
    report.add(f"besteffort.{path}.loss1", result["latencies"])
    report.add(f"besteffort.{path}.loss1.delivered", [len(result["latencies"]) / result["sent"]])
