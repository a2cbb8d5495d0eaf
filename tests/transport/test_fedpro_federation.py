"""Federates of the HLA 4 Federate Protocol (hlacore.fedpro, our own client) in one federation with hlacore's own
1516-2010 and HLA 1.3 federates, through the sanitized rtig's door (rtig --fedpro): the federation created with
FOM modules sent by content, updates and interactions both ways, a 1 000-step timestamped lockstep."""

from __future__ import annotations

import io
import pathlib
import time
import zipfile
from typing import Any, Iterator

import pytest

import hlacore.rti as rti13
from hlacore import fedpro
from hlacore.fedpro._proto import datatypes_pb2

from support.fedpro import Calls, Pair, until
from support.fedpro import door as fedpro_door
from support.rti1516e import VEHICLES, Federate


@pytest.fixture
def door(tmp_path: pathlib.Path) -> Iterator[Any]:
    with fedpro_door(tmp_path) as server:
        yield server


def fedpro_federate(address: str, name: str, create: bool = False) -> tuple[fedpro.RTIambassador, Calls]:
    amb = Calls()
    rtia = fedpro.RTIambassador(address)
    rtia.connect(amb)
    if create:
        rtia.createFederationExecutionWithModules(federationName="Road", fomModules=[VEHICLES])
    joined = rtia.joinFederationExecution(federateName=name, federateType="fedpro", federationName="Road")
    assert joined.logicalTimeImplementationName == "HLAfloat64Time" and joined.federateHandle.data
    return rtia, amb


def leave(rtia: fedpro.RTIambassador) -> None:
    """Resign (deleting what it may), destroy the federation "Road" and close the session."""
    rtia.resignFederationExecution(resignAction="CANCEL_THEN_DELETE_THEN_DIVEST")
    rtia.destroyFederationExecution(federationName="Road")
    rtia.close()


def test_a_fedpro_federate_creates_joins_and_exchanges_with_hlacore_federates(door: Any) -> None:
    rtia, amb = fedpro_federate(door.fedpro_address, "car", create=True)
    other = Federate(door.address)
    other.rtia.joinFederationExecution("truck", "1516e", "Road")
    hla13 = rti13.RTIAmbassador(door.address)
    hla13_amb = _Hla13Recorder()
    hla13.joinFederationExecution("bus", "Road", hla13_amb)
    try:
        vehicle = rtia.getObjectClassHandle(objectClassName="Vehicle")
        speed = rtia.getAttributeHandle(objectClass=vehicle, attributeName="speed")
        command = rtia.getInteractionClassHandle(interactionClassName="Command")
        verb = rtia.getParameterHandle(interactionClass=command, parameterName="verb")
        # Handles are the 1516-2010 encodings: the same bytes the other federate's handles encode to.
        assert vehicle.data == other.rtia.getObjectClassHandle("Vehicle").encode()

        rtia.publishObjectClassAttributes(objectClass=vehicle, attributes=[speed])
        rtia.publishInteractionClass(interactionClass=command)
        rtia.subscribeInteractionClass(interactionClass=command)
        other_vehicle, other_command = other.rtia.getObjectClassHandle("Vehicle"), other.rtia.getInteractionClassHandle("Command")
        other.rtia.subscribeObjectClassAttributes(other_vehicle, [other.rtia.getAttributeHandle(other_vehicle, "speed")])
        other.rtia.publishInteractionClass(other_command)
        other.rtia.subscribeInteractionClass(other_command)
        hla13_vehicle = hla13.getObjectClassHandle("Vehicle")
        hla13.subscribeObjectClassAttributes(hla13_vehicle, [hla13.getAttributeHandle("speed", hla13_vehicle)])

        rtia.reserveObjectInstanceName(objectInstanceName="car-1")
        until(rtia, lambda: bool(amb.named("objectInstanceNameReservationSucceeded")))
        obj = rtia.registerObjectInstance(objectClass=vehicle, objectInstanceName="car-1")
        other.until(lambda: bool(other.amb.named("discoverObjectInstance")))
        assert other.amb.named("discoverObjectInstance")[0][2] == "car-1"
        rtia.updateAttributeValues(objectInstance=obj, attributeValues={speed.data: b"\x00\x2a"}, userSuppliedTag=b"go")
        other.until(lambda: bool(other.amb.named("reflectAttributeValues")))
        values = other.amb.named("reflectAttributeValues")[0][1]
        assert list(values.values()) == [b"\x00\x2a"]
        deadline = time.monotonic() + 10
        while not hla13_amb.reflected and time.monotonic() < deadline:
            hla13.tick(0.05, 0.1)
        assert list(hla13_amb.reflected[0].values()) == [b"\x00\x2a"], "the HLA 1.3 federate sees it too"

        # Interactions both ways.
        rtia.sendInteraction(interactionClass=command, parameterValues={verb.data: b"stop"}, userSuppliedTag=b"")
        other.until(lambda: bool(other.amb.named("receiveInteraction")))
        other.rtia.sendInteraction(other_command, {other.rtia.getParameterHandle(other_command, "verb"): b"turn"}, b"t")
        until(rtia, lambda: bool(amb.named("receiveInteraction")))
        received = amb.named("receiveInteraction")[0]
        assert fedpro.handle_values(received.parameterValues) == {verb.data: b"turn"} and received.userSuppliedTag == b"t"

        # The core's exceptions arrive under the standard's names.
        with pytest.raises(fedpro.rti_exception("NameNotFound")):
            rtia.getObjectClassHandle(objectClassName="Boat")
        with pytest.raises(fedpro.rti_exception("AttributeNotOwned")):
            rtia.updateAttributeValues(objectInstance=obj,
                                       attributeValues={rtia.getAttributeHandle(objectClass=vehicle, attributeName="position").data: b"x"},
                                       userSuppliedTag=b"")

        # HLA 4's switch getters answer what the federate set (the core's defaults first).
        assert rtia.getObjectClassRelevanceAdvisorySwitch() is True
        rtia.setObjectClassRelevanceAdvisorySwitch(value=False)
        assert rtia.getObjectClassRelevanceAdvisorySwitch() is False
        assert rtia.getAttributeScopeAdvisorySwitch() is False
        rtia.resignFederationExecution(resignAction="CANCEL_THEN_DELETE_THEN_DIVEST")  # a new join: the defaults again
        rtia.joinFederationExecution(federateName="car-again", federateType="fedpro", federationName="Road")
        assert rtia.getObjectClassRelevanceAdvisorySwitch() is True
    finally:
        hla13.resignFederationExecution(rti13.ResignAction.DeleteObjectsAndReleaseAttributes)
        other.close()
        rtia.resignFederationExecution(resignAction="CANCEL_THEN_DELETE_THEN_DIVEST")
        rtia.destroyFederationExecution(federationName="Road")
        rtia.disconnect()
        rtia.close()


class _Hla13Recorder(rti13.FederateAmbassador):
    def __init__(self) -> None:
        self.reflected: list[dict[int, bytes]] = []

    def discoverObjectInstance(self, *args: Any) -> None:
        pass

    def reflectAttributeValues(self, obj: int, attributes: dict[int, bytes], *args: Any) -> None:
        self.reflected.append(attributes)


STEPS = 1000


def test_a_thousand_step_timestamped_lockstep_with_a_1516e_federate(door: Any) -> None:
    rtia, amb = fedpro_federate(door.fedpro_address, "fedpro", create=True)
    pair = Pair(rtia, amb, door.address)
    other = pair.other
    try:
        pair.lockstep(rtia, amb, STEPS)
        assert fedpro.time_value(rtia.queryLogicalTime()) == STEPS
    finally:
        other.close()
        leave(rtia)


def test_list_federation_execution_members_names_each_federate_and_its_type(door: Any) -> None:
    """HLA 4's listFederationExecutionMembers: the members of a federation as they joined, through any API (a 1.3
    federate has no type), or that the federation does not exist; each a callback."""
    rtia, amb = fedpro_federate(door.fedpro_address, "car", create=True)
    other = Federate(door.address)
    other.rtia.joinFederationExecution("truck", "Lorry", "Road")
    hla13 = rti13.RTIAmbassador(door.address)
    hla13.joinFederationExecution("bus", "Road", _Hla13Recorder())
    try:
        rtia.listFederationExecutionMembers(federationName="Road")
        until(rtia, lambda: bool(amb.named("reportFederationExecutionMembers")))
        [report] = amb.named("reportFederationExecutionMembers")
        members = {(m.federateName, m.federateType) for m in report.report.federationExecutionMemberInformation}
        assert report.federationName == "Road"
        assert members == {("car", "fedpro"), ("truck", "Lorry"), ("bus", "")}
        rtia.listFederationExecutionMembers(federationName="Nowhere")
        until(rtia, lambda: bool(amb.named("reportFederationExecutionDoesNotExist")))
        assert [m.federationName for m in amb.named("reportFederationExecutionDoesNotExist")] == ["Nowhere"]
    finally:
        hla13.resignFederationExecution(rti13.ResignAction.NoAction)
        other.close()
        leave(rtia)


def test_an_object_class_has_the_dimensions_of_its_attributes(door: Any) -> None:
    """HLA 4's getAvailableDimensionsForObjectClass: the dimensions of any of the class's attributes (Vehicle's
    position has X and Y, its speed none); an undefined class is refused."""
    rtia, _ = fedpro_federate(door.fedpro_address, "car", create=True)
    try:
        vehicle = rtia.getObjectClassHandle(objectClassName="Vehicle")
        dimensions = rtia.getAvailableDimensionsForObjectClass(objectClass=vehicle).dimensionHandle
        assert sorted(rtia.getDimensionName(dimension=d) for d in dimensions) == ["X", "Y"]
        with pytest.raises(fedpro.rti_exception("ObjectClassNotDefined")):
            rtia.getAvailableDimensionsForObjectClass(objectClass=datatypes_pb2.ObjectClassHandle(data=b"\x00\x00\x03\xe7"))
    finally:
        leave(rtia)


def java_style_zip(name: str, content: bytes) -> bytes:
    """A zip archive of one deflated file written as Java's ZipOutputStream writes it, to a stream it cannot seek:
    the sizes and CRC after the data (a data descriptor) and in the central directory only."""

    class Unseekable(io.RawIOBase):
        def __init__(self) -> None:
            self.data = bytearray()

        def writable(self) -> bool:
            return True

        def write(self, b: Any) -> int:
            self.data += bytes(b)
            return len(b)

    out = Unseekable()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as archive:
        archive.writestr(name, content)
    return bytes(out.data)


def test_a_federation_from_a_compressed_fom_module(door: Any) -> None:
    """HLA 4's compressed FOM modules (Pitch's clients send every module over 1 KiB so): the archive's file is the
    module; an archive that does not read is ErrorReadingFOM (HLA 4's name), saying why."""
    rtia = fedpro.RTIambassador(door.fedpro_address)
    try:
        rtia.connect(Calls())
        packed = java_style_zip("vehicles.xml", pathlib.Path(VEHICLES).read_bytes())
        assert packed[6] & 0x08, "sizes after the data, as Java writes them"
        broken = packed[:40] + bytes(20) + packed[60:]
        with pytest.raises(fedpro.rti_exception("ErrorReadingFOM"), match="does not inflate|CRC"):
            rtia.createFederationExecutionWithModules(
                federationName="Road", fomModules=[datatypes_pb2.FomModule(compressedModule=broken)])
        rtia.createFederationExecutionWithModules(
            federationName="Road", fomModules=[datatypes_pb2.FomModule(compressedModule=packed)])
        rtia.joinFederationExecution(federateName="car", federateType="fedpro", federationName="Road")
        assert rtia.getObjectClassHandle(objectClassName="Vehicle").data
        rtia.resignFederationExecution(resignAction="NO_ACTION")
        rtia.destroyFederationExecution(federationName="Road")
    finally:
        rtia.close()


def test_exceptions_go_by_hla4_names_unless_the_client_declares_the_2010_api(door: Any, tmp_path: pathlib.Path) -> None:
    """HLA 4's names for what HLA 4 renamed (InconsistentFOM, CouldNotOpenFOM); a client that declares the
    1516-2010 API in its configuration (as Pitch's 1516-2010 adapter does, which maps back only the FOM-reading
    names) gets InconsistentFDD."""
    clash = tmp_path / "clash.xml"
    clash.write_text(pathlib.Path(VEHICLES).read_text().replace("<order>Receive</order>", "<order>TimeStamp</order>", 1))
    missing = datatypes_pb2.FomModule(url=str(tmp_path / "missing.xml"))
    for settings, inconsistent in (("", "InconsistentFOM"), ("API.version=IEEE 1516-2010", "InconsistentFDD")):
        rtia = fedpro.RTIambassador(door.fedpro_address)
        try:
            rtia.connect(Calls(), rtiConfiguration=datatypes_pb2.RtiConfiguration(additionalSettings=settings))
            with pytest.raises(fedpro.rti_exception(inconsistent), match="is declared otherwise at"):
                rtia.createFederationExecutionWithModules(federationName="Road", fomModules=[VEHICLES, str(clash)])
            with pytest.raises(fedpro.rti_exception("CouldNotOpenFOM"), match="missing.xml"):
                rtia.createFederationExecutionWithModules(federationName="Road", fomModules=[missing])
        finally:
            rtia.close()
