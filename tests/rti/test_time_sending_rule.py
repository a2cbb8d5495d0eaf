"""The client's sending rule agrees with the gateway's check: random federations whose federates always send
at the lowest timestamp their client allows are never dropped, and nobody receives a TSO message in its past."""

from __future__ import annotations

import itertools
import math
import time

import hypothesis.strategies as st
from hypothesis import HealthCheck, given, settings

import hlacore
import hlacore.rti as rti

from support import ROBOT_FED

KINDS = ("timeAdvanceRequest", "timeAdvanceRequestAvailable", "nextEventRequest", "nextEventRequestAvailable",
         "flushQueueRequest")
LOOKAHEADS = st.sampled_from([0.0, 0.0, 0.5, 1.0, 2.5])
_federations = itertools.count()
END = 100.0


class Checker(rti.FederateAmbassador):
    """Checks every TSO message against the federate's time when it is delivered."""

    def __init__(self) -> None:
        self.rtia: rti.RTIAmbassador
        self.errors: list[str] = []
        self.received = 0

    def receiveInteraction(self, cls, params, tag, order, transport, time=None, retraction=None) -> None:  # type: ignore[no-untyped-def]
        if time is None:
            return
        self.received += 1
        now = self.rtia.queryFederateTime()
        if time < now:
            self.errors.append(f"TSO message at {time} delivered at federate time {now}")


operation = st.one_of(
    st.tuples(st.just("request"), st.integers(0, 2), st.sampled_from(KINDS), st.sampled_from([0.0, 0.5, 1.0, 3.0])),
    st.tuples(st.just("lookahead"), st.integers(0, 2), LOOKAHEADS),
    st.tuples(st.just("send"), st.integers(0, 2)),
    st.tuples(st.just("send"), st.integers(0, 2)),
    st.tuples(st.just("deliver"), st.integers(0, 2)),
)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(
    setup=st.lists(st.tuples(LOOKAHEADS, st.booleans(), st.booleans()), min_size=3, max_size=3),
    ops=st.lists(operation, min_size=5, max_size=40),
)
def test_federates_sending_at_their_lowest_allowed_time_are_never_dropped(
    inprocess_gateway: hlacore.Gateway, setup: list[tuple[float, bool, bool]], ops: list[tuple]  # type: ignore[type-arg]
) -> None:
    address = inprocess_gateway.address
    name = f"Rule{next(_federations)}"
    creator = rti.RTIAmbassador(address)
    creator.createFederationExecution(name, ROBOT_FED)
    feds = []
    for i, (lookahead, constrained_first, constrained) in enumerate(setup):
        rtia, amb = rti.RTIAmbassador(address), Checker()
        amb.rtia = rtia
        rtia.joinFederationExecution(f"f{i}", name, amb)
        command = rtia.getInteractionClassHandle("command")
        rtia.publishInteractionClass(command)
        rtia.subscribeInteractionClass(command)
        if constrained and constrained_first:
            rtia.enableTimeConstrained()
        rtia.enableTimeRegulation(0.0, lookahead)
        rtia.modifyLookahead(lookahead)  # while enabling: the client must keep the highest
        if constrained and not constrained_first:
            rtia.enableTimeConstrained()
        feds.append((rtia, amb, command, rtia.getParameterHandle("value", command)))
    for rtia, *_ in feds:
        rtia.queryLBTS()  # every subscription is in place before anyone sends
    # Enabling may have to wait for others to advance (a constrained federate's time cannot jump past
    # messages it may still receive), so the operations go on meanwhile; refused requests are skipped.
    for op in ops:
        rtia, amb, command, value = feds[op[1]]
        if op[0] == "request" and not rtia._time_advance_pending():
            try:
                getattr(rtia, op[2])(rtia.queryFederateTime() + op[3])
            except (rti.EnableTimeRegulationPending, rti.EnableTimeConstrainedPending):
                pass
        elif op[0] == "lookahead":
            rtia.modifyLookahead(op[2])
        elif op[0] == "send":
            lowest = rtia._lowest_sendable_time()
            if math.isfinite(lowest):
                rtia.sendInteraction(command, {value: b"x"}, "", lowest)
        rtia.tick()
    # Everyone advances to the end, so the messages sent are delivered (and checked) too.
    deadline = time.monotonic() + 5.0
    while time.monotonic() < deadline and any(r.queryFederateTime() < END for r, *_ in feds):
        for rtia, *_ in feds:
            if not rtia._time_advance_pending() and rtia.queryFederateTime() < END:
                try:
                    rtia.timeAdvanceRequest(END)
                except (rti.EnableTimeRegulationPending, rti.EnableTimeConstrainedPending):
                    pass
            rtia.tick(0.001, 0.01)
    for rtia, amb, *_ in feds:
        rtia.queryLBTS()  # raises RTIinternalError if the gateway dropped this federate
        assert amb.errors == []
    for rtia, *_ in feds:
        rtia.resignFederationExecution(rti.ResignAction.NoAction)
    creator.destroyFederationExecution(name)
