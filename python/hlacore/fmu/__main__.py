"""``python -m hlacore.fmu MODEL.fmu``: run an FMI 2 or FMI 3 co-simulation FMU as a federate (docs/fmu.md).

A bad FMU or mapping is reported as ``error: ...`` on stderr with exit status 2, before joining; an RTI error
(a class the federation's FOM lacks: NameNotFound) or a time-out with status 1, after resigning. ``--alone``
runs the FMU by itself on an in-process gateway, its federation created from the mapping's FOM: a check of the
FMU and its mapping, and its outputs (``--csv``), before it joins others."""

from __future__ import annotations

import argparse
import contextlib
import csv
import pathlib
import sys
import tempfile
from typing import Any, Optional, Sequence

from .. import rti
from ..gateway import Gateway
from .errors import FmuError
from .federate import FmuFederate
from .mapping import Mapping
from .model import FmuModel


def _start_value(text: str) -> tuple[str, Any]:
    name, equals, value = text.partition("=")
    if not equals or not name:
        raise argparse.ArgumentTypeError(f"{text!r}: NAME=VALUE")
    lowered = value.strip().lower()
    if lowered in ("true", "false"):
        return name, lowered == "true"
    try:
        return name, int(value) if value.strip().lstrip("+-").isdigit() else float(value)
    except ValueError:
        return name, value  # a String's value (for another type, the FMU's check says which it takes)


def parser() -> argparse.ArgumentParser:
    """The command line of ``python -m hlacore.fmu``."""
    p = argparse.ArgumentParser(prog="python -m hlacore.fmu", description=__doc__.splitlines()[0])
    p.add_argument("fmu", help="the FMI 2 or FMI 3 co-simulation FMU")
    p.add_argument("--federation", default="FmuFed", help="the federation to join (default: %(default)s)")
    p.add_argument("--fed", help="create the federation from this .fed unless it exists")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--address", help="HOST:PORT of the gateway (default $HLACORE_RTIG, "
                       "$CERTI_HOST:$CERTI_TCP_PORT or 127.0.0.1:60400)")
    where.add_argument("--alone", action="store_true", help="run alone on an in-process gateway, the federation "
                       "created from the mapping's FOM (unless --fed names another)")
    p.add_argument("--name", help="the federate's name (default: the model's name)")
    p.add_argument("--mapping", help="a TOML mapping of variables to attributes (default: by name)")
    p.add_argument("--start", action="append", type=_start_value, default=[], metavar="NAME=VALUE",
                   help="a start value or parameter (repeatable)")
    p.add_argument("--step-size", type=float, help="the co-simulation step, also the lookahead without "
                   "--feedthrough (default: the model's DefaultExperiment)")
    p.add_argument("--stop-time", type=float, help="default: the model's DefaultExperiment")
    p.add_argument("--write-fom", metavar="FED", help="write the .fed of the mapping to FED and exit")
    p.add_argument("--save-dir", help="where federation saves keep the FMU's state (default: the current directory)")
    p.add_argument("--csv", metavar="PATH", help="write the outputs sent, one row per step")
    p.add_argument("--feedthrough", action=argparse.BooleanOptionalAction, default=None,
                   help="send outputs at the time of the inputs they follow, with lookahead 0 (default: when the "
                   "model description says an output depends directly on an input)")
    return p


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Run the command; its exit status."""
    args = parser().parse_args(argv)
    try:
        model = FmuModel(args.fmu)
        mapping = Mapping.load(args.mapping, model) if args.mapping else Mapping.by_name(model)
        if args.write_fom:
            pathlib.Path(args.write_fom).write_text(mapping.fed(args.federation))
            print(f"wrote {args.write_fom}")
            return 0
        experiment = model.description.defaultExperiment
        step = args.step_size or (experiment.stepSize if experiment and experiment.stepSize else None)
        stop = args.stop_time if args.stop_time is not None else (
            experiment.stopTime if experiment and experiment.stopTime else None)
        if step is None or stop is None:
            raise FmuError(f"{args.fmu}: no default experiment; give --step-size and --stop-time")
        with contextlib.ExitStack() as alone:
            address, fed = args.address, args.fed
            if args.alone:
                address = str(alone.enter_context(Gateway(port=0)).address)
                if fed is None:
                    fed = str(pathlib.Path(alone.enter_context(tempfile.TemporaryDirectory())) / "mapping.fed")
                    pathlib.Path(fed).write_text(mapping.fed(args.federation))
            with FmuFederate(args.fmu, args.federation, step_size=float(step), name=args.name, address=address,
                             fed_file=fed, mapping=mapping, start_values=dict(args.start),
                             save_dir=args.save_dir, feedthrough=args.feedthrough) as federate:
                federate.join()
                trajectory = federate.run(float(stop))
    except FmuError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    except (rti.RTIexception, TimeoutError) as error:  # NameNotFound for a class the FOM lacks, ...; resigned
        print(f"error: {type(error).__name__}: {error}", file=sys.stderr)
        return 1
    if args.csv:
        with open(args.csv, "w", newline="") as out:
            writer = csv.writer(out)
            writer.writerow(["time", *mapping.outputs])
            for time, values in trajectory:
                writer.writerow([time, *(values[name] for name in mapping.outputs)])
    print(f"{federate.name}: {len(trajectory) - 1} steps to t = {federate.time:g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
