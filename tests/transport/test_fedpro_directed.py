"""HLA 4's directed interactions through the Federate Protocol's door: an interaction sent to one object instance
reaches the federates that subscribed to it for the instance's class, those owning an attribute of the instance,
or, subscribed universally, all that know it; not the others. In receive and in timestamp order, refused with the
standard's exceptions, and kept by a federation save."""

from __future__ import annotations

import pathlib
from typing import Any, Iterator

import pytest

from hlacore import fedpro
from hlacore.fedpro._proto import datatypes_pb2

from support.fedpro import Calls, until
from support.fedpro import door as fedpro_door
from support.rti1516e import VEHICLES


@pytest.fixture
def door(tmp_path: pathlib.Path) -> Iterator[Any]:
    with fedpro_door(tmp_path) as server:
        yield server


class Member:
    """A FedPro federate joined to "Road", with the FOM's handles."""

    def __init__(self, address: str, name: str, create: bool = False) -> None:
        self.amb = Calls()
        self.rtia = rtia = fedpro.RTIambassador(address)
        rtia.connect(self.amb)
        if create:
            rtia.createFederationExecutionWithModules(federationName="Road", fomModules=[VEHICLES])
        self.handle = rtia.joinFederationExecution(federateName=name, federateType="fedpro", federationName="Road").federateHandle
        self.vehicle = rtia.getObjectClassHandle(objectClassName="Vehicle")
        self.position = rtia.getAttributeHandle(objectClass=self.vehicle, attributeName="position")
        self.command = rtia.getInteractionClassHandle(interactionClassName="Command")
        self.verb = rtia.getParameterHandle(interactionClass=self.command, parameterName="verb")

    def until(self, done: Any) -> None:
        until(self.rtia, done)

    def handled(self, car: Any) -> None:
        """Wait until the gateway has handled all this federate sent before: it answers a query of who owns the
        car's position after them. (Another federate's messages sent later may otherwise overtake them.)"""
        answers = ("informAttributeOwnership", "attributeIsNotOwned", "attributeIsOwnedByRTI")
        count = sum(len(self.amb.named(name)) for name in answers)
        self.rtia.queryAttributeOwnership(objectInstance=car, attributes=[self.position])
        self.until(lambda: sum(len(self.amb.named(name)) for name in answers) > count)

    def directed(self) -> list[bytes]:
        """The verbs of the directed interactions received so far (in receive or timestamp order), in order."""
        return [fedpro.handle_values(m.parameterValues)[self.verb.data] for n, m in self.amb.calls
                if n in ("receiveDirectedInteraction", "receiveDirectedInteractionWithTime")]

    def leave(self, destroy: bool = False) -> None:
        self.rtia.resignFederationExecution(resignAction="CANCEL_THEN_DELETE_THEN_DIVEST")
        if destroy:
            self.rtia.destroyFederationExecution(federationName="Road")
        self.rtia.close()


@pytest.fixture
def road(door: Any) -> Iterator[tuple[Member, Member, Member, Any]]:
    """A sender that publishes Command directed at vehicles, the owner of a vehicle subscribed to them, and a
    watcher that knows the vehicle, subscribed (owning none of it); and the owner's vehicle."""
    sender = Member(door.fedpro_address, "sender", create=True)
    owner = Member(door.fedpro_address, "owner")
    watcher = Member(door.fedpro_address, "watcher")
    members = (sender, owner, watcher)
    try:
        owner.rtia.publishObjectClassAttributes(objectClass=owner.vehicle, attributes=[owner.position])
        for m in (sender, watcher):
            m.rtia.subscribeObjectClassAttributes(objectClass=m.vehicle, attributes=[m.position])
        sender.rtia.publishObjectClassDirectedInteractions(objectClass=sender.vehicle, interactionClasses=[sender.command])
        for m in (owner, watcher):
            m.rtia.subscribeObjectClassDirectedInteractions(objectClass=m.vehicle, interactionClasses=[m.command])
        car = owner.rtia.registerObjectInstance(objectClass=owner.vehicle)
        for m in (sender, watcher):
            m.until(lambda m=m: bool(m.amb.named("discoverObjectInstance")))
        yield sender, owner, watcher, car
    finally:
        for m in reversed(members):
            m.leave(destroy=m is sender)


def send(sender: Member, car: Any, verb: bytes, **time: Any) -> Any:
    return sender.rtia.sendDirectedInteraction(interactionClass=sender.command, objectInstance=car,
                                               parameterValues={sender.verb.data: verb}, userSuppliedTag=b"tag", **time)


def test_a_directed_interaction_reaches_the_owner_and_the_universal_subscribers_only(road: Any) -> None:
    sender, owner, watcher, car = road
    send(sender, car, b"stop")
    owner.until(lambda: owner.directed() == [b"stop"])
    [got] = owner.amb.named("receiveDirectedInteraction")
    assert got.objectInstance.data == car.data and got.interactionClass.data == owner.command.data
    assert got.producingFederate.data == sender.handle.data and got.userSuppliedTag == b"tag"

    # The watcher owns nothing of the car: only universally does it receive what is sent to it. What one sender
    # sends reaches a receiver in order, so "stop" would have come before "go".
    watcher.rtia.subscribeObjectClassDirectedInteractionsUniversally(objectClass=watcher.vehicle,
                                                                      interactionClasses=[watcher.command])
    watcher.handled(car)
    send(sender, car, b"go")
    watcher.until(lambda: watcher.directed() == [b"go"])
    owner.until(lambda: owner.directed() == [b"stop", b"go"])

    # Unsubscribed, the watcher gets none; a plain interaction after it shows nothing came before.
    watcher.rtia.unsubscribeObjectClassDirectedInteractions(objectClass=watcher.vehicle)
    watcher.rtia.subscribeInteractionClass(interactionClass=watcher.command)
    watcher.handled(car)
    sender.rtia.publishInteractionClass(interactionClass=sender.command)
    send(sender, car, b"halt")
    sender.rtia.sendInteraction(interactionClass=sender.command, parameterValues={sender.verb.data: b"plain"},
                                userSuppliedTag=b"")
    watcher.until(lambda: bool(watcher.amb.named("receiveInteraction")))
    assert watcher.directed() == [b"go"]
    owner.until(lambda: owner.directed() == [b"stop", b"go", b"halt"])
    assert not owner.amb.named("receiveInteraction"), "a directed interaction is not a plain one"

    # Received while owning: the owner divests all of the car, the privilege to delete included, and gets none.
    privilege = owner.rtia.getAttributeHandle(objectClass=owner.vehicle, attributeName="HLAprivilegeToDeleteObject")
    owner.rtia.unconditionalAttributeOwnershipDivestiture(objectInstance=car, attributes=[owner.position, privilege])
    owner.rtia.subscribeInteractionClass(interactionClass=owner.command)
    owner.handled(car)
    send(sender, car, b"unowned")
    sender.rtia.sendInteraction(interactionClass=sender.command, parameterValues={sender.verb.data: b"after"},
                                userSuppliedTag=b"")
    owner.until(lambda: bool(owner.amb.named("receiveInteraction")))
    assert owner.directed() == [b"stop", b"go", b"halt"]
    assert sender.directed() == [], "a sender does not receive its own"


def test_directed_interactions_are_refused_with_the_standards_exceptions(road: Any) -> None:
    sender, owner, watcher, car = road
    with pytest.raises(fedpro.rti_exception("InteractionClassNotPublished")):
        send(owner, car, b"mine")  # subscribed, not published
    with pytest.raises(fedpro.rti_exception("ObjectInstanceNotKnown")):
        send(sender, datatypes_handle(b"\x00\x00\x03\xe7"), b"nobody")
    with pytest.raises(fedpro.rti_exception("InteractionParameterNotDefined")):
        sender.rtia.sendDirectedInteraction(interactionClass=sender.command, objectInstance=car,
                                            parameterValues={sender.position.data: b"?"}, userSuppliedTag=b"")
    with pytest.raises(fedpro.rti_exception("ObjectClassNotDefined")):
        sender.rtia.publishObjectClassDirectedInteractions(objectClass=datatypes_handle(b"\x00\x00\x03\xe7", "ObjectClassHandle"),
                                                           interactionClasses=[sender.command])
    for withdraw in (sender.rtia.unpublishObjectClassDirectedInteractionsWithSet,
                     sender.rtia.unsubscribeObjectClassDirectedInteractionsWithSet):  # nothing to withdraw: still checked
        with pytest.raises(fedpro.rti_exception("ObjectClassNotDefined")):
            withdraw(objectClass=datatypes_handle(b"\x00\x00\x03\xe7", "ObjectClassHandle"), interactionClasses=[])
    sender.rtia.unpublishObjectClassDirectedInteractionsWithSet(objectClass=sender.vehicle, interactionClasses=[sender.command])
    with pytest.raises(fedpro.rti_exception("InteractionClassNotPublished")):
        send(sender, car, b"unpublished")
    assert owner.directed() == [] and watcher.directed() == []


def datatypes_handle(data: bytes, kind: str = "ObjectInstanceHandle") -> Any:
    return getattr(datatypes_pb2, kind)(data=data)


def test_a_timestamped_directed_interaction_arrives_in_timestamp_order_at_its_time(road: Any) -> None:
    sender, owner, watcher, car = road
    sender.rtia.enableTimeRegulation(lookahead=fedpro.float64_interval(1.0))
    owner.rtia.enableTimeConstrained()
    sender.until(lambda: bool(sender.amb.named("timeRegulationEnabled")))
    owner.until(lambda: bool(owner.amb.named("timeConstrainedEnabled")))
    result = send(sender, car, b"later", time=fedpro.float64_time(5.0))
    assert result.retractionHandleIsValid
    sender.rtia.timeAdvanceRequest(time=fedpro.float64_time(10.0))  # regulating only: granted at once
    owner.rtia.timeAdvanceRequest(time=fedpro.float64_time(4.0))
    owner.until(lambda: bool(owner.amb.named("timeAdvanceGrant")))
    assert owner.directed() == [], "not before its time"
    owner.rtia.timeAdvanceRequest(time=fedpro.float64_time(6.0))
    owner.until(lambda: len(owner.amb.named("timeAdvanceGrant")) == 2)
    [got] = owner.amb.named("receiveDirectedInteractionWithTime")
    assert fedpro.time_value(got.time) == 5.0 and got.receivedOrderType == datatypes_pb2.TIMESTAMP
    assert got.optionalRetraction.data == result.messageRetractionHandle.data
    assert fedpro.time_value(owner.amb.named("timeAdvanceGrant")[-1].time) == 6.0


def save_or_restore(members: tuple[Member, ...], label: str, restore: bool) -> None:
    """A federation save (or restore) of `label`, asked by the first member, answered by each."""
    first = members[0]
    if restore:
        first.rtia.requestFederationRestore(label=label)
        for m in members:
            m.until(lambda m=m: bool(m.amb.named("initiateFederateRestore")))
            m.rtia.federateRestoreComplete()
        for m in members:
            m.until(lambda m=m: bool(m.amb.named("federationRestored")))
    else:
        first.rtia.requestFederationSave(label=label)
        for m in members:
            m.until(lambda m=m: bool(m.amb.named("initiateFederateSave")))
            m.rtia.federateSaveBegun()
            m.rtia.federateSaveComplete()
        for m in members:
            m.until(lambda m=m: bool(m.amb.named("federationSaved")))


def test_a_federation_save_keeps_the_directed_interaction_declarations(road: Any) -> None:
    """Published and subscribed when saved, withdrawn after: the restore brings both back, at the gateway (which
    routes by the subscription) and in the sender's client (which checks the publication)."""
    sender, owner, watcher, car = road
    save_or_restore(road[:3], "directed", restore=False)
    sender.rtia.unpublishObjectClassDirectedInteractions(objectClass=sender.vehicle)
    owner.rtia.unsubscribeObjectClassDirectedInteractions(objectClass=owner.vehicle)
    with pytest.raises(fedpro.rti_exception("InteractionClassNotPublished")):
        send(sender, car, b"unpublished")
    save_or_restore(road[:3], "directed", restore=True)
    send(sender, car, b"restored")
    owner.until(lambda: owner.directed() == [b"restored"])
