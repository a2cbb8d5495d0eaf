"""A best-effort stream under packet loss: rtig and two federates in a network namespace of their own whose
firewall (nftables) drops a given share of the packets to and from the gateway's port, TCP and UDP alike,
so that the stream's latency over datagrams can be compared with the same stream over TCP (where a lost
segment holds back every message behind it until it is sent again). Needs root and `nft` (Debian's
nftables; ./scripts/bench.sh and ./scripts/test.sh install it when missing)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from typing import Any

from .procs import PEERS

PORT = 60400  # the namespace is new: nothing else listens there


def _ip(*args: str) -> None:
    subprocess.run(["ip", *args], check=True, capture_output=True, timeout=30)


def stream_through_loss(rtig: str, loss: float, count: int, rate: float, datagrams: bool) -> dict[str, Any]:
    """Runs bench/peers/lossy_stream.py in a fresh namespace losing `loss` (0 to 1) of the packets of the
    gateway's port; returns its report ({"sent", "latencies", "path"})."""
    namespace = f"hlacore-loss-{os.getpid()}"
    _ip("netns", "add", namespace)
    try:
        inside = ["ip", "netns", "exec", namespace]
        subprocess.run([*inside, "ip", "link", "set", "lo", "up"], check=True, timeout=30)
        # Each packet crosses the output hook once on loopback: drop there, in both directions of the port.
        per_thousand = round(loss * 1000)
        rules = ("table inet hlacore_loss {\n chain output {\n  type filter hook output priority 0; policy accept;\n"
                 f"  meta l4proto {{ tcp, udp }} th dport {PORT} numgen random mod 1000 < {per_thousand} drop\n"
                 f"  meta l4proto {{ tcp, udp }} th sport {PORT} numgen random mod 1000 < {per_thousand} drop\n"
                 " }\n}\n")
        subprocess.run([*inside, "nft", "-f", "-"], input=rules, text=True, check=True, capture_output=True, timeout=30)
        done = subprocess.run([*inside, sys.executable, str(PEERS / "lossy_stream.py"), rtig, str(PORT), str(count),
                               str(rate), "1" if datagrams else "0"],
                              capture_output=True, text=True, timeout=count / rate + 120)
        if done.returncode != 0:
            raise RuntimeError(f"lossy_stream.py failed ({done.returncode}): {done.stderr[-2000:]}")
        report: dict[str, Any] = json.loads(done.stdout.strip().splitlines()[-1])
        return report
    finally:
        _ip("netns", "delete", namespace)
