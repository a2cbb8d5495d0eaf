"""Attribute ownership management (HLA 1.3 §7): divestiture, acquisition, release, cancellations,
queries, the privilege to delete, resigning and dying owners."""

import signal
from typing import Optional

import pytest

import hlacore.rti as rti

from support import ROBOT_FED, Federate, barrier, python_subprocess, settle, tick_until


class Robots:
    """Federate `a` registers robot 'r1' owning location, battery and the privilege to delete; `b`
    publishes location, battery and privilegeToDelete and has discovered r1. Both subscribe to location
    and battery."""

    def __init__(self, federation):
        self.a, self.b = federation("a"), federation("b")
        r = self.a.rtia
        self.robot = r.getObjectClassHandle("robot")
        self.location = r.getAttributeHandle("location", self.robot)
        self.battery = r.getAttributeHandle("battery", self.robot)
        self.compass = r.getAttributeHandle("compass", self.robot)
        self.privilege = r.getAttributeHandle("privilegeToDelete", self.robot)
        self.sonar = r.getAttributeHandle("sonar", r.getObjectClassHandle("turtlebot"))
        for fed in (self.a, self.b):
            fed.rtia.publishObjectClass(self.robot, [self.location, self.battery])
            fed.rtia.subscribeObjectClassAttributes(self.robot, [self.location, self.battery])
        self.b.rtia.publishObjectClass(self.robot, [self.location, self.battery, self.privilege])
        barrier(self.b.rtia)
        self.obj = self.a.rtia.registerObjectInstance(self.robot, "r1")
        tick_until(lambda: self.b.amb.named("discoverObjectInstance"), self.b.rtia)

    def tick_until(self, predicate, timeout=5.0):
        tick_until(predicate, self.a.rtia, self.b.rtia, timeout=timeout)

    def owner_seen_by(self, fed: Federate, attribute) -> Optional[int]:
        return owner_seen_by(fed, self.obj, attribute)

    def b_asks_for(self, attribute, tag: str = "") -> None:
        """b asks to acquire `attribute` of r1, which a owns; returns once a is asked to release it."""
        self.b.rtia.attributeOwnershipAcquisition(self.obj, [attribute], tag)
        self.tick_until(lambda: self.a.amb.named("requestAttributeOwnershipRelease"))

    def refuses(self, error, service) -> None:
        """`service` (a federate's ownership service, bound) called on r1's location raises `error`."""
        with pytest.raises(error):
            service(self.obj, [self.location])


def owner_seen_by(fed: Federate, obj, attribute) -> Optional[int]:
    """queryAttributeOwnership, ticked until answered: the owner's handle, or None when unowned.
    Clears the federate's recorded callbacks first."""
    fed.amb.calls.clear()
    fed.rtia.queryAttributeOwnership(obj, attribute)
    tick_until(lambda: fed.amb.named("informAttributeOwnership") or fed.amb.named("attributeIsNotOwned"), fed.rtia)
    informed = fed.amb.named("informAttributeOwnership")
    if informed:
        [(o, attr, owner)] = informed
        assert (o, attr) == (obj, attribute)
        assert isinstance(owner, rti.FederateHandle)
        return int(owner)
    assert fed.amb.named("attributeIsNotOwned") == [(obj, attribute)]
    return None


@pytest.fixture
def robots(federation):
    return Robots(federation)


def test_registrant_owns_its_published_attributes_and_the_privilege_to_delete(robots):
    """isAttributeOwnedByFederate answers locally; queryAttributeOwnership names the owner (§7.15-7.17)."""
    a, b, obj = robots.a, robots.b, robots.obj
    assert a.rtia.isAttributeOwnedByFederate(obj, robots.location)
    assert a.rtia.isAttributeOwnedByFederate(obj, robots.privilege)
    assert not a.rtia.isAttributeOwnedByFederate(obj, robots.compass)
    assert not b.rtia.isAttributeOwnedByFederate(obj, robots.location)
    assert robots.owner_seen_by(b, robots.location) == int(a.handle)
    assert robots.owner_seen_by(a, robots.privilege) == int(a.handle)
    assert robots.owner_seen_by(b, robots.compass) is None
    assert type(b.rtia.isAttributeOwnedByFederate(obj, robots.location)) is bool
    assert not b.amb.named("attributeOwnedByRTI")


def test_negotiated_handover_of_location(robots):
    """§7.3-7.7: the divester offers, the publisher is asked and acquires; then the new owner's updates
    are reflected and the old owner's are refused with AttributeNotOwned."""
    a, b, obj, location = robots.a, robots.b, robots.obj, robots.location
    a.rtia.negotiatedAttributeOwnershipDivestiture(obj, [location], "take it")
    assert a.rtia.isAttributeOwnedByFederate(obj, location), "still owned until the notification"
    robots.tick_until(lambda: b.amb.named("requestAttributeOwnershipAssumption"))
    assert b.amb.named("requestAttributeOwnershipAssumption") == [(obj, (location,), "take it")]
    assert not a.amb.named("requestAttributeOwnershipAssumption")
    b.rtia.attributeOwnershipAcquisition(obj, [location], "mine")
    robots.tick_until(
        lambda: b.amb.named("attributeOwnershipAcquisitionNotification")
        and a.amb.named("attributeOwnershipDivestitureNotification")
    )
    assert b.amb.named("attributeOwnershipAcquisitionNotification") == [(obj, (location,))]
    assert a.amb.named("attributeOwnershipDivestitureNotification") == [(obj, (location,))]
    assert b.rtia.isAttributeOwnedByFederate(obj, location)
    assert not a.rtia.isAttributeOwnedByFederate(obj, location)
    assert robots.owner_seen_by(a, location) == int(b.handle)

    with pytest.raises(rti.AttributeNotOwned):
        a.rtia.updateAttributeValues(obj, {location: b"old owner"}, "refused")
    b.rtia.updateAttributeValues(obj, {location: b"new owner"}, "moved")
    a.rtia.updateAttributeValues(obj, {robots.battery: b"90%"}, "battery")
    robots.tick_until(lambda: a.amb.named("reflectAttributeValues") and b.amb.named("reflectAttributeValues"))
    settle(a.rtia, b.rtia)
    assert [args[:3] for args in a.amb.named("reflectAttributeValues")] == [(obj, {location: b"new owner"}, "moved")]
    assert [args[:3] for args in b.amb.named("reflectAttributeValues")] == [(obj, {robots.battery: b"90%"}, "battery")]


def test_acquisition_if_available_of_an_unowned_attribute(robots):
    """§7.8-7.9: granted when unowned, attributeOwnershipUnavailable when someone owns it."""
    a, b, obj, location = robots.a, robots.b, robots.obj, robots.location
    a.rtia.unconditionalAttributeOwnershipDivestiture(obj, [location])
    assert not a.rtia.isAttributeOwnedByFederate(obj, location)
    assert robots.owner_seen_by(b, location) is None
    b.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [location])
    robots.tick_until(lambda: b.amb.named("attributeOwnershipAcquisitionNotification"))
    assert b.amb.named("attributeOwnershipAcquisitionNotification") == [(obj, (location,))]
    assert b.rtia.isAttributeOwnedByFederate(obj, location)
    a.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [location])
    robots.tick_until(lambda: a.amb.named("attributeOwnershipUnavailable"))
    assert a.amb.named("attributeOwnershipUnavailable") == [(obj, (location,))]
    assert not a.amb.named("attributeOwnershipAcquisitionNotification")
    # Unavailable ends that request: asking again is allowed.
    a.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [location])
    robots.tick_until(lambda: len(a.amb.named("attributeOwnershipUnavailable")) == 2)


def test_acquisition_if_available_while_the_owner_divests(robots):
    """An attribute being divested by negotiation is available (§7.8): the divester is notified."""
    a, b, obj, battery = robots.a, robots.b, robots.obj, robots.battery
    a.rtia.negotiatedAttributeOwnershipDivestiture(obj, [battery], "")
    barrier(a.rtia)
    b.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [battery])
    robots.tick_until(
        lambda: b.amb.named("attributeOwnershipAcquisitionNotification")
        and a.amb.named("attributeOwnershipDivestitureNotification")
    )
    assert not a.rtia.isAttributeOwnedByFederate(obj, battery)
    assert b.rtia.isAttributeOwnedByFederate(obj, battery)


def test_unconditional_divestiture_then_acquisition(robots):
    """§7.2 then §7.7: an unowned attribute is acquired at once, nobody is asked to release it."""
    a, b, obj, battery = robots.a, robots.b, robots.obj, robots.battery
    a.rtia.unconditionalAttributeOwnershipDivestiture(obj, [battery])
    with pytest.raises(rti.AttributeNotOwned):
        a.rtia.updateAttributeValues(obj, {battery: b"x"}, "")
    barrier(a.rtia)
    b.rtia.attributeOwnershipAcquisition(obj, [battery], "need it")
    robots.tick_until(lambda: b.amb.named("attributeOwnershipAcquisitionNotification"))
    settle(a.rtia, b.rtia)
    assert b.amb.named("attributeOwnershipAcquisitionNotification") == [(obj, (battery,))]
    assert not a.amb.named("requestAttributeOwnershipRelease")
    assert not a.amb.named("attributeOwnershipDivestitureNotification")
    b.rtia.updateAttributeValues(obj, {battery: b"50%"}, "b")
    robots.tick_until(lambda: a.amb.named("reflectAttributeValues"))
    assert a.amb.named("reflectAttributeValues")[0][1] == {battery: b"50%"}


def test_unconditional_divestiture_gives_the_attribute_to_a_waiting_acquirer(robots):
    """A federate waiting for an owned attribute (§7.7) gets it when its owner divests it."""
    a, b, obj, location = robots.a, robots.b, robots.obj, robots.location
    robots.b_asks_for(location)
    a.rtia.unconditionalAttributeOwnershipDivestiture(obj, [location])
    robots.tick_until(lambda: b.amb.named("attributeOwnershipAcquisitionNotification"))
    assert b.rtia.isAttributeOwnedByFederate(obj, location)
    assert robots.owner_seen_by(a, location) == int(b.handle)


def test_release_request_and_response(robots):
    """§7.10-7.11: acquiring an owned attribute asks its owner, whose release response returns what it gave."""
    a, b, obj, location, battery = robots.a, robots.b, robots.obj, robots.location, robots.battery
    robots.refuses(rti.FederateWasNotAskedToReleaseAttribute, a.rtia.attributeOwnershipReleaseResponse)
    robots.b_asks_for(location, "please")
    assert a.amb.named("requestAttributeOwnershipRelease") == [(obj, (location,), "please")]
    assert not b.rtia.isAttributeOwnedByFederate(obj, location)
    with pytest.raises(rti.FederateWasNotAskedToReleaseAttribute):
        a.rtia.attributeOwnershipReleaseResponse(obj, [location, battery])
    released = a.rtia.attributeOwnershipReleaseResponse(obj, [location])
    assert released == (location,)
    assert isinstance(released[0], rti.AttributeHandle)
    assert not a.rtia.isAttributeOwnedByFederate(obj, location)
    robots.tick_until(lambda: b.amb.named("attributeOwnershipAcquisitionNotification"))
    assert b.amb.named("attributeOwnershipAcquisitionNotification") == [(obj, (location,))]
    assert b.rtia.isAttributeOwnedByFederate(obj, location)
    robots.refuses(rti.AttributeNotOwned, a.rtia.attributeOwnershipReleaseResponse)


def test_release_response_from_inside_the_callback(federation, gateway_address):
    """The usual pattern: the owner answers requestAttributeOwnershipRelease from the callback itself
    (a round trip to the gateway while tick is delivering)."""

    class Releaser(rti.FederateAmbassador):
        def __init__(self):
            self.released = []

        def requestAttributeOwnershipRelease(self, obj, attributes, tag):
            self.released.append(rtia.attributeOwnershipReleaseResponse(obj, list(attributes)))

    taker = federation("taker")
    rtia = rti.RTIAmbassador(gateway_address)
    releaser = Releaser()
    rtia.joinFederationExecution("owner", "TestFed", releaser)
    robot = rtia.getObjectClassHandle("robot")
    location = rtia.getAttributeHandle("location", robot)
    rtia.publishObjectClass(robot, [location])
    taker.rtia.publishObjectClass(robot, [location])
    taker.rtia.subscribeObjectClassAttributes(robot, [location])
    barrier(taker.rtia)
    obj = rtia.registerObjectInstance(robot)
    tick_until(lambda: taker.amb.named("discoverObjectInstance"), taker.rtia)
    taker.rtia.attributeOwnershipAcquisition(obj, [location], "")
    tick_until(lambda: taker.amb.named("attributeOwnershipAcquisitionNotification"), rtia, taker.rtia)
    assert releaser.released == [(location,)]
    assert taker.rtia.isAttributeOwnedByFederate(obj, location)
    assert not rtia.isAttributeOwnedByFederate(obj, location)
    rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)


def test_cancel_acquisition(robots):
    """§7.13-7.14: a cancelled acquisition is confirmed; the owner's release response then releases nothing."""
    a, b, obj, location = robots.a, robots.b, robots.obj, robots.location
    robots.refuses(rti.AttributeAcquisitionWasNotRequested, b.rtia.cancelAttributeOwnershipAcquisition)
    robots.refuses(rti.AttributeAlreadyOwned, a.rtia.cancelAttributeOwnershipAcquisition)
    robots.b_asks_for(location)
    robots.refuses(rti.AttributeAlreadyBeingAcquired, b.rtia.attributeOwnershipAcquisitionIfAvailable)
    with pytest.raises(rti.OwnershipAcquisitionPending):
        b.rtia.unpublishObjectClass(robots.robot)
    b.rtia.cancelAttributeOwnershipAcquisition(obj, [location])
    robots.tick_until(lambda: b.amb.named("confirmAttributeOwnershipAcquisitionCancellation"))
    assert b.amb.named("confirmAttributeOwnershipAcquisitionCancellation") == [(obj, (location,))]
    barrier(b.rtia)
    assert a.rtia.attributeOwnershipReleaseResponse(obj, [location]) == ()
    assert a.rtia.isAttributeOwnedByFederate(obj, location)
    settle(a.rtia, b.rtia)
    assert not b.amb.named("attributeOwnershipAcquisitionNotification")
    robots.refuses(rti.AttributeAcquisitionWasNotRequested, b.rtia.cancelAttributeOwnershipAcquisition)
    b.rtia.unpublishObjectClass(robots.robot)


def test_cancel_negotiated_divestiture(robots):
    """§7.12: after cancelling, the attribute is no longer available."""
    a, b, obj, location = robots.a, robots.b, robots.obj, robots.location
    robots.refuses(rti.AttributeDivestitureWasNotRequested, a.rtia.cancelNegotiatedAttributeOwnershipDivestiture)
    robots.refuses(rti.AttributeNotOwned, b.rtia.cancelNegotiatedAttributeOwnershipDivestiture)
    a.rtia.negotiatedAttributeOwnershipDivestiture(obj, [location], "offer")
    robots.tick_until(lambda: b.amb.named("requestAttributeOwnershipAssumption"))
    a.rtia.cancelNegotiatedAttributeOwnershipDivestiture(obj, [location])
    barrier(a.rtia)
    b.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [location])
    robots.tick_until(lambda: b.amb.named("attributeOwnershipUnavailable"))
    settle(a.rtia, b.rtia)
    assert not a.amb.named("attributeOwnershipDivestitureNotification")
    assert a.rtia.isAttributeOwnedByFederate(obj, location)
    robots.refuses(rti.AttributeDivestitureWasNotRequested, a.rtia.cancelNegotiatedAttributeOwnershipDivestiture)


def test_negotiated_divestiture_goes_to_a_waiting_acquirer_at_once(robots):
    """An owner asked to release that divests by negotiation hands the attribute to the waiting federate."""
    a, b, obj, battery = robots.a, robots.b, robots.obj, robots.battery
    robots.b_asks_for(battery)
    a.rtia.negotiatedAttributeOwnershipDivestiture(obj, [battery], "")
    robots.tick_until(
        lambda: b.amb.named("attributeOwnershipAcquisitionNotification")
        and a.amb.named("attributeOwnershipDivestitureNotification")
    )
    assert not b.amb.named("requestAttributeOwnershipAssumption")
    # The request was answered by the transfer: nothing is left to release.
    with pytest.raises(rti.AttributeNotOwned):
        a.rtia.attributeOwnershipReleaseResponse(obj, [battery])


def test_local_delete_ends_a_pending_acquisition(robots):
    """A federate that forgets the object (§6.10) no longer waits for its attributes."""
    a, b, obj, location = robots.a, robots.b, robots.obj, robots.location
    robots.b_asks_for(location)
    b.rtia.localDeleteObjectInstance(obj)
    barrier(b.rtia)
    assert a.rtia.attributeOwnershipReleaseResponse(obj, [location]) == ()
    assert a.rtia.isAttributeOwnedByFederate(obj, location)


def test_first_waiting_acquirer_gets_the_attribute_and_subclass_instances_qualify(federation):
    """Acquirers wait in request order; an instance discovered as its superclass is acquired through the
    superclass's published attributes."""
    a, b, c = federation("a"), federation("b"), federation("c")
    robot = a.rtia.getObjectClassHandle("robot")
    turtle = a.rtia.getObjectClassHandle("turtlebot")
    location = a.rtia.getAttributeHandle("location", robot)
    a.rtia.publishObjectClass(turtle, [location])
    for fed in (b, c):
        fed.rtia.publishObjectClass(robot, [location])
        fed.rtia.subscribeObjectClassAttributes(robot, [location])
        barrier(fed.rtia)
    obj = a.rtia.registerObjectInstance(turtle)
    tick_until(lambda: b.amb.named("discoverObjectInstance") and c.amb.named("discoverObjectInstance"), b.rtia, c.rtia)
    assert b.rtia.getObjectClass(obj) == robot
    b.rtia.attributeOwnershipAcquisition(obj, [location], "b")
    barrier(b.rtia)
    c.rtia.attributeOwnershipAcquisition(obj, [location], "c")
    tick_until(lambda: len(a.amb.named("requestAttributeOwnershipRelease")) == 2, a.rtia)
    assert [args[2] for args in a.amb.named("requestAttributeOwnershipRelease")] == ["b", "c"]
    assert a.rtia.attributeOwnershipReleaseResponse(obj, [location]) == (location,)
    tick_until(lambda: b.amb.named("attributeOwnershipAcquisitionNotification"), b.rtia)
    # c is still waiting: when b lets the attribute go, c gets it.
    b.rtia.unconditionalAttributeOwnershipDivestiture(obj, [location])
    tick_until(lambda: c.amb.named("attributeOwnershipAcquisitionNotification"), c.rtia)
    assert c.rtia.isAttributeOwnedByFederate(obj, location)


def test_ownership_service_errors(robots, federation):
    """HLA 1.3 §7's exceptions, raised by the caller's RTI ambassador."""
    a, b, obj = robots.a, robots.b, robots.obj
    location, compass, sonar = robots.location, robots.compass, robots.sonar
    stranger = federation("stranger")  # knows no object and publishes nothing
    watcher = federation("watcher")
    watcher.rtia.subscribeObjectClassAttributes(robots.robot, [location])
    tick_until(lambda: watcher.amb.named("discoverObjectInstance"), watcher.rtia)

    with pytest.raises(rti.AttributeNotOwned):
        a.rtia.unconditionalAttributeOwnershipDivestiture(obj, [compass])
    with pytest.raises(rti.AttributeNotOwned):
        b.rtia.negotiatedAttributeOwnershipDivestiture(obj, [location], "")
    a.rtia.negotiatedAttributeOwnershipDivestiture(obj, [location], "")
    with pytest.raises(rti.AttributeAlreadyBeingDivested):
        a.rtia.negotiatedAttributeOwnershipDivestiture(obj, [location], "")
    a.rtia.cancelNegotiatedAttributeOwnershipDivestiture(obj, [location])

    with pytest.raises(rti.AttributeNotPublished):
        b.rtia.attributeOwnershipAcquisition(obj, [compass], "")
    with pytest.raises(rti.AttributeNotPublished):
        b.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [compass])
    with pytest.raises(rti.ObjectClassNotPublished):
        watcher.rtia.attributeOwnershipAcquisition(obj, [location], "")
    with pytest.raises(rti.FederateOwnsAttributes):
        a.rtia.attributeOwnershipAcquisition(obj, [location], "")
    with pytest.raises(rti.FederateOwnsAttributes):
        a.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [location])
    with pytest.raises(rti.AttributeNotDefined):
        a.rtia.unconditionalAttributeOwnershipDivestiture(obj, [sonar])
    with pytest.raises(rti.AttributeNotDefined):
        b.rtia.attributeOwnershipAcquisition(obj, [sonar], "")
    with pytest.raises(rti.AttributeNotDefined):
        a.rtia.isAttributeOwnedByFederate(obj, sonar)
    with pytest.raises(rti.AttributeNotDefined):
        b.rtia.queryAttributeOwnership(obj, sonar)
    for call in (
        lambda: stranger.rtia.unconditionalAttributeOwnershipDivestiture(obj, [location]),
        lambda: stranger.rtia.negotiatedAttributeOwnershipDivestiture(obj, [location], ""),
        lambda: stranger.rtia.attributeOwnershipAcquisition(obj, [location], ""),
        lambda: stranger.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [location]),
        lambda: stranger.rtia.attributeOwnershipReleaseResponse(obj, [location]),
        lambda: stranger.rtia.cancelNegotiatedAttributeOwnershipDivestiture(obj, [location]),
        lambda: stranger.rtia.cancelAttributeOwnershipAcquisition(obj, [location]),
        lambda: stranger.rtia.queryAttributeOwnership(obj, location),
        lambda: stranger.rtia.isAttributeOwnedByFederate(obj, location),
    ):
        with pytest.raises(rti.ObjectNotKnown):
            call()
    with pytest.raises(TypeError):
        a.rtia.isAttributeOwnedByFederate(obj, robots.robot)
    # Nothing above reached the gateway as a transfer.
    assert robots.owner_seen_by(b, location) == int(a.handle)


def test_not_joined_raises_federate_not_execution_member(inprocess_gateway):
    """The ownership services need a joined federate."""
    rtia = rti.RTIAmbassador(inprocess_gateway.address)
    creator = rti.RTIAmbassador(inprocess_gateway.address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    try:
        fed = Federate(inprocess_gateway.address, "a")
        robot = fed.rtia.getObjectClassHandle("robot")
        location = fed.rtia.getAttributeHandle("location", robot)
        fed.rtia.publishObjectClass(robot, [location])
        obj = fed.rtia.registerObjectInstance(robot)
        with pytest.raises(rti.FederateNotExecutionMember):
            rtia.isAttributeOwnedByFederate(obj, location)
        with pytest.raises(rti.FederateNotExecutionMember):
            rtia.attributeOwnershipAcquisition(obj, [location], "")
        fed.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    finally:
        creator.destroyFederationExecution("TestFed")


def test_privilege_to_delete_transfers_like_an_attribute(robots):
    """HLA 1.3: whoever owns privilegeToDelete may delete the object."""
    a, b, obj, privilege = robots.a, robots.b, robots.obj, robots.privilege
    with pytest.raises(rti.DeletePrivilegeNotHeld):
        b.rtia.deleteObjectInstance(obj, "not yours")
    a.rtia.unconditionalAttributeOwnershipDivestiture(obj, [privilege])
    with pytest.raises(rti.DeletePrivilegeNotHeld):
        a.rtia.deleteObjectInstance(obj, "given away")
    barrier(a.rtia)
    b.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [privilege])
    robots.tick_until(lambda: b.amb.named("attributeOwnershipAcquisitionNotification"))
    b.rtia.deleteObjectInstance(obj, "mine now")
    robots.tick_until(lambda: a.amb.named("removeObjectInstance"))
    assert a.amb.named("removeObjectInstance") == [(obj, "mine now")]


def test_publishing_fewer_attributes_or_unpublishing_divests_them(robots):
    """HLA 1.3 §5.2-5.3: owned attributes no longer published are divested unconditionally; the privilege
    to delete goes with the class."""
    a, b, obj, location, battery = robots.a, robots.b, robots.obj, robots.location, robots.battery
    a.rtia.publishObjectClass(robots.robot, [location])
    assert not a.rtia.isAttributeOwnedByFederate(obj, battery)
    assert a.rtia.isAttributeOwnedByFederate(obj, location)
    assert a.rtia.isAttributeOwnedByFederate(obj, robots.privilege)
    with pytest.raises(rti.AttributeNotOwned):
        a.rtia.updateAttributeValues(obj, {battery: b"x"}, "")
    assert robots.owner_seen_by(b, battery) is None
    b.rtia.attributeOwnershipAcquisition(obj, [location], "")
    barrier(b.rtia)
    a.rtia.unpublishObjectClass(robots.robot)
    assert not a.rtia.isAttributeOwnedByFederate(obj, location)
    with pytest.raises(rti.DeletePrivilegeNotHeld):
        a.rtia.deleteObjectInstance(obj, "")
    robots.tick_until(lambda: b.amb.named("attributeOwnershipAcquisitionNotification"))
    assert b.amb.named("attributeOwnershipAcquisitionNotification") == [(obj, (location,))]
    assert robots.owner_seen_by(b, robots.privilege) is None
    # b publishes robot without naming privilegeToDelete: the class is enough to take it.
    b.rtia.publishObjectClass(robots.robot, [location, battery])
    b.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [robots.privilege])
    robots.tick_until(lambda: b.amb.named("attributeOwnershipAcquisitionNotification"))
    b.rtia.deleteObjectInstance(obj, "")


def test_resign_releasing_attributes_leaves_them_available(robots):
    """ReleaseAttributes (HLA 1.3 §4.5): unowned afterwards, a waiting acquirer gets its attribute at once."""
    a, b, obj, location, battery = robots.a, robots.b, robots.obj, robots.location, robots.battery
    robots.b_asks_for(battery)
    a.rtia.resignFederationExecution(rti.ResignAction.ReleaseAttributes)
    tick_until(lambda: b.amb.named("attributeOwnershipAcquisitionNotification"), b.rtia)
    assert b.amb.named("attributeOwnershipAcquisitionNotification") == [(obj, (battery,))]
    assert robots.owner_seen_by(b, location) is None
    assert robots.owner_seen_by(b, robots.privilege) is None
    b.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [location, robots.privilege])
    tick_until(lambda: len(b.amb.named("attributeOwnershipAcquisitionNotification")) == 1, b.rtia)
    b.rtia.updateAttributeValues(obj, {location: b"b"}, "")
    b.rtia.deleteObjectInstance(obj, "")


def test_resign_without_releasing_owned_attributes_is_refused(robots):
    """NoAction and DeleteObjects must not leave owned attributes behind (FederateOwnsAttributes)."""
    a, b, obj, battery = robots.a, robots.b, robots.obj, robots.battery
    a.rtia.unconditionalAttributeOwnershipDivestiture(obj, [battery])
    barrier(a.rtia)
    b.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [battery])
    robots.tick_until(lambda: b.amb.named("attributeOwnershipAcquisitionNotification"))
    with pytest.raises(rti.FederateOwnsAttributes):
        b.rtia.resignFederationExecution(rti.ResignAction.DeleteObjects)  # b may not delete r1
    with pytest.raises(rti.FederateOwnsAttributes):
        a.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    b.rtia.unconditionalAttributeOwnershipDivestiture(obj, [battery])
    b.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    a.rtia.resignFederationExecution(rti.ResignAction.DeleteObjects)


def test_dying_owner_attributes_become_available(rtig):
    """A SIGKILLed federate is resigned with DeleteObjectsAndReleaseAttributes: the attributes it acquired
    go to a waiting acquirer or become unowned, available to attributeOwnershipAcquisitionIfAvailable."""
    creator = rti.RTIAmbassador(rtig.address)
    creator.createFederationExecution("TestFed", ROBOT_FED)
    a = Federate(rtig.address, "a")
    victim = None
    try:
        robot = a.rtia.getObjectClassHandle("robot")
        location = a.rtia.getAttributeHandle("location", robot)
        battery = a.rtia.getAttributeHandle("battery", robot)
        a.rtia.publishObjectClass(robot, [location, battery])
        a.rtia.subscribeObjectClassAttributes(robot, [location])
        obj = a.rtia.registerObjectInstance(robot, "r1")
        a.rtia.unconditionalAttributeOwnershipDivestiture(obj, [location, battery])
        victim = python_subprocess("ownership_victim.py", rtig.address)
        line = victim.read_line(15.0)
        assert line.startswith("owner "), line
        victim_handle = int(line.split()[1])
        tick_until(lambda: a.amb.named("reflectAttributeValues"), a.rtia)
        assert a.amb.named("reflectAttributeValues")[0][1] == {location: b"victim"}
        assert owner_seen_by(a, obj, location) == victim_handle
        a.rtia.attributeOwnershipAcquisition(obj, [battery], "")
        barrier(a.rtia)

        victim.send_signal(signal.SIGKILL)
        victim.wait(timeout=10)
        tick_until(lambda: a.amb.named("attributeOwnershipAcquisitionNotification"), a.rtia)
        assert a.amb.named("attributeOwnershipAcquisitionNotification") == [(obj, (battery,))]
        assert owner_seen_by(a, obj, location) is None
        a.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [location])
        tick_until(lambda: a.amb.named("attributeOwnershipAcquisitionNotification"), a.rtia)
        assert a.rtia.isAttributeOwnedByFederate(obj, location)
        a.rtia.updateAttributeValues(obj, {location: b"a again"}, "")
    finally:
        if victim is not None:
            victim.close()
        a.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        creator.destroyFederationExecution("TestFed")

