"""Federation save and restore (HLA 1.3 §4.11-4.22): the state machine and its exceptions, what the
gateway and the clients get back on restore (objects, owners, times, queued timestamped messages), timed
saves, save files, restoring after `rtig` was restarted, and unusable saves. Contract: docs/save-restore.md."""

from __future__ import annotations

import pathlib
from typing import Any, Callable, Optional

import hlacore
import hlacore.rti as rti
import hlacore.status
import pytest
from support import (ROBOT_FED, Recorder, joined_federation, peer_says, python_subprocess, running_rtig, settle,
                     tick_until)


class Fed:
    """One joined federate with a Recorder, and the robot class handles."""

    def __init__(self, address: str, name: str) -> None:
        self.name = name
        self.rtia = rti.RTIAmbassador(address)
        self.amb = Recorder()
        self.handle = self.rtia.joinFederationExecution(name, "TestFed", self.amb)
        self.robot = self.rtia.getObjectClassHandle("robot")
        self.location = self.rtia.getAttributeHandle("location", self.robot)
        self.battery = self.rtia.getAttributeHandle("battery", self.robot)

    def named(self, name: str) -> list[tuple[Any, ...]]:
        return self.amb.named(name)

    def enable_time(self, lookahead: float = 1.0) -> None:
        self.rtia.enable_time_management(lookahead, timeout=5.0)


def tick_all(predicate, *feds: Fed, timeout: float = 5.0) -> None:
    tick_until(predicate, *(f.rtia for f in feds), timeout=timeout)


def save(label: str, requester: Fed, *feds: Fed, time: Optional[float] = None) -> None:
    """requestFederationSave, every federate completes its save, all see federationSaved."""
    requester.rtia.requestFederationSave(label, time) if time is not None else requester.rtia.requestFederationSave(label)
    complete_save(label, *feds)


def request_save(label: str, requester: Fed, *feds: Fed) -> None:
    """requester asks for save `label`; returns once every one of feds has been told to save."""
    requester.rtia.requestFederationSave(label)
    tick_all(lambda: all(f.named("initiateFederateSave") for f in feds), *feds)


def complete_save(label: str, *feds: Fed) -> None:
    tick_all(lambda: all(f.named("initiateFederateSave") for f in feds), *feds)
    for f in feds:
        assert f.named("initiateFederateSave") == [(label,)]
        f.rtia.federateSaveBegun()
        f.rtia.federateSaveComplete()
    tick_all(lambda: all(f.named("federationSaved") for f in feds), *feds)


def restore(label: str, requester: Fed, *feds: Fed) -> None:
    """requestFederationRestore, every federate restores, all see federationRestored."""
    requester.rtia.requestFederationRestore(label)
    tick_all(lambda: all(f.named("initiateFederateRestore") for f in feds), *feds)
    assert requester.named("requestFederationRestoreSucceeded") == [(label,)]
    for f in feds:
        assert f.named("federationRestoreBegun") == [()]
        f.rtia.federateRestoreComplete()
    tick_all(lambda: all(f.named("federationRestored") for f in feds), *feds)


def federation_status(address: str) -> dict[str, Any]:
    [fed] = [f for f in hlacore.status.status(address)["federations"] if f["name"] == "TestFed"]
    return dict(fed)


def saved_view(status: dict[str, Any]) -> dict[str, Any]:
    """What a restore must bring back, from a federation's status: objects and owners, and per federate
    its time, lookahead, switches and queued messages (pending requests are not saved)."""
    keep = ("handle", "name", "time", "lookahead", "regulating", "constrained", "queued_tso", "queued_ro")
    return {
        "instances": status["instances"],
        "federates": sorted(({k: f[k] for k in keep} for f in status["federates"]), key=lambda f: f["handle"]),
    }


@pytest.fixture
def testfed(gateway_address: str):
    """Creates TestFed; yields a function joining a Fed; resigns and destroys at the end."""
    with joined_federation(gateway_address, "TestFed", ROBOT_FED, Fed) as join:
        yield join


# ---- the state machine ----


def test_every_federate_saves_then_all_are_told_federation_saved(testfed, gateway_address):
    a, b = testfed("a"), testfed("b")
    request_save("s1", a, a, b)
    b.rtia.federateSaveBegun()
    b.rtia.federateSaveComplete()
    settle(a.rtia, b.rtia)
    assert not a.named("federationSaved") and not b.named("federationSaved")  # a has not saved yet
    assert federation_status(gateway_address)["save_restore"]["state"] == "saving"
    a.rtia.federateSaveComplete()  # federateSaveBegun is optional
    tick_all(lambda: a.named("federationSaved") and b.named("federationSaved"), a, b)
    assert not a.named("federationNotSaved") and not b.named("federationNotSaved")
    status = federation_status(gateway_address)["save_restore"]
    assert status["state"] == "idle" and status["saves"] == ["s1"]


def test_a_federate_that_cannot_save_makes_the_save_fail(testfed, gateway_address):
    a, b = testfed("a"), testfed("b")
    request_save("s2", b, a, b)
    a.rtia.federateSaveComplete()
    b.rtia.federateSaveNotComplete()
    tick_all(lambda: a.named("federationNotSaved") and b.named("federationNotSaved"), a, b)
    assert not a.named("federationSaved")
    assert federation_status(gateway_address)["save_restore"]["saves"] == []
    a.rtia.requestFederationRestore("s2")
    tick_all(lambda: a.named("requestFederationRestoreFailed"), a)
    [(label, reason)] = a.named("requestFederationRestoreFailed")
    assert label == "s2" and "no save labelled 's2'" in reason


def refuses_while_busy(error: type[Exception], a: Fed, obj: Any, *more: Callable[[], object]) -> None:
    """a's client, told of a save or restore, raises `error` itself for each call: a time advance, an update
    of obj, resigning, another save or restore request, then `more`."""
    for call in (
        lambda: a.rtia.timeAdvanceRequest(1.0),
        lambda: a.rtia.updateAttributeValues(obj, {a.location: b"x"}, "t"),
        lambda: a.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes),
        lambda: a.rtia.requestFederationSave("again"),
        lambda: a.rtia.requestFederationRestore("busy"),
        *more,
    ):
        with pytest.raises(error):
            call()


def accepted_once(answer: Callable[[], object], error: type[Exception]) -> None:
    """A federate's answer to a save or restore is taken once; a second has nothing to answer: `error`."""
    answer()
    with pytest.raises(error):
        answer()


def test_services_refused_during_a_save_and_a_restore(testfed, gateway_address):
    a, b = testfed("a"), testfed("b")
    obj_class = a.robot
    a.rtia.publishObjectClass(obj_class, [a.location])
    obj = a.rtia.registerObjectInstance(obj_class, "r1")
    # Before any save: the answers that need one.
    with pytest.raises(rti.SaveNotInitiated):
        a.rtia.federateSaveComplete()
    with pytest.raises(rti.SaveNotInitiated):
        a.rtia.federateSaveBegun()
    with pytest.raises(rti.RestoreNotRequested):
        a.rtia.federateRestoreComplete()

    a.rtia.requestFederationSave("busy")
    # b has not been delivered initiateFederateSave yet: the gateway refuses for it.
    with pytest.raises(rti.SaveInProgress):
        b.rtia.requestFederationSave("other")
    with pytest.raises(rti.SaveInProgress):
        b.rtia.requestFederationRestore("busy")
    with pytest.raises(rti.SaveInProgress):
        b.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
    with pytest.raises(rti.SaveInProgress):
        Fed(gateway_address, "late")
    tick_all(lambda: a.named("initiateFederateSave") and b.named("initiateFederateSave"), a, b)
    # Once told, the client refuses by itself.
    refuses_while_busy(
        rti.SaveInProgress, a, obj,
        lambda: a.rtia.nextEventRequest(1.0),
        lambda: a.rtia.enableTimeRegulation(0.0, 1.0),
        lambda: a.rtia.enableTimeConstrained(),
        lambda: a.rtia.modifyLookahead(2.0),
        lambda: a.rtia.registerObjectInstance(obj_class),
        lambda: a.rtia.deleteObjectInstance(obj, "t"),
    )
    with pytest.raises(rti.RestoreNotRequested):
        a.rtia.federateRestoreComplete()
    accepted_once(a.rtia.federateSaveBegun, rti.SaveNotInitiated)
    accepted_once(a.rtia.federateSaveComplete, rti.SaveNotInitiated)
    b.rtia.federateSaveComplete()
    tick_all(lambda: a.named("federationSaved") and b.named("federationSaved"), a, b)
    # Services work again.
    a.rtia.updateAttributeValues(obj, {a.location: b"x"}, "t")

    # During a restore: RestoreInProgress, from the gateway first, then from the client.
    a.rtia.requestFederationRestore("busy")
    with pytest.raises(rti.RestoreInProgress):
        Fed(gateway_address, "late")
    tick_all(lambda: a.named("initiateFederateRestore") and b.named("initiateFederateRestore"), a, b)
    refuses_while_busy(rti.RestoreInProgress, a, obj)
    with pytest.raises(rti.SaveNotInitiated):
        a.rtia.federateSaveComplete()
    accepted_once(a.rtia.federateRestoreComplete, rti.RestoreNotRequested)
    b.rtia.federateRestoreNotComplete()
    tick_all(lambda: a.named("federationNotRestored") and b.named("federationNotRestored"), a, b)
    assert not a.named("federationRestored")
    a.rtia.timeAdvanceRequest(1.0)  # allowed again
    tick_all(lambda: a.named("timeAdvanceGrant"), a)


# ---- what a restore brings back ----


def test_restore_brings_back_objects_owners_times_and_queued_messages(testfed, gateway_address):
    a, b = testfed("a"), testfed("b")
    for f in (a, b):
        f.enable_time(1.0)
        f.rtia.publishObjectClass(f.robot, [f.location, f.battery])
        f.rtia.subscribeObjectClassAttributes(f.robot, [f.location, f.battery])
    r1 = a.rtia.registerObjectInstance(a.robot, "r1")
    tick_all(lambda: b.named("discoverObjectInstance"), a, b)
    a.rtia.updateAttributeValues(r1, {a.location: b"queued at 3"}, "before", 3.0)
    settle(a.rtia, b.rtia)  # b is not advancing: the message stays queued at the gateway
    assert not b.named("reflectAttributeValues")

    # A save at time 2: both advance there, then save; the message at 3 stays queued for b.
    a.rtia.requestFederationSave("s", 2.0)
    a.rtia.timeAdvanceRequest(2.0)
    b.rtia.timeAdvanceRequest(2.0)
    complete_save("s", a, b)
    before = saved_view(federation_status(gateway_address))
    [b_before] = [f for f in before["federates"] if f["name"] == "b"]
    assert b_before["queued_tso"] == 1 and b_before["time"] == 2.0
    assert not b.named("reflectAttributeValues")
    assert before["instances"] == [
        {"handle": int(r1), "name": "r1", "class": "robot",
         "owners": {"privilegeToDelete": int(a.handle), "battery": int(a.handle), "location": int(a.handle)}}
    ]

    # Change everything: advance (b gets the queued message), a new object, an ownership change,
    # another timestamped message in flight.
    a.rtia.timeAdvanceRequest(5.0)
    b.rtia.timeAdvanceRequest(5.0)
    tick_all(lambda: len(a.named("timeAdvanceGrant")) == 2 and len(b.named("timeAdvanceGrant")) == 2, a, b)
    assert [args[1] for args in b.named("reflectAttributeValues")] == [{b.location: b"queued at 3"}]
    r2 = a.rtia.registerObjectInstance(a.robot, "r2")
    a.rtia.unconditionalAttributeOwnershipDivestiture(r1, [a.battery])
    b.rtia.attributeOwnershipAcquisitionIfAvailable(r1, [b.battery])
    tick_all(lambda: b.named("attributeOwnershipAcquisitionNotification"), a, b)
    a.rtia.updateAttributeValues(r1, {a.location: b"after the save"}, "after", 7.0)
    tick_all(lambda: len(b.named("discoverObjectInstance")) == 2, a, b)
    assert b.rtia.isAttributeOwnedByFederate(r1, b.battery)
    assert saved_view(federation_status(gateway_address)) != before

    for f in (a, b):
        f.amb.calls.clear()
    restore("s", b, a, b)
    # Every federate is told, with the handle it had in the save.
    assert a.named("initiateFederateRestore") == [("s", a.handle)]
    assert b.named("initiateFederateRestore") == [("s", b.handle)]
    assert saved_view(federation_status(gateway_address)) == before
    # The clients' mirrors are the saved ones too.
    for f in (a, b):
        assert f.rtia.queryFederateTime() == 2.0
        assert f.rtia.queryLookahead() == 1.0
    assert a.rtia.isAttributeOwnedByFederate(r1, a.battery)
    assert not b.rtia.isAttributeOwnedByFederate(r1, b.battery)
    with pytest.raises(rti.AttributeNotOwned):
        b.rtia.updateAttributeValues(r1, {b.battery: b"mine?"}, "t", 4.0)
    with pytest.raises(rti.InvalidFederationTime):  # the sending rule is the restored one: time 2 + lookahead 1
        a.rtia.updateAttributeValues(r1, {a.location: b"too early"}, "t", 2.5)
    for f in (a, b):
        with pytest.raises(rti.ObjectNotKnown):
            f.rtia.getObjectInstanceName(r2)
    assert b.rtia.getObjectInstanceHandle("r1") == r1
    with pytest.raises(rti.FederationTimeAlreadyPassed):
        a.rtia.timeAdvanceRequest(1.0)  # the restored time is 2

    # The queued message is delivered again after the restore; the one sent after the save is gone.
    a.rtia.timeAdvanceRequest(8.0)
    b.rtia.timeAdvanceRequest(8.0)
    tick_all(lambda: a.named("timeAdvanceGrant") and b.named("timeAdvanceGrant"), a, b)
    reflected = b.named("reflectAttributeValues")
    assert [(args[1], args[5]) for args in reflected] == [({b.location: b"queued at 3"}, 3.0)]
    assert b.named("timeAdvanceGrant") == [(8.0,)]
    # New objects do not reuse handles given out before the restore.
    r3 = a.rtia.registerObjectInstance(a.robot, "r3")
    assert int(r3) > int(r2)


def test_restore_failures_leave_the_federation_serving(testfed, gateway_address):
    a, b = testfed("a"), testfed("b")
    a.rtia.requestFederationRestore("never saved")
    tick_all(lambda: a.named("requestFederationRestoreFailed"), a)
    [(label, reason)] = a.named("requestFederationRestoreFailed")
    assert label == "never saved" and "no save labelled 'never saved'" in reason
    save("pair", a, a, b)
    c = testfed("c")  # the save was of a and b only
    c.amb.calls.clear()
    a.rtia.requestFederationRestore("pair")
    tick_all(lambda: len(a.named("requestFederationRestoreFailed")) == 2, a)
    reason = a.named("requestFederationRestoreFailed")[1][1]
    assert "federates joined now (a, b, c) are not those of the save (a, b)" in reason
    settle(a.rtia, b.rtia, c.rtia)
    assert not any(f.named("federationRestoreBegun") for f in (a, b, c))
    c.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    restore("pair", a, a, b)


def test_timed_save_happens_at_the_grant_of_the_save_time(testfed, gateway_address):
    a, b, c = testfed("a"), testfed("b"), testfed("c")  # c is not time-managed
    a.enable_time(1.0)
    b.enable_time(1.0)
    a.rtia.timeAdvanceRequest(2.0)
    b.rtia.timeAdvanceRequest(2.0)
    tick_all(lambda: a.named("timeAdvanceGrant") and b.named("timeAdvanceGrant"), a, b)
    with pytest.raises(rti.FederationTimeAlreadyPassed):
        a.rtia.requestFederationSave("too late", 1.5)
    a.rtia.requestFederationSave("at 5", 5.0)
    tick_all(lambda: c.named("initiateFederateSave"), c)  # c at once
    settle(a.rtia, b.rtia)
    assert not a.named("initiateFederateSave") and not b.named("initiateFederateSave")
    status = federation_status(gateway_address)["save_restore"]
    assert status["state"] == "waiting for the save time" and status["told"] == [int(c.handle)]
    a.rtia.timeAdvanceRequest(2.5)
    tick_all(lambda: len(a.named("timeAdvanceGrant")) == 2, a, b)  # below the save time: no save yet
    a.rtia.timeAdvanceRequest(7.0)
    settle(a.rtia, b.rtia)
    assert not a.named("initiateFederateSave")  # a cannot be granted before b moves
    b.rtia.nextEventRequest(5.0)  # NER at the save time counts too
    tick_all(lambda: a.named("initiateFederateSave") and b.named("initiateFederateSave"), a, b)
    # A request beyond the save time is granted the save time, then the federate is told.
    for f, granted in ((a, 5.0), (b, 5.0)):
        names = [n for n, _ in f.amb.calls if n in ("timeAdvanceGrant", "initiateFederateSave")]
        assert names[-2:] == ["timeAdvanceGrant", "initiateFederateSave"]  # the grant comes first
        assert f.named("timeAdvanceGrant")[-1] == (granted,)
        assert f.rtia.queryFederateTime() == granted
    for f in (a, b, c):
        f.rtia.federateSaveComplete()
    tick_all(lambda: all(f.named("federationSaved") for f in (a, b, c)), a, b, c)
    times = {f["name"]: f["time"] for f in federation_status(gateway_address)["federates"]}
    assert times == {"a": 5.0, "b": 5.0, "c": 0.0}

    a.rtia.timeAdvanceRequest(9.0)
    b.rtia.timeAdvanceRequest(9.0)
    tick_all(lambda: a.rtia.queryFederateTime() == 9.0 and b.rtia.queryFederateTime() == 9.0, a, b)
    for f in (a, b, c):
        f.amb.calls.clear()
    restore("at 5", c, a, b, c)
    assert (a.rtia.queryFederateTime(), b.rtia.queryFederateTime()) == (5.0, 5.0)


# ---- save files, rtig restarts, unusable saves ----


def test_save_file_and_restore_after_rtig_restart(tmp_path: pathlib.Path):
    """a (this process) and b (a separate process) save at a time with a message queued for b; rtig is
    stopped, started again on the same --save-dir, a and b join again in the other order, and the
    restore brings back handles, objects, owners, times and the queued message."""
    save_dir = tmp_path / "saves"
    with running_rtig(tmp_path, "--save-dir", str(save_dir)) as server:
        creator = rti.RTIAmbassador(server.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        a = Fed(server.address, "a")
        a.enable_time(1.0)
        a.rtia.publishObjectClass(a.robot, [a.location, a.battery])
        peer = python_subprocess("save_peer.py", server.address)
        try:
            assert peer_says(peer) == {"ready": True, "handle": 2}
            r1 = a.rtia.registerObjectInstance(a.robot, "r1")
            a.rtia.updateAttributeValues(r1, {a.location: b"queued at 3"}, "before", 3.0)
            request_save("snap", a, a)
            a.rtia.federateSaveComplete()
            tick_all(lambda: a.named("federationSaved"), a)
            assert peer_says(peer) == {"event": "initiateFederateSave", "label": "snap"}
            assert peer_says(peer) == {"event": "federationSaved"}
            before = saved_view(federation_status(server.address))
        finally:
            peer.close()
    assert [p.name for p in save_dir.iterdir()] == ["TestFed--snap.hlasave"]
    assert [f["queued_tso"] for f in before["federates"]] == [0, 1]

    with running_rtig(tmp_path, "--save-dir", str(save_dir)) as server:
        creator = rti.RTIAmbassador(server.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        peer = python_subprocess("save_peer.py", server.address)
        try:
            assert peer_says(peer) == {"ready": True, "handle": 1}  # b joins first this time
            a = Fed(server.address, "a")
            assert int(a.handle) == 2
            restore("snap", a, a)
            [(label, handle)] = a.named("initiateFederateRestore")
            assert (label, int(handle)) == ("snap", 1)  # a's handle in the save
            assert int(a.rtia._federate_handle()) == 1
            assert peer_says(peer) == {"event": "initiateFederateRestore", "label": "snap", "handle": 2,
                                       "time": 0.0, "lookahead": 1.0, "knows": ["r1"]}
            assert peer_says(peer) == {"event": "federationRestored"}
            assert saved_view(federation_status(server.address)) == before
            assert a.rtia.isAttributeOwnedByFederate(r1, a.location)
            assert a.rtia.getObjectInstanceName(r1) == "r1"
            # Advancing together delivers the restored queued message to b.
            a.rtia.timeAdvanceRequest(5.0)
            tick_all(lambda: a.named("timeAdvanceGrant"), a, timeout=10)
            assert peer_says(peer) == {"event": "reflect", "time": 3.0, "location": "queued at 3"}
            a.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
            assert peer_says(peer) == {"event": "granted", "time": 5.0}
        finally:
            peer.close()


def test_corrupt_or_missing_save_file_fails_the_restore_and_rtig_keeps_serving(tmp_path: pathlib.Path):
    save_dir = tmp_path / "saves"
    with running_rtig(tmp_path, "--save-dir", str(save_dir)) as server:
        creator = rti.RTIAmbassador(server.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        a, b = Fed(server.address, "a"), Fed(server.address, "b")
        for f in (a, b):
            f.enable_time(1.0)
        a.rtia.publishObjectClass(a.robot, [a.location])
        b.rtia.subscribeObjectClassAttributes(b.robot, [b.location])
        r1 = a.rtia.registerObjectInstance(a.robot, "r1")
        a.rtia.updateAttributeValues(r1, {a.location: b"queued at 3"}, "t", 3.0)  # queued for b
        save("good/../label", a, a, b)
        [written] = list(save_dir.iterdir())
        assert written.name == "TestFed--good%2F..%2Flabel.hlasave"  # no label leaves the directory
        data = written.read_bytes()
        (save_dir / "TestFed--truncated.hlasave").write_bytes(data[: len(data) // 2])
        (save_dir / "TestFed--garbage.hlasave").write_bytes(b"not a save at all")
        (save_dir / "TestFed--version.hlasave").write_bytes(data[:8] + b"\x63\x00\x00\x00" + data[12:])
        # The queued reflection's frame: u32 length, u16 type, u32 object, u32 count, u32 attribute, u32 size,
        # then the value. An unknown type inside it leaves the file's structure intact.
        type_at = data.index(b"queued at 3") - 18
        (save_dir / "TestFed--frame.hlasave").write_bytes(data[:type_at] + b"\xff\xff" + data[type_at + 2 :])
        reasons = {}
        for label in ("missing", "truncated", "garbage", "version", "frame"):
            a.amb.calls.clear()
            a.rtia.requestFederationRestore(label)
            tick_all(lambda: a.named("requestFederationRestoreFailed"), a)
            [(got, reason)] = a.named("requestFederationRestoreFailed")
            assert got == label
            reasons[label] = reason
        assert "cannot open" in reasons["missing"] and "No such file" in reasons["missing"]
        assert "is unusable: " in reasons["truncated"] and reasons["truncated"].endswith(" in the save")
        assert "is unusable: not an hlacore save" in reasons["garbage"]
        assert "save format version 99" in reasons["version"]
        assert "is unusable: unknown message type" in reasons["frame"]
        assert not b.named("federationRestoreBegun")
        a.amb.calls.clear()
        restore("good/../label", a, a, b)  # the good one still restores
        for f in (a, b):
            f.rtia.timeAdvanceRequest(4.0)
        tick_all(lambda: a.named("timeAdvanceGrant") and b.named("timeAdvanceGrant"), a, b)
        assert [args[1] for args in b.named("reflectAttributeValues")] == [{b.location: b"queued at 3"}]
        for f in (a, b):
            f.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        creator.destroyFederationExecution("TestFed")


def test_a_federate_dying_during_a_save_makes_it_fail(tmp_path: pathlib.Path):
    with running_rtig(tmp_path) as server:
        creator = rti.RTIAmbassador(server.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        a = Fed(server.address, "a")
        a.enable_time(1.0)
        peer = python_subprocess("save_peer.py", server.address, "--no-answer")
        try:
            assert peer_says(peer) == {"ready": True, "handle": 2}
            a.rtia.requestFederationSave("doomed")
            tick_all(lambda: a.named("initiateFederateSave"), a)
            a.rtia.federateSaveComplete()
            assert peer_says(peer) == {"event": "initiateFederateSave", "label": "doomed"}
            peer.kill()
            tick_all(lambda: a.named("federationNotSaved"), a)
            assert "saves" in federation_status(server.address)["save_restore"]
            assert federation_status(server.address)["save_restore"]["saves"] == []
            a.rtia.timeAdvanceRequest(1.0)  # the federation goes on without it
            tick_all(lambda: a.named("timeAdvanceGrant"), a)
        finally:
            peer.close()
        a.rtia.resignFederationExecution(rti.ResignAction.NoAction)
        creator.destroyFederationExecution("TestFed")


def test_inprocess_gateway_writes_saves_to_its_save_dir(tmp_path: pathlib.Path):
    with hlacore.Gateway(port=0, save_dir=tmp_path / "gw") as gw:
        creator = rti.RTIAmbassador(gw.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        a = Fed(gw.address, "a")
        save("mem", a, a)
        assert gw.status()["federations"][0]["save_restore"]["save_dir"] == str(tmp_path / "gw")
        a.rtia.resignFederationExecution(rti.ResignAction.NoAction)
        creator.destroyFederationExecution("TestFed")
    assert (tmp_path / "gw" / "TestFed--mem.hlasave").is_file()
    with hlacore.Gateway(port=0, save_dir=tmp_path / "gw") as gw:  # a new gateway on the same directory
        creator = rti.RTIAmbassador(gw.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        a = Fed(gw.address, "a")
        restore("mem", a, a)
        a.rtia.resignFederationExecution(rti.ResignAction.NoAction)
        creator.destroyFederationExecution("TestFed")
        # The same federation name with another FOM: the save does not fit it.
        other_fom = tmp_path / "other.fed"
        other_fom.write_text(pathlib.Path(ROBOT_FED).read_text().replace("(parameter priority)", "(parameter level)"))
        creator.createFederationExecution("TestFed", str(other_fom))
        a = Fed(gw.address, "a")
        a.rtia.requestFederationRestore("mem")
        tick_all(lambda: a.named("requestFederationRestoreFailed"), a)
        [(label, reason)] = a.named("requestFederationRestoreFailed")
        assert label == "mem" and reason.startswith("the save was made with another FOM")
        a.rtia.resignFederationExecution(rti.ResignAction.NoAction)
        creator.destroyFederationExecution("TestFed")


def test_a_save_that_cannot_be_written_is_not_saved(tmp_path: pathlib.Path):
    """A save directory that cannot be created (here a regular file is in the way) fails the save:
    federationNotSaved, and the reason in the status; the federation goes on."""
    blocker = tmp_path / "not a directory"
    blocker.write_text("")
    with hlacore.Gateway(port=0, save_dir=blocker) as gw:
        creator = rti.RTIAmbassador(gw.address)
        creator.createFederationExecution("TestFed", ROBOT_FED)
        a = Fed(gw.address, "a")
        a.rtia.requestFederationSave("lost")
        tick_all(lambda: a.named("initiateFederateSave"), a)
        a.rtia.federateSaveComplete()
        tick_all(lambda: a.named("federationNotSaved"), a)
        status = federation_status(gw.address)["save_restore"]
        assert status["saves"] == [] and status["save_error"].startswith(f"cannot write {blocker}/TestFed--lost")
        a.rtia.publishObjectClass(a.robot, [a.location])
        a.rtia.registerObjectInstance(a.robot, "still serving")
        a.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        creator.destroyFederationExecution("TestFed")


def test_what_is_sent_to_a_saving_federate_waits_and_is_part_of_the_save(testfed, gateway_address):
    """b registers an object while a is already saving (b has not been delivered initiateFederateSave yet):
    a discovers it only after federationSaved, and again after a restore of that save, since a's own
    saved state does not have it."""
    a, b = testfed("a"), testfed("b")
    a.rtia.subscribeObjectClassAttributes(a.robot, [a.location])
    b.rtia.publishObjectClass(b.robot, [b.location])
    request_save("window", a, a)  # b does not tick yet
    b.rtia.registerObjectInstance(b.robot, "during")
    settle(a.rtia)
    assert not a.named("discoverObjectInstance")
    a.rtia.federateSaveComplete()
    complete_save("window", b)
    tick_all(lambda: a.named("discoverObjectInstance"), a)
    order = [n for n, _ in a.amb.calls if n in ("federationSaved", "discoverObjectInstance")]
    assert order == ["federationSaved", "discoverObjectInstance"]

    for f in (a, b):
        f.amb.calls.clear()
    restore("window", a, a, b)
    tick_all(lambda: a.named("discoverObjectInstance"), a)
    order = [n for n, _ in a.amb.calls if n in ("federationRestored", "discoverObjectInstance")]
    assert order == ["federationRestored", "discoverObjectInstance"]
    assert [args[2] for args in a.named("discoverObjectInstance")] == ["during"]
