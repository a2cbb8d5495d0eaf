"""A run's files: the CSV trace (one row per control cycle) and the PNG of the four trajectories."""

from __future__ import annotations

import csv
import pathlib
from typing import Any

from .run import PERIOD, Result
from .scenario import BOX_SIZE, BOX_X, LANES, MIRROR, ROSBOT

COLOURS = {"reference": "tab:blue", "real": "tab:green", "mirror": "tab:red", "rosbot": "tab:purple"}
LABELS = {"reference": "reference (ideal controller)", "real": "real robot (odometry)",
          "mirror": "mirror (world robot)", "rosbot": "ROS robot (own lane)"}


def write_trace(result: Result, path: pathlib.Path) -> pathlib.Path:
    """One row per control cycle: time, the reference's, the real robot's, the mirror's and the ROS robot's
    poses at that time, the sonar's front range, the command, what the mirror was sent and the mode."""
    by_grant = {round(t / PERIOD): poses for t, poses in result.world}
    reference = {round(t / result.cycle): p for t, p in result.reference}
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["time"] + [f"{w}_{c}" for w in ("reference", "real", "mirror", "rosbot") for c in "xyt"]
                        + ["front", "linear", "angular", "mirror_linear", "mirror_angular", "mode", "avoidances"])
        for r in result.real:
            poses = by_grant.get(round(r["time"] / PERIOD), {})
            row: list[Any] = [repr(r["time"])]
            row += [repr(v) for v in reference.get(r["cycle"], ("", "", ""))]
            row += [repr(v) for v in r["pose"]]
            for name in (MIRROR, ROSBOT):
                p = poses.get(name)
                row += ["", "", ""] if p is None else [repr(p.x), repr(p.y), repr(p.theta)]
            row += [repr(r["front"]), *map(repr, r["command"]), *map(repr, r["mirrored"]), r["mode"], r["avoidances"]]
            writer.writerow(row)
    return path


def plot(result: Result, path: pathlib.Path) -> pathlib.Path:
    """The four trajectories in world coordinates, with the boxes, all named in the legend (matplotlib;
    ImportError without it)."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.patches import Rectangle
    except ImportError:
        raise ImportError("plotting trajectories needs matplotlib: pip install matplotlib") from None
    fig, ax = plt.subplots(figsize=(9, 6.5))
    for i, lane in enumerate(sorted(set(LANES[n] for n in (MIRROR, ROSBOT)))):
        ax.add_patch(Rectangle((BOX_X - BOX_SIZE / 2, lane - BOX_SIZE / 2), BOX_SIZE, BOX_SIZE, color="black",
                               label=f"box ({BOX_SIZE:g} m)" if i == 0 else None))
    for who in ("reference", "real", "mirror"):
        xs, ys = zip(*result.path(who))
        ax.plot(xs, ys, color=COLOURS[who], label=LABELS[who], lw=2 if who == "real" else 1.5,
                ls="--" if who == "reference" else "-", zorder=3 if who == "reference" else 2)
    xs, ys = zip(*((poses[ROSBOT].x, poses[ROSBOT].y) for _, poses in result.world))
    ax.plot(xs, ys, color=COLOURS["rosbot"], label=LABELS["rosbot"])
    kind = ("corrected control" if result.corrected else "open-loop control") + (
        f", defective wheel {result.defective_wheel:.0%}" if result.defective_wheel else ", calibrated")
    ax.set_title(f"paper 2 §6.2: {kind}; mirror repeats the {result.mirror_from}")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_aspect("equal")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
