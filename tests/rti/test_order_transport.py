"""Transport and order changes (HLA 1.3 §6.19-6.22) through the real gateway (in-process and rtig): the
changed order and transport are used per message and reported in the callbacks, the changes belong to the
owner (or publisher) that made them, and every exception."""

from __future__ import annotations

import pathlib
from typing import Any, Callable

import pytest

import hlacore.rti as rti

from support import Federate, barrier, settle, tick_until

Join = Callable[[str], Federate]


def robot_with(a: Federate, b: Federate, name: str = "r1") -> tuple[rti.ObjectHandle, rti.AttributeHandle, rti.AttributeHandle]:
    """a publishes robot.location and robot.battery and registers an instance; b subscribes to both."""
    robot = a.rtia.getObjectClassHandle("robot")
    location = a.rtia.getAttributeHandle("location", robot)
    battery = a.rtia.getAttributeHandle("battery", robot)
    a.rtia.publishObjectClass(robot, [location, battery])
    b.rtia.subscribeObjectClassAttributes(robot, [location, battery])
    barrier(b.rtia)
    obj = a.rtia.registerObjectInstance(robot, name)
    tick_until(lambda: bool(b.amb.named("discoverObjectInstance")), b.rtia)
    return obj, location, battery


def delivered(fed: Federate, callback: str) -> list[tuple[dict, str, str, object]]:
    """Each reflectAttributeValues or receiveInteraction as (values, ordering name, transportation name,
    time or None)."""
    out = []
    for args in fed.amb.named(callback):
        time = args[5] if len(args) == 7 else None
        out.append((args[1], fed.rtia.getOrderingName(args[3]), fed.rtia.getTransportationName(args[4]), time))
    return out


def reflections(fed: Federate) -> list[tuple[dict, str, str, object]]:
    return delivered(fed, "reflectAttributeValues")


def receptions(fed: Federate) -> list[tuple[dict, str, str, object]]:
    return delivered(fed, "receiveInteraction")


def location_in_receive_order(federation: Join) -> tuple[Federate, Federate, Any, Any, Any]:
    """'a' regulates and owns a robot whose location it changed to receive order; 'b' is constrained with
    asynchronous delivery and subscribes location and battery."""
    a, b = federation("a"), federation("b")
    obj, location, battery = robot_with(a, b)
    a.enable_time(lookahead=1.0, constrained=False)
    b.enable_time(lookahead=None)
    b.rtia.enableAsynchronousDelivery()
    a.rtia.changeAttributeOrderType(obj, [location], a.rtia.getOrderingHandle("Receive"))
    return a, b, obj, location, battery


def test_timestamp_attribute_changed_to_receive_order_arrives_receive_order(federation: Join) -> None:
    a, b, obj, location, battery = location_in_receive_order(federation)
    # From a regulating sender to a constrained receiver, with a time: location goes receive order (no
    # time), battery (timestamp in the FOM, unchanged) waits for b's grant.
    a.rtia.updateAttributeValues(obj, {location: b"here", battery: b"90"}, "t", 5.0)
    tick_until(lambda: bool(b.amb.named("reflectAttributeValues")), b.rtia)
    settle(b.rtia)
    assert reflections(b) == [({location: b"here"}, "Receive", "HLAreliable", None)]
    assert a.rtia.advance_to(5.0, timeout=5.0) == 5.0
    assert b.rtia.advance_to(5.0, timeout=5.0) == 5.0
    assert reflections(b)[1:] == [({battery: b"90"}, "Timestamp", "HLAreliable", 5.0)]
    # Changed back to timestamp, location goes timestamp order again.
    a.rtia.changeAttributeOrderType(obj, [location], a.rtia.getOrderingHandle("Timestamp"))
    a.rtia.updateAttributeValues(obj, {location: b"there"}, "t", 7.0)
    assert a.rtia.advance_to(7.0, timeout=5.0) == 7.0
    assert b.rtia.advance_to(7.0, timeout=5.0) == 7.0
    assert reflections(b)[2:] == [({location: b"there"}, "Timestamp", "HLAreliable", 7.0)]


def test_an_attribute_order_change_is_forgotten_when_ownership_moves(federation: Join) -> None:
    a, b, obj, location, battery = location_in_receive_order(federation)
    a.rtia.unconditionalAttributeOwnershipDivestiture(obj, [location])
    a.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [location])
    tick_until(lambda: bool(a.amb.named("attributeOwnershipAcquisitionNotification")), a.rtia)
    a.rtia.updateAttributeValues(obj, {location: b"back"}, "t", 3.0)
    barrier(a.rtia)
    settle(b.rtia)
    assert reflections(b) == []  # timestamp order again: held until b's grant
    assert a.rtia.advance_to(3.0, timeout=5.0) == 3.0
    assert b.rtia.advance_to(3.0, timeout=5.0) == 3.0
    assert reflections(b) == [({location: b"back"}, "Timestamp", "HLAreliable", 3.0)]


def test_receive_interaction_changed_to_timestamp_arrives_timestamp_order(federation: Join) -> None:
    a, b = federation("a"), federation("b")
    reply = a.rtia.getInteractionClassHandle("reply")  # best_effort receive in the FOM
    value = a.rtia.getParameterHandle("value", reply)
    a.rtia.publishInteractionClass(reply)
    b.rtia.subscribeInteractionClass(reply)
    a.enable_time(lookahead=1.0, constrained=False)
    b.enable_time(lookahead=None)
    b.rtia.enableAsynchronousDelivery()
    barrier(b.rtia)
    a.rtia.sendInteraction(reply, {value: b"ro"}, "", 2.0)
    tick_until(lambda: bool(b.amb.named("receiveInteraction")), b.rtia)
    assert receptions(b) == [({value: b"ro"}, "Receive", "HLAbestEffort", None)]
    a.rtia.changeInteractionOrderType(reply, a.rtia.getOrderingHandle("Timestamp"))
    a.rtia.sendInteraction(reply, {value: b"tso"}, "", 3.0)
    barrier(a.rtia)
    settle(b.rtia)
    assert len(receptions(b)) == 1  # held for the grant
    assert a.rtia.advance_to(3.0, timeout=5.0) == 3.0
    assert b.rtia.advance_to(3.0, timeout=5.0) == 3.0
    assert receptions(b)[1:] == [({value: b"tso"}, "Timestamp", "HLAbestEffort", 3.0)]
    # Unpublishing forgets the change: published again, the class is receive order as in the FOM.
    a.rtia.unpublishInteractionClass(reply)
    a.rtia.publishInteractionClass(reply)
    a.rtia.sendInteraction(reply, {value: b"ro again"}, "", 5.0)
    tick_until(lambda: len(b.amb.named("receiveInteraction")) == 3, b.rtia)
    assert receptions(b)[2:] == [({value: b"ro again"}, "Receive", "HLAbestEffort", None)]


def test_transport_changes_are_reported_in_the_callbacks(federation: Join) -> None:
    a, b = federation("a"), federation("b")
    obj, location, battery = robot_with(a, b)
    command = a.rtia.getInteractionClassHandle("command")  # reliable timestamp in the FOM
    value = a.rtia.getParameterHandle("value", command)
    a.rtia.publishInteractionClass(command)
    b.rtia.subscribeInteractionClass(command)
    barrier(b.rtia)
    best_effort = a.rtia.getTransportationHandle("HLAbestEffort")
    a.rtia.changeAttributeTransportationType(obj, [location], best_effort)
    a.rtia.changeInteractionTransportationType(command, best_effort)
    a.rtia.updateAttributeValues(obj, {location: b"l", battery: b"b"}, "")
    a.rtia.sendInteraction(command, {value: b"v"}, "")
    tick_until(lambda: len(b.amb.named("reflectAttributeValues")) == 2 and bool(b.amb.named("receiveInteraction")),
               b.rtia)
    assert sorted(reflections(b), key=lambda r: r[2]) == [
        ({location: b"l"}, "Receive", "HLAbestEffort", None),
        ({battery: b"b"}, "Receive", "HLAreliable", None),
    ]
    assert receptions(b) == [({value: b"v"}, "Receive", "HLAbestEffort", None)]
    # Back to reliable: one reflection again.
    a.rtia.changeAttributeTransportationType(obj, [location], a.rtia.getTransportationHandle("HLAreliable"))
    a.rtia.updateAttributeValues(obj, {location: b"l2", battery: b"b2"}, "")
    tick_until(lambda: len(b.amb.named("reflectAttributeValues")) == 3, b.rtia)
    assert reflections(b)[2] == ({location: b"l2", battery: b"b2"}, "Receive", "HLAreliable", None)


def test_a_new_owner_does_not_inherit_the_previous_owners_change(federation: Join) -> None:
    a, b = federation("a"), federation("b")
    obj, location, battery = robot_with(a, b)
    robot = b.rtia.getObjectClassHandle("robot")
    b.rtia.publishObjectClass(robot, [location])
    a.rtia.subscribeObjectClassAttributes(robot, [location])
    a.rtia.changeAttributeTransportationType(obj, [location], a.rtia.getTransportationHandle("HLAbestEffort"))
    a.rtia.unconditionalAttributeOwnershipDivestiture(obj, [location])
    barrier(a.rtia)
    b.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [location])
    tick_until(lambda: bool(b.amb.named("attributeOwnershipAcquisitionNotification")), b.rtia)
    b.rtia.updateAttributeValues(obj, {location: b"b's"}, "")
    tick_until(lambda: bool(a.amb.named("reflectAttributeValues")), a.rtia)
    assert reflections(a) == [({location: b"b's"}, "Receive", "HLAreliable", None)]


def test_exceptions(federation: Join, gateway_address: str, tmp_path: pathlib.Path) -> None:
    a, b = federation("a"), federation("b")
    robot = a.rtia.getObjectClassHandle("robot")
    location = a.rtia.getAttributeHandle("location", robot)
    battery = a.rtia.getAttributeHandle("battery", robot)
    sonar = a.rtia.getAttributeHandle("sonar", a.rtia.getObjectClassHandle("turtlebot"))
    reply = a.rtia.getInteractionClassHandle("reply")
    receive = a.rtia.getOrderingHandle("Receive")
    reliable = a.rtia.getTransportationHandle("HLAreliable")
    a.rtia.publishObjectClass(robot, [location])
    obj = a.rtia.registerObjectInstance(robot, "r1")

    with pytest.raises(rti.ObjectNotKnown):
        b.rtia.changeAttributeOrderType(obj, [location], receive)
    with pytest.raises(rti.ObjectNotKnown):
        b.rtia.changeAttributeTransportationType(obj, [location], reliable)
    for change, handle in ((a.rtia.changeAttributeOrderType, receive),
                           (a.rtia.changeAttributeTransportationType, reliable)):
        with pytest.raises(rti.AttributeNotDefined):
            change(obj, [location, sonar], handle)
        with pytest.raises(rti.AttributeNotOwned):
            change(obj, [location, battery], handle)  # battery is not published, so unowned
    b.rtia.subscribeObjectClassAttributes(robot, [location])
    tick_until(lambda: bool(b.amb.named("discoverObjectInstance")), b.rtia)
    with pytest.raises(rti.AttributeNotOwned):
        b.rtia.changeAttributeOrderType(obj, [location], receive)
    with pytest.raises(rti.InvalidOrderingHandle):
        a.rtia.changeAttributeOrderType(obj, [location], rti._core._ordering_handle(3))
    with pytest.raises(rti.InvalidTransportationHandle):
        a.rtia.changeAttributeTransportationType(obj, [location], rti._core._transportation_handle(0))
    with pytest.raises(TypeError):
        a.rtia.changeAttributeOrderType(obj, [location], 1)  # type: ignore[arg-type]
    with pytest.raises(TypeError):
        a.rtia.changeAttributeTransportationType(obj, [location], receive)  # type: ignore[arg-type]

    with pytest.raises(rti.InteractionClassNotPublished):
        a.rtia.changeInteractionOrderType(reply, receive)
    with pytest.raises(rti.InteractionClassNotPublished):
        a.rtia.changeInteractionTransportationType(reply, reliable)
    a.rtia.publishInteractionClass(reply)
    with pytest.raises(rti.InvalidOrderingHandle):
        a.rtia.changeInteractionOrderType(reply, rti._core._ordering_handle(0))
    with pytest.raises(rti.InvalidTransportationHandle):
        a.rtia.changeInteractionTransportationType(reply, rti._core._transportation_handle(3))
    # An interaction class handle beyond robot.fed's, from a federation with a larger FOM.
    fed = tmp_path / "many.fed"
    classes = "".join(f"   (class extra{k} reliable receive)\n" for k in range(20))
    fed.write_text(f"(FED (Federation Many) (FEDversion v1.3) (spaces) (objects (class ObjectRoot))\n"
                   f" (interactions\n  (class InteractionRoot reliable receive\n{classes}  )))\n")
    other = rti.RTIAmbassador(gateway_address)
    other.createFederationExecution("Many", str(fed))
    try:
        other.joinFederationExecution("o", "Many", rti.FederateAmbassador())
        undefined = other.getInteractionClassHandle("extra19")
        with pytest.raises(rti.InteractionClassNotDefined):
            a.rtia.changeInteractionOrderType(undefined, receive)
        with pytest.raises(rti.InteractionClassNotDefined):
            a.rtia.changeInteractionTransportationType(undefined, reliable)
        other.resignFederationExecution(rti.ResignAction.NoAction)
    finally:
        other.destroyFederationExecution("Many")

    outsider = rti.RTIAmbassador(gateway_address)
    for call in (lambda: outsider.changeAttributeOrderType(obj, [location], receive),
                 lambda: outsider.changeAttributeTransportationType(obj, [location], reliable),
                 lambda: outsider.changeInteractionOrderType(reply, receive),
                 lambda: outsider.changeInteractionTransportationType(reply, reliable)):
        with pytest.raises(rti.FederateNotExecutionMember):
            call()
    # Nothing refused reached the gateway as a protocol violation: a still works.
    a.rtia.changeAttributeOrderType(obj, [location], receive)
    a.rtia.changeInteractionOrderType(reply, a.rtia.getOrderingHandle("Timestamp"))
    barrier(a.rtia)
