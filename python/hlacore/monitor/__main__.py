"""``python -m hlacore.monitor [HOST:PORT] [--listen HOST:PORT] [--interval SECONDS]``: serve the live view of
a gateway until Ctrl-C (docs/monitor.md)."""

from __future__ import annotations

import argparse
import sys
import time
from typing import Optional

from . import DEFAULT_PORT, Monitor
from .state import HOLD_SECONDS


def listen_address(text: str) -> tuple[str, int]:
    """HOST:PORT as (host, port), for argparse."""
    host, sep, port = text.rpartition(":")
    if not sep or not host or not port.isdigit() or not 0 <= int(port) <= 65535:
        raise argparse.ArgumentTypeError(f"expected HOST:PORT, not {text!r}")
    return host, int(port)


def main(argv: Optional[list[str]] = None) -> int:
    """Serve the monitor until Ctrl-C; returns the exit status (1 when it cannot listen)."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.monitor", description=__doc__.splitlines()[0])
    parser.add_argument("address", nargs="?",
                        help="the gateway's HOST:PORT (default $HLACORE_RTIG, $CERTI_HOST:$CERTI_TCP_PORT or "
                             "127.0.0.1:60400)")
    parser.add_argument("--listen", type=listen_address, default=("127.0.0.1", DEFAULT_PORT), metavar="HOST:PORT",
                        help=f"where to serve the page (default 127.0.0.1:{DEFAULT_PORT}; port 0 picks one)")
    parser.add_argument("--interval", type=float, default=0.5, metavar="SECONDS",
                        help="seconds between two status queries, 0.05 to 1 (default 0.5)")
    parser.add_argument("--hold", type=float, default=HOLD_SECONDS, metavar="SECONDS",
                        help="how long a time advance request waits before its federate counts as held back "
                             f"(default {HOLD_SECONDS:g})")
    parser.add_argument("--secret-file", metavar="FILE", help="the gateway's shared secret (default "
                                                              "$HLACORE_SECRET_FILE)")
    parser.add_argument("--tls-ca", metavar="FILE", help="TLS, trusting the CA or certificate in FILE")
    args = parser.parse_args(argv)
    host, port = args.listen
    try:
        monitor = Monitor(args.address, host=host, port=port, interval=args.interval, hold_seconds=args.hold,
                          secret_file=args.secret_file, tls=args.tls_ca)
    except ValueError as e:
        parser.error(str(e))
    try:
        monitor.start()
    except OSError as e:
        print(f"hlacore.monitor: cannot serve on {host}:{port}: {e}", file=sys.stderr)
        return 1
    print(f"hlacore.monitor: {monitor.url} shows the gateway at {monitor.gateway_host}:{monitor.gateway_port} "
          "(Ctrl-C stops)", flush=True)
    try:
        while True:
            time.sleep(1.0)
    except KeyboardInterrupt:
        pass
    finally:
        monitor.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
