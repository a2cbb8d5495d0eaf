"""The delay decomposition of the paper's Table 1, from wall-clock marks of the robot and the testbench.

Per cycle (all ``time.monotonic()``, one clock for every process on a host):

=====================  =====================================================================================
row                    what
=====================  =====================================================================================
``t_cycle^emb``        the robot's control cycle: sense, decide, command the device, publish
``C^emb->DE``          from the robot's ``updateAttributeValues`` to the reflection callback in the
                       testbench: the paper's ``C_RTI^emb + t_cycle^RTI + C_PT^RTI``, which the gateway does
                       not let us split
``t_cycle^DE``         from the reflection to the checker's verdict: the DE side's cycle (waiting for its
                       grant, firing the model)
``d_RT``               from the end of the robot's action to the verdict: ``t_obs - t_action``
=====================  =====================================================================================
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable, Mapping, Sequence

from .checker import Verdict

__all__ = ["ROWS", "Stats", "decompose", "delay_table", "format_table"]

ROWS = ("t_cycle^emb", "C^emb->DE", "t_cycle^DE", "d_RT")


@dataclass(frozen=True)
class Stats:
    """Mean, max, min and (population) standard deviation in milliseconds over ``count`` samples."""

    mean: float
    max: float
    min: float
    std: float
    count: int

    @classmethod
    def of(cls, samples_s: Sequence[float]) -> "Stats":
        """Statistics of ``samples_s`` (seconds), in ms; NaN when there is none."""
        if not samples_s:
            nan = math.nan
            return cls(nan, nan, nan, nan, 0)
        ms = [s * 1000.0 for s in samples_s]
        mean = sum(ms) / len(ms)
        std = math.sqrt(sum((m - mean) ** 2 for m in ms) / len(ms))
        return cls(mean, max(ms), min(ms), std, len(ms))


def decompose(verdict: Verdict, reflected_at: float) -> dict[str, float]:
    """The four delays (seconds) of one checked cycle whose reflection came at wall time ``reflected_at``."""
    report = verdict.report
    if report is None:
        raise ValueError(f"cycle {verdict.cycle} has no report")
    return {
        "t_cycle^emb": report.t_cycle,
        "C^emb->DE": reflected_at - report.t_send,
        "t_cycle^DE": verdict.observed - reflected_at,
        "d_RT": verdict.observed - report.t_action,
    }


def delay_table(verdicts: Iterable[Verdict], reflected_at: Mapping[int, float]) -> dict[str, Stats]:
    """Table 1 over the cycles that have a report and a reflection time."""
    samples: dict[str, list[float]] = {row: [] for row in ROWS}
    for verdict in verdicts:
        if verdict.report is None or verdict.cycle not in reflected_at:
            continue
        for row, value in decompose(verdict, reflected_at[verdict.cycle]).items():
            samples[row].append(value)
    return {row: Stats.of(values) for row, values in samples.items()}


def format_table(table: Mapping[str, Stats]) -> str:
    """Table 1's form as a Markdown table (ms)."""
    count = max((s.count for s in table.values()), default=0)
    lines = [f"| delay ({count} cycles, ms) | mean | max | min | std |", "|---|---:|---:|---:|---:|"]
    for row, s in table.items():
        lines.append(f"| {row} | {s.mean:.3f} | {s.max:.3f} | {s.min:.3f} | {s.std:.3f} |")
    return "\n".join(lines) + "\n"
