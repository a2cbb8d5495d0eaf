"""FOM modules added at join (IEEE 1516-2010 §4.5, docs/fom-modules.md): a federation created from one module
of tests/data/rti1516e/fleet grows as federates join with modules of their own. Every handle given out before
keeps its meaning (an attribute added to a class goes above every member of its subclasses); the federates
joined before learn the extended FOM as it arrives and discover, reflect and receive what it adds (1516-2010
and HLA 1.3 in Python here, the C++ API's in tests/cpp/rti1516e/services.cpp, JCERTI's in
test_certi_rtia.py); a module that contradicts the FOM is refused with InconsistentFDD at its FILE:LINE:COL
naming the other place, one that cannot be opened with CouldNotOpenFDD, one that does not read with
ErrorReadingFDD, and a save made after an extension restores, also once the FOM grew further."""

from __future__ import annotations

import pathlib
import re
import time
from typing import Any, Callable, Iterator

import pytest

import hlacore.rti as rti
import hlacore.rti1516e as rti1516e
from hlacore import _core
from support import ROBOT_FED, RtigProcess, Recorder as Recorder13, tick_until
from support.rti1516e import FLEET, Federate

VESSELS, BOATS, HARBOUR = (str(FLEET / f"fleet-{name}.xml") for name in ("vessels", "boats", "harbour"))
Numbered = dict[str, tuple[int, dict[str, int]]]


def module(path: str) -> tuple[str, str]:
    """(text, file name), as _core takes a module."""
    return pathlib.Path(path).read_text(), path


def numbered(fom: dict[str, Any]) -> tuple[Numbered, Numbered]:
    """The object and interaction classes by qualified name: (handle, {member name: handle})."""
    objects = {c[2]: (c[0], {a[1]: a[0] for a in c[5]}) for c in fom["object_classes"]}
    interactions = {c[2]: (c[0], {p[1]: p[0] for p in c[8]}) for c in fom["interaction_classes"]}
    return objects, interactions


def extended(created: list[str], *added: str) -> dict[str, Any]:
    """The FOM of a federation created from `created`, then extended by each of `added` at a join."""
    bundle = _core.fom_bundle([module(p) for p in created], [module(p) for p in added])
    return _core.parse_fed(bundle.decode("utf-8"), "the federation's FOM")


# ---- the numbering ----

def test_modules_added_at_join_keep_every_handle_and_number_what_they_add() -> None:
    """Vessels at creation, then Boats, then Harbour: Harbour's attribute of Vessel takes 6, above Boat's own
    propulsion (4) and speed (5), in Vessel and in every subclass; new classes follow the old ones."""
    before = numbered(_core.parse_fom_modules([module(VESSELS)]))
    after = numbered(extended([VESSELS], BOATS, HARBOUR))
    for old, new in zip(before, after):
        for name, (handle, members) in old.items():
            assert new[name][0] == handle and {m: h for m, h in new[name][1].items() if m in members} == members
    objects, interactions = after
    inherited = {"HLAprivilegeToDeleteObject": 1, "pose": 2, "route": 3}
    assert objects["Vessel"] == (2, {**inherited, "callsign": 6})
    assert objects["Vessel.Boat"] == (3, {**inherited, "propulsion": 4, "speed": 5, "callsign": 6})
    assert objects["Vessel.Barge"] == (4, {**inherited, "callsign": 6, "cargo": 7})
    assert objects["Harbour"] == (5, {"HLAprivilegeToDeleteObject": 1, "berths": 2})
    assert interactions["Order"] == (2, {"waypoints": 1, "berth": 3})
    assert interactions["Order.Tow"] == (3, {"waypoints": 1, "line": 2, "berth": 3})
    assert interactions["Moor"] == (4, {"harbour": 1})


def test_a_bundle_without_modules_added_at_join_reads_as_before() -> None:
    modules = [module(VESSELS), module(BOATS)]
    bundle = _core.fom_bundle(modules)
    assert bundle.startswith(b"hlacore FOM modules\n") and b" added\n" not in bundle
    assert _core.parse_fed(bundle.decode("utf-8"), "fom") == _core.parse_fom_modules(modules)


def test_a_creation_module_after_one_added_at_join_is_a_malformed_bundle() -> None:
    (vessels, name), (boats, boats_name) = module(VESSELS), module(BOATS)
    bundle = (f"hlacore FOM modules\n{len(boats_name)} {len(boats.encode())} added\n{boats_name}{boats}"
              f"{len(name)} {len(vessels.encode())}\n{name}{vessels}")
    with pytest.raises(rti.ErrorReadingFED, match="^fom:1:1: malformed bundle of FOM modules: a module of the "
                                                  "creation after one added at join$"):
        _core.parse_fed(bundle, "fom")


PING = """<objectModel><interactions><interactionClass><name>HLAinteractionRoot</name>
<interactionClass><name>Ping</name>{delivery}</interactionClass></interactionClass></interactions></objectModel>"""


def test_what_an_added_module_may_not_change(tmp_path: pathlib.Path) -> None:
    """An attribute added to a class that a subclass declares already (the error at the added one, naming the
    subclass's), and another delivery for an interaction class that had its parent's: refused, where merging
    the same modules at creation takes them."""
    speedy = tmp_path / "speedy.xml"
    speedy.write_text(pathlib.Path(HARBOUR).read_text().replace("<name>callsign</name>", "<name>speed</name>"))
    with pytest.raises(rti.ErrorReadingFED, match=rf"^{re.escape(str(speedy))}:12:\d+: 'speed' is declared already by "
                                                  rf"the subclass 'Vessel\.Boat' at {re.escape(BOATS)}:\d+:\d+$"):
        extended([VESSELS], BOATS, str(speedy))
    plain, timed = tmp_path / "plain.xml", tmp_path / "timed.xml"
    plain.write_text(PING.format(delivery=""))
    timed.write_text(PING.format(delivery="<transportation>HLAreliable</transportation><order>TimeStamp</order>"))
    with pytest.raises(rti.ErrorReadingFED, match=rf"^{re.escape(str(timed))}:2:\d+: interaction class 'Ping' has "
                                                  rf"another transportation or order than the federation's FOM gives "
                                                  rf"it \(declared at {re.escape(str(plain))}:2:\d+\)$"):
        extended([str(plain)], str(timed))
    merged = _core.parse_fom_modules([module(str(plain)), module(str(timed))])
    assert [c[6] for c in merged["interaction_classes"] if c[1] == "Ping"] == ["timestamp"]


# ---- through the gateway ----

@pytest.fixture
def fleet(rtig: RtigProcess) -> Iterator[Callable[[], Federate]]:
    """Federation Fleet, created from fleet-vessels.xml alone, and connected 1516-2010 federates made on demand;
    at the end each resigns and disconnects, and the federation is destroyed."""
    made: list[Federate] = []

    def make() -> Federate:
        made.append(Federate(rtig.address))
        return made[-1]
    make().rtia.createFederationExecution("Fleet", [VESSELS])
    yield make
    for f in reversed(made):
        f.close()
    rti.RTIAmbassador(rtig.address).destroyFederationExecution("Fleet")


def knows(lookup: Callable[[], Any], *names_not_found: type[BaseException]) -> bool:
    """Whether `lookup` finds what it looks for yet."""
    try:
        lookup()
    except names_not_found:
        return False
    return True


def test_federates_joined_before_use_what_a_joining_federate_adds(rtig: RtigProcess,
                                                                   fleet: Callable[[], Federate]) -> None:
    """A 1516-2010 and an HLA 1.3 federate join Fleet; a third joins adding fleet-boats.xml and fleet-harbour.xml,
    registers a Boat, updates its pose and the callsign Harbour gives every Vessel, and sends a Moor: the first
    two, their handles unchanged, discover the Boat (as a Boat, as a Vessel), reflect it and receive the Moor."""
    watcher = fleet()
    watcher.rtia.joinFederationExecution("watcher", "test", "Fleet")
    w = watcher.rtia
    vessel, order = w.getObjectClassHandle("Vessel"), w.getInteractionClassHandle("Order")
    known = (vessel, w.getAttributeHandle(vessel, "pose"), order, w.getParameterHandle(order, "waypoints"))
    old_amb = Recorder13()
    old = rti.RTIAmbassador(rtig.address)
    old.joinFederationExecution("old", "Fleet", old_amb)
    old_vessel = old.getObjectClassHandle("Vessel")
    with pytest.raises(rti1516e.NameNotFound):
        w.getObjectClassHandle("Vessel.Boat")

    builder = fleet()
    builder.rtia.joinFederationExecution("builder", "test", "Fleet", [BOATS, HARBOUR])
    b = builder.rtia
    boat, moor = b.getObjectClassHandle("Vessel.Boat"), b.getInteractionClassHandle("Moor")
    pose, callsign = b.getAttributeHandle(boat, "pose"), b.getAttributeHandle(boat, "callsign")
    assert b.getAttributeHandle(vessel, "callsign") == callsign and b.getAttributeHandle(boat, "speed") != callsign

    watcher.until(lambda: knows(lambda: w.getObjectClassHandle("Vessel.Boat"), rti1516e.NameNotFound))
    assert w.getObjectClassHandle("Vessel.Boat") == boat and w.getInteractionClassHandle("Moor") == moor
    assert (vessel, w.getAttributeHandle(vessel, "pose"), order, w.getParameterHandle(order, "waypoints")) == known
    w.subscribeObjectClassAttributes(boat, [w.getAttributeHandle(boat, "pose"), w.getAttributeHandle(boat, "callsign")])
    w.subscribeInteractionClass(moor)
    tick_until(lambda: knows(lambda: old.getAttributeHandle("callsign", old_vessel), rti.NameNotFound), old)
    assert old.getObjectClassHandle("Vessel") == old_vessel
    old.subscribeObjectClassAttributes(old_vessel, [old.getAttributeHandle("callsign", old_vessel)])

    b.publishObjectClassAttributes(boat, [pose, callsign])
    b.publishInteractionClass(moor)
    obj = b.registerObjectInstance(boat)
    b.updateAttributeValues(obj, {pose: b"at sea", callsign: b"F-ABC"}, b"")
    b.sendInteraction(moor, {b.getParameterHandle(moor, "harbour"): b"Brest"}, b"")
    deadline = time.monotonic() + 10
    while not (watcher.amb.named("reflectAttributeValues") and watcher.amb.named("receiveInteraction")
               and old_amb.named("reflectAttributeValues")):
        assert time.monotonic() < deadline, (watcher.amb.calls, old_amb.calls)
        w.evokeMultipleCallbacks(0.01, 0.05)
        old.tick(0.01, 0.05)
    assert [d[:2] for d in watcher.amb.named("discoverObjectInstance")] == [(obj, boat)]
    assert watcher.amb.named("reflectAttributeValues")[0][1] == {pose: b"at sea", callsign: b"F-ABC"}
    received = watcher.amb.named("receiveInteraction")[0]
    assert received[0] == moor and list(received[1].values()) == [b"Brest"]
    assert [d[1] for d in old_amb.named("discoverObjectInstance")] == [old_vessel]
    assert list(old_amb.named("reflectAttributeValues")[0][1].values()) == [b"F-ABC"]
    old.resignFederationExecution(rti.ResignAction.NoAction)


def test_modules_that_do_not_fit_are_refused_and_add_nothing(fleet: Callable[[], Federate],
                                                               tmp_path: pathlib.Path) -> None:
    """A path that cannot be opened, XML that does not read, a module that contradicts the creation's, one that
    gives Vessel an attribute a subclass added earlier has: each join refused with its exception, the federate
    not joined and the FOM as it was; then it joins."""
    watcher = fleet()
    watcher.rtia.joinFederationExecution("watcher", "test", "Fleet")
    late = fleet()
    missing = tmp_path / "missing.xml"
    with pytest.raises(rti1516e.CouldNotOpenFDD, match="missing.xml"):
        late.rtia.joinFederationExecution("late", "test", "Fleet", [str(missing)])
    broken = tmp_path / "broken.xml"
    broken.write_text("<objectModel><objects>")
    with pytest.raises(rti1516e.ErrorReadingFDD, match=rf"{re.escape(str(broken))}:1:\d+: not well-formed XML"):
        late.rtia.joinFederationExecution("late", "test", "Fleet", [str(broken)])
    contradicting = tmp_path / "contradicting.xml"
    contradicting.write_text(pathlib.Path(VESSELS).read_text().replace(
        "<order>Receive</order></attribute>", "<order>TimeStamp</order></attribute>", 1))
    with pytest.raises(rti1516e.InconsistentFDD, match=rf"^InconsistentFDD: {re.escape(str(contradicting))}:\d+:\d+: "
                                                       rf"attribute 'route' of object class 'Vessel' is declared "
                                                       rf"otherwise at {re.escape(VESSELS)}:\d+:\d+$"):
        late.rtia.joinFederationExecution("late", "test", "Fleet", [str(contradicting)])
    fleet().rtia.joinFederationExecution("boats", "test", "Fleet", [BOATS])
    speedy = tmp_path / "speedy.xml"
    speedy.write_text(pathlib.Path(HARBOUR).read_text().replace("<name>callsign</name>", "<name>speed</name>"))
    with pytest.raises(rti1516e.InconsistentFDD, match=rf"{re.escape(str(speedy))}:\d+:\d+: 'speed' is declared "
                                                       rf"already by the subclass 'Vessel\.Boat' at "):
        late.rtia.joinFederationExecution("late", "test", "Fleet", [str(speedy)])
    with pytest.raises(rti1516e.FederateNotExecutionMember):
        late.rtia.getObjectClassHandle("Vessel")
    late.rtia.joinFederationExecution("late", "test", "Fleet")
    for f in (watcher, late):  # Boats' class, not Harbour's nor speedy's
        f.until(lambda: knows(lambda: f.rtia.getObjectClassHandle("Vessel.Boat"), rti1516e.NameNotFound))
        vessel = f.rtia.getObjectClassHandle("Vessel")
        for absent in (lambda: f.rtia.getAttributeHandle(vessel, "speed"),
                       lambda: f.rtia.getObjectClassHandle("Harbour")):
            with pytest.raises(rti1516e.NameNotFound):
                absent()


def test_a_federation_created_from_a_fed_takes_no_modules_at_join(rtig: RtigProcess) -> None:
    creator = rti.RTIAmbassador(rtig.address)
    creator.createFederationExecution("Robots", ROBOT_FED)
    f = Federate(rtig.address)
    try:
        with pytest.raises(rti1516e.InconsistentFDD, match=rf"^InconsistentFDD: {re.escape(ROBOT_FED)}:1:1: the "
                                                           rf"federation was created from an HLA 1\.3 \.fed, which "
                                                           rf"takes no FOM modules at join$"):
            f.rtia.joinFederationExecution("f", "test", "Robots", [VESSELS])
    finally:
        f.close()
        creator.destroyFederationExecution("Robots")


def test_modules_that_contradict_each_other_are_inconsistent_not_unreadable(rtig: RtigProcess,
                                                                           tmp_path: pathlib.Path) -> None:
    """Modules that read but contradict each other (an attribute with another order), given together at creation
    or at join: InconsistentFDD naming both places, not ErrorReadingFDD."""
    clash = tmp_path / "clash.xml"
    clash.write_text(pathlib.Path(VESSELS).read_text().replace("<order>Receive</order>", "<order>TimeStamp</order>"))
    f = Federate(rtig.address)
    try:
        with pytest.raises(rti1516e.InconsistentFDD, match=rf"{re.escape(str(clash))}:\d+:\d+: attribute 'route' of "
                                                           rf"object class 'Vessel' is declared otherwise at "
                                                           rf"{re.escape(VESSELS)}:"):
            f.rtia.createFederationExecution("Clash", [VESSELS, str(clash)])
        f.rtia.createFederationExecution("Clash", [VESSELS])
        with pytest.raises(rti1516e.InconsistentFDD, match=rf"{re.escape(str(clash))}:\d+:\d+: "):
            f.rtia.joinFederationExecution("f", "test", "Clash", [HARBOUR, str(clash)])
        f.rtia.destroyFederationExecution("Clash")
    finally:
        f.close()


def test_a_save_after_an_extension_restores_also_once_the_fom_grew_further(fleet: Callable[[], Federate]) -> None:
    """Saved once Boats extended the FOM; a federate then joins adding Harbour and leaves; the restore takes the
    save (its handles mean the same in the grown FOM) and the Boat registered before it is known again."""
    first, second = fleet(), fleet()
    first.rtia.joinFederationExecution("first", "test", "Fleet")
    second.rtia.joinFederationExecution("second", "test", "Fleet", [BOATS])
    b = second.rtia
    boat = b.getObjectClassHandle("Vessel.Boat")
    b.publishObjectClassAttributes(boat, [b.getAttributeHandle(boat, "pose")])
    obj = b.registerObjectInstance(boat)
    b.requestFederationSave("boats")
    for f in (first, second):
        f.until(lambda: bool(f.amb.named("initiateFederateSave")))
        f.rtia.federateSaveBegun()
        f.rtia.federateSaveComplete()
    for f in (first, second):
        f.until(lambda: bool(f.amb.named("federationSaved")))
    third = fleet()
    third.rtia.joinFederationExecution("third", "test", "Fleet", [HARBOUR])
    third.rtia.resignFederationExecution(rti1516e.NO_ACTION)
    b.requestFederationRestore("boats")
    second.until(lambda: bool(second.amb.named("requestFederationRestoreSucceeded")))
    for f in (first, second):
        f.until(lambda: bool(f.amb.named("initiateFederateRestore")))
        f.rtia.federateRestoreComplete()
    for f in (first, second):
        f.until(lambda: bool(f.amb.named("federationRestored")))
        assert f.rtia.getObjectClassHandle("Vessel.Boat") == boat
        assert knows(lambda: f.rtia.getObjectClassHandle("Harbour"), rti1516e.NameNotFound)
    assert b.getKnownObjectClassHandle(obj) == boat
