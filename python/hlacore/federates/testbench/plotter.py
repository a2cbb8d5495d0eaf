"""The plotter: a CSV trace of every checked cycle and a trajectory PNG (robot vs reference, Fig. 8/9),
and :func:`write_outputs`, which writes both and the delay table.

The PNG needs matplotlib (the ``plot`` extra: ``pip install 'hlacore[plot]'``); without it
:func:`write_plot` returns a message saying so and writes nothing.
"""

from __future__ import annotations

import csv
import pathlib
from typing import Mapping, Optional, Sequence

from hlacore.federates.robot_driver.navigation import CELL, Scenario

from .bench import TestbenchResult
from .checker import Verdict
from .delays import SAME_CLOCK, decompose, format_table

__all__ = ["TRACE_COLUMNS", "write_trace", "write_plot", "write_outputs"]

TRACE_COLUMNS = (
    "cycle", "expected_time", "arrival", "timestamp", "ref_a", "ref_b", "robot_a", "robot_b", "x", "y",
    "heading", "commands", "value_error", "time_error", "t_cycle_emb_ms", "c_emb_de_ms", "t_cycle_de_ms",
    "d_rt_ms",
)


def _blank(value: Optional[float]) -> str:
    return "" if value is None else repr(value)


def write_trace(path: pathlib.Path, verdicts: Sequence[Verdict], reflected_at: Mapping[int, float],
                precision: float, bench_clock: tuple[float, float] = SAME_CLOCK) -> None:
    """One CSV row per verdict (columns :data:`TRACE_COLUMNS`; empty cells for a missing report);
    ``bench_clock``: the testbench's clock offset to the gateway's (:mod:`.delays`)."""
    with open(path, "w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(TRACE_COLUMNS)
        for v in sorted(verdicts, key=lambda v: v.cycle):
            r = v.report
            delays = decompose(v, reflected_at[v.cycle], bench_clock=bench_clock) if r is not None and v.cycle in reflected_at else {}
            writer.writerow([
                v.cycle, repr(v.expected_time), _blank(v.arrival), _blank(v.timestamp), v.expected[0], v.expected[1],
                "" if v.actual is None else v.actual[0], "" if v.actual is None else v.actual[1],
                "" if r is None else f"{r.pose[0]:.4f}", "" if r is None else f"{r.pose[1]:.4f}",
                "" if r is None else f"{r.pose[2]:.1f}", "" if r is None else " ".join(r.commands),
                int(v.value_error), int(v.time_error(precision)),
                *(f"{delays[k] * 1000:.3f}" if delays else "" for k in ("t_cycle^emb", "C^emb->DE", "t_cycle^DE", "d_RT")),
            ])


def write_plot(path: pathlib.Path, verdicts: Sequence[Verdict], scenario: Scenario, title: str) -> str:
    """Draw the grid, the walls, the start and goal cells, the reference path, the robot's measured
    trajectory and its value errors, each named in the legend; returns a one-line message (where it went, or
    why there is no plot)."""
    try:
        import matplotlib  # type: ignore[import-not-found, unused-ignore]

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt  # type: ignore[import-not-found, unused-ignore]
    except ImportError:
        return "no plot: matplotlib is not installed (pip install 'hlacore[plot]' or matplotlib)"
    ordered = sorted(verdicts, key=lambda v: v.cycle)
    figure, axes = plt.subplots(figsize=(5.5, 6.0))
    for i, (a, b) in enumerate(scenario.walls):
        axes.add_patch(plt.Rectangle(((a - 0.5) * CELL, (b - 0.5) * CELL), CELL, CELL, color="0.6",
                                     label="wall" if i == 0 else None))
    for cell, colour, label in ((scenario.start, "tab:green", "start"), (scenario.goal, "tab:red", "goal")):
        axes.add_patch(plt.Rectangle(((cell[0] - 0.5) * CELL, (cell[1] - 0.5) * CELL), CELL, CELL,
                                     color=colour, alpha=0.35, label=f"{label} cell"))
    axes.plot([v.expected[0] * CELL for v in ordered], [v.expected[1] * CELL for v in ordered], "o-",
              color="tab:blue", markersize=10, label="reference model")
    poses = [v.report.pose for v in ordered if v.report is not None]
    axes.plot([p[0] for p in poses], [p[1] for p in poses], "s--", color="tab:orange", markersize=5,
              label="robot (measured)")
    errors = [v for v in ordered if v.value_error and v.report is not None]
    if errors:
        axes.plot([v.report.pose[0] for v in errors if v.report], [v.report.pose[1] for v in errors if v.report],
                  "x", color="tab:red", markersize=10, label="value error")
    axes.set_xlim(-0.5 * CELL, (scenario.width - 0.5) * CELL)
    axes.set_ylim(-0.5 * CELL, (scenario.height - 0.5) * CELL)
    axes.set_xticks([i * CELL for i in range(scenario.width)], [str(i) for i in range(scenario.width)])
    axes.set_yticks([i * CELL for i in range(scenario.height)], [str(i) for i in range(scenario.height)])
    axes.set_aspect("equal")
    axes.grid(True, linewidth=0.3)
    axes.set_xlabel("first coordinate (cells of 33 cm)")
    axes.set_ylabel("second coordinate")
    axes.set_title(title)
    axes.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=3, fontsize=8)  # walls, cells, paths
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)
    return f"plot: {path}"


def write_outputs(out: pathlib.Path, result: TestbenchResult, scenario: Scenario, title: str) -> list[str]:
    """Write ``trace.csv``, ``trajectory.png`` (if matplotlib) and ``delays.md`` into ``out``; returns a
    line about each."""
    write_trace(out / "trace.csv", result.verdicts, result.reflected_at, result.precision, result.bench_clock)
    (out / "delays.md").write_text(format_table(result.delays))
    return [f"trace: {out / 'trace.csv'}", write_plot(out / "trajectory.png", result.verdicts, scenario, title),
            f"delay table: {out / 'delays.md'}"]
