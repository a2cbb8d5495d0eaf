"""The bench's child processes, through hlacore.processes: its peers (bench/peers/) and the rtig it
measures (the Release one `pip install .` put beside this interpreter; $HLACORE_BENCH_RTIG overrides, and
$HLACORE_BENCH_RTIG_ARGS adds arguments: `--tls-cert FILE --tls-key FILE` with $HLACORE_TLS=FILE for the
federates measures TLS, docs/networking.md)."""

from __future__ import annotations

import contextlib
import json
import os
import pathlib
import shlex
import sys
import tempfile
import time
import urllib.request
from typing import Iterator, Optional

from hlacore.processes import Child, Rtig, python_peer

PEERS = pathlib.Path(__file__).parent / "peers"
BUSY_POLL_US = "50"  # the busy-polling group's spin (rtig --busy-poll, $HLACORE_BUSY_POLL_US), in µs


def start_peer(script: str, *args: object) -> Child:
    """bench/peers/<script> under this interpreter."""
    return python_peer(PEERS / script, *args)


def close_all(children: list[Child]) -> None:
    for child in children:
        child.close()


def bench_rtig(*args: str, executable: Optional[str] = None) -> Rtig:
    """The rtig under test ($HLACORE_BENCH_RTIG, else beside Python) with `args` and $HLACORE_BENCH_RTIG_ARGS."""
    return Rtig(*shlex.split(os.environ.get("HLACORE_BENCH_RTIG_ARGS", "")), *args,
                executable=executable or os.environ.get("HLACORE_BENCH_RTIG"))


@contextlib.contextmanager
def unix_rtig(*args: str) -> Iterator[tuple[Rtig, str]]:
    """bench_rtig(*args) also listening on a Unix socket in a directory of its own (`rtig --unix`), and the
    address federates connect to it by ("unix:PATH"); the directory is removed when it stops."""
    with tempfile.TemporaryDirectory(prefix="hlacore-bench-") as directory, \
            bench_rtig("--unix", os.path.join(directory, "rtig.sock"), *args) as rtig:
        assert rtig.unix_address is not None
        yield rtig, rtig.unix_address


def cpu_seconds(pid: int) -> float:
    """The CPU time (user + system) process `pid` has used, all its threads: its CPU clock, the scheduler's
    count in nanoseconds (what /proc/PID/task/*/schedstat shows per thread), where /proc/PID/stat counts 10 ms
    ticks (18 µs a step over 550 steps); /proc/PID/stat where that clock cannot be read."""
    try:
        return time.clock_gettime(_process_cpu_clock(pid))
    except OSError:
        fields = pathlib.Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime, stime: fields 14 and 15


def _process_cpu_clock(pid: int) -> int:
    """clock_getcpuclockid(pid) of glibc, which Python does not expose: Linux encodes the process's CPU clock
    (its scheduler runtime, CPUCLOCK_SCHED = 2) in a negative clock id."""
    return ((~pid) << 3) | 2


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
