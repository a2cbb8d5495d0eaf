"""Data distribution management (HLA 1.3 §9) through the real gateway (in-process and rtig), then over rtig
with the subscribers in separate processes: updates and interactions reach only the federates whose
regions overlap the sender's, region changes apply from the next message, discovery follows scope, and
every exception. The FOM is tests/data/ddm.fed; the contract is docs/ddm.md."""

from __future__ import annotations

import json
import pathlib
from typing import Any, Callable, Iterator

import pytest

import hlacore.rti as rti

from support import Federate, RtigProcess, barrier, joined_federation, python_subprocess, settle, tick_until
from support.federations import DDM_FED, Legit, fom_of
from support.wire import dropped_line, frame, handles, raw_client, u32

Join = Callable[[str], Federate]


@pytest.fixture
def ddm(gateway_address: str) -> Iterator[Join]:
    """Creates DdmFed from tests/data/ddm.fed; returns a function joining federates to it."""
    with joined_federation(gateway_address, "DdmFed", DDM_FED, lambda address, name: Federate(address, name, "DdmFed")) as join:
        yield join


def reflected(fed: Federate) -> list[tuple[Any, dict]]:
    return [(args[0], args[1]) for args in fed.amb.named("reflectAttributeValues")]


def discovered(fed: Federate) -> list[str]:
    return [args[2] for args in fed.amb.named("discoverObjectInstance")]


def received(fed: Federate) -> list[tuple[Any, dict]]:
    return [(args[0], args[1]) for args in fed.amb.named("receiveInteraction")]


# ---- support services and regions ----


def test_spaces_dimensions_and_region_extents(ddm: Join) -> None:
    a = ddm("a")
    h = fom_of(a.rtia)
    assert a.rtia.getRoutingSpaceName(h.geo) == "Geo" and a.rtia.getRoutingSpaceName(h.band) == "Band"
    assert [a.rtia.getDimensionName(d, h.geo) for d in (h.x, h.y)] == ["X", "Y"]
    assert a.rtia.getDimensionName(h.frequency, h.band) == "Frequency"
    assert a.rtia.getAttributeRoutingSpaceHandle(h.position, h.vehicle) == h.geo
    assert a.rtia.getAttributeRoutingSpaceHandle(h.channel, h.vehicle) == h.band
    assert int(a.rtia.getAttributeRoutingSpaceHandle(h.name, h.vehicle)) == 0  # no routing space
    assert a.rtia.getInteractionRoutingSpaceHandle(h.alarm) == h.geo
    assert int(a.rtia.getInteractionRoutingSpaceHandle(h.broadcast)) == 0
    # Dimensions not given span the whole axis; a modification replaces the whole extent.
    region = a.rtia.createRegion(h.geo, [(h.x, (10, 20))])
    assert isinstance(region, rti.RegionHandle)
    assert a.rtia.getRegionExtent(region) == (h.geo, [(h.x, (10, 20)), (h.y, (rti.MIN_EXTENT, rti.MAX_EXTENT))])
    a.rtia.notifyAboutRegionModification(region, [(h.y, (5, 5))])
    assert a.rtia.getRegionExtent(region) == (h.geo, [(h.x, (rti.MIN_EXTENT, rti.MAX_EXTENT)), (h.y, (5, 5))])
    a.rtia.notifyAboutRegionModification(region)  # PyHLA's form: the region's own extent again
    other = a.rtia.createRegion(h.band, [])
    assert other != region and a.rtia.getRegionExtent(other) == (h.band, [(h.frequency, (0, 0xFFFFFFFF))])
    a.rtia.deleteRegion(other)
    with pytest.raises(rti.RegionNotKnown):
        a.rtia.getRegionExtent(other)


def test_status_counts_each_federates_regions(ddm: Join) -> None:
    a, b = ddm("a"), ddm("b")
    h = fom_of(a.rtia)
    for _ in range(2):
        a.rtia.createRegion(h.geo, [])
    gone = b.rtia.createRegion(h.band, [])
    b.rtia.deleteRegion(gone)
    barrier(a.rtia)
    barrier(b.rtia)
    (federation,) = [f for f in json.loads(a.rtia._status())["federations"] if f["name"] == "DdmFed"]
    assert {f["name"]: f["regions"] for f in federation["federates"]} == {"a": 2, "b": 0}


# ---- the acceptance cases ----


def test_two_subscribers_with_disjoint_regions_receive_only_overlapping_updates(ddm: Join) -> None:
    pub, west, east, plain = ddm("pub"), ddm("west"), ddm("east"), ddm("plain")
    h = fom_of(pub.rtia)
    pub.rtia.publishObjectClass(h.vehicle, [h.position, h.speed])
    west_region = west.rtia.createRegion(h.geo, [(h.x, (0, 99))])
    east_region = east.rtia.createRegion(h.geo, [(h.x, (100, 199))])
    west.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, west_region, [h.position])
    east.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, east_region, [h.position])
    plain.rtia.subscribeObjectClassAttributes(h.vehicle, [h.position])  # the default region: everything
    for fed in (west, east, plain):
        barrier(fed.rtia)
    at_west = pub.rtia.createRegion(h.geo, [(h.x, (10, 20)), (h.y, (0, 5))])
    at_east = pub.rtia.createRegion(h.geo, [(h.x, (150, 160))])
    vw = pub.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, at_west)], "v-west")
    ve = pub.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, at_east)], "v-east")
    for i in range(3):
        pub.rtia.updateAttributeValues(vw, {h.position: b"w%d" % i}, "")
        pub.rtia.updateAttributeValues(ve, {h.position: b"e%d" % i}, "")
    everyone = (west.rtia, east.rtia, plain.rtia)
    tick_until(lambda: len(reflected(west)) == 3 and len(reflected(east)) == 3 and len(reflected(plain)) == 6, *everyone)
    barrier(pub.rtia)
    settle(*everyone)
    assert discovered(west) == ["v-west"] and discovered(east) == ["v-east"]
    assert sorted(discovered(plain)) == ["v-east", "v-west"]
    assert reflected(west) == [(vw, {h.position: b"w%d" % i}) for i in range(3)]
    assert reflected(east) == [(ve, {h.position: b"e%d" % i}) for i in range(3)]


def vehicle_in_region(ddm: Join, x: tuple[int, int], name: str):
    """"sub" subscribes vehicle.position through a region X in [0, 99]; "pub" registers vehicle `name` whose
    position updates in a region of X in `x`. Returns pub, sub, the FOM handles, both regions, the object."""
    pub, sub = ddm("pub"), ddm("sub")
    h = fom_of(pub.rtia)
    pub.rtia.publishObjectClass(h.vehicle, [h.position])
    wanted = sub.rtia.createRegion(h.geo, [(h.x, (0, 99))])
    sub.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, wanted, [h.position])
    barrier(sub.rtia)
    at = pub.rtia.createRegion(h.geo, [(h.x, x)])
    return pub, sub, h, wanted, at, pub.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, at)], name)


def test_modifying_a_region_changes_delivery_from_the_next_update(ddm: Join) -> None:
    pub, sub, h, wanted, at, v = vehicle_in_region(ddm, (10, 20), "v")
    pub.rtia.updateAttributeValues(v, {h.position: b"a: inside"}, "")
    tick_until(lambda: len(reflected(sub)) == 1, sub.rtia)
    # The publisher's region moves out: the next update stays in the gateway.
    pub.rtia.notifyAboutRegionModification(at, [(h.x, (150, 160))])
    pub.rtia.updateAttributeValues(v, {h.position: b"b: outside"}, "")
    barrier(pub.rtia)
    # The subscriber's region follows: the next update arrives. Updates from one federate are handled in
    # order, so a delivered b would come before c.
    sub.rtia.notifyAboutRegionModification(wanted, [(h.x, (100, 199))])
    barrier(sub.rtia)
    pub.rtia.updateAttributeValues(v, {h.position: b"c: inside again"}, "")
    tick_until(lambda: len(reflected(sub)) == 2, sub.rtia)
    assert reflected(sub) == [(v, {h.position: b"a: inside"}), (v, {h.position: b"c: inside again"})]


def test_an_instance_is_discovered_when_it_comes_into_scope(ddm: Join) -> None:
    pub, sub, h, wanted, at, v = vehicle_in_region(ddm, (500, 600), "far")
    pub.rtia.updateAttributeValues(v, {h.position: b"far away"}, "")
    barrier(pub.rtia)
    settle(sub.rtia)
    assert discovered(sub) == [] and reflected(sub) == []
    # Moving into scope is enough to be discovered, before any update.
    pub.rtia.notifyAboutRegionModification(at, [(h.x, (50, 60))])
    tick_until(lambda: discovered(sub) == ["far"], sub.rtia)
    pub.rtia.updateAttributeValues(v, {h.position: b"near"}, "")
    tick_until(lambda: bool(reflected(sub)), sub.rtia)
    assert reflected(sub) == [(v, {h.position: b"near"})]


def test_ranges_are_closed_and_every_dimension_must_overlap(ddm: Join) -> None:
    pub, sub = ddm("pub"), ddm("sub")
    h = fom_of(pub.rtia)
    pub.rtia.publishObjectClass(h.vehicle, [h.position])
    wanted = sub.rtia.createRegion(h.geo, [(h.x, (10, 20)), (h.y, (100, 200))])
    sub.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, wanted, [h.position])
    barrier(sub.rtia)
    cases = {
        "touches-upper": ([(h.x, (20, 30))], True),
        "touches-lower": ([(h.x, (0, 10))], True),
        "point-inside": ([(h.x, (15, 15)), (h.y, (150, 150))], True),
        "just-above": ([(h.x, (21, 30))], False),
        "just-below": ([(h.x, (0, 9))], False),
        "x-only": ([(h.x, (10, 20)), (h.y, (201, 300))], False),
        "whole-space": ([], True),
    }
    objects = {}
    for name, (extent, _) in cases.items():
        objects[name] = pub.rtia.registerObjectInstanceWithRegion(
            h.vehicle, [(h.position, pub.rtia.createRegion(h.geo, extent))], name)
        pub.rtia.updateAttributeValues(objects[name], {h.position: name.encode()}, "")
    inside = sorted(name for name, (_, overlaps) in cases.items() if overlaps)
    tick_until(lambda: len(reflected(sub)) == len(inside), sub.rtia)
    barrier(pub.rtia)
    settle(sub.rtia)
    assert sorted(discovered(sub)) == inside
    assert sorted(values[h.position].decode() for _, values in reflected(sub)) == inside


def test_subclass_instances_are_filtered_at_the_class_the_subscriber_knows(ddm: Join) -> None:
    pub, sub = ddm("pub"), ddm("sub")
    h = fom_of(pub.rtia)
    load = pub.rtia.getAttributeHandle("load", h.truck)
    pub.rtia.publishObjectClass(h.truck, [h.position, load])
    region = sub.rtia.createRegion(h.geo, [(h.y, (0, 10))])
    sub.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, region, [h.position])
    barrier(sub.rtia)
    near, far = pub.rtia.createRegion(h.geo, [(h.y, (10, 10))]), pub.rtia.createRegion(h.geo, [(h.y, (11, 11))])
    t1 = pub.rtia.registerObjectInstanceWithRegion(h.truck, [(h.position, near), (load, far)], "t1")
    t2 = pub.rtia.registerObjectInstanceWithRegion(h.truck, [(h.position, far), (load, near)], "t2")
    for t in (t1, t2):
        pub.rtia.updateAttributeValues(t, {h.position: b"p", load: b"l"}, "")
    barrier(pub.rtia)
    barrier(sub.rtia)
    sub.rtia.tick()
    # Discovered as vehicle, the class subscribed; load is not a vehicle attribute, so never reflected.
    assert sub.amb.named("discoverObjectInstance") == [(t1, h.vehicle, "t1")]
    assert reflected(sub) == [(t1, {h.position: b"p"})]


def test_associating_and_unassociating_an_update_region(ddm: Join) -> None:
    pub, west, east = ddm("pub"), ddm("west"), ddm("east")
    h = fom_of(pub.rtia)
    pub.rtia.publishObjectClass(h.vehicle, [h.position, h.speed])
    for fed, low in ((west, 0), (east, 100)):
        region = fed.rtia.createRegion(h.geo, [(h.x, (low, low + 99))])
        fed.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, region, [h.position, h.speed])
        barrier(fed.rtia)
    # Registered without region: the default region (the whole space) overlaps both.
    v = pub.rtia.registerObjectInstance(h.vehicle, "v")
    pub.rtia.updateAttributeValues(v, {h.position: b"1", h.speed: b"1"}, "")
    tick_until(lambda: len(reflected(west)) == 1 and len(reflected(east)) == 1, west.rtia, east.rtia)
    at_west = pub.rtia.createRegion(h.geo, [(h.x, (42, 42))])
    pub.rtia.associateRegionForUpdates(at_west, v, [h.position])
    pub.rtia.updateAttributeValues(v, {h.position: b"2", h.speed: b"2"}, "")
    pub.rtia.unassociateRegionForUpdates(at_west, v)
    pub.rtia.updateAttributeValues(v, {h.position: b"3", h.speed: b"3"}, "")
    tick_until(lambda: len(reflected(west)) == 3 and len(reflected(east)) == 3, west.rtia, east.rtia)
    barrier(pub.rtia)
    settle(west.rtia, east.rtia)
    # Each attribute is filtered by its own region: speed stayed in the default region.
    assert [values for _, values in reflected(west)] == [{h.position: b"%d" % i, h.speed: b"%d" % i} for i in (1, 2, 3)]
    assert [values for _, values in reflected(east)] == [
        {h.position: b"1", h.speed: b"1"}, {h.speed: b"2"}, {h.position: b"3", h.speed: b"3"}]


def test_an_hla13_association_replaces_the_attributes_region(ddm: Join) -> None:
    """HLA 1.3 gives an attribute one update region: a second associateRegionForUpdates replaces the first
    (which is then no longer associated, nor in use), and an attribute named twice at registration keeps the
    last region (IEEE 1516-2010's several regions are its own services')."""
    pub, west, east = ddm("pub"), ddm("west"), ddm("east")
    h = fom_of(pub.rtia)
    pub.rtia.publishObjectClass(h.vehicle, [h.position])
    for fed, low in ((west, 0), (east, 100)):
        region = fed.rtia.createRegion(h.geo, [(h.x, (low, low + 99))])
        fed.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, region, [h.position])
        barrier(fed.rtia)
    at_west = pub.rtia.createRegion(h.geo, [(h.x, (42, 42))])
    at_east = pub.rtia.createRegion(h.geo, [(h.x, (142, 142))])
    v = pub.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, at_west), (h.position, at_east)], "v")
    pub.rtia.updateAttributeValues(v, {h.position: b"1: east"}, "")
    pub.rtia.associateRegionForUpdates(at_west, v, [h.position])
    pub.rtia.updateAttributeValues(v, {h.position: b"2: west"}, "")
    with pytest.raises(rti.InvalidRegionContext):  # no longer associated, nor in use
        pub.rtia.unassociateRegionForUpdates(at_east, v)
    pub.rtia.deleteRegion(at_east)
    pub.rtia.unassociateRegionForUpdates(at_west, v)  # back to the default region
    pub.rtia.updateAttributeValues(v, {h.position: b"3: both"}, "")
    tick_until(lambda: len(reflected(west)) == 2 and len(reflected(east)) == 2, west.rtia, east.rtia)
    barrier(pub.rtia)
    settle(west.rtia, east.rtia)
    assert [values[h.position] for _, values in reflected(west)] == [b"2: west", b"3: both"]
    assert [values[h.position] for _, values in reflected(east)] == [b"1: east", b"3: both"]


def test_attributes_without_routing_space_and_plain_subscriptions_are_unaffected(ddm: Join) -> None:
    pub, sub = ddm("pub"), ddm("sub")
    h = fom_of(pub.rtia)
    pub.rtia.publishObjectClass(h.vehicle, [h.position, h.name])
    truck_region = sub.rtia.createRegion(h.geo, [(h.x, (0, 9))])
    sub.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, truck_region, [h.position])
    sub.rtia.subscribeObjectClassAttributes(h.vehicle, [h.name])  # name has no routing space
    barrier(sub.rtia)
    far = pub.rtia.createRegion(h.geo, [(h.x, (1000, 2000))])
    v = pub.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, far)], "v")
    pub.rtia.updateAttributeValues(v, {h.position: b"far", h.name: b"Ada"}, "")
    tick_until(lambda: bool(reflected(sub)), sub.rtia)
    barrier(pub.rtia)
    settle(sub.rtia)
    assert discovered(sub) == ["v"]  # the plain subscription discovers as before
    assert reflected(sub) == [(v, {h.name: b"Ada"})]


def test_interactions_sent_with_a_region_reach_only_overlapping_subscribers(ddm: Join) -> None:
    sender, west, east, plain = ddm("sender"), ddm("west"), ddm("east"), ddm("plain")
    h = fom_of(sender.rtia)
    for cls in (h.radio, h.alarm, h.broadcast):
        sender.rtia.publishInteractionClass(cls)
    west_region = west.rtia.createRegion(h.geo, [(h.x, (0, 99))])
    east_region = east.rtia.createRegion(h.geo, [(h.x, (100, 199))])
    west.rtia.subscribeInteractionClassWithRegion(h.radio, west_region)
    east.rtia.subscribeInteractionClassWithRegion(h.radio, east_region)
    west.rtia.subscribeInteractionClass(h.broadcast)  # no routing space
    plain.rtia.subscribeInteractionClass(h.radio)
    for fed in (west, east, plain):
        barrier(fed.rtia)
    to_west = sender.rtia.createRegion(h.geo, [(h.x, (50, 60))])
    to_east = sender.rtia.createRegion(h.geo, [(h.x, (100, 100))])
    sender.rtia.sendInteractionWithRegion(h.radio, {h.text: b"west"}, to_west, "")
    sender.rtia.sendInteractionWithRegion(h.radio, {h.text: b"east"}, to_east, "")
    sender.rtia.sendInteraction(h.radio, {h.text: b"all"}, "")  # the default region: every subscriber
    sender.rtia.sendInteractionWithRegion(h.alarm, {h.text: b"alarm", h.level: b"9"}, to_west, "")
    sender.rtia.sendInteraction(h.broadcast, {h.broadcast_text: b"news"}, "")
    everyone = (west.rtia, east.rtia, plain.rtia)
    tick_until(lambda: len(received(west)) == 4 and len(received(east)) == 2 and len(received(plain)) == 4, *everyone)
    barrier(sender.rtia)
    settle(*everyone)
    # alarm is received as the subscribed radio, with radio's parameters.
    assert received(west) == [(h.radio, {h.text: b"west"}), (h.radio, {h.text: b"all"}),
                              (h.radio, {h.text: b"alarm"}), (h.broadcast, {h.broadcast_text: b"news"})]
    assert received(east) == [(h.radio, {h.text: b"east"}), (h.radio, {h.text: b"all"})]
    assert [values[h.text] for _, values in received(plain)] == [b"west", b"east", b"all", b"alarm"]
    # Unsubscribed through its region, east receives nothing more.
    east.rtia.unsubscribeInteractionClassWithRegion(h.radio, east_region)
    barrier(east.rtia)
    sender.rtia.sendInteractionWithRegion(h.radio, {h.text: b"east again"}, to_east, "")
    tick_until(lambda: len(received(plain)) == 5, plain.rtia)
    barrier(sender.rtia)
    settle(east.rtia)
    assert len(received(east)) == 2


def test_timestamped_interaction_with_a_region(ddm: Join) -> None:
    sender, sub = ddm("sender"), ddm("sub")
    h = fom_of(sender.rtia)
    sender.rtia.publishInteractionClass(h.radio)
    region = sub.rtia.createRegion(h.geo, [(h.y, (0, 10))])
    sub.rtia.subscribeInteractionClassWithRegion(h.radio, region)
    sender.enable_time(lookahead=1.0, constrained=False)
    sub.enable_time(lookahead=None)
    barrier(sub.rtia)
    near = sender.rtia.createRegion(h.geo, [(h.y, (10, 20))])
    far = sender.rtia.createRegion(h.geo, [(h.y, (11, 20))])
    retraction = sender.rtia.sendInteractionWithRegion(h.radio, {h.text: b"near"}, near, "", 4.0)
    assert isinstance(retraction, rti.EventRetractionHandle)
    sender.rtia.sendInteractionWithRegion(h.radio, {h.text: b"far"}, far, "", 4.5)
    assert sender.rtia.advance_to(5.0, timeout=5.0) == 5.0
    assert sub.rtia.advance_to(5.0, timeout=5.0) == 5.0
    receptions = sub.amb.named("receiveInteraction")
    assert [(args[1], args[5]) for args in receptions] == [({h.text: b"near"}, 4.0)]
    assert sub.rtia.getOrderingName(receptions[0][3]) == "Timestamp"


def test_request_class_update_with_region_asks_only_the_overlapping_owners(ddm: Join) -> None:
    pub, other, asker = ddm("pub"), ddm("other"), ddm("asker")
    h = fom_of(pub.rtia)
    for fed in (pub, other):
        fed.rtia.publishObjectClass(h.vehicle, [h.position, h.name])
    near = pub.rtia.createRegion(h.geo, [(h.x, (5, 5))])
    far = other.rtia.createRegion(h.geo, [(h.x, (500, 500))])
    v_near = pub.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, near)], "near")
    v_default = pub.rtia.registerObjectInstance(h.vehicle, "default")
    other.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, far)], "far")
    barrier(pub.rtia)
    barrier(other.rtia)
    region = asker.rtia.createRegion(h.geo, [(h.x, (0, 10))])
    asker.rtia.requestClassAttributeValueUpdateWithRegion(h.vehicle, [h.position], region)
    tick_until(lambda: len(pub.amb.named("provideAttributeValueUpdate")) == 2, pub.rtia)
    barrier(asker.rtia)
    settle(pub.rtia, other.rtia)
    assert sorted((int(obj), attrs) for obj, attrs in pub.amb.named("provideAttributeValueUpdate")) == sorted(
        [(int(v_near), (h.position,)), (int(v_default), (h.position,))])
    assert other.amb.named("provideAttributeValueUpdate") == []


def test_deleted_regions_and_resigned_subscribers_leave_routing_intact(ddm: Join) -> None:
    pub, sub, leaver = ddm("pub"), ddm("sub"), ddm("leaver")
    h = fom_of(pub.rtia)
    pub.rtia.publishObjectClass(h.vehicle, [h.position])
    for fed in (sub, leaver):
        region = fed.rtia.createRegion(h.geo, [(h.x, (0, 10))])
        fed.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, region, [h.position])
        barrier(fed.rtia)
    at = pub.rtia.createRegion(h.geo, [(h.x, (5, 5))])
    v = pub.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, at)], "v")
    leaver.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    pub.rtia.updateAttributeValues(v, {h.position: b"1"}, "")
    tick_until(lambda: len(reflected(sub)) == 1, sub.rtia)
    # Deleting the object frees its update region; deleting the region is then allowed.
    pub.rtia.deleteObjectInstance(v, "")
    pub.rtia.deleteRegion(at)
    w = pub.rtia.registerObjectInstance(h.vehicle, "w")
    pub.rtia.updateAttributeValues(w, {h.position: b"2"}, "")
    tick_until(lambda: len(reflected(sub)) == 2, sub.rtia)
    assert reflected(sub)[1] == (w, {h.position: b"2"})


# ---- attribute scope and relevance advisories (HLA 1.3 §6.13-6.14, §6.17-6.18) ----


def advisory_events(fed: Federate, on: str, off: str) -> list[tuple[str, Any, set]]:
    """The `on` and `off` advisories fed got, in order: (callback name, object, set of attributes)."""
    return [(name, args[0], set(args[1])) for name, args in fed.amb.calls if name in (on, off)]


def scope_events(fed: Federate) -> list[tuple[str, Any, set]]:
    return advisory_events(fed, "attributesInScope", "attributesOutOfScope")


def relevance_events(fed: Federate) -> list[tuple[str, Any, set]]:
    return advisory_events(fed, "turnUpdatesOnForObjectInstance", "turnUpdatesOffForObjectInstance")


def test_attributes_come_into_and_go_out_of_scope(ddm: Join) -> None:
    pub, sub, quiet = ddm("pub"), ddm("sub"), ddm("quiet")
    h = fom_of(pub.rtia)
    pub.rtia.publishObjectClass(h.vehicle, [h.position, h.speed, h.name])
    sub.rtia.enableAttributeScopeAdvisorySwitch()
    wanted = sub.rtia.createRegion(h.geo, [(h.x, (0, 99))])
    sub.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, wanted, [h.position, h.speed])
    sub.rtia.subscribeObjectClassAttributes(h.vehicle, [h.name])
    quiet.rtia.subscribeObjectClassAttributes(h.vehicle, [h.position])  # its switch stays off
    barrier(sub.rtia)
    barrier(quiet.rtia)
    at = pub.rtia.createRegion(h.geo, [(h.x, (50, 50))])
    v = pub.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, at), (h.speed, at)], "v")
    tick_until(lambda: len(scope_events(sub)) == 1, sub.rtia)
    assert [name for name, _ in sub.amb.calls][:2] == ["discoverObjectInstance", "attributesInScope"]
    # The region moves away: position and speed leave the scope, name (no routing space) stays.
    pub.rtia.notifyAboutRegionModification(at, [(h.x, (500, 500))])
    tick_until(lambda: len(scope_events(sub)) == 2, sub.rtia)
    # Unassociated, both go back to the default region; position alone is associated again.
    pub.rtia.unassociateRegionForUpdates(at, v)
    tick_until(lambda: len(scope_events(sub)) == 3, sub.rtia)
    pub.rtia.associateRegionForUpdates(at, v, [h.position])
    tick_until(lambda: len(scope_events(sub)) == 4, sub.rtia)
    pub.rtia.notifyAboutRegionModification(at, [(h.x, (60, 60))])
    tick_until(lambda: len(scope_events(sub)) == 5, sub.rtia)
    # An unowned attribute is out of scope.
    pub.rtia.unconditionalAttributeOwnershipDivestiture(v, [h.position])
    tick_until(lambda: len(scope_events(sub)) == 6, sub.rtia)
    sub.rtia.disableAttributeScopeAdvisorySwitch()
    barrier(sub.rtia)
    pub.rtia.unconditionalAttributeOwnershipDivestiture(v, [h.speed])
    barrier(pub.rtia)
    settle(sub.rtia, quiet.rtia)
    assert scope_events(sub) == [
        ("attributesInScope", v, {h.position, h.speed, h.name}),
        ("attributesOutOfScope", v, {h.position, h.speed}),
        ("attributesInScope", v, {h.position, h.speed}),
        ("attributesOutOfScope", v, {h.position}),
        ("attributesInScope", v, {h.position}),
        ("attributesOutOfScope", v, {h.position}),
    ]
    assert scope_events(quiet) == []


def test_owners_are_told_when_their_attributes_are_wanted(ddm: Join) -> None:
    pub, west, east = ddm("pub"), ddm("west"), ddm("east")
    h = fom_of(pub.rtia)
    pub.rtia.enableAttributeRelevanceAdvisorySwitch()
    pub.rtia.publishObjectClass(h.vehicle, [h.position, h.speed])
    at = pub.rtia.createRegion(h.geo, [(h.x, (50, 50))])
    v = pub.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, at), (h.speed, at)], "v")
    barrier(pub.rtia)
    settle(pub.rtia)
    assert relevance_events(pub) == []  # nobody subscribes yet
    west_region = west.rtia.createRegion(h.geo, [(h.x, (0, 99))])
    west.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, west_region, [h.position])
    tick_until(lambda: len(relevance_events(pub)) == 1, pub.rtia)
    east.rtia.subscribeObjectClassAttributes(h.vehicle, [h.position, h.speed])  # plain: speed too
    tick_until(lambda: len(relevance_events(pub)) == 2, pub.rtia)
    east.rtia.unsubscribeObjectClass(h.vehicle)
    tick_until(lambda: len(relevance_events(pub)) == 3, pub.rtia)
    # The update region moves away from west's: nobody wants position any more.
    pub.rtia.notifyAboutRegionModification(at, [(h.x, (500, 500))])
    tick_until(lambda: len(relevance_events(pub)) == 4, pub.rtia)
    pub.rtia.disableAttributeRelevanceAdvisorySwitch()
    pub.rtia.notifyAboutRegionModification(at, [(h.x, (50, 50))])
    barrier(pub.rtia)
    settle(pub.rtia)
    assert relevance_events(pub) == [
        ("turnUpdatesOnForObjectInstance", v, {h.position}),
        ("turnUpdatesOnForObjectInstance", v, {h.speed}),
        ("turnUpdatesOffForObjectInstance", v, {h.speed}),
        ("turnUpdatesOffForObjectInstance", v, {h.position}),
    ]


# ---- exceptions ----


def test_exceptions(ddm: Join, gateway_address: str, tmp_path: pathlib.Path) -> None:
    a, b = ddm("a"), ddm("b")
    h = fom_of(a.rtia)
    geo_region = a.rtia.createRegion(h.geo, [(h.x, (0, 10))])
    band_region = a.rtia.createRegion(h.band, [(h.frequency, (88, 108))])

    with pytest.raises(rti.DimensionNotDefined):
        a.rtia.createRegion(h.band, [(h.y, (0, 1))])  # Band has one dimension
    for bad in ([(h.x, (5, 4))], [(h.x, (-1, 4))], [(h.x, (0, rti.MAX_EXTENT + 1))], [(h.x, (0, 1)), (h.x, (2, 3))]):
        with pytest.raises(rti.InvalidExtents):
            a.rtia.createRegion(h.geo, bad)
        with pytest.raises(rti.InvalidExtents):
            a.rtia.notifyAboutRegionModification(geo_region, bad)
    with pytest.raises(TypeError):
        a.rtia.createRegion(h.geo, [(h.band, (0, 1))])  # type: ignore[list-item]
    with pytest.raises(TypeError):
        a.rtia.createRegion(1, [])  # type: ignore[arg-type]
    spaces = tmp_path / "spaces.fed"
    spaces.write_text("(FED (Federation S) (FEDversion v1.3) (spaces (space A (dimension D)) (space B (dimension D))"
                      " (space C (dimension D))) (objects (class ObjectRoot)) (interactions (class InteractionRoot reliable receive)))\n")
    other = rti.RTIAmbassador(gateway_address)
    other.createFederationExecution("S", str(spaces))
    try:
        other.joinFederationExecution("o", "S", rti.FederateAmbassador())
        with pytest.raises(rti.SpaceNotDefined):
            a.rtia.createRegion(other.getRoutingSpaceHandle("C"), [])
        other.resignFederationExecution(rti.ResignAction.NoAction)
    finally:
        other.destroyFederationExecution("S")

    # A region of another federate, or a deleted one.
    b_region = b.rtia.createRegion(h.geo, [])
    gone = b.rtia.createRegion(h.geo, [])
    b.rtia.deleteRegion(gone)
    for unknown, fed in ((b_region, a), (gone, b)):
        for call in (lambda: fed.rtia.notifyAboutRegionModification(unknown),
                     lambda: fed.rtia.deleteRegion(unknown),
                     lambda: fed.rtia.getRegionExtent(unknown),
                     lambda: fed.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, unknown, [h.position]),
                     lambda: fed.rtia.subscribeInteractionClassWithRegion(h.radio, unknown),
                     lambda: fed.rtia.requestClassAttributeValueUpdateWithRegion(h.vehicle, [h.position], unknown)):
            with pytest.raises(rti.RegionNotKnown):
                call()

    # Regions of another routing space than the attribute's or interaction's (or of none).
    for attr, region in ((h.name, geo_region), (h.channel, geo_region), (h.position, band_region)):
        with pytest.raises(rti.InvalidRegionContext):
            a.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, region, [attr])
    with pytest.raises(rti.InvalidRegionContext):
        a.rtia.subscribeInteractionClassWithRegion(h.broadcast, geo_region)
    with pytest.raises(rti.InvalidRegionContext):
        a.rtia.subscribeInteractionClassWithRegion(h.radio, band_region)
    with pytest.raises(rti.ObjectClassNotSubscribed):
        a.rtia.unsubscribeObjectClassWithRegion(h.vehicle, geo_region)
    with pytest.raises(rti.InteractionClassNotSubscribed):
        a.rtia.unsubscribeInteractionClassWithRegion(h.radio, geo_region)

    with pytest.raises(rti.ObjectClassNotPublished):
        a.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, geo_region)], "v")
    a.rtia.publishObjectClass(h.vehicle, [h.position, h.channel, h.name])
    with pytest.raises(rti.AttributeNotPublished):
        a.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.speed, geo_region)], "v")
    with pytest.raises(rti.InvalidRegionContext):
        a.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.channel, geo_region)], "v")
    v = a.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, geo_region), (h.channel, band_region)], "v")
    with pytest.raises(rti.ObjectAlreadyRegistered):
        a.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, geo_region)], "v")
    with pytest.raises(rti.InvalidRegionContext):
        a.rtia.associateRegionForUpdates(geo_region, v, [h.name])
    with pytest.raises(rti.ObjectNotKnown):
        b.rtia.associateRegionForUpdates(b_region, v, [h.position])
    with pytest.raises(rti.RegionInUse):
        a.rtia.deleteRegion(geo_region)  # v's position is updated in it
    a.rtia.unassociateRegionForUpdates(geo_region, v)
    with pytest.raises(rti.InvalidRegionContext):
        a.rtia.unassociateRegionForUpdates(geo_region, v)  # no longer associated

    a.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, geo_region, [h.position])
    with pytest.raises(rti.RegionInUse):
        a.rtia.deleteRegion(geo_region)
    a.rtia.unsubscribeObjectClassWithRegion(h.vehicle, geo_region)
    a.rtia.subscribeInteractionClassWithRegion(h.radio, geo_region)
    with pytest.raises(rti.RegionInUse):
        a.rtia.deleteRegion(geo_region)
    a.rtia.unsubscribeInteractionClassWithRegion(h.radio, geo_region)
    a.rtia.deleteRegion(geo_region)

    with pytest.raises(rti.InteractionClassNotPublished):
        a.rtia.sendInteractionWithRegion(h.radio, {h.text: b""}, band_region, "")
    a.rtia.publishInteractionClass(h.radio)
    a.rtia.publishInteractionClass(h.broadcast)
    with pytest.raises(rti.InvalidRegionContext):
        a.rtia.sendInteractionWithRegion(h.radio, {h.text: b""}, band_region, "")
    with pytest.raises(rti.InvalidRegionContext):
        a.rtia.sendInteractionWithRegion(h.broadcast, {h.broadcast_text: b""}, band_region, "")
    with pytest.raises(rti.InteractionParameterNotDefined):
        a.rtia.sendInteractionWithRegion(h.radio, {h.level: b""}, band_region, "")
    with pytest.raises(rti.RegionNotKnown):
        a.rtia.sendInteractionWithRegion(h.radio, {h.text: b""}, geo_region, "")

    outsider = rti.RTIAmbassador(gateway_address)
    for call in (lambda: outsider.createRegion(h.geo, []),
                 lambda: outsider.notifyAboutRegionModification(band_region),
                 lambda: outsider.subscribeInteractionClassWithRegion(h.radio, band_region)):
        with pytest.raises(rti.FederateNotExecutionMember):
            call()
    # Nothing refused reached the gateway as a protocol violation: a and b still work.
    b.rtia.subscribeObjectClassAttributes(h.vehicle, [h.channel])
    barrier(b.rtia)
    a.rtia.updateAttributeValues(v, {h.channel: b"ok"}, "")
    tick_until(lambda: reflected(b) == [(v, {h.channel: b"ok"})], b.rtia)


# ---- the gateway drops a client that sends what its client library would have refused ----


@pytest.mark.parametrize(
    "message, payload, why",
    [
        ("CreateRegion", u32(1) + u32(1) + handles([]), "routing space handle 1 is not defined in the FOM"),
        ("ModifyRegion", u32(7) + handles([]), "region 7 is not known"),
        ("SubscribeObjectClassWithRegion", u32(1) + u32(7) + handles([]) + b"\x01", "region 7 is not known"),
        ("SendInteractionWithRegion", None, "region 7 is not known"),
    ],
    ids=["undefined-space", "modify-unknown", "subscribe-unknown", "send-unknown"],
)
def test_region_protocol_violations_drop_only_the_offender(
    rtig: RtigProcess, legit: Legit, message: str, payload: bytes | None, why: str
) -> None:
    with raw_client(rtig.address) as hostile:
        handle = hostile.join("hostile")
        if payload is None:  # command, no values, empty tag, no time, serial 1, regions [7]
            payload = u32(int(legit.command)) + u32(0) + u32(0) + b"\x00" + (1).to_bytes(8, "little") + handles([7])
        hostile.send(frame(message, payload))
        hostile.wait_eof()
        line = dropped_line(rtig, hostile)
    assert f"(federate {handle} of 'TestFed'): protocol error: " in line and why in line, line
    legit.check_working()


# ---- over rtig, the subscribers in their own processes ----


def test_subscribers_in_separate_processes_receive_only_their_region(rtig: RtigProcess) -> None:
    pub = rti.RTIAmbassador(rtig.address)
    pub.createFederationExecution("DdmFed", DDM_FED)
    peers = {}
    try:
        amb = rti.FederateAmbassador()
        pub.joinFederationExecution("pub", "DdmFed", amb)
        h = fom_of(pub)
        for name, low, high in (("west", 0, 99), ("east", 100, 199)):
            peers[name] = python_subprocess("ddm_subscriber.py", rtig.address, name, str(low), str(high))
        for name in peers:
            assert peers[name].read_json() == {"ready": True}
        pub.publishObjectClass(h.vehicle, [h.position])
        pub.publishInteractionClass(h.broadcast)
        pub.publishInteractionClass(h.radio)
        at_west = pub.createRegion(h.geo, [(h.x, (10, 20))])
        at_east = pub.createRegion(h.geo, [(h.x, (150, 160))])
        vw = pub.registerObjectInstanceWithRegion(h.vehicle, [(h.position, at_west)], "v-west")
        ve = pub.registerObjectInstanceWithRegion(h.vehicle, [(h.position, at_east)], "v-east")
        for i in range(5):
            pub.updateAttributeValues(vw, {h.position: b"w%d" % i}, "")
            pub.updateAttributeValues(ve, {h.position: b"e%d" % i}, "")
        pub.sendInteractionWithRegion(h.radio, {h.text: b"to east"}, at_east, "")
        # v-west drives east: from its next update on, east has it and west does not.
        pub.notifyAboutRegionModification(at_west, [(h.x, (120, 130))])
        pub.updateAttributeValues(vw, {h.position: b"w-moved"}, "")
        pub.sendInteraction(h.broadcast, {h.broadcast_text: b"stop"}, "")
        results = {name: peers[name].read_json() for name in peers}
        for proc in peers.values():
            assert proc.wait(timeout=30) == 0
    finally:
        for proc in peers.values():
            proc.close()
        try:
            pub.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        finally:
            pub.destroyFederationExecution("DdmFed")
    assert results["west"] == {"discovered": ["v-west"], "reflected": [["v-west", "w%d" % i] for i in range(5)],
                               "received": []}
    assert results["east"] == {
        "discovered": ["v-east", "v-west"],
        "reflected": [["v-east", "e%d" % i] for i in range(5)] + [["v-west", "w-moved"]],
        "received": ["to east"],
    }
