"""Property tests: the C++ TimeManager against the reference model of docs/time-management.md
(tests/support/time_reference.py), on random federations driven only through legal operations."""

from __future__ import annotations

import math
from typing import Any, Dict, List, Optional, Tuple

import pytest
from hypothesis import HealthCheck, Phase, given, note, settings
from hypothesis import strategies as st

from hlacore import _core

from support.time_reference import FQR, INF, NER, NERA, TAR, TARA, ReferenceTimeManager, after

T_END = 1.0e6
LOOKAHEADS = st.one_of(
    st.sampled_from([0.0, 0.0, 0.5, 1.0, 2.5]),
    st.sampled_from([1e-9, 5e-324, 0.1]),
    st.floats(0.0, 3.0, allow_nan=False, allow_infinity=False),
)
DELTAS = st.one_of(
    st.sampled_from([0.0, 0.0, 0.5, 1.0, 2.5, 3.0]),
    st.floats(0.0, 5.0, allow_nan=False, allow_infinity=False),
)
KINDS = st.sampled_from([TAR, TARA, NER, NERA, FQR])


def tso_payload(ts: float, sender: int, serial: int) -> bytes:
    return f"T|{ts!r}|{sender}|{serial}".encode()


def parse_tso(p: bytes) -> Tuple[float, int, int]:
    _, ts, sender, serial = p.decode().split("|")
    return float(ts), int(sender), int(serial)


def is_tso_payload(p: bytes) -> bool:
    return p.startswith(b"T|")


# ---------------------------------------------------------------------------------------------- driver


def apply(tm: Any, op: tuple) -> Any:
    """Apply one operation to a time manager: the C++ class or the reference model, which share the method
    names. Returns what enable_regulation, disable_constrained (as a list) and retract return, else None."""
    name = op[0]
    if name == "add":
        tm.add_federate(op[1])
    elif name == "remove":
        tm.remove_federate(op[1])
    elif name == "enable_regulation":
        return tm.enable_regulation(op[1], op[2], op[3])
    elif name == "disable_regulation":
        tm.disable_regulation(op[1])
    elif name == "enable_constrained":
        tm.enable_constrained(op[1])
    elif name == "disable_constrained":
        return list(tm.disable_constrained(op[1]))
    elif name == "async":
        tm.set_asynchronous_delivery(op[1], op[2])
    elif name == "lookahead":
        tm.modify_lookahead(op[1], op[2])
    elif name == "request":
        tm.request(op[1], op[2], op[3])
    elif name == "send":
        _, sender, ts, serial, receivers = op
        for r in receivers:
            tm.enqueue_tso(r, ts, sender, serial, tso_payload(ts, sender, serial))
    elif name == "send_ro":
        tm.enqueue_receive_order(op[1], op[2])
    elif name == "retract":
        return tm.retract(op[1], op[2])
    else:  # pragma: no cover
        raise AssertionError(op)
    return None


def execute(tm: Any, op: tuple, present: List[int]) -> tuple:
    """Apply one operation to the C++ class, then release() and every query: the raw observable trace."""
    ret = apply(tm, op)
    released = [(f, list(frames), g, ce, re) for f, frames, g, ce, re in tm.release()]
    queries = {
        f: (
            tm.output_bound(f),
            tm.lbts(f),
            tm.min_next_event_time(f),
            tm.federate_time(f),
            tm.holds_receive_order(f),
        )
        for f in present
    }
    return ret, released, queries


def aggregate(released: List[tuple], extra: Optional[Tuple[int, List[bytes]]] = None) -> Dict[int, tuple]:
    """Per federate: (TSO frames, RO frames, grant, constrained_enabled, regulation_enabled) of one step."""
    out: Dict[int, list] = {}
    if extra is not None and extra[1]:
        out[extra[0]] = [list(extra[1]), [], None, None, None]
    for f, frames, grant, ce, re in released:
        agg = out.setdefault(f, [[], [], None, None, None])
        for p in frames:
            (agg[0] if is_tso_payload(p) else agg[1]).append(p)
        if grant is not None:
            assert agg[2] is None, f"two grants to {f} in one release"
            agg[2] = grant
        if ce is not None:
            assert agg[3] is None, f"two constrained-enabled to {f} in one release"
            agg[3] = ce
        if re is not None:
            assert agg[4] is None, f"two regulation-enabled to {f} in one release"
            agg[4] = re
    # RO frames and re-ordered TSO frames are checked separately, so split the disable_constrained ones
    return {f: (tuple(v[0]), tuple(v[1]), v[2], v[3], v[4]) for f, v in out.items()}


class Harness:
    """Drives the C++ class and the reference model in lockstep, checking properties 1-4 after each step, under
    the exact rules or CERTI's (docs/time-management.md)."""

    def __init__(self, semantics: str = "exact") -> None:
        self.semantics = semantics
        self.tm = _core._TimeManager(semantics)
        self.ref = ReferenceTimeManager(semantics)
        self.log: List[tuple] = []
        self.trace: List[tuple] = []
        self.serial: Dict[int, int] = {}
        self.sent: Dict[Tuple[int, int], float] = {}  # (sender, serial) -> ts
        self.queued: Dict[int, set] = {}  # receiver -> {(sender, serial)} enqueued, not yet delivered
        self.delivered: Dict[int, List[Tuple[float, int, int]]] = {}  # receiver -> TSO delivery order
        self.ro_sent: Dict[int, List[bytes]] = {}
        self.ro_got: Dict[int, List[bytes]] = {}
        self.last_kind: Dict[int, int] = {}
        self.floor: Dict[int, float] = {}  # last grant (or constrained-enabled) time: no TSO below it
        self.ro_counter = 0
        self._pending_kind: Dict[int, int] = {}
        # The sending rule's memory, as a client keeps it: what it was allowed before lowering its lookahead,
        # and the highest lookahead it had since asking for regulation (it learns t0 only at the callback).
        self.kept: Dict[int, float] = {}
        self.enable_lookahead: Dict[int, float] = {}

    # -------------------------------------------------------------- helpers
    @property
    def present(self) -> List[int]:
        return sorted(self.ref.feds)

    def allowed_send_minimum(self, f: int) -> float:
        """The document's sending rule as a client can follow it: after(T, L, last grant kind), also
        after(t, L, kind) while a request is pending, and never below what was allowed before a lowered
        lookahead. It knows nothing of the bounds: send() checks that they never exceed this."""
        return max(self.ref.sending_minimum(f), self.kept.get(f, -INF))

    # -------------------------------------------------------------- one step
    def step(self, op: tuple) -> None:
        note(f"op {len(self.log)}: {op!r}")
        self.log.append(op)
        strict_before = {f: self.last_kind.get(f) in (TAR, NER) for f in self.ref.feds}
        expected_ret = apply(self.ref, op)
        expected_rel = self.ref.release()
        present = self.present
        ret, released, queries = execute(self.tm, op, present)
        self.trace.append((ret, released, queries))
        ctx = f"after op {len(self.log) - 1} {op!r}"

        # return values
        if op[0] in ("enable_regulation", "retract"):
            assert ret == expected_ret, f"{ctx}: returned {ret!r}, model {expected_ret!r}"
        extra = None
        if op[0] == "disable_constrained":
            assert ret == expected_ret, f"{ctx}: disable_constrained returned {ret!r}, model {expected_ret!r}"
            extra = (op[1], ret)
        if op[0] == "retract":
            # property 4 bookkeeping: the count is the receivers where it still waited
            key = (op[1], op[2])
            waiting = [r for r, q in self.queued.items() if key in q]
            assert ret == len(waiting), f"{ctx}: retract removed {ret}, {len(waiting)} receivers still had it"
            for r in waiting:
                self.queued[r].discard(key)

        # property 2: releases (grants, constrained_enabled, frames) equal the model's
        got = aggregate(released, extra)
        want = {}
        for f, r in expected_rel.items():
            tso = (list(extra[1]) if extra and extra[0] == f else []) + list(r.tso)
            want[f] = (tuple(tso), tuple(r.ro), r.grant, r.constrained_enabled, r.regulation_enabled)
        if extra and extra[1] and extra[0] not in want:
            want[extra[0]] = (tuple(extra[1]), (), None, None, None)
        assert got == want, f"{ctx}: release {released!r}\n  model {want!r}"

        # property 1 and 4: timestamps, order, exactly-once (disable_constrained hands back first)
        if extra:
            tso = [parse_tso(p) for p in extra[1]]
            assert tso == sorted(tso)
            for m in tso:
                assert m[0] >= self.floor.get(extra[0], 0.0), f"{ctx}: queued TSO {m} below the last grant"
            self._mark_delivered(extra[0], tso, ctx)

        for f, frames, grant, _ce, re in released:
            kind = self.ref_kind_of_grant(op, f, grant)
            t_before = self.floor.get(f, 0.0)
            tso = [parse_tso(p) for p in frames if is_tso_payload(p)]
            for m in tso:
                assert m[0] >= t_before, f"{ctx}: {f} at {t_before} got TSO {m} in its past"
                if strict_before.get(f) and self.semantics == "exact":  # CERTI's: a newcomer may send at it
                    assert m[0] > t_before, f"{ctx}: {f} strictly granted {t_before} got TSO {m}"
                if grant is not None and kind in (TAR, TARA, NER, NERA):
                    assert m[0] <= grant, f"{ctx}: {f} got TSO {m} with its grant to {grant}"
                if re is not None:  # delivered before timeRegulationEnabled(re), like TARA(re)
                    assert m[0] <= re, f"{ctx}: {f} got TSO {m} with its regulation enabled at {re}"
            assert tso == sorted(tso), f"{ctx}: {f} got TSO out of order {tso}"
            self._mark_delivered(f, tso, ctx)
            self.ro_got.setdefault(f, []).extend(p for p in frames if not is_tso_payload(p))
            if _ce is not None:
                self.floor[f] = _ce
                self.last_kind.pop(f, None)
            if re is not None:
                L = self.enable_lookahead.pop(f)
                self.kept[f] = max(self.kept.get(f, -INF), after(re, L, False))
                if re > t_before:  # moved to re like TARA(re); at t_before nothing changes for receiving
                    self.floor[f] = re
                    self.last_kind.pop(f, None)
            if grant is not None:
                self.last_kind[f] = kind
                self.floor[f] = grant
        # property 2: queries
        bounds = self.ref.compute_bounds()
        for f in present:
            lbts = min((v for g, v in bounds.items() if g != f), default=INF)
            earliest = self.ref.feds[f].tso[0][0] if self.ref.feds[f].tso else INF
            want_q = (
                bounds.get(f, INF),
                lbts,
                min(lbts, earliest),
                self.ref.federate_time(f),
                self.ref.holds_receive_order(f),
            )
            assert queries[f] == want_q, (
                f"{ctx}: federate {f} (output_bound, lbts, mnet, time, holds_ro) = {queries[f]!r}, model {want_q!r}"
            )
            s, tm = self.ref.feds[f], self.tm
            states = (tm.regulating(f), tm.enabling_regulation(f), tm.advancing(f))
            assert states == (s.regulating, s.enabling is not None, bool(s.pending)), f"{ctx}: {f} states {states}"
            # the gateway's check of timestamps (may_send) accepts exactly what is at or above the bound
            b = bounds.get(f, INF) if s.regulating else -INF
            assert tm.promise(f) == b, f"{ctx}: promise of {f} is {tm.promise(f)}, model bound {b}"
            assert tm.may_send(f, b) and (b == -INF or not tm.may_send(f, math.nextafter(b, -INF)))

    def ref_kind_of_grant(self, op: tuple, f: int, grant: Optional[float]) -> Optional[int]:
        if grant is None:
            return None
        return self._pending_kind.get(f)

    def _mark_delivered(self, f: int, tso: List[Tuple[float, int, int]], ctx: str) -> None:
        q = self.queued.setdefault(f, set())
        for ts, sender, serial in tso:
            key = (sender, serial)
            assert key in q, f"{ctx}: {f} got {key} at {ts} which it was not waiting for (lost/duplicated/retracted)"
            assert self.sent[key] == ts
            q.discard(key)
            self.delivered.setdefault(f, []).append((ts, sender, serial))

    # -------------------------------------------------------------- legal operations

    def run_op(self, op: tuple) -> None:
        name = op[0]
        if name == "request":
            self._pending_kind[op[1]] = op[2]
        elif name in ("enable_regulation", "disable_regulation", "remove"):
            self.kept.pop(op[1], None)
            self.enable_lookahead.pop(op[1], None)
            if name == "enable_regulation":
                self.enable_lookahead[op[1]] = op[3]
        elif name == "lookahead":
            f = op[1]
            if f in self.enable_lookahead:
                self.enable_lookahead[f] = max(self.enable_lookahead[f], op[2])
            else:
                self.kept[f] = self.allowed_send_minimum(f)
        self.step(op)

    def send(self, sender: int, ts: float) -> None:
        assert ts >= self.allowed_send_minimum(sender)
        b = self.ref.output_bound(sender)
        assert ts >= b, (
            f"document inconsistency: the sending rule allows {ts} but the model's bound of {sender} is {b}"
        )
        assert self.tm.may_send(sender, ts), f"the gateway would drop {sender} for a legal timestamp {ts}"
        receivers = []
        for r in self.present:
            if r == sender:
                continue
            want = self.ref.is_tso(sender, r)
            assert self.tm.is_tso(sender, r) == want, f"is_tso({sender}, {r}) disagrees with model {want}"
            if want:
                receivers.append(r)
        serial = self.serial.get(sender, 0)
        self.serial[sender] = serial + 1
        self.sent[(sender, serial)] = ts
        for r in receivers:
            self.queued.setdefault(r, set()).add((sender, serial))
        self.run_op(("send", sender, ts, serial, tuple(receivers)))

    def draw_op(self, draw: Any) -> None:
        feds = self.ref.feds
        present = self.present
        idle = [
            f for f in present if not feds[f].pending and not feds[f].constrained_pending and feds[f].enabling is None
        ]
        regulating = [f for f in present if feds[f].regulating]
        # no timestamps before timeRegulationEnabled: the federate does not know t0 yet
        senders = [f for f in regulating if feds[f].enabling is None]
        choices = []
        if idle:
            choices += ["request"] * 6
        if senders:
            choices += ["send"] * 6
        if regulating:
            choices += ["lookahead"]
        choices += ["send_ro", "async", "regulation", "constrained"]
        if any(self.sent.get(k, -INF) > feds[k[0]].time for k in self.sent if k[0] in feds):
            choices.append("retract")
        if len(present) > 1:
            choices.append("remove")
        if len(idle) > 1:
            choices += ["everyone"] * 3
        what = draw(st.sampled_from(choices))
        if what == "everyone":  # a federation-wide step: every idle federate requests the same way
            kind, delta = draw(KINDS), draw(DELTAS)
            for f in idle:
                if f in feds and not feds[f].pending and not feds[f].constrained_pending:
                    self.run_op(("request", f, kind, feds[f].time + delta))
        elif what == "request":
            f = draw(st.sampled_from(idle))
            kind = draw(KINDS)
            q = [m[0] for m in feds[f].tso]
            if q and draw(st.booleans()):
                t = max(feds[f].time, draw(st.sampled_from(q)))
            else:
                t = feds[f].time + draw(DELTAS)
            self.run_op(("request", f, kind, t))
        elif what == "send":
            f = draw(st.sampled_from(senders))
            self.send(f, self.allowed_send_minimum(f) + draw(DELTAS))
        elif what == "lookahead":
            f = draw(st.sampled_from(regulating))
            self.run_op(("lookahead", f, draw(LOOKAHEADS)))
        elif what == "send_ro":
            f = draw(st.sampled_from(present))
            held = self.ref.holds_receive_order(f)
            assert self.tm.holds_receive_order(f) == held
            if held:  # otherwise the client delivers it directly
                self.ro_counter += 1
                p = f"R|{self.ro_counter}".encode()
                self.ro_sent.setdefault(f, []).append(p)
                self.run_op(("send_ro", f, p))
        elif what == "async":
            f = draw(st.sampled_from(present))
            self.run_op(("async", f, not feds[f].asynchronous))
        elif what == "regulation":
            f = draw(st.sampled_from(present))
            if feds[f].regulating:
                if feds[f].enabling is None:  # disabling a pending enable is refused by the client
                    self.run_op(("disable_regulation", f))
            elif not feds[f].pending:
                self.run_op(("enable_regulation", f, feds[f].time + draw(DELTAS), draw(LOOKAHEADS)))
        elif what == "constrained":
            f = draw(st.sampled_from(present))
            if feds[f].constrained:
                self.run_op(("disable_constrained", f))
            elif not feds[f].constrained_pending and not feds[f].pending:
                self.run_op(("enable_constrained", f))
        elif what == "retract":
            keys = sorted(k for k, ts in self.sent.items() if k[0] in feds and ts > feds[k[0]].time)
            sender, serial = draw(st.sampled_from(keys))
            self.run_op(("retract", sender, serial))
        elif what == "remove":
            f = draw(st.sampled_from(present))
            self.run_op(("remove", f))
            self.queued.pop(f, None)
            self.ro_sent.pop(f, None)
            self.ro_got.pop(f, None)

    def finish(self, draw: Any) -> None:
        """Properties 4 and 5: everyone advances to T_END; all messages arrive, nobody is left waiting."""
        feds = self.ref.feds
        # one kind for everyone: a zero-lookahead TARA(T_END) sender blocks a TAR(T_END) receiver
        kind = draw(st.sampled_from([TAR, TARA]))

        def waiting(s: Any) -> bool:
            return bool(s.pending or s.constrained_pending or s.enabling is not None)

        for _round in range(6):
            # everyone idle at the start of the round: then all of them request T_END in this round
            all_request = not any(waiting(feds[f]) for f in self.present)
            for f in self.present:
                s = feds[f]
                if not waiting(s) and s.time < T_END:
                    self.run_op(("request", f, kind, T_END))
            stuck = [f for f in self.present if waiting(feds[f])]
            if all_request:
                # one release (the one after the last request) must have granted every request
                assert not stuck, f"deadlock: {stuck} still waiting after everyone requested {T_END}"
            if not stuck and all(feds[f].time == T_END for f in self.present):
                break
        else:
            raise AssertionError("federates did not all reach T_END in 6 rounds")
        status = {d["federate"]: d for d in self.tm.status()}
        for f in self.present:
            assert self.tm.federate_time(f) == T_END
            assert status[f]["pending"] == 0 and status[f]["queued_tso"] == 0 and status[f]["queued_ro"] == 0
            assert not status[f]["enabling_regulation"]
            assert not self.queued.get(f), f"{f} never received {sorted(self.queued[f])}"
            assert self.ro_got.get(f, []) == self.ro_sent.get(f, []), f"receive-order messages to {f}"


# ---------------------------------------------------------------------------------------------- properties


@st.composite
def scenario(draw: Any, semantics: str) -> Harness:
    h = Harness(semantics)
    n = draw(st.one_of(st.integers(1, 4), st.integers(1, 16)))
    ids = draw(st.lists(st.integers(1, 40), min_size=n, max_size=n, unique=True))
    for f in ids:
        h.run_op(("add", f))
    for f in ids:
        regulating, constrained = draw(st.integers(0, 3)) > 0, draw(st.integers(0, 3)) > 0
        # constrained first: its regulation enable may have to wait for messages below t0
        if constrained and draw(st.booleans()):
            h.run_op(("enable_constrained", f))
            constrained = False
        if regulating:
            h.run_op(("enable_regulation", f, 0.0, draw(LOOKAHEADS)))
        if constrained:
            h.run_op(("enable_constrained", f))
    for _ in range(draw(st.integers(0, 60))):
        h.draw_op(draw)
    return h


@pytest.mark.slow
@pytest.mark.parametrize("semantics", ["exact", "certi"])
@settings(
    max_examples=500,
    deadline=None,
    phases=[Phase.explicit, Phase.reuse, Phase.generate, Phase.shrink],
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
@given(data=st.data())
def test_random_federations_match_reference_model(data: Any, semantics: str) -> None:
    """Random legal federations: grants, bounds, deliveries equal the model; no past, loss, dup or deadlock."""
    h = data.draw(scenario(semantics))
    h.finish(data.draw)
    # property 3: TSO order per receiver is by (time, sender, serial) among what was queued together,
    # and the whole run is reproduced exactly by a fresh TimeManager fed the same operations
    tm2 = _core._TimeManager(semantics)
    present: List[int] = []
    for op, recorded in zip(h.log, h.trace):
        if op[0] == "add":
            present = sorted(present + [op[1]])
        elif op[0] == "remove":
            present = [f for f in present if f != op[1]]
        assert execute(tm2, op, present) == recorded, f"second run differs at {op!r}"


# ---------------------------------------------------------------------------------------------- examples

NEXT = math.nextafter


def federation(*specs: Tuple[int, Optional[float], bool]) -> Any:
    """A TimeManager with federates (handle, lookahead or None if not regulating, constrained)."""
    tm = _core._TimeManager()
    for f, lookahead, constrained in specs:
        tm.add_federate(f)
        if lookahead is not None:
            assert tm.enable_regulation(f, 0.0, lookahead) == 0.0
        if constrained:
            tm.enable_constrained(f)
    assert all(grant is None for _f, _frames, grant, _ce, _re in tm.release())
    return tm


def grants(released: List[tuple]) -> Dict[int, float]:
    return {f: g for f, _frames, g, _ce, _re in released if g is not None}


def frames(released: List[tuple]) -> Dict[int, List[bytes]]:
    out: Dict[int, List[bytes]] = {}
    for f, fr, _g, _ce, _re in released:
        out.setdefault(f, []).extend(fr)
    return out


def test_zero_lookahead_tar_and_tara() -> None:
    """Zero lookahead: all-TAR(1) and all-TARA(1) are granted; a TARA(1) sender holds a TAR(1) receiver."""
    tm = federation((1, 0.0, True), (2, 0.0, True))
    tm.request(1, TAR, 1.0)
    assert tm.release() == []  # 2 may still send at 0
    tm.request(2, TAR, 1.0)  # pending TAR(1) with L=0: sends only > 1 (the document's after())
    assert grants(tm.release()) == {1: 1.0, 2: 1.0}
    assert tm.output_bound(1) == tm.output_bound(2) == NEXT(1.0, INF)

    tm = federation((1, 0.0, True), (2, 0.0, True))
    tm.request(1, TARA, 1.0)
    tm.request(2, TARA, 1.0)
    assert grants(tm.release()) == {1: 1.0, 2: 1.0}
    assert tm.output_bound(1) == tm.output_bound(2) == 1.0

    tm = federation((1, 0.0, True), (2, 0.0, True))
    tm.request(1, TARA, 1.0)
    tm.request(2, TAR, 1.0)
    assert grants(tm.release()) == {1: 1.0}  # 1 may now send at 1 itself: 2's TAR(1) must wait
    assert tm.release() == [] and tm.lbts(2) == 1.0
    tm.enqueue_tso(2, 1.0, 1, 0, b"at-1")
    tm.request(1, TARA, 2.0)
    assert tm.release() == [(2, [b"at-1"], 1.0, None, None)]


def test_nextafter_strictness() -> None:
    """After TAR/NER/FQR with zero lookahead the bound is nextafter(T); after TARA/NERA it is T."""
    tm = federation((1, 0.0, False), (2, None, True))
    for kind, t, bound in [
        (TAR, 1.0, NEXT(1.0, INF)),
        (TARA, 2.0, 2.0),
        (NER, 3.0, NEXT(3.0, INF)),
        (NERA, 4.0, 4.0),
        (FQR, 5.0, NEXT(5.0, INF)),
    ]:
        tm.request(1, kind, t)
        assert grants(tm.release()) == {1: t}
        assert tm.output_bound(1) == bound and tm.lbts(2) == bound and tm.min_next_event_time(2) == bound
    tm.modify_lookahead(1, 5e-324)  # 5 + 5e-324 == 5: still zero lookahead for after()
    tm.request(1, TAR, 5.0)
    tm.release()
    assert tm.output_bound(1) == NEXT(5.0, INF)
    tm.modify_lookahead(1, 0.5)
    assert tm.output_bound(1) == 5.5


def test_enable_regulation_start_time() -> None:
    """enable_regulation starts at t0 = max(time, T, M - L), M over receivable times and promises."""
    tm = federation((1, 2.0, False), (2, None, True), (3, None, False), (4, None, False), (5, None, False))
    tm.request(2, TAR, 1.0)  # LBTS(2) = 2: granted 1, strictly
    assert grants(tm.release()) == {2: 1.0}
    assert tm.enable_regulation(3, 0.0, 0.5) == 1.5  # M = promise of 1 = 2
    assert tm.enable_regulation(4, 7.0, 0.5) == 7.0  # time
    tm.request(5, TAR, 9.0)  # not constrained: granted at once
    assert grants(tm.release()) == {5: 9.0}
    assert tm.enable_regulation(5, 0.0, 0.5) == 9.0  # T
    for f in (1, 3, 4, 5):
        tm.disable_regulation(f)
    tm.add_federate(6)
    assert tm.enable_regulation(6, 0.0, 0.0) == NEXT(1.0, INF)  # 2 was granted 1 by TAR: receives > 1
    assert tm.output_bound(6) == NEXT(1.0, INF)


@pytest.mark.parametrize("regulating_first", [False, True])
def test_tar_grant_stays_strict_for_newcomers(regulating_first: bool) -> None:
    """A TAR grant to T is final whatever the receiver's lookahead or later regulation: newcomers start > T."""
    tm = federation((1, 0.5 if regulating_first else None, True), (2, None, False))
    tm.request(1, TAR, 0.0)
    assert grants(tm.release()) == {1: 0.0}  # every TSO message <= 0 has been delivered to 1
    if regulating_first:
        tm.disable_regulation(1)  # its lookahead was 0.5 when granted
    else:
        assert tm.enable_regulation(1, 0.0, 0.0) == 0.0  # regulation does not undo what 1 received
        assert tm.release() == [(1, [], None, None, 0.0)]
        tm.disable_regulation(1)
    t0 = tm.enable_regulation(2, 0.0, 0.0)
    assert tm.release() == [(2, [], None, None, t0)]
    # a message at t0 (allowed: no grant yet, zero lookahead) must not reach 1 at its TAR-granted time 0
    tm.enqueue_tso(1, t0, 2, 0, tso_payload(t0, 2, 0))
    tm.request(1, TAR, 1.0)
    tm.request(2, TAR, 2.0)
    got = frames(tm.release()).get(1, [])
    assert [parse_tso(p)[0] for p in got] == [t0]
    assert t0 > 0.0, "newcomer may send at 0 to a federate already granted 0 by TAR"


@pytest.mark.parametrize("semantics, start", [("exact", NEXT(0.0, INF)), ("certi", 0.0)])
def test_a_regulator_joining_after_a_zero_lookahead_tar_grant(semantics: str, start: float) -> None:
    """1 (zero lookahead, regulating and constrained) was granted TAR(0) and asks TAR(0) again; 2 enables
    regulation: above 0 by the exact rules (nothing may reach 1 at 0 any more), at 0 by CERTI's, where its
    message at 0 still reaches 1 with 1's next grant to 0."""
    tm = _core._TimeManager(semantics)
    for f in (1, 2):
        tm.add_federate(f)
    assert tm.enable_regulation(1, 0.0, 0.0) == 0.0
    tm.enable_constrained(1)
    tm.release()
    tm.request(1, TAR, 0.0)
    assert grants(tm.release()) == {1: 0.0}
    tm.request(1, TAR, 0.0)
    assert tm.enable_regulation(2, 0.0, 0.0) == start
    # exact: 1 is granted at once (2 cannot send at 0); CERTI's: 1 waits for 2, which may send at 0
    assert grants(tm.release()) == ({1: 0.0} if semantics == "exact" else {})
    tm.enqueue_tso(1, start, 2, 0, tso_payload(start, 2, 0))
    tm.request(2, TAR, start)
    got = tm.release()
    assert grants(got) == ({2: start} if semantics == "exact" else {1: 0.0, 2: 0.0})
    assert [parse_tso(p)[0] for p in frames(got).get(1, [])] == ([] if semantics == "exact" else [0.0])


def test_enabling_regulation_never_moves_a_constrained_federate_past_its_messages() -> None:
    """A constrained federate enabling regulation must not jump past TSO messages it may still receive: it
    gets them first, then timeRegulationEnabled(t0), like a TARA(t0)."""
    tm = federation((1, 0.0, False), (2, 1.0, False), (3, None, True))
    t0 = tm.enable_regulation(3, 0.0, 0.0)  # M = promise of 2 = 1 although LBTS(3) = 0
    assert t0 == 1.0
    assert tm.release() == [] and tm.federate_time(3) == 0.0  # 1 may still send at 0
    assert tm.enabling_regulation(3) and tm.regulating(3) and not tm.holds_receive_order(3)
    assert tm.output_bound(3) == 1.0 and tm.lbts(1) == 1.0  # its bound counts at once
    tm.enqueue_tso(3, 0.0, 1, 0, tso_payload(0.0, 1, 0))  # legal: 1 may send at 0
    with pytest.raises(RuntimeError, match="request while enabling regulation"):
        tm.request(3, TAR, 2.0)
    tm.request(1, TAR, 3.0)  # not constrained: granted at once, LBTS(3) = min(next(3), 2 + 1) >= t0
    assert tm.release() == [(1, [], 3.0, None, None), (3, [tso_payload(0.0, 1, 0)], None, None, 1.0)]
    assert tm.federate_time(3) == 1.0 and not tm.enabling_regulation(3)
    tm.request(3, TAR, 2.0)
    tm.request(2, TAR, 3.0)
    assert grants(tm.release()) == {2: 3.0, 3: 2.0}


def test_regulation_enable_waits_for_lbts_and_delivers_only_up_to_t0() -> None:
    """The pending enable of a constrained federate completes once t0 <= LBTS (not <: like TARA), with the
    queued messages at or below t0 only; held receive-order messages go at once (it counts as advancing)."""
    tm = federation((1, 0.5, False), (2, None, True))
    tm.request(1, TAR, 2.0)  # 1's bound 2.5
    assert grants(tm.release()) == {1: 2.0}
    tm.enqueue_receive_order(2, b"ro")
    for ts, serial in ((2.5, 0), (3.0, 1), (4.0, 2)):
        tm.enqueue_tso(2, ts, 1, serial, tso_payload(ts, 1, serial))
    assert tm.enable_regulation(2, 3.0, 1.0) == 3.0
    assert tm.release() == [(2, [b"ro"], None, None, None)]  # LBTS(2) = 2.5 < 3
    tm.request(1, TAR, 2.5)  # LBTS(2) = 3 = t0: enough
    assert sorted(tm.release()) == [
        (1, [], 2.5, None, None),
        (2, [tso_payload(2.5, 1, 0), tso_payload(3.0, 1, 1)], None, None, 3.0),
    ]
    assert tm.federate_time(2) == 3.0 and tm.min_next_event_time(2) == 3.0
    # 1 may still send at 3 itself (its bound), so nothing was skipped: TAR(3) must wait for it
    tm.request(2, TAR, 3.0)
    assert tm.release() == []
    tm.enqueue_tso(2, 3.0, 1, 3, tso_payload(3.0, 1, 3))
    tm.request(1, TAR, 5.0)
    assert tm.release() == [(1, [], 5.0, None, None), (2, [tso_payload(3.0, 1, 3)], 3.0, None, None)]


def test_regulation_enable_completes_at_once_unless_constrained_and_ahead() -> None:
    """Not constrained, or t0 = T: the time is t0 at once and the callback comes with the next release; a
    pending enable is cancelled by disabling regulation and completed by disabling constraint."""
    tm = federation((1, 1.0, False), (2, None, False), (3, None, True), (4, None, True), (5, None, True))
    assert tm.enable_regulation(2, 0.0, 0.0) == 1.0  # M = promise of 1
    assert tm.federate_time(2) == 1.0 and tm.enabling_regulation(2)
    assert tm.enable_regulation(3, 0.0, 2.0) == 0.0  # t0 = T
    assert tm.release() == [(2, [], None, None, 1.0), (3, [], None, None, 0.0)]
    tm.disable_regulation(2)
    # 4 waits (LBTS 1 < t0 = 5); disabling regulation cancels it without a callback
    assert tm.enable_regulation(4, 5.0, 0.0) == 5.0
    assert tm.release() == [] and tm.lbts(1) == 2.0  # 3's bound 2 now, 4's bound 5
    tm.disable_regulation(4)
    assert tm.release() == [] and not tm.enabling_regulation(4) and tm.federate_time(4) == 0.0
    # 5 waits; disabling constraint hands back its messages (receive order now) and completes it
    tm.enqueue_tso(5, 1.5, 1, 0, tso_payload(1.5, 1, 0))
    assert tm.enable_regulation(5, 5.0, 0.0) == 5.0
    assert tm.release() == []
    assert tm.disable_constrained(5) == [tso_payload(1.5, 1, 0)]
    assert tm.release() == [(5, [], None, None, 5.0)]
    assert tm.federate_time(5) == 5.0
    with pytest.raises(RuntimeError, match="enable_regulation while regulating"):
        tm.enable_regulation(5, 6.0, 0.0)


def test_may_send_checks_the_promise() -> None:
    """may_send: anything from a federate that is not regulating; from a regulating one, nothing below the
    highest bound ever computed for it, even after its lookahead is lowered."""
    tm = federation((1, 2.0, False), (2, None, True))
    assert tm.may_send(2, -1e300) and tm.may_send(2, math.nan) and tm.promise(2) == -INF
    assert not tm.may_send(1, math.nan)
    assert tm.promise(1) == 2.0 and tm.may_send(1, 2.0) and not tm.may_send(1, NEXT(2.0, -INF))
    tm.modify_lookahead(1, 0.5)
    tm.release()
    assert tm.output_bound(1) == 2.0 and not tm.may_send(1, 1.0)
    tm.request(1, TAR, 3.0)
    tm.release()
    assert tm.promise(1) == 3.5 and not tm.may_send(1, 3.0) and tm.may_send(1, 3.5)
    tm.disable_regulation(1)
    assert tm.may_send(1, 0.0)


def test_receive_order_held_while_constrained_and_idle() -> None:
    """RO messages wait while constrained, idle and synchronous; released in order on request or async."""
    tm = federation((1, 1.0, False), (2, None, True))
    assert tm.holds_receive_order(2) and not tm.holds_receive_order(1)
    tm.enqueue_receive_order(2, b"r1")
    tm.enqueue_receive_order(2, b"r2")
    assert tm.release() == []
    tm.request(2, TAR, 5.0)  # cannot be granted (LBTS 1), but a request releases them
    assert not tm.holds_receive_order(2)
    assert tm.release() == [(2, [b"r1", b"r2"], None, None, None)]
    tm.request(1, TAR, 10.0)
    assert grants(tm.release()) == {1: 10.0, 2: 5.0}
    assert tm.holds_receive_order(2)
    tm.enqueue_receive_order(2, b"r3")
    assert tm.release() == []
    tm.set_asynchronous_delivery(2, True)
    assert not tm.holds_receive_order(2)
    assert tm.release() == [(2, [b"r3"], None, None, None)]


def test_disable_constrained_returns_queue_in_order() -> None:
    """disable_constrained hands back queued TSO messages by (time, sender, serial), not arrival."""
    tm = federation((1, 1.0, False), (2, 1.0, False), (3, None, True))
    sends = [(3.0, 2, 0), (1.5, 2, 1), (1.5, 1, 0), (1.5, 2, 2), (1.0, 2, 3)]
    for ts, sender, serial in sends:
        tm.enqueue_tso(3, ts, sender, serial, tso_payload(ts, sender, serial))
    assert [d["queued_tso"] for d in tm.status() if d["federate"] == 3] == [5]
    assert tm.min_next_event_time(3) == 1.0
    got = [parse_tso(p) for p in tm.disable_constrained(3)]
    assert got == sorted(sends)
    assert tm.release() == [] and not tm.is_tso(1, 3)


def test_retract_removes_undelivered_message() -> None:
    """retract removes a message from every queue where it still waits, and only there."""
    tm = federation((1, 1.0, False), (2, None, True), (3, None, True))
    for r in (2, 3):
        tm.enqueue_tso(r, 1.5, 1, 0, tso_payload(1.5, 1, 0))
        tm.enqueue_tso(r, 2.0, 1, 1, tso_payload(2.0, 1, 1))
    assert tm.retract(1, 0) == 2
    tm.request(1, TAR, 5.0)
    tm.request(2, TAR, 3.0)
    assert {f: fr for f, fr in frames(tm.release()).items() if fr} == {2: [tso_payload(2.0, 1, 1)]}
    assert tm.retract(1, 1) == 1  # 2 already has it; 3 still waits for it
    tm.request(3, TAR, 3.0)
    assert tm.release() == [(3, [], 3.0, None, None)]


def test_next_event_request_grants_at_each_message() -> None:
    """Three regulating+constrained federates (L=1) in NER(10) are granted exactly at their next messages."""
    tm = federation((1, 1.0, True), (2, 1.0, True), (3, 1.0, True))

    def send(sender: int, ts: float, serial: int) -> None:
        for r in (1, 2, 3):
            if r != sender:
                tm.enqueue_tso(r, ts, sender, serial, tso_payload(ts, sender, serial))

    send(1, 1.3, 0)
    send(2, 1.1, 0)
    send(3, 2.7, 0)
    tm.request(1, NER, 10.0)
    tm.request(2, NER, 10.0)
    assert tm.release() == []  # 3 may still send at 1
    tm.request(3, NER, 10.0)
    assert sorted(tm.release()) == [
        (1, [tso_payload(1.1, 2, 0)], 1.1, None, None),
        (2, [tso_payload(1.3, 1, 0)], 1.3, None, None),
        (3, [tso_payload(1.1, 2, 0)], 1.1, None, None),
    ]
    send(2, 2.31, 1)  # after its grant at 1.3, 2 may send from 2.3
    for f in (1, 2, 3):
        tm.request(f, NER, 10.0)
    assert tm.release() == [(3, [tso_payload(1.3, 1, 0)], 1.3, None, None)]
    tm.request(3, NER, 10.0)
    assert sorted(tm.release()) == [
        (1, [tso_payload(2.31, 2, 1)], 2.31, None, None),
        (2, [tso_payload(2.7, 3, 0)], 2.7, None, None),
        (3, [tso_payload(2.31, 2, 1)], 2.31, None, None),
    ]
    tm.request(1, NER, 10.0)
    tm.request(3, NER, 10.0)
    assert tm.release() == [(1, [tso_payload(2.7, 3, 0)], 2.7, None, None)]
    tm.request(1, NER, 10.0)
    tm.request(2, NER, 10.0)
    assert sorted(tm.release()) == [(1, [], 10.0, None, None), (2, [], 10.0, None, None), (3, [], 10.0, None, None)]
