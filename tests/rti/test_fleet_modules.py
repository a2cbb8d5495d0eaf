"""A FOM of our own in three modules (tests/data/rti1516e/fleet): the data types in one, vessels and orders in
the second, subclasses of both in the third, which declares its parents again and a type of its own. They
parse and merge (the subclasses inherit), every declared data type packs to the bytes written out below by
hand from IEEE 1516.2's encoding rules and unpacks back, a module that contradicts another is refused at its
FILE:LINE:COL naming the other's, and a federation created from the three serves 1516-2010 federates that know
the classes at different depths."""

from __future__ import annotations

import time
from typing import Any

import pytest

import hlacore.omt as omt
import hlacore.rti as rti
import hlacore.rti1516e as rti1516e
from hlacore import _core
from support import ROOT, RtigProcess
from support.rti1516e import Recorder

FLEET = ROOT / "tests" / "data" / "rti1516e" / "fleet"
MODULES = ["fleet-types.xml", "fleet-vessels.xml", "fleet-boats.xml"]


def texts() -> list[tuple[str, str]]:
    return [((FLEET / name).read_text(), name) for name in MODULES]


def test_the_three_modules_merge_and_the_subclasses_inherit() -> None:
    fom = _core.parse_fom_modules(texts())
    objects = {c[1]: [a[1] for a in c[5]] for c in fom["object_classes"]}
    interactions = {c[1]: [p[1] for p in c[8]] for c in fom["interaction_classes"]}
    assert objects["Vessel"] == ["HLAprivilegeToDeleteObject", "pose", "route"]
    assert objects["Boat"] == ["HLAprivilegeToDeleteObject", "pose", "route", "propulsion", "speed"]
    assert interactions["Tow"] == ["waypoints", "line"]


def test_a_module_that_contradicts_another_is_refused_where_it_does() -> None:
    types, vessels, boats = texts()
    again = vessels[0].replace("<order>Receive</order></attribute>", "<order>TimeStamp</order></attribute>", 1)
    with pytest.raises(rti.ErrorReadingFED, match=r"^again\.xml:\d+:\d+: attribute 'route' of object class 'Vessel' "
                                                  r"is declared otherwise at fleet-vessels\.xml:\d+:\d+$"):
        _core.parse_fom_modules([types, vessels, boats, (again, "again.xml")])


# Each declared data type: values, and their bytes written out by hand (big-endian unless the type says LE;
# each field, element and alternative padded to its own octet boundary from the composite's start).
ONE, TWO, THREE = "3ff0000000000000", "4000000000000000", "4008000000000000"  # 1.0, 2.0, 3.0 as HLAfloat64BE
BYTES: list[tuple[str, Any, str]] = [
    ("Millimeters32BE", 1200, "000004b0"),
    ("Meters", 2.0, TWO),
    ("Knots", 1.5, "0000c03f"),                                   # HLAfloat32LE
    ("HullKind", "Trimaran", "03"),
    ("Vector3", [1.0, 2.0, 3.0], ONE + TWO + THREE),
    ("Waypoints", [[1.0, 2.0, 3.0]], "00000001" + "00000000" + ONE + TWO + THREE),  # count, padded to 8
    ("Waypoints", [], "00000000"),
    ("Pose", {"hull": "Catamaran", "position": [1.0, 2.0, 3.0], "heading": 0.5, "depth": 1200},
     "02" + "00" * 7 + ONE + TWO + THREE + "3f000000" + "000004b0"),
    ("Propulsion", {"hull": "Catamaran", "engines": 2}, "02" + "00" + "0002"),     # discriminant, pad to 2, value
    ("Propulsion", {"hull": "Monohull", "sail": 1.5}, "01" + "000000" + "0000c03f"),
    ("Propulsion", {"hull": "Trimaran"}, "03"),
    ("TowLine", {"length": 30.0, "name": "ab"}, "403e000000000000" + "00000002" + "0061" + "0062"),
]


@pytest.fixture
def fleet_types() -> dict[str, Any]:
    """The modules' types, loaded last module first (a type may be used before its module is loaded)."""
    declared: dict[str, Any] = {}
    for name in reversed(MODULES):
        declared.update(omt.HLAuse(FLEET / name))
    return declared


def test_every_declared_data_type_packs_to_its_bytes_and_back(fleet_types: dict[str, Any]) -> None:
    assert set(fleet_types) == {name for name, _, _ in BYTES}
    for name, value, hexbytes in BYTES:
        data = fleet_types[name].pack(value)
        assert data.hex() == hexbytes, name
        decoded, used = fleet_types[name].unpack(data)
        assert used == len(data)
        assert fleet_types[name].pack(decoded) == data, name


def test_a_federation_of_the_three_modules_serves_each_class_at_its_depth(rtig: RtigProcess,
                                                                          fleet_types: dict[str, Any]) -> None:
    """A Boat registered by one federate is a Vessel to a federate subscribed to Vessel, with the pose it was
    sent; a Tow is an Order to a federate subscribed to Order, with the waypoints."""
    ambs = [Recorder(), Recorder()]
    owner, watcher = rti1516e.RTIambassador(), rti1516e.RTIambassador()
    for amb, rtia in zip(ambs, (owner, watcher)):
        rtia.connect(amb, "HLA_EVOKED", rtig.address)
    owner.createFederationExecution("Fleet", [str(FLEET / name) for name in MODULES])
    try:
        owner.joinFederationExecution("owner", "test", "Fleet")
        watcher.joinFederationExecution("watcher", "test", "Fleet")
        boat, vessel = owner.getObjectClassHandle("Vessel.Boat"), watcher.getObjectClassHandle("Vessel")
        pose = owner.getAttributeHandle(boat, "pose")
        owner.publishObjectClassAttributes(boat, [pose])
        watcher.subscribeObjectClassAttributes(vessel, [watcher.getAttributeHandle(vessel, "pose")])
        tow, order = owner.getInteractionClassHandle("Order.Tow"), watcher.getInteractionClassHandle("Order")
        owner.publishInteractionClass(tow)
        watcher.subscribeInteractionClass(order)
        obj = owner.registerObjectInstance(boat)
        sent_pose = fleet_types["Pose"].pack({"hull": "Monohull", "position": [1.0, 2.0, 3.0], "heading": 0.25,
                                              "depth": 7})
        route = fleet_types["Waypoints"].pack([[4.0, 5.0, 6.0]])
        owner.updateAttributeValues(obj, {pose: sent_pose}, b"")
        owner.sendInteraction(tow, {owner.getParameterHandle(tow, "waypoints"): route,
                                    owner.getParameterHandle(tow, "line"): fleet_types["TowLine"].pack(
                                        {"length": 5.0, "name": "rope"})}, b"")
        deadline = time.monotonic() + 10
        while not (ambs[1].named("reflectAttributeValues") and ambs[1].named("receiveInteraction")):
            assert time.monotonic() < deadline, ambs[1].calls
            owner.evokeMultipleCallbacks(0.0, 0.01)
            watcher.evokeMultipleCallbacks(0.01, 0.05)
        [discovered] = ambs[1].named("discoverObjectInstance")
        assert discovered[1] == vessel
        [reflected] = ambs[1].named("reflectAttributeValues")
        assert list(reflected[1].values()) == [sent_pose]
        assert fleet_types["Pose"].unpack(sent_pose)[0]["heading"] == 0.25
        [received] = ambs[1].named("receiveInteraction")
        assert received[0] == order and list(received[1].values()) == [route]  # the Order's parameter only
    finally:
        for rtia in (owner, watcher):
            try:
                rtia.resignFederationExecution(rti1516e.CANCEL_THEN_DELETE_THEN_DIVEST)
            except rti1516e.FederateNotExecutionMember:
                pass
        owner.destroyFederationExecution("Fleet")
        for rtia in (owner, watcher):
            rtia.disconnect()
