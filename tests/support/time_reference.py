"""Reference model of docs/time-management.md in plain Python, written from the document alone.

Bounds are the greatest solution of the document's equations, found by naive fixed-point iteration
(start every bound at +inf, relax until nothing changes) rather than by Dijkstra as the C++ class does.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

INF = math.inf
TAR, TARA, NER, NERA, FQR = 1, 2, 3, 4, 5
KIND_NAMES = {TAR: "TAR", TARA: "TARA", NER: "NER", NERA: "NERA", FQR: "FQR"}
STRICT_KINDS = (TAR, NER, FQR)  # "strictly greater than x" with zero lookahead
NEXT_EVENT_KINDS = (NER, NERA, FQR)


def after(x: float, lookahead: float, strict: bool) -> float:
    """The lowest timestamp a federate may send once at x: x + L, or x / nextafter(x) with zero lookahead."""
    if lookahead > 0 and x + lookahead > x:
        return x + lookahead
    return math.nextafter(x, INF) if strict else x


@dataclass
class Fed:
    time: float = 0.0
    lookahead: float = 0.0
    regulating: bool = False
    constrained: bool = False
    constrained_pending: bool = False
    asynchronous: bool = False
    # Sending side: the last grant kind is strict, i.e. TAR/NER/FQR, or TARA/NERA to the time a strict grant
    # reached (no grant yet: not strict). Enabling regulation starts afresh at t0 (the document says "TARA
    # when there was none since regulation was enabled"; t0 already respects every receiver, see M).
    strict: bool = False
    # Receiving side, for M: the last grant was strict, so nothing at T will be delivered any more. Not
    # reset by enabling regulation: what the federate has received does not change.
    strict_receive: bool = False
    pending: int = 0
    pending_time: float = 0.0
    promise: float = -INF
    # t0 of a regulation enable whose timeRegulationEnabled(t0) has not been released yet.
    enabling: Optional[float] = None
    tso: List[Tuple[float, int, int, bytes]] = field(default_factory=list)  # sorted by (time, sender, serial)
    ro: List[bytes] = field(default_factory=list)


@dataclass
class Release:
    tso: List[bytes] = field(default_factory=list)
    ro: List[bytes] = field(default_factory=list)
    grant: Optional[float] = None
    constrained_enabled: Optional[float] = None
    regulation_enabled: Optional[float] = None


class ReferenceTimeManager:
    def __init__(self, semantics: str = "exact") -> None:
        self.semantics = semantics  # "certi": a newcomer starts at a constrained federate's time even after TAR
        self.feds: Dict[int, Fed] = {}
        self.bounds: Dict[int, float] = {}

    # ------------------------------------------------------------------ bounds
    def _earliest(self, s: Fed) -> float:
        return s.tso[0][0] if s.tso else INF

    def _own(self, s: Fed) -> float:
        if s.enabling is not None:
            return after(s.enabling, s.lookahead, False)  # like TARA(t0)
        if not s.pending:
            return after(s.time, s.lookahead, s.strict)
        strict = s.pending in STRICT_KINDS
        if s.pending in (TAR, TARA):
            return after(s.pending_time, s.lookahead, strict)
        q = self._earliest(s) if s.constrained else INF
        return after(min(s.pending_time, q), s.lookahead, strict)

    def compute_bounds(self) -> Dict[int, float]:
        regulating = [f for f, s in self.feds.items() if s.regulating]
        b = {f: INF for f in regulating}
        for _ in range(100000):
            changed = False
            for g in regulating:
                s = self.feds[g]
                value = self._own(s)
                if s.constrained and s.pending in NEXT_EVENT_KINDS:
                    others = min((b[h] for h in regulating if h != g), default=INF)
                    value = min(value, after(others, s.lookahead, s.pending in STRICT_KINDS))
                value = max(s.promise, value)
                if value != b[g]:
                    b[g] = value
                    changed = True
            if not changed:
                break
        else:  # pragma: no cover
            raise AssertionError("bound iteration did not converge")
        for g in regulating:
            self.feds[g].promise = max(self.feds[g].promise, b[g])
        self.bounds = b
        return b

    def output_bound(self, f: int) -> float:
        return self.compute_bounds().get(f, INF)

    def lbts(self, f: int) -> float:
        b = self.compute_bounds()
        return min((v for g, v in b.items() if g != f), default=INF)

    def min_next_event_time(self, f: int) -> float:
        return min(self.lbts(f), self._earliest(self.feds[f]))

    def federate_time(self, f: int) -> float:
        return self.feds[f].time

    def sending_minimum(self, f: int) -> float:
        """after(T, L, last grant kind), and also after(t, L, kind) while a request is pending (no memory of
        lowered lookaheads). Both: a TARA(T) after a strict grant to T does not allow T itself."""
        s = self.feds[f]
        minimum = after(s.time, s.lookahead, s.strict)
        if s.pending:
            minimum = max(minimum, after(s.pending_time, s.lookahead, s.pending in STRICT_KINDS))
        return minimum

    # ------------------------------------------------------------------ operations
    def add_federate(self, f: int) -> None:
        self.feds[f] = Fed()

    def remove_federate(self, f: int) -> None:
        del self.feds[f]

    def regulation_start(self, f: int, time: float, lookahead: float) -> float:
        """t0 = max(time, T, M - L), M over every other constrained federate's lowest receivable time and
        every other regulating federate's promise; with CERTI's semantics over the constrained federates'
        times only."""
        self.compute_bounds()  # promises up to date
        m = -INF
        for g, o in self.feds.items():
            if g == f:
                continue
            exact = self.semantics == "exact"
            if o.constrained:
                m = max(m, math.nextafter(o.time, INF) if exact and o.strict_receive else o.time)
            if o.regulating and exact:
                m = max(m, o.promise)
        start = m - lookahead
        # The document's intent ("a newcomer can never send ... below a bound others were already granted
        # on"): in floating point M - L + L may round below M, so take the next doubles until it does not.
        while start > -INF and after(start, lookahead, False) < m:
            start = math.nextafter(start, INF)
        return max(time, self.feds[f].time, start)

    def enable_regulation(self, f: int, time: float, lookahead: float) -> float:
        s = self.feds[f]
        assert not s.regulating and not s.pending, "refused by the client and the gateway"
        t0 = self.regulation_start(f, time, lookahead)
        s.regulating = True
        s.lookahead = lookahead
        s.strict = False
        s.promise = -INF
        s.enabling = t0
        # Constrained and t0 > T: the time moves in release(), like TARA(t0). Otherwise at once.
        if not (s.constrained and t0 > s.time):
            s.time = t0
        return t0

    def disable_regulation(self, f: int) -> None:
        s = self.feds[f]
        s.regulating = False
        s.promise = -INF
        s.enabling = None  # cancels a pending enable

    def enable_constrained(self, f: int) -> None:
        self.feds[f].constrained_pending = True

    def disable_constrained(self, f: int) -> List[bytes]:
        s = self.feds[f]
        s.constrained = False
        out = [m[3] for m in s.tso]
        s.tso = []
        return out

    def set_asynchronous_delivery(self, f: int, on: bool) -> None:
        self.feds[f].asynchronous = on

    def modify_lookahead(self, f: int, lookahead: float) -> None:
        self.feds[f].lookahead = lookahead

    def request(self, f: int, kind: int, time: float) -> None:
        s = self.feds[f]
        assert not s.pending and s.enabling is None and time >= s.time
        s.pending, s.pending_time = kind, time

    def is_tso(self, sender: int, receiver: int) -> bool:
        return self.feds[sender].regulating and self.feds[receiver].constrained

    def holds_receive_order(self, f: int) -> bool:
        s = self.feds[f]
        return s.constrained and not s.pending and s.enabling is None and not s.asynchronous

    def enqueue_tso(self, receiver: int, time: float, sender: int, serial: int, payload: bytes) -> None:
        bisect.insort(self.feds[receiver].tso, (time, sender, serial, payload))

    def enqueue_receive_order(self, receiver: int, payload: bytes) -> None:
        self.feds[receiver].ro.append(payload)

    def retract(self, sender: int, serial: int) -> int:
        n = 0
        for s in self.feds.values():
            kept = [m for m in s.tso if not (m[1] == sender and m[2] == serial)]
            n += len(s.tso) - len(kept)
            s.tso = kept
        return n

    def release(self) -> Dict[int, Release]:
        out: Dict[int, Release] = {}

        def rel(f: int) -> Release:
            return out.setdefault(f, Release())

        while True:
            changed = False
            self.compute_bounds()
            for f, s in self.feds.items():
                if s.ro and not self.holds_receive_order(f):
                    rel(f).ro.extend(s.ro)
                    s.ro = []
            lbts = {f: min((v for g, v in self.bounds.items() if g != f), default=INF) for f in self.feds}
            for f, s in self.feds.items():
                if s.constrained_pending and lbts[f] >= s.time:
                    s.constrained_pending = False
                    s.constrained = True
                    s.strict_receive = False  # timeConstrainedEnabled(T): messages at T may still come
                    rel(f).constrained_enabled = s.time
                    changed = True
            for f, s in self.feds.items():
                if s.enabling is None:
                    continue
                t0 = s.enabling
                if s.time < t0:  # constrained when enabling; maybe not any more
                    if s.constrained:
                        if not t0 <= lbts[f]:
                            continue
                        while s.tso and s.tso[0][0] <= t0:
                            rel(f).tso.append(s.tso.pop(0)[3])
                    s.time = t0
                    s.strict_receive = False  # like TARA(t0): messages at t0 may still come
                s.enabling = None
                rel(f).regulation_enabled = t0
                changed = True
            for f, s in self.feds.items():
                if not s.pending:
                    continue
                t, kind = s.pending_time, s.pending
                if not s.constrained:
                    grant, limit = t, None
                else:
                    q = self._earliest(s)
                    grant = None
                    if kind == TAR and t < lbts[f]:
                        grant, limit = t, t
                    elif kind == TARA and t <= lbts[f]:
                        grant, limit = t, t
                    elif kind == NER and min(t, q) < lbts[f]:
                        grant = limit = min(t, q)
                    elif kind == NERA and min(t, q) <= lbts[f]:
                        grant = limit = min(t, q)
                    elif kind == FQR:
                        grant, limit = max(s.time, min(t, lbts[f], q)), INF
                    if grant is None:
                        continue
                    while s.tso and s.tso[0][0] <= limit:
                        rel(f).tso.append(s.tso.pop(0)[3])
                r = rel(f)
                assert r.grant is None
                r.grant = grant
                # "last grant kind": a TARA/NERA grant to the time a strict grant reached stays strict
                s.strict = kind in STRICT_KINDS or (s.strict and grant == s.time)
                s.time = grant
                # A TAR/NER grant to G means every TSO message <= G was delivered (t < LBTS), whatever the
                # lookahead: HLA 1.3's reading of the document's "strict grant". FQR only counts where the
                # document's after() is strict (zero lookahead); it may grant LBTS itself.
                s.strict_receive = s.constrained and kind in (TAR, NER) or s.constrained and (
                    kind == FQR and after(grant, s.lookahead, True) == math.nextafter(grant, INF)
                )
                s.pending = 0
                changed = True
            if not changed:
                break
        self.compute_bounds()
        return {
            f: r
            for f, r in out.items()
            if r.tso or r.ro or r.grant is not None or r.constrained_enabled is not None or r.regulation_enabled is not None
        }
