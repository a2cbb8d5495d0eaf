"""Synchronization points: registration, announcement, achievement, late joiners and resigning members."""

import pytest

import hlacore.rti as rti

from support import barrier, settle, tick_until


def test_whole_federation_point(federation):
    """Registered for everyone: announced to all, synchronized once all achieved."""
    a, b = federation("a"), federation("b")
    a.rtia.registerFederationSynchronizationPoint("ready", "tag!")
    tick_until(lambda: a.amb.named("announceSynchronizationPoint") and b.amb.named("announceSynchronizationPoint"),
               a.rtia, b.rtia)
    assert a.amb.named("synchronizationPointRegistrationSucceeded") == [("ready",)]
    assert b.amb.named("announceSynchronizationPoint") == [("ready", "tag!")]
    a.rtia.synchronizationPointAchieved("ready")
    settle(a.rtia, b.rtia)
    assert not a.amb.named("federationSynchronized")
    b.rtia.synchronizationPointAchieved("ready")
    tick_until(lambda: a.amb.named("federationSynchronized") and b.amb.named("federationSynchronized"),
               a.rtia, b.rtia)


def test_duplicate_label_fails_registration(federation):
    """A label already pending gives synchronizationPointRegistrationFailed."""
    a, b = federation("a"), federation("b")
    a.rtia.registerFederationSynchronizationPoint("p", "")
    barrier(a.rtia)
    b.rtia.registerFederationSynchronizationPoint("p", "")
    tick_until(lambda: b.amb.named("synchronizationPointRegistrationFailed"), b.rtia)
    assert not b.amb.named("synchronizationPointRegistrationSucceeded")


def test_explicit_federate_set(federation):
    """With a federate set, only those federates are announced and awaited."""
    a, b, c = federation("a"), federation("b"), federation("c")
    a.rtia.registerFederationSynchronizationPoint("pair", "", [a.handle, b.handle])
    tick_until(lambda: b.amb.named("announceSynchronizationPoint"), a.rtia, b.rtia)
    a.rtia.synchronizationPointAchieved("pair")
    b.rtia.synchronizationPointAchieved("pair")
    tick_until(lambda: a.amb.named("federationSynchronized") and b.amb.named("federationSynchronized"),
               a.rtia, b.rtia)
    settle(c.rtia)
    assert not c.amb.calls
    with pytest.raises(rti.SynchronizationPointLabelWasNotAnnounced):
        c.rtia.synchronizationPointAchieved("pair")


def test_achieving_an_unannounced_label_raises(federation):
    """synchronizationPointAchieved for a label never announced raises the typed exception."""
    a = federation("a")
    with pytest.raises(rti.SynchronizationPointLabelWasNotAnnounced):
        a.rtia.synchronizationPointAchieved("never")


def test_late_joiner_is_announced_and_awaited(federation):
    """A federate joining while a whole-federation point is pending is announced it and must achieve it."""
    a, b = federation("a"), federation("b")
    a.rtia.registerFederationSynchronizationPoint("start", "")
    tick_until(lambda: a.amb.named("announceSynchronizationPoint"), a.rtia)
    a.rtia.synchronizationPointAchieved("start")
    late = federation("late")
    tick_until(lambda: late.amb.named("announceSynchronizationPoint"), late.rtia)
    tick_until(lambda: b.amb.named("announceSynchronizationPoint"), b.rtia)
    b.rtia.synchronizationPointAchieved("start")
    settle(a.rtia, b.rtia)
    assert not a.amb.named("federationSynchronized")
    late.rtia.synchronizationPointAchieved("start")
    tick_until(lambda: all(f.amb.named("federationSynchronized") for f in (a, b, late)), a.rtia, b.rtia, late.rtia)


def test_resigning_member_no_longer_holds_the_point(federation):
    """When the last member that has not achieved resigns, the others are synchronized."""
    a, b = federation("a"), federation("b")
    a.rtia.registerFederationSynchronizationPoint("p", "")
    tick_until(lambda: b.amb.named("announceSynchronizationPoint"), a.rtia, b.rtia)
    a.rtia.synchronizationPointAchieved("p")
    b.rtia.resignFederationExecution(rti.ResignAction.NoAction)
    tick_until(lambda: a.amb.named("federationSynchronized"), a.rtia)
