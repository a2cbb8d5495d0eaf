"""IEEE 1516-2010 in Python (hlacore.rti1516e, docs/rti1516e.md): OpenRTI's module's shape over hlacore's core,
through rtig: FOM modules merged at creation, both time types, the 1516-2010 callbacks with their fixed
positional arguments, exceptions named as in C++, and 1516-2010 and HLA 1.3 federates in one federation."""

from __future__ import annotations

import struct
import time
from typing import Any, Callable, Iterator

import pytest

import hlacore.rti as rti
import hlacore.rti1516e as rti1516e
from hlacore import _core
from support import RtigProcess, running_rtig
from support.rti1516e import CARS, VEHICLES, Federate, Recorder


@pytest.fixture
def federates(rtig: Any) -> Iterator[Callable[[], Federate]]:
    made: list[Federate] = []

    def make() -> Federate:
        made.append(Federate(rtig.address))
        return made[-1]
    yield make
    for f in reversed(made):
        f.close()


def joined(federates: Callable[[], Federate], name: str, time_type: str = "HLAfloat64Time") -> Federate:
    f = federates()
    try:
        f.rtia.createFederationExecution("Vehicles", [VEHICLES, CARS], time_type)
    except rti1516e.FederationExecutionAlreadyExists:
        pass
    f.rtia.joinFederationExecution(name, "test", "Vehicles")
    return f


def reserve(f: Federate, name: str) -> None:
    f.rtia.reserveObjectInstanceName(name)
    f.until(lambda: (name,) in f.amb.named("objectInstanceNameReservationSucceeded"))


def test_handles_enumerations_and_exceptions_have_the_standards_shape() -> None:
    empty = rti1516e.ObjectClassHandle()
    assert not empty.isValid() and repr(empty) == "rti1516e::ObjectClassHandle(Invalid)" and empty.encode() == b""
    assert empty == rti1516e.ObjectClassHandle() and empty != rti1516e.AttributeHandle()
    assert len({empty, rti1516e.ObjectClassHandle()}) == 1
    assert (rti1516e.RECEIVE, rti1516e.TIMESTAMP, rti1516e.RELIABLE, rti1516e.BEST_EFFORT) == (1, 2, 1, 2)
    assert rti1516e.NO_ACTION == 5 and rti1516e.CANCEL_THEN_DELETE_THEN_DIVEST == 4
    assert issubclass(rti1516e.NameNotFound, rti1516e.Exception) and issubclass(rti1516e.Exception, Exception)
    assert len(rti1516e._exceptions.NAMES) == 121
    moved = rti1516e._exceptions.translate(_core.ObjectNotKnown("object 7"))
    assert type(moved) is rti1516e.ObjectInstanceNotKnown and str(moved) == "ObjectInstanceNotKnown: object 7"
    assert type(rti1516e._exceptions.translate(_core.GatewayNotResponding("gone"))) is rti1516e.NotConnected


def test_connect_create_from_two_modules_join_and_list(federates: Callable[[], Federate], rtig: Any) -> None:
    a = federates()
    with pytest.raises(rti1516e.FederateNotExecutionMember):
        a.rtia.getObjectClassHandle("Vehicle")
    with pytest.raises(rti1516e.CouldNotCreateLogicalTimeFactory):
        a.rtia.createFederationExecution("Vehicles", [VEHICLES], "HLAfloat32Time")
    a.rtia.createFederationExecution("Vehicles", [VEHICLES, CARS], "HLAinteger64Time")
    with pytest.raises(rti1516e.FederationExecutionAlreadyExists):
        a.rtia.createFederationExecution("Vehicles", VEHICLES)
    me = a.rtia.joinFederationExecution("a", "test", "Vehicles")
    assert me.isValid() and a.rtia.getTimeFactory() == "HLAinteger64Time"
    car = a.rtia.getObjectClassHandle("HLAobjectRoot.Vehicle.Car")  # from the second module
    assert a.rtia.getObjectClassName(car).endswith("Car")
    doors = a.rtia.getAttributeHandle(car, "doors")
    assert a.rtia.getAttributeName(car, doors) == "doors"
    assert a.rtia.getAttributeHandle(car, "position").isValid()  # inherited from the first
    b = federates()
    anonymous = b.rtia.joinFederationExecution("test", "Vehicles")  # no name: a unique one
    assert anonymous != me and b.rtia.getFederateName(anonymous).startswith("test-")
    assert a.rtia.getFederateHandle("a") == me and a.rtia.getFederateName(me) == "a"
    with pytest.raises(rti1516e.FederateNameAlreadyInUse):
        federates().rtia.joinFederationExecution("a", "test", "Vehicles")
    a.rtia.listFederationExecutions()
    a.until(lambda: bool(a.amb.named("reportFederationExecutions")))
    assert a.amb.named("reportFederationExecutions")[0][0] == [
        {"federationExecutionName": "Vehicles", "logicalTimeImplementationName": "HLAinteger64Time"}]


def test_a_bad_module_is_refused_at_the_caller_with_its_place(federates: Callable[[], Federate], tmp_path: Any) -> None:
    bad = tmp_path / "bad.xml"
    bad.write_text("<objectModel><objects><objectClass><name>HLAobjectRoot</name></objects></objectModel>")
    f = federates()
    with pytest.raises(rti1516e.ErrorReadingFDD, match=r"bad\.xml:1:"):
        f.rtia.createFederationExecution("Bad", [VEHICLES, str(bad)])
    with pytest.raises(rti1516e.CouldNotOpenFDD):
        f.rtia.createFederationExecution("Bad", [VEHICLES, str(tmp_path / "missing.xml")])


def test_the_callback_model_and_the_connection_are_checked(rtig: Any) -> None:
    rtia = rti1516e.RTIambassador()
    with pytest.raises(rti1516e.NotConnected):
        rtia.createFederationExecution("X", VEHICLES)
    with pytest.raises(rti1516e.UnsupportedCallbackModel):
        rtia.connect(Recorder(), "HLA_LATER", rtig.address)
    with pytest.raises(rti1516e.InvalidLocalSettingsDesignator):
        rtia.connect(Recorder(), "HLA_EVOKED", "no address")
    rtia.connect(Recorder(), "HLA_EVOKED", "rti://" + rtig.address + "/")
    with pytest.raises(rti1516e.AlreadyConnected):
        rtia.connect(Recorder(), "HLA_EVOKED", rtig.address)
    rtia.disconnect()
    with pytest.raises(rti1516e.ConnectionFailed):
        rti1516e.RTIambassador(timeout=0.5).connect(Recorder(), "HLA_EVOKED", "127.0.0.1:1")


def test_objects_and_interactions_arrive_with_the_standards_arguments(federates: Callable[[], Federate]) -> None:
    a, b = joined(federates, "a"), joined(federates, "b")
    vehicle = a.rtia.getObjectClassHandle("Vehicle")
    speed = a.rtia.getAttributeHandle(vehicle, "speed")
    command = a.rtia.getInteractionClassHandle("Command")
    verb = a.rtia.getParameterHandle(command, "verb")
    a.rtia.publishObjectClassAttributes(vehicle, [speed])
    a.rtia.publishInteractionClass(command)
    b.rtia.subscribeObjectClassAttributes(vehicle, {speed})
    b.rtia.subscribeInteractionClass(command)
    reserve(a, "v1")
    obj = a.rtia.registerObjectInstance(vehicle, "v1")
    assert a.rtia.getObjectInstanceName(obj) == "v1"
    b.until(lambda: bool(b.amb.named("discoverObjectInstance")))
    assert b.amb.named("discoverObjectInstance")[0] == (obj, vehicle, "v1")
    assert a.rtia.updateAttributeValues(obj, {speed: b"\x00\x07"}, b"tag") is None
    a.rtia.sendInteraction(command, {verb: b"stop"}, b"")
    b.until(lambda: bool(b.amb.named("reflectAttributeValues")) and bool(b.amb.named("receiveInteraction")))
    reflected = b.amb.named("reflectAttributeValues")[0]
    assert len(reflected) == 9 and reflected[:8] == (obj, {speed: b"\x00\x07"}, b"tag", rti1516e.RECEIVE,
                                                     rti1516e.RELIABLE, None, None, None)
    assert reflected[8]["hasProducingFederate"] is False and reflected[8]["sentRegions"] == set()
    received = b.amb.named("receiveInteraction")[0]
    assert len(received) == 9 and received[:2] == (command, {verb: b"stop"}) and received[5:8] == (None, None, None)
    assert b.rtia.getKnownObjectClassHandle(obj) == vehicle and b.rtia.getObjectInstanceHandle("v1") == obj
    a.rtia.deleteObjectInstance(obj, b"bye")
    b.until(lambda: bool(b.amb.named("removeObjectInstance")))
    removed = b.amb.named("removeObjectInstance")[0]
    assert len(removed) == 7 and removed[:3] == (obj, b"bye", rti1516e.RECEIVE)
    with pytest.raises(TypeError):
        a.rtia.updateAttributeValues(obj, {speed: "text"}, b"")  # values are bytes
    with pytest.raises(rti1516e.ObjectClassNotDefined):
        a.rtia.registerObjectInstance(rti1516e.ObjectClassHandle())
    with pytest.raises(rti1516e.ObjectInstanceNotKnown):
        a.rtia.updateAttributeValues(obj, {speed: b""}, b"")


def test_publications_add_up_and_unpublish_removes_some(federates: Callable[[], Federate]) -> None:
    a = joined(federates, "a")
    vehicle = a.rtia.getObjectClassHandle("Vehicle")
    position, speed = (a.rtia.getAttributeHandle(vehicle, n) for n in ("position", "speed"))
    a.rtia.publishObjectClassAttributes(vehicle, [position])
    a.rtia.publishObjectClassAttributes(vehicle, [speed])
    obj = a.rtia.registerObjectInstance(vehicle)
    a.rtia.updateAttributeValues(obj, {position: b"p", speed: b"s"}, b"")
    a.rtia.unpublishObjectClassAttributes(vehicle, [position])
    assert a.rtia.isAttributeOwnedByFederate(obj, speed)
    a.rtia.registerObjectInstance(vehicle)  # speed is still published
    a.rtia.unpublishObjectClassAttributes(vehicle, [speed])
    with pytest.raises(rti1516e.ObjectClassNotPublished):
        a.rtia.registerObjectInstance(vehicle)


def test_an_integer_time_lockstep_with_retraction_handles(federates: Callable[[], Federate]) -> None:
    a, b = joined(federates, "a", "HLAinteger64Time"), joined(federates, "b", "HLAinteger64Time")
    vehicle = a.rtia.getObjectClassHandle("Vehicle")
    position = a.rtia.getAttributeHandle(vehicle, "position")
    a.rtia.publishObjectClassAttributes(vehicle, [position])
    b.rtia.subscribeObjectClassAttributes(vehicle, [position])
    for f in (a, b):
        f.rtia.enableTimeRegulation(1)
        f.rtia.enableTimeConstrained()
    for f in (a, b):
        f.until(lambda: bool(f.amb.named("timeRegulationEnabled")) and bool(f.amb.named("timeConstrainedEnabled")))
    assert a.amb.named("timeRegulationEnabled")[0] == (0,) and a.rtia.queryLookahead() == 1
    obj = a.rtia.registerObjectInstance(vehicle)
    b.until(lambda: bool(b.amb.named("discoverObjectInstance")))
    for step in range(1, 21):
        handle = a.rtia.updateAttributeValues(obj, {position: step.to_bytes(4, "big")}, b"", step)
        assert isinstance(handle, rti1516e.MessageRetractionHandle) and handle.isValid()
        for f in (a, b):
            f.rtia.timeAdvanceRequest(step)
        for f in (a, b):
            f.until(lambda: (step,) in f.amb.named("timeAdvanceGrant"))
        reflected = b.amb.named("reflectAttributeValues")
        assert len(reflected) == step, "every update before its grant"
        assert reflected[-1][5] == step and type(reflected[-1][5]) is int and reflected[-1][6] == rti1516e.TIMESTAMP
        assert isinstance(reflected[-1][7], rti1516e.MessageRetractionHandle)
        assert reflected[-1][8]["hasProducingFederate"] and reflected[-1][8]["producingFederate"] == \
            a.rtia.getFederateHandle("a")
    assert a.rtia.queryLogicalTime() == 20 and type(a.rtia.queryLogicalTime()) is int
    assert a.rtia.queryGALT() == 21 and b.rtia.queryLITS() is not None


def test_a_1516e_federate_and_an_hla13_federate_share_a_federation(federates: Callable[[], Federate],
                                                                   rtig: Any) -> None:
    a = joined(federates, "new")
    old_amb = Recorder()
    old = rti.RTIAmbassador(rtig.address)
    old.joinFederationExecution("old", "Vehicles", old_amb)  # type: ignore[arg-type]
    try:
        vehicle = old.getObjectClassHandle("Vehicle")
        speed = old.getAttributeHandle("speed", vehicle)
        old.subscribeObjectClassAttributes(vehicle, [speed])
        cls = a.rtia.getObjectClassHandle("Vehicle")
        attribute = a.rtia.getAttributeHandle(cls, "speed")
        a.rtia.publishObjectClassAttributes(cls, [attribute])
        reserve(a, "shared")
        obj = a.rtia.registerObjectInstance(cls, "shared")
        a.rtia.updateAttributeValues(obj, {attribute: b"fast"}, b"1516e")
        deadline = time.monotonic() + 10
        while not old_amb.named("reflectAttributeValues") and time.monotonic() < deadline:
            old.tick(0.02, 0.1)
        values = old_amb.named("reflectAttributeValues")[0][1]
        assert list(values.values()) == [b"fast"] and old_amb.named("discoverObjectInstance")[0][2] == "shared"
    finally:
        old.resignFederationExecution(rti.ResignAction.NoAction)


def test_synchronization_points_with_a_set_and_the_failure_reason(federates: Callable[[], Federate]) -> None:
    a, b = joined(federates, "a"), joined(federates, "b")
    b_handle = a.rtia.getFederateHandle("b")
    a.rtia.registerFederationSynchronizationPoint("ready", b"t", [b_handle])
    b.until(lambda: bool(b.amb.named("announceSynchronizationPoint")))
    assert b.amb.named("announceSynchronizationPoint")[0] == ("ready", b"t")
    b.rtia.synchronizationPointAchieved("ready")
    b.until(lambda: bool(b.amb.named("federationSynchronized")))
    assert b.amb.named("federationSynchronized") == [("ready", set())]
    a.until(lambda: bool(a.amb.named("synchronizationPointRegistrationSucceeded")))
    assert a.amb.named("synchronizationPointRegistrationSucceeded") == [("ready",)]
    assert not a.amb.named("announceSynchronizationPoint")
    a.rtia.registerFederationSynchronizationPoint("all", b"")
    a.rtia.registerFederationSynchronizationPoint("all", b"")
    a.until(lambda: bool(a.amb.named("synchronizationPointRegistrationFailed")))
    assert a.amb.named("synchronizationPointRegistrationFailed") == [("all", rti1516e.SYNCHRONIZATION_POINT_LABEL_NOT_UNIQUE)]


def test_negotiated_divestiture_asks_for_confirmation(federates: Callable[[], Federate]) -> None:
    a, b = joined(federates, "a"), joined(federates, "b")
    vehicle = a.rtia.getObjectClassHandle("Vehicle")
    speed = a.rtia.getAttributeHandle(vehicle, "speed")
    for f in (a, b):
        f.rtia.publishObjectClassAttributes(vehicle, [speed])
        f.rtia.subscribeObjectClassAttributes(vehicle, [speed])
    obj = a.rtia.registerObjectInstance(vehicle)
    b.until(lambda: bool(b.amb.named("discoverObjectInstance")))
    with pytest.raises(rti1516e.AttributeDivestitureWasNotRequested):
        a.rtia.confirmDivestiture(obj, [speed], b"")
    a.rtia.negotiatedAttributeOwnershipDivestiture(obj, [speed], b"take it")
    b.until(lambda: bool(b.amb.named("requestAttributeOwnershipAssumption")))
    assert b.amb.named("requestAttributeOwnershipAssumption")[0] == (obj, {speed}, b"take it")
    b.rtia.attributeOwnershipAcquisition(obj, [speed], b"")
    a.until(lambda: bool(a.amb.named("requestDivestitureConfirmation")))
    a.rtia.confirmDivestiture(obj, [speed], b"")
    b.until(lambda: bool(b.amb.named("attributeOwnershipAcquisitionNotification")))
    assert b.rtia.isAttributeOwnedByFederate(obj, speed) and not a.rtia.isAttributeOwnedByFederate(obj, speed)
    b.rtia.queryAttributeOwnership(obj, speed)
    b.until(lambda: bool(b.amb.named("informAttributeOwnership")))
    assert b.amb.named("informAttributeOwnership")[0] == (obj, speed, b.rtia.getFederateHandle("b"))


def test_what_is_not_served_yet_says_so(federates: Callable[[], Federate]) -> None:
    a = joined(federates, "a")
    with pytest.raises(rti1516e.RTIinternalError, match="hlacore does not serve"):
        a.rtia.synchronizationPointAchieved("x", False)


def test_an_update_rate_thins_receive_order_values_and_never_timestamped_ones(federates: Callable[[], Federate]) -> None:
    a, b = joined(federates, "a"), joined(federates, "b")
    vehicle = a.rtia.getObjectClassHandle("Vehicle")
    position, speed = (a.rtia.getAttributeHandle(vehicle, n) for n in ("position", "speed"))  # TimeStamp, Receive
    assert (a.rtia.getUpdateRateValue("HLAslow"), a.rtia.getUpdateRateValue("HLAfast")) == (2.0, 50.0)
    with pytest.raises(rti1516e.InvalidUpdateRateDesignator, match="HLAwarp"):
        b.rtia.subscribeObjectClassAttributes(vehicle, [speed], True, "HLAwarp")
    a.rtia.publishObjectClassAttributes(vehicle, [position, speed])
    b.rtia.subscribeObjectClassAttributes(vehicle, [position, speed], True, "HLAslow")
    obj = a.rtia.registerObjectInstance(vehicle)
    b.until(lambda: bool(b.amb.named("discoverObjectInstance")))
    assert b.rtia.getUpdateRateValueForAttribute(obj, speed) == 2.0
    assert a.rtia.getUpdateRateValueForAttribute(obj, speed) == 0.0  # a subscribes to nothing

    # 2 a second: of a burst, the first; half a second later, the next.
    started = time.monotonic()
    for i in range(20):
        a.rtia.updateAttributeValues(obj, {speed: b"%d" % i}, b"")
    time.sleep(0.6)
    a.rtia.updateAttributeValues(obj, {speed: b"last"}, b"")
    sending = time.monotonic() - started
    b.until(lambda: (b.amb.last("reflectAttributeValues") or ((),))[1:2] == ({speed: b"last"},))
    got = [args[1][speed] for args in b.amb.named("reflectAttributeValues")]
    assert got[0] == b"0" and got[-1] == b"last"
    assert len(got) <= 3 + int(2 * sending), got

    # Timestamped values all arrive, however fast they come.
    a.rtia.enableTimeRegulation(1.0)
    a.until(lambda: bool(a.amb.named("timeRegulationEnabled")))
    b.rtia.enableTimeConstrained()
    b.until(lambda: bool(b.amb.named("timeConstrainedEnabled")))
    for i in range(20):
        a.rtia.updateAttributeValues(obj, {position: b"%d" % i}, b"", 10.0 + i)
    a.rtia.timeAdvanceRequest(50.0)
    b.rtia.timeAdvanceRequest(40.0)
    b.until(lambda: bool(b.amb.named("timeAdvanceGrant")))
    timed = [args[1][position] for args in b.amb.named("reflectAttributeValues") if position in args[1]]
    assert timed == [b"%d" % i for i in range(20)]

    # A subscription through regions names its rate the same way.
    region = b.rtia.createRegion({b.rtia.getDimensionHandle("X")})
    b.rtia.commitRegionModifications({region})
    b.rtia.subscribeObjectClassAttributesWithRegions(vehicle, [({position}, {region})], True, "HLAfast")
    assert b.rtia.getUpdateRateValueForAttribute(obj, position) == 50.0


def test_encoded_handles_decode_to_equal_handles(federates: Callable[[], Federate]) -> None:
    a = joined(federates, "a")
    vehicle = a.rtia.getObjectClassHandle("Vehicle")
    assert a.rtia.decodeObjectClassHandle(vehicle.encode()) == vehicle
    with pytest.raises(rti1516e.CouldNotDecode):
        a.rtia.decodeObjectClassHandle(b"\x01")
    encoded = (3).to_bytes(4, "big") + (70).to_bytes(8, "big")  # federate 3's message 70
    retraction = a.rtia.decodeMessageRetractionHandle(encoded)
    assert bytes(retraction.encode()) == encoded and retraction.isValid()
    with pytest.raises(rti1516e.CouldNotDecode):
        a.rtia.decodeMessageRetractionHandle(encoded[:4])


def test_object_instance_names_are_reserved_before_registration(federates: Callable[[], Federate], rtig: Any) -> None:
    a, b = joined(federates, "a"), joined(federates, "b")
    vehicle = a.rtia.getObjectClassHandle("Vehicle")
    speed = a.rtia.getAttributeHandle(vehicle, "speed")
    for f in (a, b):
        f.rtia.publishObjectClassAttributes(vehicle, [speed])
    with pytest.raises(rti1516e.ObjectInstanceNameNotReserved):
        a.rtia.registerObjectInstance(vehicle, "one")
    with pytest.raises(rti1516e.IllegalName):
        a.rtia.reserveObjectInstanceName("HLAone")
    with pytest.raises(rti1516e.NameSetWasEmpty):
        a.rtia.reserveMultipleObjectInstanceName([])
    reserve(a, "one")
    b.rtia.reserveObjectInstanceName("one")
    b.until(lambda: bool(b.amb.named("objectInstanceNameReservationFailed")))
    assert b.amb.named("objectInstanceNameReservationFailed") == [("one",)]
    with pytest.raises(rti1516e.ObjectInstanceNameNotReserved):
        b.rtia.registerObjectInstance(vehicle, "one")
    assert a.rtia.getObjectInstanceName(a.rtia.registerObjectInstance(vehicle, "one")) == "one"
    with pytest.raises(rti1516e.ObjectInstanceNameNotReserved):  # used up by the registration
        a.rtia.releaseObjectInstanceName("one")

    a.rtia.reserveMultipleObjectInstanceName(["m1", "m2"])
    a.until(lambda: bool(a.amb.named("multipleObjectInstanceNameReservationSucceeded")))
    assert a.amb.named("multipleObjectInstanceNameReservationSucceeded") == [({"m1", "m2"},)]
    b.rtia.reserveMultipleObjectInstanceName(["m2", "m3"])  # all or none
    b.until(lambda: bool(b.amb.named("multipleObjectInstanceNameReservationFailed")))
    assert b.amb.named("multipleObjectInstanceNameReservationFailed") == [({"m2", "m3"},)]
    reserve(b, "m3")
    a.rtia.releaseMultipleObjectInstanceName(["m1"])
    a.rtia.getFederateHandle("a")  # a round trip on a's connection: the gateway has taken the release
    reserve(b, "m1")  # free again

    old = rti.RTIAmbassador(rtig.address)  # an HLA 1.3 federate cannot take a reserved name
    old.joinFederationExecution("old", "Vehicles", Recorder())  # type: ignore[arg-type]
    try:
        old.publishObjectClass(old.getObjectClassHandle("Vehicle"), [old.getAttributeHandle("speed", old.getObjectClassHandle("Vehicle"))])
        with pytest.raises(rti.ObjectAlreadyRegistered, match="reserved by federate"):
            old.registerObjectInstance(old.getObjectClassHandle("Vehicle"), "m2")
    finally:
        old.resignFederationExecution(rti.ResignAction.NoAction)
    b.rtia.resignFederationExecution(rti1516e.NO_ACTION)  # its reservations go with it
    reserve(a, "m3")


def test_a_1000_step_lockstep_of_a_1516e_and_an_hla13_federate(federates: Callable[[], Federate], rtig: Any) -> None:
    """Both regulating and constrained with lookahead 1, each updating its vehicle's position at t before
    asking for t: every grant, on both sides, comes after the other's update at its time."""
    steps = 1000
    new = joined(federates, "new")
    old_amb = Recorder()
    old = rti.RTIAmbassador(rtig.address)
    old.joinFederationExecution("old", "Vehicles", old_amb)  # type: ignore[arg-type]
    try:
        vehicle = new.rtia.getObjectClassHandle("Vehicle")
        position = new.rtia.getAttributeHandle(vehicle, "position")
        new.rtia.publishObjectClassAttributes(vehicle, [position])
        new.rtia.subscribeObjectClassAttributes(vehicle, [position])
        old_vehicle = old.getObjectClassHandle("Vehicle")
        old_position = old.getAttributeHandle("position", old_vehicle)
        old.publishObjectClass(old_vehicle, [old_position])
        old.subscribeObjectClassAttributes(old_vehicle, [old_position])
        old.enable_time_management(1.0)
        new.rtia.enableTimeRegulation(1.0)
        new.rtia.enableTimeConstrained()
        new.until(lambda: bool(new.amb.named("timeRegulationEnabled")) and bool(new.amb.named("timeConstrainedEnabled")))
        reserve(new, "new-vehicle")
        mine = new.rtia.registerObjectInstance(vehicle, "new-vehicle")
        theirs = old.registerObjectInstance(old_vehicle, "old-vehicle")
        start = new.rtia.queryLogicalTime()
        assert old.queryFederateTime() == start
        for step in range(1, steps + 1):
            t = start + step
            new.rtia.updateAttributeValues(mine, {position: b"new %d" % step}, b"", t)
            old.updateAttributeValues(theirs, {old_position: b"old %d" % step}, "", t)
            new.rtia.timeAdvanceRequest(t)
            old.timeAdvanceRequest(t)
            deadline = time.monotonic() + 30
            while not ((t,) in new.amb.named("timeAdvanceGrant") and old_amb.named("timeAdvanceGrant")[-1:] == [(t,)]):
                assert time.monotonic() < deadline, f"step {step} not granted"
                new.rtia.evokeMultipleCallbacks(0.0, 0.05)
                old.tick(0.0, 0.05)
    finally:
        old.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    for calls, peer in ((new.amb.calls, b"old"), (old_amb.calls, b"new")):
        last, grants = None, 0
        for name, args in calls:
            if name == "reflectAttributeValues" and len(args) > 5 and args[5] is not None:
                last = (bytes(next(iter(args[1].values()))), args[5])
            elif name == "timeAdvanceGrant" and args[0] > start:
                grants += 1
                assert last == (peer + b" %d" % (args[0] - start), args[0]), f"grant {args[0]} after {last}"
        assert grants == steps


def test_regions_over_the_modules_dimensions(federates: Callable[[], Federate]) -> None:
    """Ranges are half-open, [lower, upper); a dimension a region does not name spans its axis."""
    a, b = joined(federates, "a"), joined(federates, "b")
    x, y = a.rtia.getDimensionHandle("X"), a.rtia.getDimensionHandle("Y")
    assert (a.rtia.getDimensionName(x), a.rtia.getDimensionUpperBound(x), a.rtia.getDimensionUpperBound(y)) == ("X", 1000, 500)
    vehicle = a.rtia.getObjectClassHandle("Vehicle")
    position, speed = (a.rtia.getAttributeHandle(vehicle, n) for n in ("position", "speed"))
    command = a.rtia.getInteractionClassHandle("Command")
    verb = a.rtia.getParameterHandle(command, "verb")
    assert a.rtia.getAvailableDimensionsForClassAttribute(vehicle, position) == {x, y}
    assert a.rtia.getAvailableDimensionsForClassAttribute(vehicle, speed) == set()
    assert a.rtia.getAvailableDimensionsForInteractionClass(command) == {x, y}

    wanted = b.rtia.createRegion({x})
    assert b.rtia.getDimensionHandleSet(wanted) == {x} and b.rtia.getRangeBounds(wanted, x) == (0, 1000)
    b.rtia.setRangeBounds(wanted, x, (0, 100))
    b.rtia.commitRegionModifications({wanted})
    with pytest.raises(rti1516e.InvalidRangeBound):
        b.rtia.setRangeBounds(wanted, x, (10, 1001))
    with pytest.raises(rti1516e.RegionDoesNotContainSpecifiedDimension):
        b.rtia.getRangeBounds(wanted, y)
    with pytest.raises(rti1516e.RegionNotCreatedByThisFederate):
        a.rtia.getRangeBounds(wanted, x)
    b.rtia.subscribeObjectClassAttributesWithRegions(vehicle, [({position}, {wanted})])
    b.rtia.subscribeInteractionClassWithRegions(command, {wanted})
    barrier(b)  # the gateway has b's subscriptions before a's interactions (lost otherwise)

    a.rtia.publishObjectClassAttributes(vehicle, [position])
    a.rtia.publishInteractionClass(command)
    at = a.rtia.createRegion({x, y})
    a.rtia.setRangeBounds(at, x, (500, 600))
    a.rtia.commitRegionModifications([at])
    reserve(a, "v")
    v = a.rtia.registerObjectInstanceWithRegions(vehicle, [({position}, {at})], "v")
    a.rtia.updateAttributeValues(v, {position: b"far"}, b"")
    a.rtia.sendInteractionWithRegions(command, {verb: b"far"}, {at}, b"")
    a.rtia.setRangeBounds(at, x, (99, 100))  # [99, 100) meets [0, 100) at 99
    a.rtia.commitRegionModifications([at])
    a.rtia.updateAttributeValues(v, {position: b"near"}, b"")
    a.rtia.sendInteractionWithRegions(command, {verb: b"near"}, {at}, b"")
    a.rtia.setRangeBounds(at, x, (100, 200))  # [100, 200) does not
    a.rtia.commitRegionModifications([at])
    a.rtia.updateAttributeValues(v, {position: b"edge"}, b"")
    a.rtia.sendInteractionWithRegions(command, {verb: b"edge"}, {at}, b"")
    a.rtia.setRangeBounds(at, x, (0, 1))
    a.rtia.commitRegionModifications([at])
    a.rtia.updateAttributeValues(v, {position: b"back"}, b"")
    a.rtia.sendInteractionWithRegions(command, {verb: b"back"}, {at}, b"")
    a.rtia.sendInteractionWithRegions(command, {verb: b"two"}, {at, a.rtia.createRegion({y})}, b"")  # both overlap
    b.until(lambda: len(b.amb.named("reflectAttributeValues")) == 2 and len(b.amb.named("receiveInteraction")) == 3)
    assert [args[1][position] for args in b.amb.named("reflectAttributeValues")] == [b"near", b"back"]
    assert [args[1][verb] for args in b.amb.named("receiveInteraction")] == [b"near", b"back", b"two"]
    b.rtia.unsubscribeObjectClassAttributesWithRegions(vehicle, [({position}, {wanted})])
    b.rtia.unsubscribeInteractionClassWithRegions(command, {wanted})
    b.rtia.deleteRegion(wanted)
    with pytest.raises(rti1516e.RegionNotCreatedByThisFederate):
        b.rtia.deleteRegion(wanted)


def barrier(f: Federate) -> None:
    """A round trip: the gateway has handled everything f sent before."""
    with pytest.raises(rti1516e.FederationExecutionDoesNotExist):
        f.rtia.destroyFederationExecution("no-such")


def region_in(f: Federate, x: tuple[int, int]) -> Any:
    """A region of f's over X, its range [lower, upper) committed."""
    dimension = f.rtia.getDimensionHandle("X")
    region = f.rtia.createRegion({dimension})
    f.rtia.setRangeBounds(region, dimension, x)
    f.rtia.commitRegionModifications({region})
    return region


class SeveralRegions:
    """`a` publishes Vehicle.position and Command, and has regions r1 (X in [100, 200)) and r2 (X in
    [300, 400)); four federates subscribe to both through regions of theirs: `first` overlaps r1 only,
    `second` r2 only, `both` has one region overlapping r1, one overlapping r2 and one overlapping both,
    `neither` overlaps none."""

    RANGES = {"first": [(100, 110)], "second": [(350, 360)], "both": [(150, 160), (390, 400), (150, 350)],
              "neither": [(600, 700)]}

    def __init__(self, federates: Callable[[], Federate]) -> None:
        self.a = joined(federates, "a")
        r = self.a.rtia
        self.vehicle = r.getObjectClassHandle("Vehicle")
        self.position = r.getAttributeHandle(self.vehicle, "position")
        self.command = r.getInteractionClassHandle("Command")
        self.verb = r.getParameterHandle(self.command, "verb")
        r.publishObjectClassAttributes(self.vehicle, [self.position])
        r.publishInteractionClass(self.command)
        self.r1, self.r2 = region_in(self.a, (100, 200)), region_in(self.a, (300, 400))
        self.subscribers: dict[str, Federate] = {}
        for name, ranges in self.RANGES.items():
            s = joined(federates, name)
            regions = {region_in(s, x) for x in ranges}
            s.rtia.subscribeObjectClassAttributesWithRegions(self.vehicle, [({self.position}, regions)])
            s.rtia.subscribeInteractionClassWithRegions(self.command, regions)
            barrier(s)
            self.subscribers[name] = s
        self.marker = r.registerObjectInstance(self.vehicle)  # updated in the default region: reaches everyone
        self.rounds = 0

    @property
    def federates(self) -> list[Federate]:
        return [self.a, *self.subscribers.values()]

    def round(self) -> dict[str, list[bytes]]:
        """What each subscriber got since the last round, in order: the position values of the updates (the
        marker's aside) and the verbs of the interactions. `a` then updates the marker, and waits until it
        reached each subscriber: what `a` sent before cannot still be on its way."""
        self.rounds += 1
        mark = {self.position: b"marker %d" % self.rounds}

        def marked(s: Federate) -> bool:
            return (self.marker, mark) in [args[:2] for args in s.amb.named("reflectAttributeValues")]

        self.a.rtia.updateAttributeValues(self.marker, mark, b"")
        got = {}
        for name, s in self.subscribers.items():
            s.until(lambda: marked(s))
            got[name] = [args[1][self.verb] if callback == "receiveInteraction" else args[1][self.position]
                         for callback, args in s.amb.calls
                         if callback == "receiveInteraction"
                         or (callback == "reflectAttributeValues" and args[0] != self.marker)]
            s.amb.calls.clear()
        return got


def test_an_attribute_updated_in_two_regions_reaches_each_overlapping_subscriber_once(
        federates: Callable[[], Federate]) -> None:
    """An attribute associated with two regions is reflected by a subscriber whose regions overlap either,
    once however many overlap; unassociating one (attribute, region) pair keeps the other."""
    w = SeveralRegions(federates)
    a = w.a.rtia
    v = a.registerObjectInstanceWithRegions(w.vehicle, [({w.position}, {w.r1})])
    a.associateRegionsForUpdates(v, [({w.position}, {w.r2})])  # adds r2 to r1
    a.updateAttributeValues(v, {w.position: b"r1, r2"}, b"")
    assert w.round() == {"first": [b"r1, r2"], "second": [b"r1, r2"], "both": [b"r1, r2"], "neither": []}
    a.unassociateRegionsForUpdates(v, [({w.position}, {w.r1})])
    a.updateAttributeValues(v, {w.position: b"r2"}, b"")
    assert w.round() == {"first": [], "second": [b"r2"], "both": [b"r2"], "neither": []}
    with pytest.raises(rti1516e.RegionInUseForUpdateOrSubscription):
        a.deleteRegion(w.r2)
    a.unassociateRegionsForUpdates(v, [({w.position}, {w.r2})])  # no region left: the default region
    a.updateAttributeValues(v, {w.position: b"default"}, b"")
    assert w.round() == {name: [b"default"] for name in SeveralRegions.RANGES}

    v2 = a.registerObjectInstanceWithRegions(w.vehicle, [({w.position}, {w.r1, w.r2})])
    a.updateAttributeValues(v2, {w.position: b"registered in r1, r2"}, b"")
    assert w.round() == {"first": [b"registered in r1, r2"], "second": [b"registered in r1, r2"],
                         "both": [b"registered in r1, r2"], "neither": []}
    assert [args[2] for args in w.subscribers["neither"].amb.named("discoverObjectInstance")] == []


def test_an_interaction_sent_in_two_regions_reaches_each_overlapping_subscriber_once(
        federates: Callable[[], Federate]) -> None:
    """An interaction sent in two regions is received by a subscriber whose regions overlap either, once;
    sent in no region it is in the default region, which every region overlaps."""
    w = SeveralRegions(federates)
    a = w.a.rtia
    a.sendInteractionWithRegions(w.command, {w.verb: b"r1, r2"}, {w.r1, w.r2}, b"")
    a.sendInteractionWithRegions(w.command, {w.verb: b"r2"}, {w.r2}, b"")
    assert a.sendInteractionWithRegions(w.command, {w.verb: b"timed"}, [w.r1, w.r2], b"", 5.0).isValid()
    a.sendInteractionWithRegions(w.command, {w.verb: b"none"}, set(), b"")
    assert w.round() == {"first": [b"r1, r2", b"timed", b"none"], "second": [b"r1, r2", b"r2", b"timed", b"none"],
                         "both": [b"r1, r2", b"r2", b"timed", b"none"], "neither": [b"none"]}


def test_several_update_regions_are_saved_and_restored(tmp_path: Any) -> None:
    """A save keeps every region of an attribute: restored, the attribute is updated in both again (the
    client holds both in use). The save file is version 3; a version 2 file, read alike, still restores."""
    save_dir = tmp_path / "saves"
    with running_rtig(tmp_path, "--save-dir", str(save_dir)) as server:
        made: list[Federate] = []

        def federate() -> Federate:
            made.append(Federate(server.address))
            return made[-1]

        def both(label: str, request: str, begun: str, complete: str, done: str) -> None:
            getattr(w.a.rtia, request)(label)
            for f in w.federates:
                f.until(lambda: bool(f.amb.named(begun)))
                getattr(f.rtia, complete)()
            for f in w.federates:
                f.until(lambda: bool(f.amb.named(done)))
                f.amb.calls.clear()

        try:
            w = SeveralRegions(federate)
            a = w.a.rtia
            v = a.registerObjectInstanceWithRegions(w.vehicle, [({w.position}, {w.r1, w.r2})])
            both("several", "requestFederationSave", "initiateFederateSave", "federateSaveComplete", "federationSaved")
            a.unassociateRegionsForUpdates(v, [({w.position}, {w.r2})])
            a.updateAttributeValues(v, {w.position: b"r1"}, b"")
            assert w.round() == {"first": [b"r1"], "second": [], "both": [b"r1"], "neither": []}
            both("several", "requestFederationRestore", "initiateFederateRestore", "federateRestoreComplete",
                 "federationRestored")
            a.updateAttributeValues(v, {w.position: b"restored"}, b"")
            assert w.round() == {"first": [b"restored"], "second": [b"restored"], "both": [b"restored"], "neither": []}
            with pytest.raises(rti1516e.RegionInUseForUpdateOrSubscription):
                a.deleteRegion(w.r2)

            [saved] = save_dir.iterdir()
            data = saved.read_bytes()
            assert data[8:12] == struct.pack("<I", 4)
            # Version 2 and 3 files end before version 4's directed interaction declarations (here none: a count 0).
            assert data[-4:] == struct.pack("<I", 0)
            (save_dir / "Vehicles--v2.hlasave").write_bytes(data[:8] + struct.pack("<I", 2) + data[12:-4])
            a.unassociateRegionsForUpdates(v, [({w.position}, {w.r1})])
            both("v2", "requestFederationRestore", "initiateFederateRestore", "federateRestoreComplete",
                 "federationRestored")
            a.updateAttributeValues(v, {w.position: b"from version 2"}, b"")
            assert w.round() == {"first": [b"from version 2"], "second": [b"from version 2"],
                                 "both": [b"from version 2"], "neither": []}
        finally:
            for f in reversed(made):
                f.close()


def wait_for(done: Callable[[], bool], seconds: float = 10.0) -> None:
    deadline = time.monotonic() + seconds
    while not done():
        assert time.monotonic() < deadline, f"not done in {seconds} s"
        time.sleep(0.01)


def test_the_immediate_model_delivers_callbacks_on_its_own_thread(federates: Callable[[], Federate], rtig: Any) -> None:
    a = joined(federates, "a")
    amb = Recorder()
    b = rti1516e.RTIambassador()
    b.connect(amb, "HLA_IMMEDIATE", rtig.address)
    b.joinFederationExecution("b", "test", "Vehicles")
    try:
        command = a.rtia.getInteractionClassHandle("Command")
        verb = a.rtia.getParameterHandle(command, "verb")
        a.rtia.publishInteractionClass(command)
        b.subscribeInteractionClass(b.getInteractionClassHandle("Command"))
        a.rtia.getFederateHandle("b")  # a round trip: the gateway has b's subscription
        a.rtia.sendInteraction(command, {verb: b"first"}, b"")
        wait_for(lambda: len(amb.named("receiveInteraction")) == 1)  # nobody evokes
        assert b.evokeCallback(0.0) is False  # nothing left for the caller
        b.disableCallbacks()
        a.rtia.sendInteraction(command, {verb: b"held"}, b"")
        time.sleep(0.3)
        assert len(amb.named("receiveInteraction")) == 1
        b.enableCallbacks()
        wait_for(lambda: len(amb.named("receiveInteraction")) == 2)
        assert [args[1][verb] for args in amb.named("receiveInteraction")] == [b"first", b"held"]
    finally:
        b.resignFederationExecution(rti1516e.NO_ACTION)
        b.disconnect()


@pytest.mark.parametrize("model", ["HLA_EVOKED", "HLA_IMMEDIATE"])
def test_a_lost_connection_is_told_once_by_connection_lost(tmp_path: Any, model: str) -> None:
    server = RtigProcess(tmp_path)
    amb = Recorder()
    rtia = rti1516e.RTIambassador()
    rtia.connect(amb, model, server.address)
    rtia.createFederationExecution("Vehicles", VEHICLES)
    rtia.joinFederationExecution("a", "test", "Vehicles")
    server.proc.kill()
    server.stop()
    if model == "HLA_EVOKED":
        wait_for(lambda: rtia.evokeMultipleCallbacks(0.05, 0.1) is False and bool(amb.named("connectionLost")))
    else:
        wait_for(lambda: bool(amb.named("connectionLost")))
    assert len(amb.named("connectionLost")) == 1 and "lost" in amb.named("connectionLost")[0][0]
    with pytest.raises(rti1516e.NotConnected):
        rtia.evokeCallback(0.0)
    with pytest.raises(rti1516e.NotConnected):
        rtia.getObjectClassHandle("Vehicle")
    rtia.disconnect()


def test_the_save_and_restore_status_of_each_federate(federates: Callable[[], Federate]) -> None:
    a, b = joined(federates, "a"), joined(federates, "b")
    ha, hb = a.rtia.getFederateHandle("a"), a.rtia.getFederateHandle("b")

    def statuses(f: Federate, query: str) -> Any:
        getattr(f.rtia, "queryFederation%sStatus" % query)()
        callback = "federation%sStatusResponse" % query
        f.until(lambda: bool(f.amb.named(callback)))
        return dict((s[0], s[-1]) for s in f.amb.calls.pop()[1][0])

    assert statuses(a, "Save") == {ha: rti1516e.NO_SAVE_IN_PROGRESS, hb: rti1516e.NO_SAVE_IN_PROGRESS}
    a.rtia.requestFederationSave("s1")
    for f in (a, b):
        f.until(lambda: bool(f.amb.named("initiateFederateSave")))
    a.rtia.federateSaveBegun()
    assert statuses(a, "Save") == {ha: rti1516e.FEDERATE_SAVING, hb: rti1516e.FEDERATE_INSTRUCTED_TO_SAVE}
    a.rtia.federateSaveComplete()
    assert statuses(a, "Save") == {ha: rti1516e.FEDERATE_WAITING_FOR_FEDERATION_TO_SAVE,
                                   hb: rti1516e.FEDERATE_INSTRUCTED_TO_SAVE}
    b.rtia.federateSaveBegun()
    b.rtia.federateSaveComplete()
    for f in (a, b):
        f.until(lambda: bool(f.amb.named("federationSaved")))
    assert statuses(b, "Save") == {ha: rti1516e.NO_SAVE_IN_PROGRESS, hb: rti1516e.NO_SAVE_IN_PROGRESS}

    a.rtia.requestFederationRestore("s1")
    for f in (a, b):
        f.until(lambda: bool(f.amb.named("initiateFederateRestore")))
    a.rtia.federateRestoreComplete()
    restoring = statuses(a, "Restore")
    assert restoring == {ha: rti1516e.FEDERATE_WAITING_FOR_FEDERATION_TO_RESTORE, hb: rti1516e.FEDERATE_RESTORING}
    b.rtia.federateRestoreComplete()
    for f in (a, b):
        f.until(lambda: bool(f.amb.named("federationRestored")))
    assert statuses(a, "Restore") == {ha: rti1516e.NO_RESTORE_IN_PROGRESS, hb: rti1516e.NO_RESTORE_IN_PROGRESS}


def test_the_other_object_ownership_and_time_services(federates: Callable[[], Federate]) -> None:
    """The services no other test calls, each with its outcome."""
    a, b = joined(federates, "a"), joined(federates, "b")
    vehicle = a.rtia.getObjectClassHandle("Vehicle")
    speed, position = (a.rtia.getAttributeHandle(vehicle, n) for n in ("speed", "position"))
    command = a.rtia.getInteractionClassHandle("Command")
    for f in (a, b):
        f.rtia.publishObjectClassAttributes(vehicle, [speed, position])
        f.rtia.subscribeObjectClassAttributes(vehicle, [speed])
    obj = a.rtia.registerObjectInstance(vehicle)
    b.until(lambda: bool(b.amb.named("discoverObjectInstance")))
    # transportation and order: confirmed by callback, by name or constant
    a.rtia.requestAttributeTransportationTypeChange(obj, [speed], "BEST_EFFORT")
    a.rtia.publishInteractionClass(command)
    a.rtia.requestInteractionTransportationTypeChange(command, rti1516e.RELIABLE)
    a.until(lambda: bool(a.amb.named("confirmInteractionTransportationTypeChange")))
    assert a.amb.named("confirmAttributeTransportationTypeChange") == [(obj, {speed}, rti1516e.BEST_EFFORT)]
    assert a.amb.named("confirmInteractionTransportationTypeChange") == [(command, rti1516e.RELIABLE)]
    assert a.rtia.getTransportationName(rti1516e.BEST_EFFORT) == "HLAbestEffort"
    assert a.rtia.getTransportationType("HLAreliable") == rti1516e.RELIABLE
    assert (a.rtia.getOrderType("TimeStamp"), a.rtia.getOrderName(rti1516e.RECEIVE)) == (rti1516e.TIMESTAMP, "Receive")
    a.rtia.changeAttributeOrderType(obj, [speed], rti1516e.RECEIVE)
    a.rtia.changeInteractionOrderType(command, "RECEIVE")
    with pytest.raises(rti1516e.InvalidTransportationType):
        a.rtia.requestInteractionTransportationTypeChange(command, 7)
    # requestAttributeValueUpdate of an object and of a class: the owner is asked to provide
    b.rtia.requestAttributeValueUpdate(obj, [speed], b"")
    b.rtia.requestAttributeValueUpdate(vehicle, [speed], b"")
    a.until(lambda: len(a.amb.named("provideAttributeValueUpdate")) == 2)
    assert a.amb.named("provideAttributeValueUpdate")[0] == (obj, {speed}, b"")
    # ownership: b asks for speed, a gives what is wanted; then unconditionally position, b takes it
    b.rtia.attributeOwnershipAcquisition(obj, [speed], b"mine")
    a.until(lambda: bool(a.amb.named("requestAttributeOwnershipRelease")))
    assert a.rtia.attributeOwnershipDivestitureIfWanted(obj, [speed, position]) == {speed}
    b.until(lambda: bool(b.amb.named("attributeOwnershipAcquisitionNotification")))
    a.rtia.unconditionalAttributeOwnershipDivestiture(obj, [position])
    b.rtia.attributeOwnershipAcquisitionIfAvailable(obj, [position])
    b.until(lambda: len(b.amb.named("attributeOwnershipAcquisitionNotification")) == 2)
    assert b.rtia.isAttributeOwnedByFederate(obj, position) and b.rtia.isAttributeOwnedByFederate(obj, speed)
    c = joined(federates, "c")  # knows the object, owns none of it: may forget it here
    c.rtia.subscribeObjectClassAttributes(vehicle, [speed])
    c.until(lambda: bool(c.amb.named("discoverObjectInstance")))
    c.rtia.localDeleteObjectInstance(obj)
    with pytest.raises(rti1516e.ObjectInstanceNotKnown):
        c.rtia.getObjectInstanceName(obj)
    # time: each advance service granted, lookahead changed, asynchronous delivery switched
    a.rtia.enableTimeRegulation(2.0)
    a.until(lambda: bool(a.amb.named("timeRegulationEnabled")))
    a.rtia.modifyLookahead(0.5)
    assert a.rtia.queryLookahead() == 0.5
    a.rtia.enableTimeConstrained()
    a.until(lambda: bool(a.amb.named("timeConstrainedEnabled")))
    a.rtia.enableAsynchronousDelivery()
    a.rtia.disableAsynchronousDelivery()
    for advance, t in (("timeAdvanceRequestAvailable", 1.0), ("nextMessageRequest", 2.0),
                       ("nextMessageRequestAvailable", 3.0), ("flushQueueRequest", 4.0)):
        getattr(a.rtia, advance)(t)
        a.until(lambda: (t,) in a.amb.named("timeAdvanceGrant"))
    handle = a.rtia.sendInteraction(command, {}, b"", 10.0)
    a.rtia.retract(handle)  # the first time: retracted
    with pytest.raises(rti1516e.InvalidMessageRetractionHandle):
        a.rtia.retract(handle)
    a.rtia.disableTimeRegulation()
    a.rtia.disableTimeConstrained()
