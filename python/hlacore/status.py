"""What a running gateway is doing: per federation, each federate's time state.

``python -m hlacore.status [HOST:PORT] [--json] [--watch SECONDS [--count N]]`` prints it as a table that fits
the terminal, redrawn in place with ``--watch`` (``rtig --status`` prints the same report as JSON). From Python: :func:`status` or :meth:`hlacore.Gateway.status`.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import shutil
import sys
import time
from typing import Any, Optional

from . import _core
from .rti import _client_settings

_NUMBERS = ("time", "lookahead", "lbts", "output_bound")


def status(address: Optional[str] = None, secret_file: Optional[str | os.PathLike[str]] = None,
           tls: Optional[bool | str | os.PathLike[str]] = None) -> dict[str, Any]:
    """The gateway's report as a dict; ``address`` as for :class:`hlacore.rti.RTIAmbassador`.

    ``{"server", "address", "tls", "connections", "federations": [{"name", "fed", "objects", "sync_points",
    "federates": [{"handle", "name", "type", "time", "lookahead", "regulating", "enabling_regulation", "constrained",
    "asynchronous_delivery", "pending": None | {"request": "TAR"|"TARA"|"NER"|"NERA"|"FQR", "time"},
    "queued_tso", "queued_ro", "regions", "lbts", "output_bound", "updates_sent", "interactions_sent",
    "grants", "backlog": {"memory", "disk"}}], "save_restore", "instances"}], "spill": {"directory", "budget",
    "used"}, "datagrams": {"port" (None: no datagrams), "max_datagram",
    "stray", "federates": [{"federation", "federate", "path", "counts": {"sent", "send_failed", "oversize",
    "received", "lost", "reordered", "duplicates", "held_back", "early"}}]}, "process": {"pid", "rss_bytes",
    "cpu_seconds"}, "fedpro": {"address", "transport", "sessions": [{"id", "federation", "federate", "state",
    "dropped_seconds", "kept_bytes", "resumes", "reason"}]}, "events": [{"sequence", "time", "kind",
    "federation", "federate", "name", "reason"}], "last_event"}``
    ("tls": whether every connection is encrypted, docs/networking.md; "type": the federate type it joined with,
    "" for an HLA 1.3 federate; "regions": how many the federate has,
    docs/ddm.md; "datagrams": best effort over UDP, docs/networking.md, sent/failed/oversize towards each
    federate and received/lost/reordered from it). On the wire infinite times are null; here they are
    ``math.inf`` (``output_bound`` is inf for a federate that is not regulating). A pending request also has
    ``"waiting"``, the seconds since it came. "backlog" is what the gateway holds for the federate in memory
    and has spilled to disk (it is not reading: paused, or slower than its publishers; docs/robustness.md),
    "spill" the spill files' directory, disk budget and use. "fedpro", only for a gateway with the HLA 4 Federate
    Protocol's door (docs/fedpro.md), lists its sessions open ("connected", or "dropped" for "dropped_seconds"
    waiting for a resume, "kept_bytes" held to send again) and the last 32 that "ended", with their "reason". "process" is the gateway's process (an in-process gateway's is
    the program that runs it); "events" is the gateway's log of its last 256 federations "created" and
    "destroyed" and federates "joined", "resigned" and "dropped" (with the reason), numbered up to
    "last_event", with their Unix "time". A gateway with a
    secret asks for it here too: ``secret_file``, else ``$HLACORE_SECRET_FILE``; a gateway with TLS needs
    ``tls`` (else ``$HLACORE_TLS``) as :class:`hlacore.rti.RTIAmbassador` takes it.
    """
    report: dict[str, Any] = json.loads(_raw_status(address, secret_file, tls))
    for federation in report["federations"]:
        for federate in federation["federates"]:
            for key in _NUMBERS:
                if federate[key] is None:
                    federate[key] = math.inf
    return report


def _raw_status(address: Optional[str], secret_file: Optional[str | os.PathLike[str]] = None,
                tls: Optional[bool | str | os.PathLike[str]] = None) -> str:
    settings = _client_settings(address=address, secret_file=secret_file, tls=tls, datagrams=False)
    return str(_core.RTIAmbassadorBase(settings)._status())


def format_table(report: dict[str, Any], width: int = 80) -> str:
    """The report as text at most ``width`` columns wide: one block per federation, one row per federate
    (R/C: regulating, constrained; TSO/RO: messages queued for it in timestamp and receive order), then who
    waits on whom (the regulating federates that may still send at or below what a federate waits for)."""
    names = [f["name"] for fed in report["federations"] for f in fed["federates"]]
    name_width = max(8, min(max(map(len, names), default=8), width - _FIXED_COLUMNS))
    encrypted = " (TLS)" if report.get("tls") else ""
    lines = [f"{report['server']} at {report['address']}{encrypted}: {report['connections']} connection(s), "
             f"{len(report['federations'])} federation(s)"]
    for fed in report["federations"]:
        points = ", ".join(fed["sync_points"]) or "none"
        lines.append(f"\nfederation {fed['name']} ({fed['fed']}, {fed.get('time_semantics', 'exact')} time): "
                     f"{len(fed['federates'])} federate(s), {fed['objects']} object(s), sync points: {points}")
        lines.append(f"  {'fed':>4} {'name':<{name_width}} {'time':>10} {'lookahd':>7} RC {'pending':<14} "
                     f"{'TSO':>5} {'RO':>5} {'LBTS':>10}")
        for f in fed["federates"]:
            pending = f"{f['pending']['request']} {_number(f['pending']['time'], 9)}" if f["pending"] else "-"
            switches = ("R" if f["regulating"] else "-") + ("C" if f["constrained"] else "-")
            lines.append(f"  {f['handle']:>4} {f['name'][:name_width]:<{name_width}} {_number(f['time'], 10):>10} "
                         f"{_number(f['lookahead'], 7):>7} {switches} {pending:<14} {f['queued_tso']:>5} "
                         f"{f['queued_ro']:>5} {_number(f['lbts'], 10):>10}")
        for f in fed["federates"]:
            for holder in f.get("held_by", []):
                lines.append(f"  {f['name']} waits on {holder['name']}: it may still send at "
                             f"{_number(holder['output_bound'], 10)}")
    lines.extend(_datagram_lines(report))
    return "\n".join(line[:width] for line in "\n".join(lines).split("\n"))


def _datagram_lines(report: dict[str, Any]) -> list[str]:
    """Best effort over UDP: the gateway's port and each federate's counts (to it / from it)."""
    datagrams = report.get("datagrams")
    if not datagrams or datagrams["port"] is None:
        return ["\ndatagrams: none (everything over TCP)"]
    names = {(fed["name"], f["handle"]): f["name"] for fed in report["federations"] for f in fed["federates"]}
    lines = [f"\ndatagrams on port {datagrams['port']} (at most {datagrams['max_datagram']} bytes; "
             f"{datagrams['stray']} stray)"]
    for f in datagrams["federates"]:
        c = f["counts"]
        who = names.get((f["federation"], f["federate"]), "?")
        to_it = (f"to it {c['sent']} sent, {c['send_failed']} failed, {c['oversize']} by TCP for size"
                 if f["path"] else "to it: TCP only")
        lines.append(f"  {f['federate']:>4} {who} ({f['federation']}): {to_it}; from it {c['received']} received, "
                     f"{c['lost']} lost, {c['reordered']} reordered, {c['held_back']} dropped held back")
    return lines


_FIXED_COLUMNS = 68  # the row's width without the name column


def _number(value: float, width: int) -> str:
    """`value` in at most `width` characters, with as many significant digits as fit."""
    for digits in range(width, 0, -1):
        text = f"{value:.{digits}g}"
        if len(text) <= width:
            return text
    return f"{value:.0e}"


def _screen(text: str, columns: int, rows: int) -> str:
    """`text` as one screenful for --watch on a terminal: clear, draw from the top, cut what does not fit."""
    lines = text.split("\n")
    if len(lines) > rows - 1:
        hidden = len(lines) - (rows - 2)
        lines = lines[: rows - 2] + [f"... {hidden} more line(s): enlarge the terminal, or use --json"[:columns]]
    return "\x1b[H\x1b[2J" + "\n".join(lines)


def main(argv: Optional[list[str]] = None) -> int:
    """Print the gateway's status (once, or every ``--watch`` seconds); returns the exit status (1 when
    the gateway cannot be asked)."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.status", description=__doc__.splitlines()[0])
    parser.add_argument("address", nargs="?",
                        help="HOST:PORT (default $HLACORE_RTIG, $CERTI_HOST:$CERTI_TCP_PORT or 127.0.0.1:60400)")
    parser.add_argument("--json", action="store_true", help="print the raw report")
    parser.add_argument("--watch", type=float, metavar="SECONDS",
                        help="repeat every SECONDS until Ctrl-C, redrawn in place on a terminal")
    parser.add_argument("--count", type=int, metavar="N", help="with --watch: stop after N reports")
    parser.add_argument("--tls", action="store_true",
                        help="TLS, the gateway's certificate verified against the system's CA store "
                             "(default $HLACORE_TLS: 1, a CA file, or none)")
    parser.add_argument("--tls-ca", metavar="FILE",
                        help="TLS, trusting the CA or self-signed certificate in FILE")
    args = parser.parse_args(argv)
    tls: Optional[bool | str] = args.tls_ca if args.tls_ca else (True if args.tls else None)
    redraw = bool(args.watch) and not args.json and sys.stdout.isatty()
    shown = 0
    try:
        while True:
            columns, rows = shutil.get_terminal_size()
            if args.json:
                text = _raw_status(args.address, tls=tls)
            else:
                text = format_table(status(args.address, tls=tls), columns if sys.stdout.isatty() else 80)
            if redraw:
                stamp = time.strftime("%H:%M:%S")
                text = _screen(f"{text}\n(every {args.watch:g} s, last {stamp}; Ctrl-C stops)", columns, rows)
            print(text, flush=True)
            shown += 1
            if not args.watch or (args.count is not None and shown >= args.count):
                return 0
            time.sleep(args.watch)
    except _core.RTIexception as e:
        print(f"hlacore.status: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 0


if __name__ == "__main__":
    sys.exit(main())
