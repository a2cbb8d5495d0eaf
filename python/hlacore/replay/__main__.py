"""``python -m hlacore.replay``: replay federates from a recording, or compare two recordings.

    python -m hlacore.replay FILE --as NAME [--as NAME]... [--rtig HOST:PORT] [--federation NAME]
                             [--speed X] [--timeout S]
    python -m hlacore.replay diff A B [--ignore MEMBER]...

Exit status: 0 done (diff: the recordings agree), 1 diff: they differ, 2 an error (a damaged recording, a
federate that cannot be replayed, a replay that did not go as recorded).
"""

from __future__ import annotations

import argparse
import sys
import threading
from typing import Optional, Sequence

from hlacore.recording import RecordingError, read

from . import ReplayError, Replayer, script
from .diff import compare


def _diff(argv: Sequence[str]) -> int:
    parser = argparse.ArgumentParser(prog="python -m hlacore.replay diff",
                                     description="Report the first divergence between two recordings.")
    parser.add_argument("a", help="a recording (MCAP)")
    parser.add_argument("b", help="the recording to compare it with")
    parser.add_argument("--ignore", action="append", default=[], metavar="MEMBER",
                        help="in values that are JSON objects, leave out members of this name (repeatable)")
    args = parser.parse_args(argv)
    try:
        result = compare(args.a, args.b, args.ignore)
    except (RecordingError, OSError) as e:
        print(f"replay diff: {e}", file=sys.stderr)
        return 2
    if result.first is not None:
        print(result.first.describe(args.a, args.b))
    else:
        print("the recordings agree")
    print(result.summary())
    return 0 if result.same else 1


def _replay(argv: Sequence[str]) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m hlacore.replay",
        description="Join as recorded federates and do again what they did (docs/record-replay.md); "
                    "'python -m hlacore.replay diff A B' compares two recordings.")
    parser.add_argument("recording", help="a recording (rtig --record, Gateway(record=...), python -m hlacore.record)")
    parser.add_argument("--as", dest="federates", action="append", required=True, metavar="NAME",
                        help="a federate of the recording to replay (repeatable: each in its own thread)")
    parser.add_argument("--rtig", default=None, metavar="HOST:PORT",
                        help="the gateway (default: as RTIAmbassador finds it, $HLACORE_RTIG or 127.0.0.1:60400)")
    parser.add_argument("--federation", default=None,
                        help="the federation to join (default: the recorded one)")
    parser.add_argument("--speed", type=float, default=None,
                        help="keep the recorded wall-clock pace divided by this (for untimed federations)")
    parser.add_argument("--timeout", type=float, default=60.0,
                        help="seconds to wait for an expected callback (default 60)")
    args = parser.parse_args(argv)
    try:
        events = list(read(args.recording))
        replayers = [Replayer(script(events, name, args.federation), args.rtig, args.speed, args.timeout)
                     for name in args.federates]
    except (RecordingError, ReplayError, OSError, ValueError) as e:
        print(f"replay: {e}", file=sys.stderr)
        return 2
    errors: list[Optional[BaseException]] = [None] * len(replayers)

    def run(i: int) -> None:
        try:
            replayers[i].run()
        except BaseException as e:  # reported below, with the federate's name
            errors[i] = e

    threads = [threading.Thread(target=run, args=(i,), name=f"replay {r.script.federate}", daemon=True)
               for i, r in enumerate(replayers)]
    for t in threads:
        t.start()
    try:
        for t in threads:
            while t.is_alive():
                t.join(0.2)
    except KeyboardInterrupt:
        print("replay: interrupted", file=sys.stderr)
        return 130
    status = 0
    for replayer, error in zip(replayers, errors):
        name = replayer.script.federate
        if error is None:
            print(f"replay: {name!r}: {replayer.done} steps replayed")
        else:
            print(f"replay: {name!r}: {type(error).__name__}: {error} (after {replayer.done} of "
                  f"{len(replayer.script.steps)} steps)", file=sys.stderr)
            status = 2
    return status


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command line; returns the exit status."""
    args = list(sys.argv[1:] if argv is None else argv)
    if args and args[0] == "diff":
        return _diff(args[1:])
    return _replay(args)


if __name__ == "__main__":
    sys.exit(main())
