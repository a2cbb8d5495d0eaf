"""FOM modules in OMT XML (docs/fom-modules.md): read into the same FOM as a .fed file, merged when there are
several, errors at FILE:LINE:COL; a federation created from one serves hlacore's federates and CERTI's. The
real modules are the SISO Space Reference FOM's and TrickHLA's, from ../shared/foms/."""

from __future__ import annotations

import pathlib
from typing import Any, Optional

import pytest

import hlacore.rti as rti
from hlacore import _core
from hlacore.processes import tick_until
from support import ROOT, rtia_executable
from support.certi import CertiFederate

FOMS = ROOT.parent / "shared" / "foms"
SPACE_FOM = ["datatypes", "switches", "environment", "management", "management2", "entity"]

MODULE_2010 = """<?xml version="1.0" encoding="UTF-8"?>
<objectModel xmlns="http://standards.ieee.org/IEEE1516-2010">
  <modelIdentification><name>Vehicles</name></modelIdentification>
  <objects>
    <objectClass>
      <name>HLAobjectRoot</name>
      <objectClass>
        <name>Vehicle</name>
        <attribute><name>position</name><transportation>HLAreliable</transportation><order>TimeStamp</order></attribute>
        <attribute><name>speed</name><transportation>HLAbestEffort</transportation><order>Receive</order></attribute>
      </objectClass>
    </objectClass>
  </objects>
  <interactions>
    <interactionClass>
      <name>HLAinteractionRoot</name>
      <interactionClass>
        <name>Command</name><transportation>HLAreliable</transportation><order>TimeStamp</order>
        <parameter><name>verb</name></parameter>
      </interactionClass>
    </interactionClass>
  </interactions>
</objectModel>
"""
MODULE_2000 = """<?xml version="1.0"?>
<objectModel DTDversion="1516.2" name="Vehicles">
  <objects>
    <objectClass name="HLAobjectRoot">
      <objectClass name="Vehicle">
        <attribute name="position" transportation="HLAreliable" order="TimeStamp"/>
        <attribute name="speed" transportation="HLAbestEffort" order="Receive"/>
      </objectClass>
    </objectClass>
  </objects>
  <interactions>
    <interactionClass name="HLAinteractionRoot">
      <interactionClass name="Command" transportation="HLAreliable" order="TimeStamp"><parameter name="verb"/></interactionClass>
    </interactionClass>
  </interactions>
</objectModel>
"""
# A second module that adds a subclass under Vehicle, which it declares again (as scaffolding).
CARS = """<objectModel><objects><objectClass><name>HLAobjectRoot</name><objectClass><name>Vehicle</name>
<objectClass><name>Car</name><attribute><name>doors</name><transportation>HLAreliable</transportation>
<order>Receive</order></attribute></objectClass></objectClass></objectClass></objects></objectModel>"""


def shared_modules(*names: str) -> list[tuple[str, str]]:
    paths = [FOMS / name for name in names]
    missing = [str(p) for p in paths if not p.is_file()]
    assert not missing, f"the FOM modules of ../shared/foms are missing: {missing}"
    return [(p.read_text(encoding="utf-8"), p.name) for p in paths]


def classes(fom: dict[str, Any]) -> dict[str, list[tuple[str, str, str]]]:
    """Each object class's qualified name -> its attributes (name, transport, order), inherited ones first."""
    return {c[2]: [(a[1], a[2], a[3]) for a in c[5]] for c in fom["object_classes"]}


def test_the_space_reference_fom_merges_from_its_six_modules() -> None:
    fom = _core.parse_fom_modules(shared_modules(*(f"space-fom/SISO_SpaceFOM_{m}.xml" for m in SPACE_FOM)))
    found = classes(fom)
    assert list(found)[0] == "HLAobjectRoot"
    assert found["HLAobjectRoot"] == [("HLAprivilegeToDeleteObject", "reliable", "timestamp")]  # the MIM's
    # management's class, and the subclass management2 adds to it from the other module
    assert ("hla_base_time_multiplier", "reliable", "receive") in found[
        "ExecutionConfiguration.ExecutionConfiguration2"]
    dynamical = [name for name, _t, _o in found["PhysicalEntity.DynamicalEntity"]]
    assert dynamical[:3] == ["HLAprivilegeToDeleteObject", "name", "type"] and "inertia_rate" in dynamical
    assert {c[2] for c in fom["interaction_classes"]} >= {"HLAinteractionRoot", "ModeTransitionRequest"}


def test_trickhlas_test_foms_load() -> None:
    assert "STCTest" in classes(_core.parse_fom_modules(shared_modules("trickhla/Encoders_Test_FOM.xml")))
    for name in ("trickhla/FixedRecordTest.xml", "trickhla/Sine_FOM.xml"):
        fom = _core.parse_fom_modules(shared_modules(name))
        assert len(fom["object_classes"]) > 1, name  # a class of its own beside the root


def test_the_2000_and_2010_forms_read_the_same() -> None:
    a, b = _core.parse_fed(MODULE_2010, "v2010.xml"), _core.parse_fed(MODULE_2000, "v2000.xml")
    assert a["object_classes"] == b["object_classes"] and a["interaction_classes"] == b["interaction_classes"]
    assert classes(a)["Vehicle"] == [("HLAprivilegeToDeleteObject", "reliable", "timestamp"),
                                     ("position", "reliable", "timestamp"), ("speed", "best_effort", "receive")]
    command = next(c for c in a["interaction_classes"] if c[1] == "Command")
    assert command[5:7] == ("reliable", "timestamp") and [p[1] for p in command[8]] == ["verb"]


def test_modules_merge_and_conflicts_name_both_places() -> None:
    merged = classes(_core.parse_fom_modules([(MODULE_2010, "vehicles.xml"), (CARS, "cars.xml")]))
    assert merged["Vehicle.Car"][-1] == ("doors", "reliable", "receive")
    assert _core.parse_fom_modules([(MODULE_2010, "a.xml"), (MODULE_2010, "again.xml")]) is not None  # the same twice
    other = MODULE_2000.replace('name="speed" transportation="HLAbestEffort"', 'name="speed" transportation="HLAreliable"')
    with pytest.raises(rti.ErrorReadingFED, match=r"^other\.xml:7:9: attribute 'speed' of object class 'Vehicle' "
                                                  r"is declared otherwise at vehicles\.xml:10:9$") as contradiction:
        _core.parse_fom_modules([(MODULE_2010, "vehicles.xml"), (other, "other.xml")])
    assert contradiction.value.inconsistent is True  # read, but contradicting: IEEE 1516-2010's InconsistentFDD
    with pytest.raises(rti.ErrorReadingFED) as unreadable:
        _core.parse_fom_modules([(MODULE_2010, "vehicles.xml"), ("<objectModel>", "cut.xml")])
    assert unreadable.value.inconsistent is False


@pytest.mark.parametrize("text, error", [
    (MODULE_2010[:300], r"^bad\.xml:\d+:\d+: not well-formed XML: "),
    ("<federation/>", r"^bad\.xml:1:1: not an OMT FOM module: the document element is 'federation'"),
    (MODULE_2000.replace('order="TimeStamp"/>', 'order="Sometimes"/>'), r"^bad\.xml:6:9: unknown order 'Sometimes'"),
    (MODULE_2000.replace('<objectClass name="Vehicle">', "<objectClass>"), r"^bad\.xml:5:7: a subclass of object class "
                                                                           r"'HLAobjectRoot' without a name"),
    ("<objectModel>" + "<objects>" * 300, r"^bad\.xml:1:\d+: elements nested more than"),
    (MODULE_2000.replace('<objectClass name="Vehicle">', '<objectClass name="HLAobjectRoot">'),
     r"^bad\.xml:5:7: a second class named 'HLAobjectRoot' \(the first at bad\.xml:4:5\)"),
    (MODULE_2000.replace('<attribute name="position"', '<attribute name="HLAprivilegeToDeleteObject"/><attribute name="x"')
     .replace('<objectClass name="Vehicle">', '<objectClass name="Vehicle"><attribute name="HLAprivilegeToDeleteObject"/>'), None),
], ids=["truncated", "not a FOM", "order", "nameless", "deep", "twice", "MIM again"])
def test_a_bad_module_is_refused_at_its_place(text: str, error: Optional[str]) -> None:
    if error is None:  # the MIM's attribute declared again is no error
        assert _core.parse_fed(text, "bad.xml")["object_classes"][1][5][0][1] == "HLAprivilegeToDeleteObject"
        return
    with pytest.raises(rti.ErrorReadingFED, match=error):
        _core.parse_fed(text, "bad.xml")


def test_a_federation_from_an_xml_module_serves_python_and_certi_federates(rtig: Any, tmp_path: pathlib.Path) -> None:
    fom = tmp_path / "vehicles.xml"
    fom.write_text(MODULE_2010)
    creator = rti.RTIAmbassador(rtig.address)
    creator.createFederationExecution("Roads", str(fom))

    class Seen(rti.FederateAmbassador):
        def __init__(self) -> None:
            self.values: list[bytes] = []

        def reflectAttributeValues(self, obj, attributes, *rest):  # type: ignore[no-untyped-def]
            self.values += attributes.values()

    seen = Seen()
    watcher = rti.RTIAmbassador(rtig.address)
    watcher.joinFederationExecution("watcher", "Roads", seen)
    vehicle = watcher.getObjectClassHandle("HLAobjectRoot.Vehicle")
    assert watcher.getObjectClassHandle("Vehicle") == vehicle
    position = watcher.getAttributeHandle("position", vehicle)
    watcher.subscribeObjectClassAttributes(vehicle, [position])

    host, port = rtig.address.rsplit(":", 1)
    env = {"CERTI_HOST": host, "CERTI_TCP_PORT": port, "HLACORE_RTIG": ""}
    with CertiFederate(rtia_executable(), True, env, stderr=tmp_path / "rtia.log") as certi:
        certi.open()
        certi.call("JOIN_FEDERATION_EXECUTION", federation="Roads", federate_name="certi")
        cls = certi.call("GET_OBJECT_CLASS_HANDLE", name="Vehicle").object_class
        attribute = certi.call("GET_ATTRIBUTE_HANDLE", object_class=cls, name="position").attribute
        assert (cls, attribute) == (int(vehicle), int(position))
        certi.call("PUBLISH_OBJECT_CLASS", object_class=cls, handles=[attribute])
        obj = certi.call("REGISTER_OBJECT_INSTANCE", object_class=cls, name="bus").object
        certi.call("UPDATE_ATTRIBUTE_VALUES", object=obj, handles=[attribute], values=[b"km 12"], tag="")
        tick_until(watcher, lambda: b"km 12" in seen.values, 10.0)
        certi.call("RESIGN_FEDERATION_EXECUTION", resign_action=3)
        assert certi.close() == 0
    watcher.resignFederationExecution(rti.ResignAction.NoAction)
    creator.destroyFederationExecution("Roads")


DIMENSIONS = """<objectModel><objects><objectClass><name>HLAobjectRoot</name><objectClass><name>Car</name>
<attribute><name>at</name><dimensions><dimension>X</dimension></dimensions></attribute><attribute><name>colour</name>
</attribute></objectClass></objectClass></objects><interactions><interactionClass><name>HLAinteractionRoot</name>
<interactionClass><name>Honk</name><dimensions><dimension>X</dimension></dimensions><interactionClass><name>Loud</name>
</interactionClass></interactionClass></interactionClass></interactions>
<dimensions><dimension><name>X</name><upperBound>100</upperBound></dimension></dimensions></objectModel>"""


def test_dimensions_are_one_routing_space_of_the_attributes_and_classes_that_name_them() -> None:
    more = "<objectModel><dimensions><dimension name='Y' upperBound='7'/></dimensions></objectModel>"  # 2000's form
    fom = _core.parse_fom_modules([(DIMENSIONS, "cars.xml"), (more, "y.xml")])
    assert fom["spaces"] == [(1, "HLAdimensions", [(1, "X"), (2, "Y")])]
    car = next(c for c in fom["object_classes"] if c[1] == "Car")
    assert [(a[1], a[4]) for a in car[5]] == [("HLAprivilegeToDeleteObject", None), ("at", "HLAdimensions"),
                                              ("colour", None)]
    spaces = {c[1]: c[7] for c in fom["interaction_classes"]}
    assert spaces["Honk"] == spaces["Loud"] == "HLAdimensions" and spaces["HLAinteractionRoot"] is None
    assert _core.parse_fom_modules([(DIMENSIONS, "a.xml"), (DIMENSIONS, "b.xml")])["spaces"][0][2] == [(1, "X")]
    other = DIMENSIONS.replace("<upperBound>100<", "<upperBound>5<")
    with pytest.raises(_core.ErrorReadingFED, match=r"b\.xml:\d+:\d+: dimension 'X' has another upper bound at a\.xml:"):
        _core.parse_fom_modules([(DIMENSIONS, "a.xml"), (other, "b.xml")])
    with pytest.raises(_core.ErrorReadingFED, match=r"c\.xml:\d+:\d+: dimension 'X' has no upper bound"):
        _core.parse_fom_modules([(DIMENSIONS.replace("<upperBound>100</upperBound>", ""), "c.xml")])


RATES = "<objectModel><updateRates><updateRate><name>HLAslow</name><rate>2.5</rate></updateRate></updateRates></objectModel>"


def test_update_rates_merge_by_name_and_conflicts_name_both_places() -> None:
    more = "<objectModel><updateRates><updateRate name='HLAfast' rate='60'/></updateRates></objectModel>"  # 2000's form
    fom = _core.parse_fom_modules([(RATES, "a.xml"), (more, "b.xml"), (RATES, "c.xml")])
    assert fom["update_rates"] == [("HLAslow", 2.5), ("HLAfast", 60.0)]
    with pytest.raises(_core.ErrorReadingFED, match=r"b\.xml:1:\d+: update rate 'HLAslow' has another rate at a\.xml:1:"):
        _core.parse_fom_modules([(RATES, "a.xml"), (RATES.replace("2.5", "3"), "b.xml")])
    for bad in ("0", "-1", "fast", "", "inf"):
        with pytest.raises(_core.ErrorReadingFED, match=r"d\.xml:1:\d+: update rate 'HLAslow' has no positive rate"):
            _core.parse_fom_modules([(RATES.replace("2.5", bad), "d.xml")])
