"""Every HLA 1.3 service of PyHLA's RTIambassador is there and works: one scripted federation calls each,
with valid arguments, over both gateways, and none raises (no "not implemented", no RTIinternalError).
The list is PyHLA's method table (../shared/reference/hla13-rtis-and-pyhla.md §2.3), by HLA 1.3 chapter."""

from __future__ import annotations

from typing import Any

import pytest

import hlacore.rti as rti

from support import DATA, Recorder, barrier, tick_until

DDM_FED = str(DATA / "ddm.fed")  # vehicle.position/speed and the radio interaction route in space Geo (X, Y)

FEDERATION_MANAGEMENT = [
    "createFederationExecution", "destroyFederationExecution", "joinFederationExecution",
    "resignFederationExecution", "registerFederationSynchronizationPoint", "synchronizationPointAchieved",
    "requestFederationSave", "federateSaveBegun", "federateSaveComplete", "federateSaveNotComplete",
    "requestFederationRestore", "federateRestoreComplete", "federateRestoreNotComplete",
]
DECLARATION_MANAGEMENT = [
    "publishObjectClass", "unpublishObjectClass", "publishInteractionClass", "unpublishInteractionClass",
    "subscribeObjectClassAttributes", "unsubscribeObjectClass", "subscribeInteractionClass",
    "unsubscribeInteractionClass",
]
OBJECT_MANAGEMENT = [
    "registerObjectInstance", "updateAttributeValues", "sendInteraction", "deleteObjectInstance",
    "localDeleteObjectInstance", "changeAttributeTransportationType", "changeInteractionTransportationType",
    "requestObjectAttributeValueUpdate", "requestClassAttributeValueUpdate",
]
OWNERSHIP_MANAGEMENT = [
    "unconditionalAttributeOwnershipDivestiture", "negotiatedAttributeOwnershipDivestiture",
    "attributeOwnershipAcquisition", "attributeOwnershipAcquisitionIfAvailable", "attributeOwnershipReleaseResponse",
    "cancelNegotiatedAttributeOwnershipDivestiture", "cancelAttributeOwnershipAcquisition",
    "queryAttributeOwnership", "isAttributeOwnedByFederate",
]
TIME_MANAGEMENT = [
    "enableTimeRegulation", "disableTimeRegulation", "enableTimeConstrained", "disableTimeConstrained",
    "timeAdvanceRequest", "timeAdvanceRequestAvailable", "nextEventRequest", "nextEventRequestAvailable",
    "flushQueueRequest", "enableAsynchronousDelivery", "disableAsynchronousDelivery", "queryLBTS",
    "queryFederateTime", "queryMinNextEventTime", "modifyLookahead", "queryLookahead", "retract",
    "changeAttributeOrderType", "changeInteractionOrderType",
]
DATA_DISTRIBUTION_MANAGEMENT = [
    "createRegion", "notifyAboutRegionModification", "deleteRegion", "registerObjectInstanceWithRegion",
    "associateRegionForUpdates", "unassociateRegionForUpdates", "subscribeObjectClassAttributesWithRegion",
    "unsubscribeObjectClassWithRegion", "subscribeInteractionClassWithRegion",
    "unsubscribeInteractionClassWithRegion", "sendInteractionWithRegion",
    "requestClassAttributeValueUpdateWithRegion",
]
SUPPORT_SERVICES = [
    "getObjectClassHandle", "getObjectClassName", "getAttributeHandle", "getAttributeName",
    "getInteractionClassHandle", "getInteractionClassName", "getParameterHandle", "getParameterName",
    "getObjectInstanceHandle", "getObjectInstanceName", "getRoutingSpaceHandle", "getRoutingSpaceName",
    "getDimensionHandle", "getDimensionName", "getAttributeRoutingSpaceHandle", "getObjectClass",
    "getInteractionRoutingSpaceHandle", "getTransportationHandle", "getTransportationName", "getOrderingHandle",
    "getOrderingName", "enableClassRelevanceAdvisorySwitch", "disableClassRelevanceAdvisorySwitch",
    "enableAttributeRelevanceAdvisorySwitch", "disableAttributeRelevanceAdvisorySwitch",
    "enableAttributeScopeAdvisorySwitch", "disableAttributeScopeAdvisorySwitch",
    "enableInteractionRelevanceAdvisorySwitch", "disableInteractionRelevanceAdvisorySwitch", "tick",
]
SERVICES = (FEDERATION_MANAGEMENT + DECLARATION_MANAGEMENT + OBJECT_MANAGEMENT + OWNERSHIP_MANAGEMENT
            + TIME_MANAGEMENT + DATA_DISTRIBUTION_MANAGEMENT + SUPPORT_SERVICES)


def test_the_list_names_each_service_once() -> None:
    assert len(SERVICES) == len(set(SERVICES)) == 100


@pytest.mark.parametrize("service", SERVICES)
def test_service_is_a_method_of_the_ambassador(service: str) -> None:
    assert callable(getattr(rti.RTIAmbassador, service, None)), f"RTIAmbassador has no {service}"


class Session:
    """One federate of the scripted federation: its ambassador, a Recorder, and `call` by service name."""

    def __init__(self, address: str, called: set[str]) -> None:
        self.rtia, self.amb, self.called = rti.RTIAmbassador(address), Recorder(), called

    def __call__(self, service: str, *args: Any) -> Any:
        self.called.add(service)
        return getattr(self.rtia, service)(*args)

    def saw(self, callback: str) -> list[tuple[Any, ...]]:
        return self.amb.named(callback)


def test_every_service_runs(gateway_address: str) -> None:
    called: set[str] = set()
    creator = Session(gateway_address, called)
    creator("createFederationExecution", "Services", DDM_FED)
    a, b = Session(gateway_address, called), Session(gateway_address, called)
    a("joinFederationExecution", "a", "Services", a.amb)
    b("joinFederationExecution", "b", "Services", b.amb)

    def until(predicate: Any) -> None:
        tick_until(predicate, a.rtia, b.rtia)

    # Support services (HLA 1.3 §10).
    vehicle = a("getObjectClassHandle", "vehicle")
    assert a("getObjectClassName", vehicle) == "vehicle"
    position, speed = a("getAttributeHandle", "position", vehicle), a("getAttributeHandle", "speed", vehicle)
    assert a("getAttributeName", position, vehicle) == "position"
    radio = a("getInteractionClassHandle", "radio")
    assert a("getInteractionClassName", radio) == "radio"
    text = a("getParameterHandle", "text", radio)
    assert a("getParameterName", text, radio) == "text"
    reliable, best_effort = a("getTransportationHandle", "HLAreliable"), a("getTransportationHandle", "HLAbestEffort")
    assert a("getTransportationName", best_effort) == "HLAbestEffort"
    timestamp, receive = a("getOrderingHandle", "Timestamp"), a("getOrderingHandle", "Receive")
    assert a("getOrderingName", receive) == "Receive"
    geo = a("getRoutingSpaceHandle", "Geo")
    assert a("getRoutingSpaceName", geo) == "Geo"
    x = a("getDimensionHandle", "X", geo)
    assert a("getDimensionName", x, geo) == "X"
    assert a("getAttributeRoutingSpaceHandle", position, vehicle) == geo
    assert a("getInteractionRoutingSpaceHandle", radio) == geo
    for switch in ("ClassRelevance", "AttributeRelevance", "AttributeScope", "InteractionRelevance"):
        a(f"enable{switch}AdvisorySwitch")
        a(f"disable{switch}AdvisorySwitch")
    a("enableClassRelevanceAdvisorySwitch")
    a("tick")

    # Declaration management (§5) and synchronization points (§4.6-4.10).
    a("publishObjectClass", vehicle, [position, speed])
    b("publishObjectClass", vehicle, [position, speed])
    b("subscribeObjectClassAttributes", vehicle, [position, speed])
    a("publishInteractionClass", radio)
    b("subscribeInteractionClass", radio)
    barrier(b.rtia)
    a("registerFederationSynchronizationPoint", "ready", "")
    until(lambda: a.saw("announceSynchronizationPoint") and b.saw("announceSynchronizationPoint"))
    a("synchronizationPointAchieved", "ready")
    b("synchronizationPointAchieved", "ready")
    until(lambda: a.saw("federationSynchronized") and b.saw("federationSynchronized"))

    # Object management (§6).
    obj = a("registerObjectInstance", vehicle, "r1")
    until(lambda: b.saw("discoverObjectInstance"))
    assert a("getObjectInstanceHandle", "r1") == obj and a("getObjectInstanceName", obj) == "r1"
    assert a("getObjectClass", obj) == vehicle
    a("updateAttributeValues", obj, {position: b"here"}, "")
    a("sendInteraction", radio, {text: b"go"}, "")
    until(lambda: b.saw("reflectAttributeValues") and b.saw("receiveInteraction"))
    b("requestObjectAttributeValueUpdate", obj, [position])
    b("requestClassAttributeValueUpdate", vehicle, [speed])
    until(lambda: len(a.saw("provideAttributeValueUpdate")) == 2)
    a("changeAttributeTransportationType", obj, [position], best_effort)
    a("changeInteractionTransportationType", radio, reliable)
    a("changeAttributeOrderType", obj, [position], receive)
    a("changeInteractionOrderType", radio, timestamp)

    # Ownership management (§7): speed goes to b by negotiation and comes back unconditionally; a asks
    # for position back and cancels, b releases it on request.
    a("negotiatedAttributeOwnershipDivestiture", obj, [speed], "")
    a("cancelNegotiatedAttributeOwnershipDivestiture", obj, [speed])
    a("negotiatedAttributeOwnershipDivestiture", obj, [speed], "")
    until(lambda: b.saw("requestAttributeOwnershipAssumption"))
    b("attributeOwnershipAcquisition", obj, [speed], "")
    until(lambda: b.saw("attributeOwnershipAcquisitionNotification"))
    b("unconditionalAttributeOwnershipDivestiture", obj, [speed])
    a("attributeOwnershipAcquisitionIfAvailable", obj, [speed])
    until(lambda: len(a.saw("attributeOwnershipAcquisitionNotification")) == 1)
    b("attributeOwnershipAcquisition", obj, [position], "")
    until(lambda: a.saw("requestAttributeOwnershipRelease"))
    assert a("attributeOwnershipReleaseResponse", obj, [position]) == (position,)
    until(lambda: len(b.saw("attributeOwnershipAcquisitionNotification")) == 2)
    a("attributeOwnershipAcquisition", obj, [position], "")
    until(lambda: b.saw("requestAttributeOwnershipRelease"))
    a("cancelAttributeOwnershipAcquisition", obj, [position])
    until(lambda: a.saw("confirmAttributeOwnershipAcquisitionCancellation"))
    a("queryAttributeOwnership", obj, position)
    until(lambda: a.saw("informAttributeOwnership"))
    assert a("isAttributeOwnedByFederate", obj, speed) and not a("isAttributeOwnedByFederate", obj, position)

    # Time management (§8): both regulating and constrained, each kind of advance once.
    for fed in (a, b):
        fed("enableTimeRegulation", 0.0, 1.0)
        fed("enableTimeConstrained")
    until(lambda: all(len(f.saw("timeRegulationEnabled")) == len(f.saw("timeConstrainedEnabled")) == 1 for f in (a, b)))
    a("modifyLookahead", 2.0)
    assert a("queryLookahead") == 2.0
    assert a("queryFederateTime") == 0.0 and a("queryLBTS") == 1.0
    a("queryMinNextEventTime")
    a("enableAsynchronousDelivery")
    a("disableAsynchronousDelivery")
    a("retract", a("sendInteraction", radio, {text: b"never"}, "", 5.0))
    def grants(fed: Session) -> list[float]:
        return [t for (t,) in fed.saw("timeAdvanceGrant")]

    a("timeAdvanceRequest", 10.0)
    b("timeAdvanceRequestAvailable", 10.0)
    until(lambda: grants(a) == grants(b) == [10.0])
    a("nextEventRequest", 20.0)
    b("nextEventRequestAvailable", 20.0)
    until(lambda: grants(a) == grants(b) == [10.0, 20.0])
    a("flushQueueRequest", 30.0)  # granted at once, at its LBTS: b's 20 + lookahead 1
    until(lambda: grants(a) == [10.0, 20.0, 21.0])
    for fed in (a, b):
        fed("disableTimeRegulation")
        fed("disableTimeConstrained")

    # Data distribution management (§9): b listens in X [0, 10]; a's vehicle r3 is at X 5.
    near = b("createRegion", geo, [(x, (0, 10))])
    b("subscribeObjectClassAttributesWithRegion", vehicle, near, [position])
    b("subscribeInteractionClassWithRegion", radio, near)
    here = a("createRegion", geo, [(x, (5, 5))])
    tracked = a("registerObjectInstanceWithRegion", vehicle, [(position, here)], "r3")
    a("associateRegionForUpdates", here, tracked, [speed])
    a("sendInteractionWithRegion", radio, {text: b"near"}, here, "")
    until(lambda: any(args[1] == {text: b"near"} for args in b.saw("receiveInteraction")))
    b("requestClassAttributeValueUpdateWithRegion", vehicle, [position], near)
    until(lambda: (tracked, (position,)) in a.saw("provideAttributeValueUpdate"))
    b("notifyAboutRegionModification", near)
    a("unassociateRegionForUpdates", here, tracked)
    b("unsubscribeObjectClassWithRegion", vehicle, near)
    b("unsubscribeInteractionClassWithRegion", radio, near)
    for fed, region in ((a, here), (b, near)):
        fed("deleteRegion", region)

    # Save and restore (§4.11-4.22): a save, a save one federate fails, a restore one federate fails, a
    # restore.
    a("requestFederationSave", "snapshot")
    until(lambda: a.saw("initiateFederateSave") and b.saw("initiateFederateSave"))
    for fed in (a, b):
        fed("federateSaveBegun")
        fed("federateSaveComplete")
    until(lambda: a.saw("federationSaved") and b.saw("federationSaved"))
    a("requestFederationSave", "broken")
    until(lambda: len(a.saw("initiateFederateSave")) == len(b.saw("initiateFederateSave")) == 2)
    a("federateSaveComplete")
    b("federateSaveNotComplete")
    until(lambda: a.saw("federationNotSaved") and b.saw("federationNotSaved"))
    for told, (outcome, result) in enumerate([("federateRestoreNotComplete", "federationNotRestored"),
                                              ("federateRestoreComplete", "federationRestored")], start=1):
        a("requestFederationRestore", "snapshot")
        until(lambda: len(a.saw("initiateFederateRestore")) == len(b.saw("initiateFederateRestore")) == told)
        a("federateRestoreComplete")
        b(outcome)
        until(lambda: a.saw(result) and b.saw(result))
    assert len(a.saw("requestFederationRestoreSucceeded")) == 2

    # The end of object and declaration management.
    other = a("registerObjectInstance", vehicle, "r2")
    until(lambda: any(args[0] == other for args in b.saw("discoverObjectInstance")))
    b("localDeleteObjectInstance", other)
    a("deleteObjectInstance", obj, "")
    until(lambda: b.saw("removeObjectInstance"))
    b("unsubscribeObjectClass", vehicle)
    b("unsubscribeInteractionClass", radio)
    a("unpublishObjectClass", vehicle)
    a("unpublishInteractionClass", radio)

    for fed in (a, b):
        fed("resignFederationExecution", rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    creator("destroyFederationExecution", "Services")
    assert sorted(set(SERVICES) - called) == []

