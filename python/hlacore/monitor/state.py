"""What the monitor shows, computed from the gateway's successive status reports (no I/O here).

Each report (``hlacore.status``'s JSON, infinite times as ``None``) becomes a *view*: the report's federations
and federates plus what one report alone does not say: grants and updates per second from the counters of
the reports of the last few seconds, the gateway's CPU share, and which federates hold the others back. The view keeps the recent
history of every federate's logical time for the chart and the gateway's membership events, both bounded.
"""

from __future__ import annotations

import collections
from dataclasses import dataclass, field
from typing import Any, Deque, Optional

#: A federate waiting this long (seconds) for a grant counts as held back by the federates that set its LBTS.
HOLD_SECONDS = 1.0
#: Points of each federate's logical time kept for the chart (at two reports a second: two minutes).
HISTORY_POINTS = 240
#: Membership events kept (the gateway keeps its own last 256; the monitor keeps more for a long session).
EVENTS_KEPT = 1000
#: The span (seconds) grants and updates per second are averaged over: a lockstep of one step a second reads
#: as 1/s, not as 0 and 2 in turn.
RATE_SECONDS = 5.0


def federate_key(federation: str, handle: int) -> str:
    """The name a federate goes by in the view and on the page: handles repeat across federations."""
    return f"{federation}/{handle}"


def holding_back(federates: list[dict[str, Any]],
                 hold_seconds: float = HOLD_SECONDS) -> dict[int, list[tuple[int, float]]]:
    """Federate handle -> (handle, seconds waited) of each federate it holds back.

    A federate is held back when its time advance request has been pending for ``hold_seconds`` or more; the
    gateway names who holds it (``held_by``: the regulating federates that may still send at or below what it
    waits for, docs/time-management.md).
    """
    held: dict[int, list[tuple[int, float]]] = {}
    for waiting in federates:
        pending = waiting.get("pending")
        if not pending or pending.get("waiting", 0.0) < hold_seconds:
            continue
        for other in waiting.get("held_by", []):
            held.setdefault(other["handle"], []).append((waiting["handle"], pending["waiting"]))
    return held


@dataclass
class MonitorState:
    """Turns successive status reports into views (:meth:`update`) and keeps the history a new page needs
    (:meth:`hello`)."""

    hold_seconds: float = HOLD_SECONDS
    history_points: int = HISTORY_POINTS
    #: The sequence number of the last gateway event seen: the next status query asks only for later ones.
    last_event: int = 0
    events: Deque[dict[str, Any]] = field(default_factory=lambda: collections.deque(maxlen=EVENTS_KEPT))
    history: dict[str, Deque[tuple[float, float]]] = field(default_factory=dict)
    latest: Optional[dict[str, Any]] = None
    # Per federate, its counters over the last RATE_SECONDS: (monotonic time, grants, updates + interactions).
    _counters: dict[str, Deque[tuple[float, int, int]]] = field(default_factory=dict)
    _cpu: Optional[tuple[float, float]] = None  # (monotonic time, the gateway's CPU seconds) of the last report

    def update(self, report: dict[str, Any], wall: float, monotonic: float) -> dict[str, Any]:
        """The view of `report`, received at `wall` (Unix time) and `monotonic` (seconds, for rates)."""
        new_events = report.get("events", [])
        last = int(report.get("last_event", self.last_event))
        if last < self.last_event:  # a new gateway on the same address: its numbers start again
            self.events.clear()
        self.events.extend(new_events)
        self.last_event = last
        federations = []
        seen: set[str] = set()
        for federation in report["federations"]:
            held = holding_back(federation["federates"], self.hold_seconds)
            names = {f["handle"]: f["name"] for f in federation["federates"]}
            federates = []
            for f in federation["federates"]:
                key = federate_key(federation["name"], f["handle"])
                seen.add(key)
                federates.append(self._federate_view(key, f, held.get(f["handle"], []), names, wall, monotonic))
            federations.append({**{k: v for k, v in federation.items() if k != "federates"},
                                "federates": federates})
        for gone in set(self.history) - seen:
            del self.history[gone]
            self._counters.pop(gone, None)
        view = {
            "type": "update",
            "wall": wall,
            "connected": True,
            "server": report.get("server"),
            "address": report.get("address"),
            "tls": report.get("tls", False),
            "connections": report.get("connections", 0),
            "process": {**report.get("process", {}), "cpu_percent": self._cpu_percent(report, monotonic)},
            "federations": federations,
            "fedpro": report.get("fedpro"),  # the Federate Protocol's door and its sessions, when it has one
            "events": new_events,
        }
        self.latest = view
        return view

    def unreachable(self, reason: str, wall: float) -> dict[str, Any]:
        """The view while the gateway does not answer: the last federations stay, marked stale."""
        self._cpu = None
        view = {**(self.latest or {"federations": [], "process": {}}), "type": "update", "wall": wall,
                "connected": False, "error": reason, "events": []}
        self.latest = view
        return view

    def hello(self) -> dict[str, Any]:
        """What a page that just connected needs: the latest view, the chart's history and the event log."""
        return {"type": "hello", "latest": self.latest,
                "history": {key: list(points) for key, points in self.history.items()},
                "events": list(self.events), "hold_seconds": self.hold_seconds}

    def _federate_view(self, key: str, f: dict[str, Any], holds: list[tuple[int, float]], names: dict[int, str],
                       wall: float, monotonic: float) -> dict[str, Any]:
        sent = int(f.get("updates_sent", 0)) + int(f.get("interactions_sent", 0))
        grants = int(f.get("grants", 0))
        counters = self._counters.setdefault(key, collections.deque())
        counters.append((monotonic, grants, sent))
        while len(counters) > 2 and counters[1][0] <= monotonic - RATE_SECONDS:
            counters.popleft()
        grants_rate = sent_rate = 0.0
        first = counters[0]
        if monotonic > first[0]:
            grants_rate = max(0, grants - first[1]) / (monotonic - first[0])
            sent_rate = max(0, sent - first[2]) / (monotonic - first[0])
        points = self.history.setdefault(key, collections.deque(maxlen=self.history_points))
        points.append((wall, float(f["time"])))
        holding = None
        if holds:
            holding = {"federates": [names.get(h, str(h)) for h, _ in holds],
                       "seconds": max(seconds for _, seconds in holds)}
        return {**f, "key": key, "grants_per_second": grants_rate, "updates_per_second": sent_rate,
                "holding": holding}

    def _cpu_percent(self, report: dict[str, Any], monotonic: float) -> Optional[float]:
        cpu = report.get("process", {}).get("cpu_seconds")
        if cpu is None:
            return None
        previous, self._cpu = self._cpu, (monotonic, float(cpu))
        if previous is None or monotonic <= previous[0]:
            return None
        return 100.0 * max(0.0, float(cpu) - previous[1]) / (monotonic - previous[0])
