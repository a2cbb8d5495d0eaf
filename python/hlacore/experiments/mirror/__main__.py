"""``python -m hlacore.experiments.mirror [OUTDIR] [--defective-wheel [F]] [--corrected] [--mirror-from
commands|odometry] [--cycles N] [--rtig HOST:PORT]``: paper 2 §6.2 in one command (docs/mirror.md).

Without ``--rtig`` it runs an in-process gateway; without a ROS master at ``$ROS_MASTER_URI`` it starts
``roscore`` on a free loopback port and stops it by pid at the end. Writes ``mirror-trace.csv`` and
``mirror-trajectories.png`` (with matplotlib) into OUTDIR (default ``mirror-out``), prints progress, the
figures, the checks of the set-up (ok/FAIL), a one-line verdict on the real robot and one JSON summary line
last. Exits 1 when a check of the set-up fails; the real robot's divergence is the finding, not a failure (a
defective wheel is meant to diverge).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import pathlib
from typing import Any, Optional, Sequence

import hlacore
from hlacore.federates.ros_bridge.master import ros_master

from ..cli import run_command
from .outputs import plot, write_trace
from .run import run


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command (see the module docstring)."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.experiments.mirror")
    parser.add_argument("outdir", nargs="?", default="mirror-out")
    parser.add_argument("--rtig", default=None, help="gateway HOST:PORT (default: an in-process gateway)")
    parser.add_argument("--defective-wheel", nargs="?", type=float, const=0.05, default=0.0,
                        help="the real robot's right wheel loses this fraction of its speed (alone: 0.05)")
    parser.add_argument("--corrected", action="store_true", help="the control that corrects its pose each cycle")
    parser.add_argument("--mirror-from", default="commands", choices=("commands", "odometry"))
    parser.add_argument("--cycles", type=int, default=50, help="control cycles of 0.5 s")
    args = parser.parse_args(argv)
    return run_command("python -m hlacore.experiments.mirror", lambda: _run(args))


def _run(args: argparse.Namespace) -> int:
    with contextlib.ExitStack() as stack:
        print(f"ROS master at {stack.enter_context(ros_master())}", flush=True)
        address = args.rtig or str(stack.enter_context(hlacore.Gateway(port=0)).address)
        print(f"gateway at {address}; {args.cycles} control cycles of 0.5 s (a few seconds of wall time) ...",
              flush=True)
        result = run(address, args.corrected, args.defective_wheel, args.cycles, args.mirror_from)
    out = pathlib.Path(args.outdir)
    out.mkdir(parents=True, exist_ok=True)
    print(f"wrote {write_trace(result, out / 'mirror-trace.csv')}")
    try:
        print(f"wrote {plot(result, out / 'mirror-trajectories.png')}")
    except ImportError as exc:
        print(f"no trajectory plot: {exc}")
    summary = result.summary()
    for who in ("real", "mirror", "rosbot"):
        f = summary[who]
        print(f"{who:7s} {f['vs_reference']:.3f} m from the reference path, {f['box_clearance']:.3f} m from the box, "
              f"ends at ({f['end'][0]:.2f}, {f['end'][1]:.2f}), avoidances {f.get('avoidances', '-')}")
    results = checks(summary)
    for name, passed in results.items():
        print(f"{'ok  ' if passed else 'FAIL'} {name}")
    print(verdict(summary))
    print(json.dumps(summary), flush=True)
    return 0 if all(results.values()) else 1


def checks(summary: dict[str, Any]) -> dict[str, bool]:
    """What must hold for the run to say anything about the real robot, whatever its wheels do."""
    out = {
        "the lockstep never stalled": not any(summary["stall_steps"].values()),
        "the ROS robot drove around its box": bool(summary["rosbot"]["passed_box"]),
    }
    if summary["mirror_from"] == "odometry":
        out["the mirror follows the real robot's odometry"] = summary["mirror"]["vs_real"] < 0.05
    return out


def verdict(summary: dict[str, Any]) -> str:
    """The finding in one line: does the real robot behave like the reference model?"""
    real = summary["real"]
    clearance = real["box_clearance"]
    if clearance < 0:
        box = f"drove into the box (its centre {-clearance:.3f} m inside)"
    elif real["touched_box"]:
        box = f"touched the box (its centre {clearance:.3f} m from it, less than its half diagonal)"
    else:
        box = f"cleared the box (its centre {clearance:.3f} m from it)"
    if real["vs_reference"] < 0.05 and not real["touched_box"]:
        return f"verdict: the real robot behaves like the reference model ({real['vs_reference']:.3f} m apart); it {box}"
    return f"verdict: the real robot departs from the reference model by {real['vs_reference']:.3f} m; it {box}"


if __name__ == "__main__":
    raise SystemExit(main())
