"""Save/restore of data distribution management state (docs/save-restore.md, docs/ddm.md): after a restore
the gateway routes by the regions, region subscriptions and update associations of the save, and each
client's region table (handles, extents, what is in use) is the save's, on both gateways and after `rtig`
was restarted on its --save-dir. The FOM is tests/data/ddm.fed."""

from __future__ import annotations

import pathlib
import struct
from typing import Any

import pytest

import hlacore.rti as rti
from hlacore.processes import Child

from support import Recorder, barrier, peer_says, python_subprocess, running_rtig, settle, tick_until
from support.federations import DDM_FED, Fom, fom_of

FULL = (rti.MIN_EXTENT, rti.MAX_EXTENT)


class Fed:
    """A federate of DdmFed recording every callback, save/restore ones included."""

    def __init__(self, address: str, name: str) -> None:
        self.rtia = rti.RTIAmbassador(address)
        self.amb = Recorder()
        self.handle = self.rtia.joinFederationExecution(name, "DdmFed", self.amb)
        self.h: Fom = fom_of(self.rtia)

    def named(self, name: str) -> list[tuple[Any, ...]]:
        return self.amb.named(name)

    def forget(self) -> None:
        self.amb.calls.clear()


def tick_all(predicate, feds: list[Fed], timeout: float = 5.0) -> None:
    tick_until(predicate, *(f.rtia for f in feds), timeout=timeout)


def save(label: str, feds: list[Fed]) -> None:
    feds[0].rtia.requestFederationSave(label)
    tick_all(lambda: all(f.named("initiateFederateSave") for f in feds), feds)
    for f in feds:
        f.rtia.federateSaveComplete()
    tick_all(lambda: all(f.named("federationSaved") for f in feds), feds)


def restore(label: str, feds: list[Fed]) -> None:
    feds[0].rtia.requestFederationRestore(label)
    tick_all(lambda: all(f.named("initiateFederateRestore") for f in feds), feds)
    assert feds[0].named("requestFederationRestoreSucceeded") == [(label,)]
    for f in feds:
        f.rtia.federateRestoreComplete()
    tick_all(lambda: all(f.named("federationRestored") for f in feds), feds)


class World:
    """A publisher p and two subscribers s1, s2 whose regions r1 (X in [0, 10]) and r2 (X in [20, 30]) are
    disjoint. p updates vehicle v1's position in its region u (X = 5, in r1) and sends radio interactions
    in u; both subscribers also subscribe `broadcast` plainly: the marker after which nothing more comes."""

    def __init__(self, p: Fed, s1: Fed, s2: Fed) -> None:
        self.p, self.s1, self.s2 = p, s1, s2
        h = p.h
        self.r1 = self.subscribe_in(s1, (0, 10))
        self.r2 = self.subscribe_in(s2, (20, 30))
        p.rtia.publishObjectClass(h.vehicle, [h.position])
        p.rtia.publishInteractionClass(h.radio)
        p.rtia.publishInteractionClass(h.broadcast)
        self.u = p.rtia.createRegion(h.geo, [(h.x, (5, 5))])
        self.v1 = p.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, self.u)], "v1")
        tick_all(lambda: bool(s1.named("discoverObjectInstance")), self.feds)

    @staticmethod
    def subscribe_in(s: Fed, x: tuple[int, int]) -> Any:
        h = s.h
        region = s.rtia.createRegion(h.geo, [(h.x, x)])
        s.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, region, [h.position])
        s.rtia.subscribeInteractionClassWithRegion(h.radio, region)
        s.rtia.subscribeInteractionClass(h.broadcast)
        barrier(s.rtia)
        return region

    @property
    def feds(self) -> list[Fed]:
        return [self.p, self.s1, self.s2]

    def send_round(self, tag: str) -> tuple[list[str], list[str]]:
        """p updates v1 and sends a radio interaction in u, then the broadcast marker; returns what s1 and
        s2 received of the first two (and their discoveries), once both have the marker."""
        h = self.p.h
        for f in self.feds:
            f.forget()
        self.p.rtia.updateAttributeValues(self.v1, {h.position: tag.encode()}, tag)
        self.p.rtia.sendInteractionWithRegion(h.radio, {h.text: tag.encode()}, self.u, tag)
        self.p.rtia.sendInteraction(h.broadcast, {h.broadcast_text: b"marker"}, "marker")

        def marked(s: Fed) -> bool:
            return any(args[0] == h.broadcast for args in s.named("receiveInteraction"))

        tick_all(lambda: marked(self.s1) and marked(self.s2), self.feds)
        got = []
        for s in (self.s1, self.s2):
            got.append(sorted([f"discover {args[2]}" for args in s.named("discoverObjectInstance")]
                              + [f"reflect {args[2]}" for args in s.named("reflectAttributeValues")]
                              + [f"radio {args[2]}" for args in s.named("receiveInteraction") if args[0] == h.radio]))
        return got[0], got[1]

    def change_everything(self) -> Any:
        """After the save: p moves u into r2's X range and re-associates v1's position with a new region
        n; s1 unsubscribes and deletes r1; s2 narrows r2. Returns n."""
        h = self.p.h
        self.s1.rtia.unsubscribeObjectClassWithRegion(h.vehicle, self.r1)
        self.s1.rtia.unsubscribeInteractionClassWithRegion(h.radio, self.r1)
        self.s1.rtia.deleteRegion(self.r1)
        self.s2.rtia.notifyAboutRegionModification(self.r2, [(h.x, (24, 30))])
        barrier(self.s1.rtia)
        barrier(self.s2.rtia)
        self.p.rtia.notifyAboutRegionModification(self.u, [(h.x, (25, 25))])
        n = self.p.rtia.createRegion(h.geo, [(h.x, (26, 27))])
        self.p.rtia.unassociateRegionForUpdates(self.u, self.v1)
        self.p.rtia.associateRegionForUpdates(n, self.v1, [h.position])
        return n

    def check_saved_regions(self, n: Any) -> None:
        """Each client's regions are the save's: extents, what is in use, and n (created later) is gone."""
        h = self.p.h
        assert self.s1.rtia.getRegionExtent(self.r1) == (h.geo, [(h.x, (0, 10)), (h.y, FULL)])
        assert self.s2.rtia.getRegionExtent(self.r2) == (h.geo, [(h.x, (20, 30)), (h.y, FULL)])
        assert self.p.rtia.getRegionExtent(self.u) == (h.geo, [(h.x, (5, 5)), (h.y, FULL)])
        for fed, region in ((self.s1, self.r1), (self.s2, self.r2), (self.p, self.u)):
            with pytest.raises(rti.RegionInUse):  # its subscriptions / v1's association are back
                fed.rtia.deleteRegion(region)
        with pytest.raises(rti.RegionNotKnown):
            self.p.rtia.getRegionExtent(n)
        with pytest.raises(rti.RegionNotKnown):
            self.p.rtia.associateRegionForUpdates(n, self.v1, [h.position])
        with pytest.raises(rti.RegionNotKnown):  # a region handle names its own federate's region only
            self.s2.rtia.getRegionExtent(self.r1)
        # s1's subscription through r1 is back: unsubscribing it is allowed once (then not subscribed).
        self.s1.rtia.unsubscribeInteractionClassWithRegion(h.radio, self.r1)
        with pytest.raises(rti.InteractionClassNotSubscribed):
            self.s1.rtia.unsubscribeInteractionClassWithRegion(h.radio, self.r1)
        self.s1.rtia.subscribeInteractionClassWithRegion(h.radio, self.r1)
        barrier(self.s1.rtia)
        # A new region gets a number no region of this federate had.
        new = self.p.rtia.createRegion(h.geo, [])
        assert new not in (self.u, n)
        self.p.rtia.deleteRegion(new)


SAVED = (["radio saved", "reflect saved"], [])  # s1 in scope, s2 not


def test_restore_brings_back_regions_subscriptions_and_associations(gateway_address: str) -> None:
    creator = rti.RTIAmbassador(gateway_address)
    creator.createFederationExecution("DdmFed", DDM_FED)
    feds = [Fed(gateway_address, name) for name in ("p", "s1", "s2")]
    try:
        world = World(*feds)
        assert world.send_round("saved") == SAVED
        save("snap", feds)
        n = world.change_everything()
        # The changes apply: v1's position is now updated in n (X 26-27), in r2 only; s2 discovers v1.
        s1_got, s2_got = world.send_round("changed")
        assert s1_got == []
        assert s2_got == ["discover v1", "radio changed", "reflect changed"]
        restore("snap", feds)
        world.check_saved_regions(n)
        # Delivery follows the saved regions again; s2 does not know v1 (it had not discovered it then).
        assert world.send_round("saved") == SAVED
        assert [args[2] for args in feds[2].named("discoverObjectInstance")] == []
    finally:
        for f in feds:
            f.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        creator.destroyFederationExecution("DdmFed")


def peer_events_until_marker(peer: Child) -> list[dict[str, Any]]:
    """What the peer printed up to (not including) the next broadcast marker."""
    events = []
    while (event := peer_says(peer)) != {"event": "marker"}:
        events.append(event)
    return events


def round_from_p(p: Fed, s1: Fed, v1: Any, u: Any, tag: str) -> list[str]:
    """p updates v1 and sends radio in u, then the marker; returns what s1 got of the first two."""
    h = p.h
    s1.forget()
    p.rtia.updateAttributeValues(v1, {h.position: tag.encode()}, tag)
    p.rtia.sendInteractionWithRegion(h.radio, {h.text: tag.encode()}, u, tag)
    p.rtia.sendInteraction(h.broadcast, {h.broadcast_text: b"marker"}, "marker")
    tick_all(lambda: any(args[0] == h.broadcast for args in s1.named("receiveInteraction")), [p, s1])
    return sorted([f"reflect {args[2]}" for args in s1.named("reflectAttributeValues")]
                  + [f"radio {args[2]}" for args in s1.named("receiveInteraction") if args[0] == h.radio])


def test_regions_come_back_after_rtig_restarts_on_its_save_dir(tmp_path: pathlib.Path) -> None:
    """p and s1 in this process, s2 in its own (a new one after the restart, whose region numbers would
    start at 1 again): the file carries every federate's regions, subscriptions and associations."""
    save_dir = tmp_path / "saves"
    with running_rtig(tmp_path, "--save-dir", str(save_dir)) as server:
        creator = rti.RTIAmbassador(server.address)
        creator.createFederationExecution("DdmFed", DDM_FED)
        peer = python_subprocess("ddm_save_peer.py", server.address, "first")
        try:
            assert peer_says(peer) == {"ready": True, "region": 1}
            p, s1 = Fed(server.address, "p"), Fed(server.address, "s1")
            h = p.h
            r1 = World.subscribe_in(s1, (0, 10))
            p.rtia.publishObjectClass(h.vehicle, [h.position])
            p.rtia.publishInteractionClass(h.radio)
            p.rtia.publishInteractionClass(h.broadcast)
            u = p.rtia.createRegion(h.geo, [(h.x, (5, 5))])
            v1 = p.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, u)], "v1")
            assert round_from_p(p, s1, v1, u, "saved") == ["radio saved", "reflect saved"]
            assert peer_events_until_marker(peer) == []
            p.rtia.requestFederationSave("snap")
            tick_all(lambda: bool(p.named("initiateFederateSave") and s1.named("initiateFederateSave")), [p, s1])
            p.rtia.federateSaveComplete()
            s1.rtia.federateSaveComplete()
            tick_all(lambda: bool(p.named("federationSaved") and s1.named("federationSaved")), [p, s1])
            assert peer_says(peer) == {"event": "initiateFederateSave", "label": "snap"}
            assert peer_says(peer) == {"event": "federationSaved"}
            # After the save s1 deletes r1, p moves u into s2's range and updates v1 in a new region n.
            s1.rtia.unsubscribeObjectClassWithRegion(h.vehicle, r1)
            s1.rtia.unsubscribeInteractionClassWithRegion(h.radio, r1)
            s1.rtia.deleteRegion(r1)
            barrier(s1.rtia)
            p.rtia.notifyAboutRegionModification(u, [(h.x, (25, 25))])
            n = p.rtia.createRegion(h.geo, [(h.x, (26, 27))])
            p.rtia.associateRegionForUpdates(n, v1, [h.position])
            assert round_from_p(p, s1, v1, u, "changed") == []
            assert peer_events_until_marker(peer) == [
                {"event": "discover", "name": "v1"}, {"event": "reflect", "tag": "changed"},
                {"event": "radio", "text": "changed"}]
        finally:
            peer.close()
    [saved] = list(save_dir.iterdir())

    with running_rtig(tmp_path, "--save-dir", str(save_dir)) as server:
        creator = rti.RTIAmbassador(server.address)
        creator.createFederationExecution("DdmFed", DDM_FED)
        peer = python_subprocess("ddm_save_peer.py", server.address, "restart")
        try:
            assert peer_says(peer) == {"ready": True}
            p, s1 = Fed(server.address, "p"), Fed(server.address, "s1")
            restore("snap", [p, s1])
            assert peer_says(peer) == {"event": "initiateFederateRestore", "label": "snap"}
            # s2's restored region is number 1 in its new process: the next one is numbered above it.
            # getRegions() gives the new process handles for its restored regions.
            assert peer_says(peer) == {"event": "federationRestored", "new_region": 2, "restored": [1], "x": [20, 30]}
            # The handles kept from before the restart name the saved regions in the new ambassadors.
            assert s1.rtia.getRegionExtent(r1) == (h.geo, [(h.x, (0, 10)), (h.y, FULL)])
            assert p.rtia.getRegionExtent(u) == (h.geo, [(h.x, (5, 5)), (h.y, FULL)])
            with pytest.raises(rti.RegionInUse):
                p.rtia.deleteRegion(u)
            with pytest.raises(rti.RegionNotKnown):
                p.rtia.getRegionExtent(n)
            assert round_from_p(p, s1, v1, u, "saved") == ["radio saved", "reflect saved"]
            assert peer_events_until_marker(peer) == []

            # A version 1 file (before DDM was saved) and a region in an undefined space are refused.
            data = saved.read_bytes()
            (save_dir / "DdmFed--old.hlasave").write_bytes(data[:8] + struct.pack("<I", 1) + data[12:])
            u_record = struct.pack("<6I", int(h.geo), 4, 5, 5, 0, rti.MAX_EXTENT)
            assert data.count(u_record) == 1
            (save_dir / "DdmFed--space.hlasave").write_bytes(
                data.replace(u_record, struct.pack("<6I", 99, 4, 5, 5, 0, rti.MAX_EXTENT)))
            reasons = {}
            for label in ("old", "space"):
                p.forget()
                p.rtia.requestFederationRestore(label)
                tick_all(lambda: bool(p.named("requestFederationRestoreFailed")), [p])
                [(got, reasons[label])] = p.named("requestFederationRestoreFailed")
            assert "save format version 1 (this gateway reads versions 2 to 4)" in reasons["old"]
            assert "routing space handle 99 is not defined" in reasons["space"]
            # Nothing changed: delivery still follows the restored regions.
            assert round_from_p(p, s1, v1, u, "still") == ["radio still", "reflect still"]
            assert peer_events_until_marker(peer) == []
        finally:
            peer.close()


def advisories(fed: Fed) -> list[tuple[str, set]]:
    names = ("attributesInScope", "attributesOutOfScope", "turnUpdatesOnForObjectInstance",
             "turnUpdatesOffForObjectInstance")
    return [(name, set(args[1])) for name, args in fed.amb.calls if name in names]


def test_scope_and_relevance_already_announced_are_part_of_the_save(gateway_address: str) -> None:
    """s1 (scope switch on) was told v1's position is in scope and p (relevance switch on) to turn its
    updates on when the save was made; after the changes and the restore neither hears it again, and the
    next change is announced relative to the save."""
    creator = rti.RTIAmbassador(gateway_address)
    creator.createFederationExecution("DdmFed", DDM_FED)
    feds = [Fed(gateway_address, name) for name in ("p", "s1", "s2")]
    p, s1, s2 = feds
    try:
        p.rtia.enableAttributeRelevanceAdvisorySwitch()
        s1.rtia.enableAttributeScopeAdvisorySwitch()
        barrier(p.rtia)
        barrier(s1.rtia)
        world = World(p, s1, s2)
        h = p.h
        tick_all(lambda: bool(advisories(s1) and advisories(p)), feds)
        assert advisories(s1) == [("attributesInScope", {h.position})]
        assert advisories(p) == [("turnUpdatesOnForObjectInstance", {h.position})]
        save("snap", feds)
        for f in feds:
            f.forget()
        p.rtia.notifyAboutRegionModification(world.u, [(h.x, (500, 500))])  # out of r1 and r2
        tick_all(lambda: bool(advisories(s1) and advisories(p)), feds)
        assert advisories(s1) == [("attributesOutOfScope", {h.position})]
        assert advisories(p) == [("turnUpdatesOffForObjectInstance", {h.position})]
        for f in feds:
            f.forget()
        restore("snap", feds)
        for f in feds:
            barrier(f.rtia)
        settle(*(f.rtia for f in feds))
        assert advisories(s1) == [] and advisories(p) == []
        p.rtia.notifyAboutRegionModification(world.u, [(h.x, (500, 500))])
        tick_all(lambda: bool(advisories(s1) and advisories(p)), feds)
        settle(*(f.rtia for f in feds))
        assert advisories(s1) == [("attributesOutOfScope", {h.position})]
        assert advisories(p) == [("turnUpdatesOffForObjectInstance", {h.position})]
    finally:
        for f in feds:
            f.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        creator.destroyFederationExecution("DdmFed")


def test_region_services_refused_during_a_save_or_a_restore(gateway_address: str) -> None:
    """Registering with regions and sending with a region cross the snapshot like their plain forms
    (SaveInProgress, RestoreInProgress); changing regions, associations or region subscriptions is refused
    during a restore, whose regions replace this federate's (RestoreInProgress), and allowed again after."""
    creator = rti.RTIAmbassador(gateway_address)
    creator.createFederationExecution("DdmFed", DDM_FED)
    feds = [Fed(gateway_address, name) for name in ("p", "s1", "s2")]
    p = feds[0]
    h = p.h
    try:
        world = World(*feds)
        p.rtia.requestFederationSave("snap")
        tick_all(lambda: bool(p.named("initiateFederateSave")), [p])
        with pytest.raises(rti.SaveInProgress):
            p.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, world.u)], "v2")
        with pytest.raises(rti.SaveInProgress):
            p.rtia.sendInteractionWithRegion(h.radio, {h.text: b"x"}, world.u, "x")
        tick_all(lambda: all(f.named("initiateFederateSave") for f in feds), feds)
        for f in feds:
            f.rtia.federateSaveComplete()
        tick_all(lambda: all(f.named("federationSaved") for f in feds), feds)

        p.rtia.requestFederationRestore("snap")
        tick_all(lambda: bool(p.named("initiateFederateRestore")), [p])
        refused = [
            lambda: p.rtia.createRegion(h.geo, []),
            lambda: p.rtia.notifyAboutRegionModification(world.u, [(h.x, (1, 1))]),
            lambda: p.rtia.deleteRegion(world.u),
            lambda: p.rtia.associateRegionForUpdates(world.u, world.v1, [h.position]),
            lambda: p.rtia.unassociateRegionForUpdates(world.u, world.v1),
            lambda: p.rtia.subscribeObjectClassAttributesWithRegion(h.vehicle, world.u, [h.position]),
            lambda: p.rtia.unsubscribeObjectClassWithRegion(h.vehicle, world.u),
            lambda: p.rtia.subscribeInteractionClassWithRegion(h.radio, world.u),
            lambda: p.rtia.unsubscribeInteractionClassWithRegion(h.radio, world.u),
            lambda: p.rtia.registerObjectInstanceWithRegion(h.vehicle, [(h.position, world.u)], "v2"),
            lambda: p.rtia.sendInteractionWithRegion(h.radio, {h.text: b"x"}, world.u, "x"),
        ]
        for service in refused:
            with pytest.raises(rti.RestoreInProgress):
                service()
        assert p.rtia.getRegionExtent(world.u) == (h.geo, [(h.x, (5, 5)), (h.y, FULL)])  # queries answer
        for f in feds:
            tick_all(lambda f=f: bool(f.named("initiateFederateRestore")), [f])
            f.rtia.federateRestoreComplete()
        tick_all(lambda: all(f.named("federationRestored") for f in feds), feds)
        p.rtia.deleteRegion(p.rtia.createRegion(h.geo, []))
        assert world.send_round("after") == (["radio after", "reflect after"], [])
    finally:
        for f in feds:
            f.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        creator.destroyFederationExecution("DdmFed")
