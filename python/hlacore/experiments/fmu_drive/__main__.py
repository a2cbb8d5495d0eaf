"""``python -m hlacore.experiments.fmu_drive [OUTDIR] [--rtig HOST:PORT] [--steps N]``: a waypoint controller
FMU drives a robot of the pymunk world through the federation (docs/fmu.md, "An FMU in the loop").

Without ``--rtig`` it runs an in-process gateway. Compiles the controller FMU (a C compiler and FMPy: ``pip
install hlacore[fmu]``) into OUTDIR/fmu (default OUTDIR: ``fmu-drive-out``), runs it against the world
federate, then the same loop without HLA with the federation's delays and with none; writes
``fmu-drive-trace.csv`` and ``fmu-drive.png`` (with matplotlib), prints the checks (ok/FAIL) and one JSON
summary line last. Exits 1 when a check fails.
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import json
import pathlib
from typing import Any, Optional, Sequence

import hlacore
from hlacore.federates.robot_world import World, plot_trajectories

from ..cli import run_command
from .run import IDEAL, ROBOT, STEP, WAYPOINTS, Result, run, world_spec

#: The federated path equals the same loop's without HLA to this distance (m): the federation adds no error.
SAME = 1e-9


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command (see the module docstring)."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.experiments.fmu_drive")
    parser.add_argument("outdir", nargs="?", default="fmu-drive-out")
    parser.add_argument("--rtig", default=None, help="gateway HOST:PORT (default: an in-process gateway)")
    parser.add_argument("--steps", type=int, default=300, help=f"steps of {STEP} s (default: %(default)s)")
    args = parser.parse_args(argv)
    return run_command("python -m hlacore.experiments.fmu_drive", lambda: _run(args))


def _run(args: argparse.Namespace) -> int:
    out = pathlib.Path(args.outdir)
    with contextlib.ExitStack() as stack:
        address = args.rtig or str(stack.enter_context(hlacore.Gateway(port=0)).address)
        print(f"gateway at {address}; {args.steps} steps of {STEP} s ...", flush=True)
        result = run(address, args.steps, out / "fmu")
    print(f"wrote {write_trace(result, out / 'fmu-drive-trace.csv')}")
    try:
        print(f"wrote {plot(result, out / 'fmu-drive.png')}")
    except ImportError as exc:
        print(f"no plot: {exc}")
    summary = result.summary()
    for i, (when, ideal) in enumerate(zip(summary["reached"], summary["ideal_reached"])):
        print(f"waypoint {i + 1} {WAYPOINTS[i]}: reached at {_seconds(when)} (without delay: {_seconds(ideal)})")
    print(f"the federated path is {summary['vs_same_loop']:.3g} m from the same loop without HLA and "
          f"{summary['vs_ideal']:.3f} m at most from the loop without delay")
    results = checks(summary)
    for name, passed in results.items():
        print(f"{'ok  ' if passed else 'FAIL'} {name}")
    print(json.dumps(summary), flush=True)
    return 0 if all(results.values()) else 1


def _seconds(when: Optional[float]) -> str:
    return "never" if when is None else f"{when:.1f} s"


def checks(summary: dict[str, Any]) -> dict[str, bool]:
    """What the run must show."""
    return {
        "the robot reached every waypoint in order": None not in summary["reached"],
        "the federation added nothing: the same path as the loop without HLA": summary["vs_same_loop"] <= SAME,
        "the robot never touched the box": not summary["stalled"],
    }


def write_trace(result: Result, path: pathlib.Path) -> pathlib.Path:
    """One row per step: the time, the federated robot's pose, the command the FMU computed in the step from
    that time (the world applies it from the next), and the pose of the loop without delay."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fed, ideal = result.federated, result.ideal
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["time", "x", "y", "theta", "v", "w", "ideal_x", "ideal_y", "ideal_theta"])
        for i, (time, pose) in enumerate(zip(fed.times, fed.poses)):
            v, w = fed.commands[i] if i < len(fed.commands) else ("", "")
            other = ideal.poses[i]
            writer.writerow([repr(time), repr(pose.x), repr(pose.y), repr(pose.theta), repr(v), repr(w),
                             repr(other.x), repr(other.y), repr(other.theta)])
    return path


def plot(result: Result, path: pathlib.Path) -> pathlib.Path:
    """The robot's federated path and the loop's without delay over the world, with the waypoints (matplotlib;
    ImportError without it)."""
    poses = [{ROBOT: a, IDEAL: b} for a, b in zip(result.federated.poses, result.ideal.poses)]
    return plot_trajectories(World(world_spec(IDEAL)), poses, path, marks={"waypoints": WAYPOINTS},
                             title=f"a controller FMU in the loop of the robot world (steps of {STEP:g} s)")


if __name__ == "__main__":
    raise SystemExit(main())
