"""Every IEEE 1516-2010 service of hlacore.rti1516e called from Python through rtig, each with an asserted
outcome (its callbacks and their arguments, what it returns, a state seen later, or the exception it must
raise), the twin of tests/cpp/rti1516e/services.cpp: the names called are those of RTI1516E_SERVICES in the
C++ header, the overloads as Python's optional arguments; both serve the same services."""

from __future__ import annotations

import time
from typing import Any, Callable

import pytest

import hlacore.rti1516e as rti1516e
from support import RtigProcess
from support.rti1516e import CARS, VEHICLES, Recorder, service_entries

NOT_SERVED = "hlacore does not serve"


class Federate:
    """An ambassador whose every service call is noted by name (in `called`), and its recorder."""

    def __init__(self, called: set[str], address: str, model: str = "HLA_EVOKED") -> None:
        self.amb = Recorder()
        self.rtia = rti1516e.RTIambassador()
        self._called = called
        self.evoked = model == "HLA_EVOKED"
        self.call.connect(self.amb, model, address)

    @property
    def call(self) -> Any:
        """The ambassador, noting the services called through it."""
        federate = self

        class Noting:
            def __getattr__(self, name: str) -> Any:
                federate._called.add(name)
                return getattr(federate.rtia, name)
        return Noting()

    def until(self, done: Callable[[], bool], what: str = "") -> None:
        deadline = time.monotonic() + 30
        while not done():
            assert time.monotonic() < deadline, f"{what}: last callbacks {self.amb.calls[-6:]}"
            if self.evoked:
                self.call.evokeMultipleCallbacks(0.01, 0.05)
            else:
                time.sleep(0.01)

    def wait(self, name: str, *args: Any) -> None:
        """Until the callback `name` came with these arguments (its first ones, when fewer are given)."""
        self.until(lambda: any(a[:len(args)] == args for a in self.amb.named(name)), name)

    def settle(self) -> None:
        """A round trip to the gateway, then every callback it sent before delivered."""
        with pytest.raises(rti1516e.FederationExecutionDoesNotExist):
            self.rtia.destroyFederationExecution("no-such")
        while self.call.evokeMultipleCallbacks(0.0, 0.05):
            pass


def test_every_service_from_python(rtig: RtigProcess) -> None:
    called: set[str] = set()
    a = Federate(called, rtig.address)
    with pytest.raises(rti1516e.AlreadyConnected):
        a.call.connect(a.amb, "HLA_EVOKED", rtig.address)
    b = Federate(called, rtig.address)
    federation(a, b)
    world = support(a, b)
    declarations(a, b, world)
    objects(a, b, world)
    time_management(a, b, world)
    ownership(a, b, world)
    regions(a, b, world)
    sync_save_restore(a, b, world)
    callbacks(a, world)
    immediate_integer_time(Federate(called, rtig.address, "HLA_IMMEDIATE"))
    finish(a, b, world)
    every = set(service_entries())
    assert called == every, f"not called: {sorted(every - called)}; not services: {sorted(called - every)}"


def federation(a: Federate, b: Federate) -> None:
    a.call.createFederationExecution("Services", [VEHICLES, CARS], "HLAfloat64Time")
    with pytest.raises(rti1516e.FederationExecutionAlreadyExists):
        a.call.createFederationExecution("Services", VEHICLES)
    a.call.createFederationExecutionWithMIM("WithMIM", [CARS], VEHICLES)
    a.call.listFederationExecutions()
    a.wait("reportFederationExecutions")
    listed = a.amb.named("reportFederationExecutions")[0][0]
    assert {"federationExecutionName": "WithMIM", "logicalTimeImplementationName": "HLAfloat64Time"} in listed
    a.call.destroyFederationExecution("WithMIM")
    with pytest.raises(rti1516e.FederationExecutionDoesNotExist):
        a.rtia.destroyFederationExecution("WithMIM")
    ha = a.call.joinFederationExecution("a", "test", "Services")
    hb = b.rtia.joinFederationExecution("b", "test", "Services")
    assert ha.isValid() and ha != hb
    assert a.call.getFederateHandle("b") == hb and a.call.getFederateName(ha) == "a"
    with pytest.raises(rti1516e.FederateAlreadyExecutionMember):  # its modules are not added either
        a.rtia.joinFederationExecution("c", "test", "Services", [CARS])


class World:
    """The handles the scenario shares."""

    def __init__(self, a: Federate) -> None:
        r = a.rtia
        self.ha, self.hb = r.getFederateHandle("a"), r.getFederateHandle("b")
        self.vehicle = a.call.getObjectClassHandle("Vehicle")
        self.car = r.getObjectClassHandle("HLAobjectRoot.Vehicle.Car")
        self.position = a.call.getAttributeHandle(self.vehicle, "position")
        self.speed = r.getAttributeHandle(self.vehicle, "speed")
        self.doors = r.getAttributeHandle(self.car, "doors")
        self.command = a.call.getInteractionClassHandle("Command")
        self.verb = a.call.getParameterHandle(self.command, "verb")
        self.x = a.call.getDimensionHandle("X")
        self.y = r.getDimensionHandle("Y")
        self.objects: list[Any] = []


def support(a: Federate, b: Federate) -> World:
    w = World(a)
    c = a.call
    assert c.getObjectClassName(w.vehicle) == "Vehicle"
    assert c.getAttributeName(w.vehicle, w.speed) == "speed"
    assert c.getInteractionClassName(w.command) == "Command"
    assert c.getParameterName(w.command, w.verb) == "verb"
    with pytest.raises(rti1516e.NameNotFound):
        c.getObjectClassHandle("Spaceship")
    assert (c.getOrderType("TimeStamp"), c.getOrderName(rti1516e.RECEIVE)) == (rti1516e.TIMESTAMP, "Receive")
    assert c.getTransportationType("HLAbestEffort") == rti1516e.BEST_EFFORT
    assert c.getTransportationName(rti1516e.RELIABLE) == "HLAreliable"
    assert c.getDimensionName(w.y) == "Y" and c.getDimensionUpperBound(w.x) == 1000
    assert c.getAvailableDimensionsForClassAttribute(w.vehicle, w.position) == {w.x, w.y}
    assert c.getAvailableDimensionsForInteractionClass(w.command) == {w.x, w.y}
    assert c.normalizeFederateHandle(w.ha) != c.normalizeFederateHandle(w.hb)
    assert c.normalizeServiceGroup(rti1516e.SUPPORT_SERVICES) == 6
    with pytest.raises(rti1516e.InvalidServiceGroup):
        c.normalizeServiceGroup(42)
    assert c.getAutomaticResignDirective() == rti1516e.CANCEL_THEN_DELETE_THEN_DIVEST
    c.setAutomaticResignDirective(rti1516e.CANCEL_THEN_DELETE_THEN_DIVEST)
    with pytest.raises(rti1516e.RTIinternalError, match=NOT_SERVED):
        c.setAutomaticResignDirective(rti1516e.NO_ACTION)
    assert c.getUpdateRateValue("HLAfast") == 50.0
    with pytest.raises(rti1516e.InvalidUpdateRateDesignator):
        c.getUpdateRateValue("HLAwarp")
    with pytest.raises(rti1516e.ObjectInstanceNotKnown):
        c.getUpdateRateValueForAttribute(rti1516e.ObjectInstanceHandle(), w.speed)
    assert c.getTimeFactory() == "HLAfloat64Time"
    return w


def declarations(a: Federate, b: Federate, w: World) -> None:
    """Off, the class and interaction relevance switches keep quiet; on, they report b's subscriptions."""
    a.call.disableObjectClassRelevanceAdvisorySwitch()
    a.call.disableInteractionRelevanceAdvisorySwitch()
    a.call.enableAttributeRelevanceAdvisorySwitch()
    a.call.publishObjectClassAttributes(w.vehicle, [w.position, w.speed])
    a.call.publishInteractionClass(w.command)
    b.call.subscribeObjectClassAttributes(w.vehicle, [w.position, w.speed])
    b.call.subscribeInteractionClass(w.command)
    b.settle()
    a.settle()
    assert not a.amb.named("startRegistrationForObjectClass") and not a.amb.named("turnInteractionsOn")
    a.call.enableObjectClassRelevanceAdvisorySwitch()
    a.call.enableInteractionRelevanceAdvisorySwitch()
    a.wait("startRegistrationForObjectClass", w.vehicle)
    a.wait("turnInteractionsOn", w.command)
    a.rtia.publishObjectClassAttributes(w.car, [w.doors])
    a.call.unpublishObjectClassAttributes(w.car, [w.doors])
    with pytest.raises(rti1516e.ObjectClassNotPublished):
        a.rtia.registerObjectInstance(w.car)


def objects(a: Federate, b: Federate, w: World) -> None:
    a.call.reserveObjectInstanceName("car-1")
    a.wait("objectInstanceNameReservationSucceeded", "car-1")
    b.rtia.reserveObjectInstanceName("car-1")
    b.wait("objectInstanceNameReservationFailed", "car-1")
    v1 = a.call.registerObjectInstance(w.vehicle, "car-1")
    v2, v3, v4 = (a.rtia.registerObjectInstance(w.vehicle) for _ in range(3))
    w.objects = [v1, v2, v3, v4]
    assert a.call.getObjectInstanceName(v1) == "car-1" and a.call.getObjectInstanceHandle("car-1") == v1
    b.wait("discoverObjectInstance", v1, w.vehicle, "car-1")
    b.until(lambda: len(b.amb.named("discoverObjectInstance")) == 4)
    assert b.call.getKnownObjectClassHandle(v2) == w.vehicle
    assert b.rtia.getUpdateRateValueForAttribute(v2, w.speed) == 0.0  # subscribed with no rate
    a.wait("turnUpdatesOnForObjectInstance", v1, {w.position, w.speed})

    a.rtia.reserveObjectInstanceName("spare")
    a.wait("objectInstanceNameReservationSucceeded", "spare")
    a.call.releaseObjectInstanceName("spare")
    a.settle()  # the gateway has the release before b asks
    b.rtia.reserveObjectInstanceName("spare")
    b.wait("objectInstanceNameReservationSucceeded", "spare")
    a.call.reserveMultipleObjectInstanceName(["m1", "m2"])
    a.wait("multipleObjectInstanceNameReservationSucceeded", {"m1", "m2"})
    a.call.releaseMultipleObjectInstanceName(["m1", "m2"])
    a.settle()
    b.rtia.reserveMultipleObjectInstanceName(["m1", "m2"])
    b.wait("multipleObjectInstanceNameReservationSucceeded", {"m1", "m2"})

    assert a.call.updateAttributeValues(v1, {w.speed: b"fast"}, b"t1") is None
    b.wait("reflectAttributeValues", v1, {w.speed: b"fast"}, b"t1", rti1516e.RECEIVE, rti1516e.RELIABLE)
    assert a.call.sendInteraction(w.command, {w.verb: b"go"}, b"t2") is None
    b.wait("receiveInteraction", w.command, {w.verb: b"go"}, b"t2", rti1516e.RECEIVE, rti1516e.RELIABLE)
    b.call.unsubscribeObjectClassAttributes(w.vehicle, [w.speed])
    b.settle()  # the gateway has it before a's update
    a.rtia.updateAttributeValues(v1, {w.speed: b"hidden", w.position: b"shown"}, b"")
    b.wait("reflectAttributeValues", v1, {w.position: b"shown"})
    b.rtia.subscribeObjectClassAttributes(w.vehicle, [w.speed])

    b.call.requestAttributeValueUpdate(v1, [w.speed], b"")
    a.wait("provideAttributeValueUpdate", v1, {w.speed})
    b.rtia.requestAttributeValueUpdate(w.vehicle, [w.position], b"")
    a.wait("provideAttributeValueUpdate", v2, {w.position})

    a.call.requestAttributeTransportationTypeChange(v1, [w.speed], rti1516e.BEST_EFFORT)
    a.wait("confirmAttributeTransportationTypeChange", v1, {w.speed}, rti1516e.BEST_EFFORT)
    a.rtia.updateAttributeValues(v1, {w.speed: b"fast"}, b"t3")
    b.wait("reflectAttributeValues", v1, {w.speed: b"fast"}, b"t3", rti1516e.RECEIVE, rti1516e.BEST_EFFORT)
    # Reported to another federate asking: as changed, else the FOM's.
    b.call.queryAttributeTransportationType(v1, w.speed)
    b.wait("reportAttributeTransportationType", v1, w.speed, rti1516e.BEST_EFFORT)
    b.rtia.queryAttributeTransportationType(v1, w.position)
    b.wait("reportAttributeTransportationType", v1, w.position, rti1516e.RELIABLE)
    a.rtia.requestInteractionTransportationTypeChange(w.command, rti1516e.BEST_EFFORT)
    a.settle()  # the gateway has the change before b asks
    b.call.queryInteractionTransportationType(w.ha, w.command)
    b.wait("reportInteractionTransportationType", w.ha, w.command, rti1516e.BEST_EFFORT)
    a.call.requestInteractionTransportationTypeChange(w.command, rti1516e.RELIABLE)
    a.wait("confirmInteractionTransportationTypeChange", w.command, rti1516e.RELIABLE)
    a.settle()
    b.rtia.queryInteractionTransportationType(w.ha, w.command)
    b.until(lambda: len(b.amb.named("reportInteractionTransportationType")) == 2)
    assert b.amb.last("reportInteractionTransportationType") == (w.ha, w.command, rti1516e.RELIABLE)
    with pytest.raises(rti1516e.ObjectInstanceNotKnown):
        b.rtia.queryAttributeTransportationType(rti1516e.ObjectInstanceHandle(), w.speed)

    a.call.deleteObjectInstance(v2, b"bye")
    b.wait("removeObjectInstance", v2, b"bye", rti1516e.RECEIVE)
    b.call.localDeleteObjectInstance(v3)
    with pytest.raises(rti1516e.ObjectInstanceNotKnown):
        b.rtia.getObjectInstanceName(v3)


def time_management(a: Federate, b: Federate, w: World) -> None:
    """a regulating with lookahead 2, b constrained."""
    v1, v4 = w.objects[0], w.objects[3]
    a.call.enableTimeRegulation(1.0)
    a.wait("timeRegulationEnabled", 0.0)
    b.call.enableTimeConstrained()
    b.wait("timeConstrainedEnabled", 0.0)
    a.call.modifyLookahead(2.0)
    assert a.call.queryLookahead() == 2.0
    h3 = a.rtia.updateAttributeValues(v1, {w.position: b"p3"}, b"", 3.0)
    h4 = a.rtia.sendInteraction(w.command, {w.verb: b"c4"}, b"", 4.0)
    a.call.changeAttributeOrderType(v1, [w.speed], rti1516e.TIMESTAMP)
    h5 = a.rtia.updateAttributeValues(v1, {w.speed: b"s5"}, b"", 5.0)
    h8 = a.rtia.updateAttributeValues(v1, {w.position: b"p8"}, b"", 8.0)
    a.call.retract(h8)
    a.call.changeInteractionOrderType(w.command, rti1516e.RECEIVE)
    a.rtia.sendInteraction(w.command, {w.verb: b"ro"}, b"", 5.0)
    a.call.timeAdvanceRequest(6.0)
    a.wait("timeAdvanceGrant", 6.0)
    b.call.enableAsynchronousDelivery()
    with pytest.raises(rti1516e.AsynchronousDeliveryAlreadyEnabled):
        b.rtia.enableAsynchronousDelivery()
    b.wait("receiveInteraction", w.command, {w.verb: b"ro"}, b"", rti1516e.RECEIVE, rti1516e.RELIABLE, None)
    b.call.disableAsynchronousDelivery()
    with pytest.raises(rti1516e.AsynchronousDeliveryAlreadyDisabled):
        b.rtia.disableAsynchronousDelivery()

    # b's advances, each granted after the messages up to its time (a at 6 + lookahead 2 bounds b at 8).
    tso = (rti1516e.TIMESTAMP,)
    for advance, asked, granted, callback, message in (
            ("timeAdvanceRequest", 3.0, 3.0, "reflectAttributeValues",
             (v1, {w.position: b"p3"}, b"", *tso, rti1516e.RELIABLE, 3.0, *tso, h3)),
            ("nextMessageRequest", 7.0, 4.0, "receiveInteraction",
             (w.command, {w.verb: b"c4"}, b"", *tso, rti1516e.RELIABLE, 4.0, *tso, h4)),
            ("timeAdvanceRequestAvailable", 5.0, 5.0, "reflectAttributeValues",
             (v1, {w.speed: b"s5"}, b"", *tso, rti1516e.BEST_EFFORT, 5.0, *tso, h5))):
        getattr(b.call, advance)(asked)
        b.wait("timeAdvanceGrant", granted)
        assert message in [r[:8] for r in b.amb.named(callback)], advance
    b.call.nextMessageRequestAvailable(7.0)  # none before 7: p8 was retracted
    b.wait("timeAdvanceGrant", 7.0)
    assert (b.call.queryGALT(), b.call.queryLogicalTime(), b.call.queryLITS()) == (8.0, 7.0, 8.0)

    h9 = a.rtia.updateAttributeValues(v1, {w.position: b"p9"}, b"", 9.0)
    a.settle()  # queued for b before b flushes
    b.call.flushQueueRequest(20.0)
    b.until(lambda: len(b.amb.named("timeAdvanceGrant")) == 5, "the flush's grant")
    b.wait("reflectAttributeValues", v1, {w.position: b"p9"}, b"", *tso, rti1516e.RELIABLE, 9.0, *tso, h9)
    a.rtia.retract(h9)
    b.wait("requestRetraction", h9)
    assert not [r for r in b.amb.named("reflectAttributeValues") if r[1] == {w.position: b"p8"}]

    h10 = a.rtia.deleteObjectInstance(v4, b"late", 10.0)
    a.rtia.timeAdvanceRequest(9.0)
    b.rtia.timeAdvanceRequest(10.0)
    b.wait("timeAdvanceGrant", 10.0)
    assert (v4, b"late", *tso, 10.0, *tso, h10) in [r[:6] for r in b.amb.named("removeObjectInstance")]
    assert a.call.decodeMessageRetractionHandle(h10.encode()) == h10
    a.call.disableTimeRegulation()
    with pytest.raises(rti1516e.TimeRegulationIsNotEnabled):
        a.rtia.disableTimeRegulation()
    b.call.disableTimeConstrained()
    with pytest.raises(rti1516e.TimeConstrainedIsNotEnabled):
        b.rtia.disableTimeConstrained()


def ownership(a: Federate, b: Federate, w: World) -> None:
    v1 = w.objects[0]
    b.rtia.publishObjectClassAttributes(w.vehicle, [w.position, w.speed])
    b.call.attributeOwnershipAcquisition(v1, [w.speed], b"want")
    a.wait("requestAttributeOwnershipRelease", v1, {w.speed}, b"want")
    a.call.attributeOwnershipReleaseDenied(v1, [w.speed])
    assert a.call.isAttributeOwnedByFederate(v1, w.speed)
    assert a.call.attributeOwnershipDivestitureIfWanted(v1, [w.speed, w.position]) == {w.speed}
    b.wait("attributeOwnershipAcquisitionNotification", v1, {w.speed})
    assert b.rtia.isAttributeOwnedByFederate(v1, w.speed) and not a.rtia.isAttributeOwnedByFederate(v1, w.speed)
    a.call.negotiatedAttributeOwnershipDivestiture(v1, [w.position], b"offer")
    b.wait("requestAttributeOwnershipAssumption", v1, {w.position}, b"offer")
    a.call.cancelNegotiatedAttributeOwnershipDivestiture(v1, [w.position])
    with pytest.raises(rti1516e.AttributeDivestitureWasNotRequested):
        a.rtia.cancelNegotiatedAttributeOwnershipDivestiture(v1, [w.position])
    a.rtia.negotiatedAttributeOwnershipDivestiture(v1, [w.position], b"again")
    b.wait("requestAttributeOwnershipAssumption", v1, {w.position}, b"again")
    b.rtia.attributeOwnershipAcquisition(v1, [w.position], b"")
    a.wait("requestDivestitureConfirmation", v1, {w.position})
    a.call.confirmDivestiture(v1, [w.position], b"")
    with pytest.raises(rti1516e.AttributeDivestitureWasNotRequested):
        a.rtia.confirmDivestiture(v1, [w.position], b"")
    b.wait("attributeOwnershipAcquisitionNotification", v1, {w.position})
    b.call.unconditionalAttributeOwnershipDivestiture(v1, [w.speed])
    b.call.queryAttributeOwnership(v1, w.speed)
    b.wait("attributeIsNotOwned", v1, w.speed)
    a.call.attributeOwnershipAcquisitionIfAvailable(v1, [w.speed])
    a.wait("attributeOwnershipAcquisitionNotification", v1, {w.speed})
    a.rtia.queryAttributeOwnership(v1, w.position)
    a.wait("informAttributeOwnership", v1, w.position, w.hb)
    a.rtia.attributeOwnershipAcquisition(v1, [w.position], b"back")
    b.wait("requestAttributeOwnershipRelease", v1, {w.position}, b"back")
    a.call.cancelAttributeOwnershipAcquisition(v1, [w.position])
    a.wait("confirmAttributeOwnershipAcquisitionCancellation", v1, {w.position})
    assert b.rtia.isAttributeOwnedByFederate(v1, w.position)


def regions(a: Federate, b: Federate, w: World) -> None:
    """b's regions decide what reaches it once it has no subscription of the default region (the whole space)."""
    b.call.unsubscribeObjectClass(w.vehicle)
    a.wait("stopRegistrationForObjectClass", w.vehicle)
    b.call.unsubscribeInteractionClass(w.command)
    a.wait("turnInteractionsOff", w.command)
    a.call.disableAttributeRelevanceAdvisorySwitch()
    b.call.enableAttributeScopeAdvisorySwitch()
    wanted = b.call.createRegion({w.x})
    assert b.call.getDimensionHandleSet(wanted) == {w.x} and b.call.getRangeBounds(wanted, w.x) == (0, 1000)
    b.call.setRangeBounds(wanted, w.x, (0, 100))
    with pytest.raises(rti1516e.InvalidRangeBound):
        b.rtia.setRangeBounds(wanted, w.x, (10, 1001))
    b.call.commitRegionModifications({wanted})
    b.call.subscribeObjectClassAttributesWithRegions(w.vehicle, [({w.position}, {wanted})])
    b.call.subscribeInteractionClassWithRegions(w.command, {wanted})
    b.settle()  # the gateway has b's subscriptions before a's updates

    far, near = a.rtia.createRegion({w.x, w.y}), a.rtia.createRegion({w.x})
    a.rtia.setRangeBounds(far, w.x, (500, 600))
    a.rtia.setRangeBounds(near, w.x, (50, 60))
    a.rtia.commitRegionModifications({far, near})
    a.rtia.reserveObjectInstanceName("ddm-1")
    a.wait("objectInstanceNameReservationSucceeded", "ddm-1")
    d1 = a.call.registerObjectInstanceWithRegions(w.vehicle, [({w.position}, {far})], "ddm-1")
    d2 = a.rtia.registerObjectInstanceWithRegions(w.vehicle, [({w.position}, {near})])

    def update(o: Any, v: bytes) -> None:
        a.rtia.updateAttributeValues(o, {w.position: v}, b"")

    update(d1, b"far")
    update(d2, b"near-2")
    a.call.sendInteractionWithRegions(w.command, {w.verb: b"far"}, {far}, b"")
    a.rtia.sendInteractionWithRegions(w.command, {w.verb: b"near"}, {near}, b"")
    assert a.rtia.sendInteractionWithRegions(w.command, {w.verb: b"timed"}, {near}, b"", 50.0).isValid()
    a.call.associateRegionsForUpdates(d1, [({w.position}, {near})])
    update(d1, b"near-1")
    a.rtia.setRangeBounds(near, w.x, (200, 300))
    a.rtia.commitRegionModifications([near])
    update(d1, b"moved")
    a.call.unassociateRegionsForUpdates(d1, [({w.position}, {far, near})])  # associating near added it to far
    update(d1, b"free")
    b.wait("reflectAttributeValues", d1, {w.position: b"free"})
    b.until(lambda: any(r[1] == {w.verb: b"timed"} for r in b.amb.named("receiveInteraction")))
    a.settle()
    b.settle()
    got = [r[1][w.position] for r in b.amb.named("reflectAttributeValues") if r[0] in (d1, d2)]
    assert got == [b"near-2", b"near-1", b"free"]
    heard = [r[1][w.verb] for r in b.amb.named("receiveInteraction")]
    assert b"near" in heard and b"far" not in heard
    assert (d2, {w.position}) in b.amb.named("attributesInScope") and (d2, {w.position}) in b.amb.named("attributesOutOfScope")

    b.call.disableAttributeScopeAdvisorySwitch()
    in_scope = len(b.amb.named("attributesInScope"))
    a.rtia.setRangeBounds(near, w.x, (50, 60))
    a.rtia.commitRegionModifications([near])
    a.settle()  # the gateway has the commit before b's request
    b.call.requestAttributeValueUpdateWithRegions(w.vehicle, [({w.position}, {wanted})], b"")
    a.wait("provideAttributeValueUpdate", d2, {w.position})
    a.settle()
    b.settle()
    assert len(b.amb.named("attributesInScope")) == in_scope

    b.call.unsubscribeObjectClassAttributesWithRegions(w.vehicle, [({w.position}, {wanted})])
    b.call.unsubscribeInteractionClassWithRegions(w.command, {wanted})
    counts = len(b.amb.named("reflectAttributeValues")), len(b.amb.named("receiveInteraction"))
    update(d2, b"after")
    a.rtia.sendInteractionWithRegions(w.command, {w.verb: b"after"}, {near}, b"")
    a.settle()
    b.settle()
    assert (len(b.amb.named("reflectAttributeValues")), len(b.amb.named("receiveInteraction"))) == counts
    b.call.deleteRegion(wanted)
    with pytest.raises(rti1516e.RegionNotCreatedByThisFederate):
        b.rtia.deleteRegion(wanted)
    assert a.call.decodeRegionHandle(far.encode()) == far
    assert a.call.decodeDimensionHandle(w.x.encode()) == w.x


def sync_save_restore(a: Federate, b: Federate, w: World) -> None:
    def both(name: str, *args: Any) -> None:
        for f in (a, b):
            f.wait(name, *args)

    a.call.registerFederationSynchronizationPoint("all", b"x")
    a.wait("synchronizationPointRegistrationSucceeded", "all")
    both("announceSynchronizationPoint", "all", b"x")
    a.call.synchronizationPointAchieved("all")
    b.rtia.synchronizationPointAchieved("all")
    both("federationSynchronized", "all")
    a.rtia.registerFederationSynchronizationPoint("just-b", b"y", [w.hb])
    b.wait("announceSynchronizationPoint", "just-b", b"y")
    b.rtia.synchronizationPointAchieved("just-b")
    b.wait("federationSynchronized", "just-b", set())
    a.settle()
    assert ("just-b", b"y") not in a.amb.named("announceSynchronizationPoint")

    def statuses(query: str) -> dict[Any, int]:
        getattr(a.call, f"queryFederation{query}Status")()
        a.wait(f"federation{query}StatusResponse")
        return {s[0]: s[-1] for s in a.amb.calls.pop()[1][0]}

    a.call.requestFederationSave("s1")
    both("initiateFederateSave", "s1")
    a.call.federateSaveBegun()
    assert statuses("Save") == {w.ha: rti1516e.FEDERATE_SAVING, w.hb: rti1516e.FEDERATE_INSTRUCTED_TO_SAVE}
    a.call.federateSaveComplete()
    b.rtia.federateSaveBegun()
    b.rtia.federateSaveComplete()
    both("federationSaved")
    with pytest.raises(rti1516e.SaveNotInProgress):
        a.call.abortFederationSave()
    a.call.requestFederationSave("s2", 50.0)
    both("initiateFederateSave", "s2")
    a.rtia.federateSaveBegun()
    a.rtia.federateSaveComplete()
    b.rtia.federateSaveBegun()
    b.call.federateSaveNotComplete()
    both("federationNotSaved", rti1516e.FEDERATE_REPORTED_FAILURE_DURING_SAVE)
    # A save aborted by b while a has answered: both hear it was aborted.
    a.rtia.requestFederationSave("s3")
    both("initiateFederateSave", "s3")
    a.rtia.federateSaveBegun()
    a.rtia.federateSaveComplete()
    b.rtia.abortFederationSave()
    both("federationNotSaved", rti1516e.SAVE_ABORTED)

    a.call.requestFederationRestore("nothing")
    a.wait("requestFederationRestoreFailed", "nothing")
    a.rtia.requestFederationRestore("s1")
    a.wait("requestFederationRestoreSucceeded", "s1")
    both("federationRestoreBegun")
    a.wait("initiateFederateRestore", "s1", "a", w.ha)
    b.wait("initiateFederateRestore", "s1", "b", w.hb)
    a.call.federateRestoreComplete()
    assert statuses("Restore") == {w.ha: rti1516e.FEDERATE_WAITING_FOR_FEDERATION_TO_RESTORE,
                                   w.hb: rti1516e.FEDERATE_RESTORING}
    b.rtia.federateRestoreComplete()
    both("federationRestored")
    with pytest.raises(rti1516e.RestoreNotInProgress):
        a.call.abortFederationRestore()

    def restore_again(restores: int, b_ends: Callable[[], None]) -> None:
        """s1 restored again, a answering, then b ending it."""
        a.rtia.requestFederationRestore("s1")
        for f in (a, b):
            f.until(lambda: len(f.amb.named("initiateFederateRestore")) == restores)
        a.rtia.federateRestoreComplete()
        b_ends()
    restore_again(2, b.call.federateRestoreNotComplete)
    both("federationNotRestored", rti1516e.FEDERATE_REPORTED_FAILURE_DURING_RESTORE)
    restore_again(3, b.rtia.abortFederationRestore)  # aborted by b while a has answered
    both("federationNotRestored", rti1516e.RESTORE_ABORTED)


def callbacks(a: Federate, w: World) -> None:
    """evokeCallback delivers one callback; disabled, callbacks wait until enabled."""
    a.settle()
    a.rtia.reserveObjectInstanceName("one-callback")
    with pytest.raises(rti1516e.FederationExecutionDoesNotExist):  # a round trip: the answer is queued
        a.rtia.destroyFederationExecution("no-such")
    before = len(a.amb.calls)
    assert a.call.evokeCallback(1.0) is False and len(a.amb.calls) == before + 1
    assert a.amb.calls[-1] == ("objectInstanceNameReservationSucceeded", ("one-callback",))
    a.call.disableCallbacks()
    a.rtia.reserveObjectInstanceName("held")
    with pytest.raises(rti1516e.FederationExecutionDoesNotExist):
        a.rtia.destroyFederationExecution("no-such")
    assert a.rtia.evokeMultipleCallbacks(0.0, 0.1) is True and len(a.amb.calls) == before + 1
    a.call.enableCallbacks()
    a.wait("objectInstanceNameReservationSucceeded", "held")
    for kind, handle in ((rti1516e.FederateHandle, w.hb), (rti1516e.ObjectClassHandle, w.car),
                         (rti1516e.InteractionClassHandle, w.command), (rti1516e.ObjectInstanceHandle, w.objects[0]),
                         (rti1516e.AttributeHandle, w.doors), (rti1516e.ParameterHandle, w.verb)):
        assert getattr(a.call, f"decode{kind.__name__}")(handle.encode()) == handle
    with pytest.raises(rti1516e.CouldNotDecode):
        a.rtia.decodeAttributeHandle(b"abc")


def immediate_integer_time(c: Federate) -> None:
    """An HLA_IMMEDIATE federate in an HLAinteger64Time federation: nobody evokes, times are ints."""
    with pytest.raises(rti1516e.FederateNameAlreadyInUse):
        c.rtia.joinFederationExecution("a", "test", "Services")
    c.rtia.createFederationExecution("Integers", VEHICLES, "HLAinteger64Time")
    hc = c.call.joinFederationExecution("test", "Integers")
    assert hc.isValid() and c.rtia.getTimeFactory() == "HLAinteger64Time"
    c.rtia.enableTimeRegulation(2)
    c.wait("timeRegulationEnabled", 0)
    assert c.rtia.queryLookahead() == 2 and type(c.rtia.queryLookahead()) is int
    c.rtia.disableCallbacks()
    c.rtia.timeAdvanceRequest(3)
    time.sleep(0.3)
    assert not c.amb.named("timeAdvanceGrant")
    c.rtia.enableCallbacks()
    c.wait("timeAdvanceGrant", 3)
    assert c.rtia.queryLogicalTime() == 3 and type(c.rtia.queryLogicalTime()) is int
    c.rtia.resignFederationExecution(rti1516e.NO_ACTION)
    c.rtia.destroyFederationExecution("Integers")
    c.rtia.disconnect()


def finish(a: Federate, b: Federate, w: World) -> None:
    a.call.unpublishInteractionClass(w.command)
    with pytest.raises(rti1516e.InteractionClassNotPublished):
        a.rtia.sendInteraction(w.command, {}, b"")
    a.call.unpublishObjectClass(w.vehicle)
    with pytest.raises(rti1516e.ObjectClassNotPublished):
        a.rtia.registerObjectInstance(w.vehicle)
    with pytest.raises(rti1516e.FederateIsExecutionMember):
        a.call.disconnect()
    b.call.resignFederationExecution(rti1516e.CANCEL_THEN_DELETE_THEN_DIVEST)
    with pytest.raises(rti1516e.FederateNotExecutionMember):
        b.rtia.getObjectClassHandle("Vehicle")
    with pytest.raises(rti1516e.FederatesCurrentlyJoined):
        a.rtia.destroyFederationExecution("Services")
    a.rtia.resignFederationExecution(rti1516e.DELETE_OBJECTS_THEN_DIVEST)
    a.rtia.destroyFederationExecution("Services")
    a.rtia.disconnect()
    b.rtia.disconnect()
    with pytest.raises(rti1516e.NotConnected):
        a.rtia.getObjectClassHandle("Vehicle")
