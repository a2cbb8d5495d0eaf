"""The delay decomposition of the paper's Table 1, from wall-clock marks of the robot, the gateway and the
testbench.

Per cycle, from marks on three clocks: the robot's and the testbench's ``time.monotonic()`` and the
gateway's (its message trace, :mod:`hlacore.trace`; the three rows that need it are left out without one).
Each federate measures its offset to the gateway's clock (``RTIAmbassador.clock_offset``; the robot sends
its own in every report), so every mark is put on the gateway's clock first, and a row whose two marks
come from different processes carries the sum of their offsets' uncertainties (the ``± clock`` column):
they may be on different hosts.

=====================  =====================================================================================
row                    what
=====================  =====================================================================================
``t_cycle^emb``        the robot's control cycle: sense, decide, command the device, publish
``C_RTI^emb``          from the robot's ``updateAttributeValues`` to the gateway reading it
``t_cycle^RTI``        from the gateway reading the update to its writing the reflection to the testbench's
                       socket (a timestamp-ordered one waits there until the testbench's grant allows it)
``C_PT^RTI``           from that write to the reflection callback in the testbench
``C^emb->DE``          from the robot's ``updateAttributeValues`` to the reflection callback: the sum of the
                       three rows above
``t_cycle^DE``         from the reflection to the checker's verdict: the DE side's cycle (waiting for its
                       grant, firing the model)
``d_RT``               from the end of the robot's action to the verdict: ``t_obs - t_action``
=====================  =====================================================================================
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable, Mapping, Optional, Sequence

from hlacore.trace import Hop

from .checker import Verdict

__all__ = ["ROWS", "SAME_CLOCK", "Stats", "cycle_hops", "decompose", "delay_table", "format_table"]

ROWS = ("t_cycle^emb", "C_RTI^emb", "t_cycle^RTI", "C_PT^RTI", "C^emb->DE", "t_cycle^DE", "d_RT")

#: A process's clock offset to the gateway, ``(offset, uncertainty)`` in seconds as
#: ``RTIAmbassador.clock_offset`` gives it: none.
SAME_CLOCK: tuple[float, float] = (0.0, 0.0)

# The processes other than the gateway whose clocks a row's two marks are read from.
_CLOCKS = {"t_cycle^emb": (), "C_RTI^emb": ("robot",), "t_cycle^RTI": (), "C_PT^RTI": ("bench",),
           "C^emb->DE": ("robot", "bench"), "t_cycle^DE": (), "d_RT": ("robot", "bench")}


@dataclass(frozen=True)
class Stats:
    """Mean, max, min and (population) standard deviation in milliseconds over ``count`` samples;
    ``clock``: the largest clock uncertainty (ms) among them, that each sample may be off by."""

    mean: float
    max: float
    min: float
    std: float
    count: int
    clock: float = 0.0

    @classmethod
    def of(cls, samples_s: Sequence[float], clock_s: float = 0.0) -> "Stats":
        """Statistics of ``samples_s`` (seconds), in ms; NaN when there is none."""
        if not samples_s:
            nan = math.nan
            return cls(nan, nan, nan, nan, 0)
        ms = [s * 1000.0 for s in samples_s]
        mean = sum(ms) / len(ms)
        std = math.sqrt(sum((m - mean) ** 2 for m in ms) / len(ms))
        return cls(mean, max(ms), min(ms), std, len(ms), clock_s * 1000.0)


def decompose(verdict: Verdict, reflected_at: float, hop: Optional[Hop] = None,
              bench_clock: tuple[float, float] = SAME_CLOCK) -> dict[str, float]:
    """The delays (seconds) of one checked cycle whose reflection came at the testbench's time
    ``reflected_at``; with the gateway's ``hop`` of its report, the communication split in three.
    ``bench_clock``: the testbench's offset to the gateway (the robot's is in its report)."""
    report = verdict.report
    if report is None:
        raise ValueError(f"cycle {verdict.cycle} has no report")
    # Every mark on the gateway's clock.
    sent, acted = report.t_send + report.clock_offset, report.t_action + report.clock_offset
    reflected, observed = reflected_at + bench_clock[0], verdict.observed + bench_clock[0]
    delays = {
        "t_cycle^emb": report.t_cycle,
        "C^emb->DE": reflected - sent,
        "t_cycle^DE": observed - reflected,
        "d_RT": observed - acted,
    }
    if hop is not None:
        delays["C_RTI^emb"] = hop.received - sent
        delays["t_cycle^RTI"] = hop.forwarded - hop.received
        delays["C_PT^RTI"] = reflected - hop.forwarded
    return delays


def delay_table(
    verdicts: Iterable[Verdict], reflected_at: Mapping[int, float], hops: Optional[Mapping[int, Hop]] = None,
    bench_clock: tuple[float, float] = SAME_CLOCK,
) -> dict[str, Stats]:
    """Table 1 over the cycles that have a report and a reflection time; ``hops``: the gateway's marks of
    each cycle's report (:func:`cycle_hops`), without which the split rows have no sample;
    ``bench_clock``: the testbench's offset to the gateway's clock."""
    samples: dict[str, list[float]] = {row: [] for row in ROWS}
    clock: dict[str, float] = {row: 0.0 for row in ROWS}
    for verdict in verdicts:
        if verdict.report is None or verdict.cycle not in reflected_at:
            continue
        hop = hops.get(verdict.cycle) if hops is not None else None
        uncertainty = {"robot": verdict.report.clock_uncertainty, "bench": bench_clock[1]}
        for row, value in decompose(verdict, reflected_at[verdict.cycle], hop, bench_clock).items():
            samples[row].append(value)
            clock[row] = max(clock[row], sum(uncertainty[p] for p in _CLOCKS[row]))
    return {row: Stats.of(values, clock[row]) for row, values in samples.items()}


def cycle_hops(hops: Sequence[Hop]) -> dict[int, Hop]:
    """The robot's reports by cycle: it sends exactly one update per cycle, from cycle 0, so its k-th
    message through the gateway is cycle k's report."""
    return dict(enumerate(hops))


def format_table(table: Mapping[str, Stats]) -> str:
    """Table 1's form as a Markdown table (ms), with each row's clock uncertainty; rows without samples are
    left out."""
    count = max((s.count for s in table.values()), default=0)
    lines = [f"| delay ({count} cycles, ms) | mean | max | min | std | ± clock |", "|---|---:|---:|---:|---:|---:|"]
    for row, s in table.items():
        if s.count == 0:
            continue
        lines.append(f"| {row} | {s.mean:.3f} | {s.max:.3f} | {s.min:.3f} | {s.std:.3f} | {s.clock:.3f} |")
    return "\n".join(lines) + "\n"
