"""The bench's child processes, through hlacore.processes: its peers (bench/peers/) and the rtig it
measures (the Release one `pip install .` put beside this interpreter; $HLACORE_BENCH_RTIG overrides, and
$HLACORE_BENCH_RTIG_ARGS adds arguments: `--tls-cert FILE --tls-key FILE` with $HLACORE_TLS=FILE for the
federates measures TLS, docs/networking.md)."""

from __future__ import annotations

import os
import pathlib
import shlex
from typing import Optional

from hlacore.processes import Child, Rtig, python_peer

PEERS = pathlib.Path(__file__).parent / "peers"


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
