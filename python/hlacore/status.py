"""What a running gateway is doing: per federation, each federate's time state.

``python -m hlacore.status [HOST:PORT] [--json] [--watch SECONDS]`` prints it as a table (``rtig --status``
prints the same report as JSON). From Python: :func:`status` or :meth:`hlacore.Gateway.status`.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from typing import Any, Optional

from . import _core
from .rti import _resolve_address

_NUMBERS = ("time", "lookahead", "lbts", "output_bound")


def status(address: Optional[str] = None) -> dict[str, Any]:
    """The gateway's report as a dict; ``address`` as for :class:`hlacore.rti.RTIAmbassador`.

    ``{"server", "address", "connections", "federations": [{"name", "fed", "objects", "sync_points",
    "federates": [{"handle", "name", "time", "lookahead", "regulating", "enabling_regulation", "constrained",
    "asynchronous_delivery", "pending": None | {"request": "TAR"|"TARA"|"NER"|"NERA"|"FQR", "time"},
    "queued_tso", "queued_ro", "regions", "lbts", "output_bound"}]}]}`` ("regions": how many the federate
    has, docs/ddm.md). On the wire infinite times are null; here
    they are ``math.inf`` (``output_bound`` is inf for a federate that is not regulating).
    """
    report: dict[str, Any] = json.loads(_raw_status(address))
    for federation in report["federations"]:
        for federate in federation["federates"]:
            for key in _NUMBERS:
                if federate[key] is None:
                    federate[key] = math.inf
    return report


def _raw_status(address: Optional[str]) -> str:
    host, port = _resolve_address(address)
    return str(_core.RTIAmbassadorBase(host, port)._status())


def format_table(report: dict[str, Any]) -> str:
    """The report as text: one block per federation, one row per federate."""
    lines = [f"{report['server']} at {report['address']}: {report['connections']} connection(s), "
             f"{len(report['federations'])} federation(s)"]
    for fed in report["federations"]:
        points = ", ".join(fed["sync_points"]) or "none"
        lines.append(f"\nfederation {fed['name']} ({fed['fed']}): {len(fed['federates'])} federate(s), "
                     f"{fed['objects']} object(s), sync points: {points}")
        lines.append(f"  {'handle':>6} {'name':<16} {'time':>12} {'lookahead':>9} {'R':>1} {'C':>1} "
                     f"{'pending':<16} {'TSO':>5} {'RO':>5} {'LBTS':>12}")
        for f in fed["federates"]:
            pending = f"{f['pending']['request']}({f['pending']['time']:g})" if f["pending"] else "-"
            lines.append(f"  {f['handle']:>6} {f['name'][:16]:<16} {f['time']:>12g} {f['lookahead']:>9g} "
                         f"{'R' if f['regulating'] else '-':>1} {'C' if f['constrained'] else '-':>1} "
                         f"{pending:<16} {f['queued_tso']:>5} {f['queued_ro']:>5} {f['lbts']:>12g}")
    return "\n".join(lines)


def main(argv: Optional[list[str]] = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m hlacore.status", description=__doc__.splitlines()[0])
    parser.add_argument("address", nargs="?", help="HOST:PORT (default $HLACORE_RTIG or 127.0.0.1:60400)")
    parser.add_argument("--json", action="store_true", help="print the raw report")
    parser.add_argument("--watch", type=float, metavar="SECONDS", help="repeat every SECONDS until Ctrl-C")
    args = parser.parse_args(argv)
    try:
        while True:
            print(_raw_status(args.address) if args.json else format_table(status(args.address)), flush=True)
            if not args.watch:
                return 0
            time.sleep(args.watch)
    except _core.RTIexception as e:
        print(f"hlacore.status: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 0


if __name__ == "__main__":
    sys.exit(main())
