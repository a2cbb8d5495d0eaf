"""The recorder federate: record a federation of a gateway you do not run (docs/record-replay.md).

    python -m hlacore.record HOST:PORT FEDERATION FILE [--name NAME] [--until-alone]

joins ``FEDERATION`` as ``NAME`` (default ``hlacore-recorder``) and asks the gateway for the federation's
recording (:meth:`hlacore.rti.RTIAmbassador.start_recording`): the same records ``rtig --record`` writes,
from the FOM and the federates joined so far on. It neither subscribes nor manages time, so the federation
runs as it would without it: a subscription would change the relevance advice the publishers get, and no
subscription would show the others' time advance requests, which the gateway's recording has. It prints
``recording FEDERATION into FILE`` once recording, and stops on Ctrl-C or SIGTERM, or with ``--until-alone``
once it is the federation's last federate; then it closes the file and resigns. Exit status 0, or 2 with a
message (the federation does not exist, the file cannot be written).
"""

from __future__ import annotations

import argparse
import json
import signal
import sys
import time
from types import FrameType
from typing import Optional, Sequence

from hlacore import rti

__all__ = ["main"]


def _others_joined(rtia: rti.RTIAmbassador, federation: str, name: str) -> int:
    report = json.loads(rtia._status())
    for entry in report["federations"]:
        if entry["name"] == federation:
            return sum(1 for f in entry["federates"] if f["name"] != name)
    return 0


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command line; returns the exit status."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.record", description=__doc__.splitlines()[0])
    parser.add_argument("address", metavar="HOST:PORT", help="the gateway")
    parser.add_argument("federation", help="the federation to record (it must exist)")
    parser.add_argument("file", help="the MCAP file to write")
    parser.add_argument("--name", default="hlacore-recorder", help="the recorder's federate name")
    parser.add_argument("--until-alone", action="store_true",
                        help="stop once every other federate has left (checked twice a second)")
    args = parser.parse_args(argv)

    def terminate(signum: int, frame: Optional[FrameType]) -> None:
        raise KeyboardInterrupt

    signal.signal(signal.SIGTERM, terminate)
    try:
        rtia = rti.RTIAmbassador(args.address)
        rtia.joinFederationExecution(args.name, args.federation, rti.FederateAmbassador())
        rtia.start_recording(args.file)
    except (rti.RTIexception, RuntimeError, OSError) as e:
        print(f"record: {type(e).__name__}: {e}", file=sys.stderr)
        return 2
    print(f"recording {args.federation} into {args.file}", flush=True)
    seen_others = False
    try:
        next_check = time.monotonic()
        while True:
            rtia.tick(0.1, 0.1)
            if args.until_alone and time.monotonic() >= next_check:
                next_check = time.monotonic() + 0.5
                others = _others_joined(rtia, args.federation, args.name)
                seen_others |= others > 0
                if seen_others and others == 0:
                    break
    except KeyboardInterrupt:
        pass
    status = 0
    try:
        count = rtia.stop_recording()
        print(f"recorded {count} events into {args.file}", flush=True)
    except RuntimeError as e:
        print(f"record: the recording is incomplete: {e}", file=sys.stderr)
        status = 2
    try:
        rtia.resignFederationExecution(rti.ResignAction.NoAction)
    except rti.RTIexception as e:
        print(f"record: resigning failed: {e}", file=sys.stderr)
    return status


if __name__ == "__main__":
    sys.exit(main())
