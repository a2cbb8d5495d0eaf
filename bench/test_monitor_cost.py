"""The monitor's cost on the gateway (issue 21): the 2-federate lockstep through an rtig watched by
``python -m hlacore.monitor`` (its own process, a status query every 0.5 s, a page connected to it) against
the same rtig unwatched, in alternating rounds of one run."""

from __future__ import annotations

import contextlib
import json
import sys
import urllib.request
from typing import Iterator

import pytest

from hlacore.processes import Child

from .procs import bench_rtig
from .test_grant import ROUNDS as LOCKSTEP_ROUNDS
from .test_grant import run_lockstep
from .test_recording_cost import ALTERNATION, PAIRS


@contextlib.contextmanager
def watching(address: str) -> Iterator[None]:
    """`python -m hlacore.monitor` on `address`, serving on a free port, with a WebSocket client reading every
    view as a page would; both stopped on exit."""
    monitor = Child([sys.executable, "-m", "hlacore.monitor", address, "--listen", "127.0.0.1:0"])
    try:
        line = monitor.read_line(30.0)
        url = line.split()[1]
        with urllib.request.urlopen(url + "view.json", timeout=10) as response:
            json.loads(response.read())
        page = Child([sys.executable, "-c", _PAGE, url.replace("http://", "ws://") + "ws"])
        try:
            assert page.read_line(30.0).strip() == "connected"
            yield
        finally:
            page.close()
    finally:
        monitor.close()


# A page's share of the work: reads every view the monitor pushes (aiohttp's client, a dependency already).
_PAGE = """
import asyncio, sys, aiohttp
async def main():
    async with aiohttp.ClientSession() as session:
        async with session.ws_connect(sys.argv[1]) as ws:
            print("connected", flush=True)
            async for _ in ws:
                pass
asyncio.run(main())
"""


@pytest.mark.benchmark(group="monitor: lockstep of 2 federates")
@pytest.mark.parametrize("side", ALTERNATION)
def test_lockstep_watched(measure, side: str) -> None:
    with bench_rtig() as server, (watching(server.address) if side.startswith("on") else contextlib.nullcontext()):
        run_lockstep(measure, server.address, 2, f"monitor.grant.2.{side.split('-')[0]}", extend=True,
                     rounds=LOCKSTEP_ROUNDS[2] // PAIRS)
