"""The PNG of grant latency against federate count (matplotlib, no display needed)."""

from __future__ import annotations

import pathlib
import statistics

import matplotlib

matplotlib.use("Agg")  # files only: the bench runs without a display
import matplotlib.pyplot as plt  # noqa: E402

from .report import FEDERATES, Report, p99  # noqa: E402

# Medians of the reference RTIs on the same kind of machine (measured 2026-11-23 with C++ federates in the
# same loop, as report.ANCHORS; not re-measured by a run).
ANCHORS_US = {"OpenRTI 0.10": {2: 151, 4: 563, 8: 1631}, "CERTI 3.5.1": {2: 398, 4: 975, 8: 3617}}


def grant_latency_png(report: Report, path: pathlib.Path) -> bool:
    """Write the plot; False (nothing written) when no lockstep figure was measured."""
    ks = [k for k in FEDERATES if report.samples.get(f"grant.rtig.{k}")]
    if not ks:
        return False
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=110)
    medians = [statistics.median(report.samples[f"grant.rtig.{k}"]) * 1e6 for k in ks]
    p99s = [p99(report.samples[f"grant.rtig.{k}"]) * 1e6 for k in ks]
    ax.plot(ks, medians, "o-", color="tab:blue", label="hlacore rtig, with updates, median")
    ax.plot(ks, p99s, "o--", color="tab:blue", alpha=0.5, label="hlacore rtig, with updates, p99")
    pure = [k for k in FEDERATES if report.samples.get(f"grant.pure.{k}")]
    if pure:
        ax.plot(pure, [statistics.median(report.samples[f"grant.pure.{k}"]) * 1e6 for k in pure], "D-",
                color="tab:purple", label="hlacore rtig, TAR→TAG only, median")
    inprocess = report.samples.get("grant.inprocess.2")
    if inprocess:
        ax.plot([2], [statistics.median(inprocess) * 1e6], "s", color="tab:green", label="hlacore in-process, median")
    for (name, points), color in zip(ANCHORS_US.items(), ("tab:orange", "tab:red")):
        ax.plot(list(points), list(points.values()), "^:", color=color, label=f"{name} with updates (reference)")
    floors = (("grant.floor.cpp", "-", "raw TCP RTT, C++"), ("grant.floor.py", "--", "raw TCP RTT, Python"))
    for key, style, name in floors:
        floor = report.median(key)
        if floor:
            ax.axhline(floor * 1e6, color="gray", linestyle=style, linewidth=1, label=name)
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xticks(list(FEDERATES), [str(k) for k in FEDERATES])
    ax.set_xlabel("federates in lockstep (one process each)")
    ax.set_ylabel("time per step (µs)")
    ax.set_title("Lockstep step time: [TSO update,] TAR(t+1), tick to TAG; lookahead 1")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path)
    plt.close(fig)
    return True
