"""Time management through the real gateway (in-process and rtig): services, callbacks, the sending rule,
TSO delivery before grants, NER at message times, zero lookahead, retraction and receive-order holding."""

from __future__ import annotations

import asyncio
import math
import threading
from typing import Callable

import pytest

import hlacore.rti as rti
from hlacore.aio import AsyncAmbassador

from support import Federate, barrier, settle, tick_until

Join = Callable[[str], Federate]
INF = math.inf


def robot_location(fed: Federate) -> tuple[rti.ObjectClassHandle, rti.AttributeHandle]:
    robot = fed.rtia.getObjectClassHandle("robot")
    return robot, fed.rtia.getAttributeHandle("location", robot)


def command_class(fed: Federate) -> tuple[rti.InteractionClassHandle, rti.ParameterHandle]:
    command = fed.rtia.getInteractionClassHandle("command")
    return command, fed.rtia.getParameterHandle("value", command)


def regulating_sender_constrained_receiver(
    federation: Join,
) -> tuple[Federate, Federate, rti.InteractionClassHandle, rti.ParameterHandle]:
    """'a' publishes command and regulates (lookahead 1), 'b' subscribes and is constrained only."""
    a, b = federation("a"), federation("b")
    command, value = command_class(a)
    a.rtia.publishInteractionClass(command)
    b.rtia.subscribeInteractionClass(command)
    a.enable_time(lookahead=1.0, constrained=False)
    b.enable_time(lookahead=None)
    barrier(b.rtia)
    return a, b, command, value


def timeline(fed: Federate) -> list[tuple[str, float]]:
    """The federate's timestamped callbacks and grants, as (name, time), in delivery order."""
    out = []
    for name, args in fed.amb.calls:
        if name == "timeAdvanceGrant":
            out.append(("grant", args[0]))
        elif name in ("reflectAttributeValues", "receiveInteraction") and len(args) == 7:
            out.append((name, args[5]))
    return out


def test_time_state_before_and_after_enabling(federation: Join) -> None:
    a, b = federation("a"), federation("b")
    assert a.rtia.queryFederateTime() == 0.0
    assert a.rtia.queryLookahead() == 0.0
    assert a.rtia.queryLBTS() == INF
    assert a.rtia.queryMinNextEventTime() == INF
    a.enable_time(lookahead=2.5)
    assert a.amb.named("timeRegulationEnabled") == [(0.0,)]
    assert a.amb.named("timeConstrainedEnabled") == [(0.0,)]
    assert a.rtia.queryLookahead() == 2.5
    assert b.rtia.queryLBTS() == 2.5
    assert b.rtia.queryMinNextEventTime() == 2.5
    assert a.rtia.queryLBTS() == INF  # no other regulating federate


def test_lockstep_updates_arrive_in_order_before_the_grant_to_their_time(federation: Join) -> None:
    """The paper-2 lockstep in one process: both regulating and constrained, lookahead 1, TSO updates."""
    a, b = federation("a"), federation("b")
    robot, location = robot_location(a)
    a.rtia.publishObjectClass(robot, [location])
    b.rtia.subscribeObjectClassAttributes(robot, [location])
    a.enable_time()
    b.enable_time()
    barrier(b.rtia)
    obj = a.rtia.registerObjectInstance(robot, "r1")
    steps = 50
    handles = []
    for k in range(steps):
        handles.append(a.rtia.updateAttributeValues(obj, {location: b"%d" % k}, "step", k + 1.0))
        a.rtia.timeAdvanceRequest(k + 1.0)
        b.rtia.timeAdvanceRequest(k + 1.0)
        assert a.rtia.await_grant(5.0) == k + 1.0
        assert b.rtia.await_grant(5.0) == k + 1.0
    expected = []
    for k in range(steps):
        expected += [("reflectAttributeValues", k + 1.0), ("grant", k + 1.0)]
    assert timeline(b) == expected
    reflections = b.amb.named("reflectAttributeValues")
    assert [r[1][location] for r in reflections] == [b"%d" % k for k in range(steps)]
    assert {b.rtia.getOrderingName(r[3]) for r in reflections} == {"Timestamp"}
    assert [r[6] for r in reflections] == handles
    assert all(h.sendingFederate == int(a.handle) for h in handles)


def test_sending_rule_raises_invalid_federation_time(federation: Join) -> None:
    a = federation("a")
    command, value = command_class(a)
    a.rtia.publishInteractionClass(command)
    a.enable_time(lookahead=1.0, constrained=False)
    with pytest.raises(rti.InvalidFederationTime, match="below 1"):
        a.rtia.sendInteraction(command, {value: b"x"}, "", 0.5)
    for not_finite in (math.nan, math.inf, -math.inf):
        with pytest.raises(rti.InvalidFederationTime, match="not finite"):
            a.rtia.sendInteraction(command, {value: b"x"}, "", not_finite)
    assert isinstance(a.rtia.sendInteraction(command, {value: b"x"}, "", 1.0), rti.EventRetractionHandle)
    # While a request for 5 is pending, nothing below 5 + lookahead may be sent.
    a.rtia.timeAdvanceRequest(5.0)
    with pytest.raises(rti.InvalidFederationTime, match="requested time 5"):
        a.rtia.sendInteraction(command, {value: b"x"}, "", 5.5)
    assert a.rtia.await_grant(5.0) == 5.0
    # A lower lookahead never allows a timestamp below one allowed before (HLA 1.3 §8.18).
    a.rtia.modifyLookahead(0.25)
    assert a.rtia.queryLookahead() == 0.25
    with pytest.raises(rti.InvalidFederationTime):
        a.rtia.sendInteraction(command, {value: b"x"}, "", 5.5)
    a.rtia.sendInteraction(command, {value: b"x"}, "", 6.0)
    # Without regulation a timestamp is only a label: the message goes receive order.
    a.rtia.disableTimeRegulation()
    assert a.rtia.sendInteraction(command, {value: b"x"}, "", 0.0) is not None


def test_time_service_exceptions(federation: Join) -> None:
    a = federation("a")
    r = a.rtia
    with pytest.raises(rti.TimeRegulationWasNotEnabled):
        r.disableTimeRegulation()
    with pytest.raises(rti.TimeConstrainedWasNotEnabled):
        r.disableTimeConstrained()
    with pytest.raises(rti.InvalidLookahead):
        r.enableTimeRegulation(0.0, -1.0)
    with pytest.raises(rti.InvalidLookahead):
        r.modifyLookahead(math.nan)
    with pytest.raises(rti.InvalidFederationTime):
        r.enableTimeRegulation(math.inf, 1.0)
    with pytest.raises(rti.TimeAdvanceWasNotInProgress):
        r.await_grant()
    r.enableTimeRegulation(0.0, 1.0)
    with pytest.raises(rti.EnableTimeRegulationPending):
        r.enableTimeRegulation(0.0, 1.0)
    with pytest.raises(rti.EnableTimeRegulationPending):
        r.timeAdvanceRequest(1.0)  # the callback has not been delivered yet
    tick_until(lambda: bool(a.amb.named("timeRegulationEnabled")), r)
    with pytest.raises(rti.TimeRegulationAlreadyEnabled):
        r.enableTimeRegulation(0.0, 1.0)
    r.enableTimeConstrained()
    with pytest.raises(rti.EnableTimeConstrainedPending):
        r.enableTimeConstrained()
    with pytest.raises(rti.EnableTimeConstrainedPending):
        r.nextEventRequest(1.0)
    tick_until(lambda: bool(a.amb.named("timeConstrainedEnabled")), r)
    with pytest.raises(rti.TimeConstrainedAlreadyEnabled):
        r.enableTimeConstrained()
    assert r.advance_to(3.0, timeout=5.0) == 3.0
    with pytest.raises(rti.FederationTimeAlreadyPassed):
        r.timeAdvanceRequest(2.0)
    for not_finite in (math.nan, math.inf):
        with pytest.raises(rti.InvalidFederationTime, match="not finite"):
            r.timeAdvanceRequest(not_finite)
        with pytest.raises(rti.InvalidFederationTime, match="not finite"):
            r.nextEventRequest(not_finite)
    with pytest.raises(rti.InvalidLookahead):
        r.modifyLookahead(math.inf)
    r.timeAdvanceRequest(4.0)
    with pytest.raises(rti.TimeAdvanceAlreadyInProgress):
        r.nextEventRequest(5.0)
    with pytest.raises(rti.TimeAdvanceAlreadyInProgress):
        r.flushQueueRequest(5.0)
    assert r.await_grant(5.0) == 4.0
    r.enableAsynchronousDelivery()
    with pytest.raises(rti.AsynchronousDeliveryAlreadyEnabled):
        r.enableAsynchronousDelivery()
    r.disableAsynchronousDelivery()
    with pytest.raises(rti.AsynchronousDeliveryAlreadyDisabled):
        r.disableAsynchronousDelivery()


def test_a_grant_to_the_current_time_is_allowed(federation: Join) -> None:
    """PyHLA federates commonly ask for their current time (the papers' TAR(queryFederateTime()))."""
    a = federation("a")
    a.enable_time()
    assert a.rtia.advance_to(a.rtia.queryFederateTime(), timeout=5.0) == 0.0


def test_zero_lookahead_with_available_requests(federation: Join) -> None:
    """Zero lookahead needs TARA: after a TARA grant to t a federate may send at t itself, after TAR only above."""
    a, b = federation("a"), federation("b")
    command, value = command_class(a)
    a.rtia.publishInteractionClass(command)
    b.rtia.subscribeInteractionClass(command)
    a.enable_time(lookahead=0.0)
    b.enable_time(lookahead=0.0)
    barrier(b.rtia)
    a.rtia.timeAdvanceRequestAvailable(1.0)
    b.rtia.timeAdvanceRequestAvailable(1.0)
    assert a.rtia.await_grant(5.0) == 1.0
    assert b.rtia.await_grant(5.0) == 1.0
    a.rtia.sendInteraction(command, {value: b"at 1"}, "", 1.0)  # allowed after TARA
    b.rtia.timeAdvanceRequest(2.0)
    a.rtia.timeAdvanceRequest(2.0)
    assert a.rtia.await_grant(5.0) == 2.0
    assert b.rtia.await_grant(5.0) == 2.0
    assert timeline(b)[-2:] == [("receiveInteraction", 1.0), ("grant", 2.0)]
    with pytest.raises(rti.InvalidFederationTime):
        a.rtia.sendInteraction(command, {value: b"x"}, "", 2.0)  # after TAR: strictly above 2
    a.rtia.sendInteraction(command, {value: b"above 2"}, "", math.nextafter(2.0, INF))


def test_next_event_requests_grant_exactly_at_message_times(federation: Join) -> None:
    """Three regulating+constrained federates, each driven by NER to its own irregular events; at each own
    event it sends a command 0.5 later. Every grant lands exactly on an own event or a received message."""
    names = ("a", "b", "c")
    events = {"a": [1.7, 4.2], "b": [2.9, 8.05], "c": [3.3]}
    end = 10.0
    feds = {n: federation(n) for n in names}
    for fed in feds.values():
        command, _ = command_class(fed)
        fed.rtia.publishInteractionClass(command)
        fed.rtia.subscribeInteractionClass(command)
    for fed in feds.values():
        fed.enable_time(lookahead=0.1)
    for fed in feds.values():
        barrier(fed.rtia)
    grants: dict[str, list[float]] = {n: [] for n in names}
    errors: list[BaseException] = []

    def run(name: str) -> None:
        fed = feds[name]
        command, value = command_class(fed)
        own = list(events[name])
        try:
            while True:
                target = own[0] if own else end
                granted = fed.rtia.next_event(target, timeout=10.0)
                grants[name].append(granted)
                if own and granted == own[0]:
                    fed.rtia.sendInteraction(command, {value: name.encode()}, "", own.pop(0) + 0.5)
                if granted == end:
                    return
        except BaseException as e:  # reported by the main thread
            errors.append(e)

    threads = [threading.Thread(target=run, args=(n,)) for n in names]
    for t in threads:
        t.start()
    for t in threads:
        t.join(30)
    assert not errors, errors
    sent = {n: [t + 0.5 for t in events[n]] for n in names}
    for n in names:
        received = sorted(t for m in names if m != n for t in sent[m])
        assert grants[n] == sorted(set(events[n] + received + [end])), n
        assert [t for name, t in timeline(feds[n]) if name == "receiveInteraction"] == received


def test_retraction_removes_queued_messages_and_asks_receivers(federation: Join) -> None:
    a, b, command, value = regulating_sender_constrained_receiver(federation)
    at5 = a.rtia.sendInteraction(command, {value: b"5"}, "", 5.0)
    at7 = a.rtia.sendInteraction(command, {value: b"7"}, "", 7.0)
    a.rtia.retract(at7)  # still queued at b: it disappears
    with pytest.raises(rti.InvalidRetractionHandle):
        a.rtia.retract(at7)
    with pytest.raises(rti.InvalidRetractionHandle):
        b.rtia.retract(at5)  # not b's message
    assert a.rtia.advance_to(4.5, timeout=5.0) == 4.5
    assert b.rtia.next_event(10.0, timeout=5.0) == 5.0
    assert timeline(b) == [("receiveInteraction", 5.0), ("grant", 5.0)]
    a.rtia.retract(at5)  # b already has it: b is asked to retract it
    tick_until(lambda: bool(b.amb.named("requestRetraction")), b.rtia)
    assert b.amb.named("requestRetraction") == [(at5,)]
    assert a.rtia.advance_to(9.5, timeout=5.0) == 9.5
    with pytest.raises(rti.InvalidRetractionHandle):
        a.rtia.retract(at5)  # at or below a's time now
    assert b.rtia.next_event(10.0, timeout=5.0) == 10.0
    assert timeline(b)[-1] == ("grant", 10.0)
    assert [t for n, t in timeline(b) if n == "receiveInteraction"] == [5.0]


def test_a_retraction_handle_is_a_value_naming_one_message(federation: Join) -> None:
    """The sender's handle and the one its receiver gets are equal and hash alike; each message has its own;
    only the RTI makes them (bindings/retraction.cpp)."""
    a, b, command, value = regulating_sender_constrained_receiver(federation)
    at5 = a.rtia.sendInteraction(command, {value: b"5"}, "", 5.0)
    at6 = a.rtia.sendInteraction(command, {value: b"6"}, "", 6.0)
    assert a.rtia.advance_to(5.5, timeout=5.0) == 5.5
    assert b.rtia.next_event(5.5, timeout=5.0) == 5.0
    received = b.amb.named("receiveInteraction")[0][6]
    assert received == at5 and not received != at5 and hash(received) == hash(at5)
    assert received is not at5 and at5 != at6 and {at5: 5, at6: 6}[received] == 5
    assert isinstance(at5.sendingFederate, int) and at5.sendingFederate == at6.sendingFederate
    assert at6.serial == at5.serial + 1
    assert repr(at5) == f"<rti.EventRetractionHandle={at5.sendingFederate}:{at5.serial}>"
    assert at5 != (at5.sendingFederate, at5.serial)
    with pytest.raises(TypeError):
        type(at5)()
    with pytest.raises(TypeError):
        a.rtia.retract((at5.sendingFederate, at5.serial))


def test_retraction_reaches_every_receiver_of_the_message(federation: Join) -> None:
    """The gateway keeps one routing record per timestamped message with all its receivers."""
    a, b, command, value = regulating_sender_constrained_receiver(federation)
    c = federation("c")
    c.rtia.subscribeInteractionClass(command)
    c.enable_time(lookahead=None)
    barrier(c.rtia)
    at5 = a.rtia.sendInteraction(command, {value: b"5"}, "", 5.0)
    assert a.rtia.advance_to(4.5, timeout=5.0) == 4.5
    for receiver in (b, c):
        assert receiver.rtia.next_event(10.0, timeout=5.0) == 5.0
    a.rtia.retract(at5)  # both have it: both are asked to retract it
    tick_until(lambda: bool(b.amb.named("requestRetraction") and c.amb.named("requestRetraction")), b.rtia, c.rtia)
    assert b.amb.named("requestRetraction") == c.amb.named("requestRetraction") == [(at5,)]


def test_a_timestamped_update_reaches_each_receiver_with_its_own_attributes(federation: Join) -> None:
    """Receivers of one timestamped update that subscribe different attributes get exactly theirs (the gateway
    encodes the reflection once for the receivers that get the same attributes)."""
    a = federation("a")
    robot, location = robot_location(a)
    compass = a.rtia.getAttributeHandle("compass", robot)
    a.rtia.publishObjectClass(robot, [location, compass])
    a.enable_time(lookahead=1.0, constrained=False)
    subscriptions = {"b": [location], "c": [location, compass], "d": [location]}
    receivers = {name: federation(name) for name in subscriptions}
    for name, receiver in receivers.items():
        receiver.rtia.subscribeObjectClassAttributes(robot, subscriptions[name])
        receiver.enable_time(lookahead=None)
        barrier(receiver.rtia)
    obj = a.rtia.registerObjectInstance(robot)
    a.rtia.updateAttributeValues(obj, {location: b"L", compass: b"C"}, "", 5.0)
    assert a.rtia.advance_to(4.5, timeout=5.0) == 4.5
    for name, receiver in receivers.items():
        assert receiver.rtia.next_event(10.0, timeout=5.0) == 5.0
        reflected = receiver.amb.named("reflectAttributeValues")
        assert [(args[1], args[5]) for args in reflected] == [
            ({h: {location: b"L", compass: b"C"}[h] for h in subscriptions[name]}, 5.0)]


def test_receive_order_is_held_from_a_constrained_federate_until_it_advances(federation: Join) -> None:
    a, b = federation("a"), federation("b")
    reply = a.rtia.getInteractionClassHandle("reply")
    value = a.rtia.getParameterHandle("value", reply)
    a.rtia.publishInteractionClass(reply)
    b.rtia.subscribeInteractionClass(reply)
    b.enable_time(lookahead=None)
    barrier(b.rtia)
    a.rtia.sendInteraction(reply, {value: b"held"}, "")
    settle(b.rtia)
    assert b.amb.named("receiveInteraction") == []
    assert b.rtia.advance_to(1.0, timeout=5.0) == 1.0  # no regulator: granted at once, RO released first
    assert [args[1][value] for args in b.amb.named("receiveInteraction")] == [b"held"]
    b.rtia.enableAsynchronousDelivery()
    a.rtia.sendInteraction(reply, {value: b"async"}, "")
    tick_until(lambda: len(b.amb.named("receiveInteraction")) == 2, b.rtia)


def test_timestamped_messages_of_a_non_regulating_sender_are_receive_order(federation: Join) -> None:
    a, b = federation("a"), federation("b")
    command, value = command_class(a)
    a.rtia.publishInteractionClass(command)
    b.rtia.subscribeInteractionClass(command)
    b.enable_time(lookahead=None)
    b.rtia.enableAsynchronousDelivery()
    barrier(b.rtia)
    assert a.rtia.sendInteraction(command, {value: b"x"}, "", 42.0) is not None
    tick_until(lambda: bool(b.amb.named("receiveInteraction")), b.rtia)
    (args,) = b.amb.named("receiveInteraction")
    assert b.rtia.getOrderingName(args[3]) == "Receive"


def test_disabling_constrained_delivers_the_queued_messages(federation: Join) -> None:
    a, b, command, value = regulating_sender_constrained_receiver(federation)
    a.rtia.sendInteraction(command, {value: b"6"}, "", 6.0)
    a.rtia.sendInteraction(command, {value: b"5"}, "", 5.0)
    barrier(a.rtia)
    settle(b.rtia)
    assert b.amb.named("receiveInteraction") == []
    b.rtia.disableTimeConstrained()
    tick_until(lambda: len(b.amb.named("receiveInteraction")) == 2, b.rtia)
    assert [args[1][value] for args in b.amb.named("receiveInteraction")] == [b"5", b"6"]


def test_asyncio_advance_waits_on_the_socket(federation: Join) -> None:
    a, b = federation("a"), federation("b")
    a.enable_time()
    b.enable_time()

    async def lockstep() -> list[tuple[float, float]]:
        fa, fb = AsyncAmbassador(a.rtia), AsyncAmbassador(b.rtia)
        out = []
        for k in range(1, 21):
            out.append(tuple(await asyncio.gather(fa.advance_to(float(k)), fb.next_event(float(k)))))
        return out

    assert asyncio.run(asyncio.wait_for(lockstep(), 30)) == [(float(k), float(k)) for k in range(1, 21)]
    assert a.amb.named("timeAdvanceGrant") == [(float(k),) for k in range(1, 21)]


def test_await_grant_times_out_with_the_request_still_pending(federation: Join) -> None:
    a, b = federation("a"), federation("b")
    a.enable_time()
    b.enable_time()
    with pytest.raises(TimeoutError, match=r"^no time advance grant within 0\.2 s$"):
        a.rtia.advance_to(5.0, timeout=0.2)  # b has not moved: LBTS(a) = 1
    with pytest.raises(rti.TimeAdvanceAlreadyInProgress):
        a.rtia.timeAdvanceRequest(6.0)
    b.rtia.timeAdvanceRequest(5.0)
    assert a.rtia.await_grant(5.0) == 5.0
    assert b.rtia.await_grant(5.0) == 5.0


def test_a_resigning_regulator_releases_the_federates_waiting_on_it(federation: Join) -> None:
    a, b = federation("a"), federation("b")
    a.enable_time()
    b.enable_time()
    a.rtia.timeAdvanceRequest(10.0)
    with pytest.raises(TimeoutError):
        a.rtia.await_grant(0.2)  # b, at 0 with lookahead 1, holds a's LBTS at 1
    b.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    assert a.rtia.await_grant(5.0) == 10.0
    assert a.rtia.queryLBTS() == INF
