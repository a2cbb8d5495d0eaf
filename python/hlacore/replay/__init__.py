"""Replaying federates from a recording (docs/record-replay.md): ``python -m hlacore.replay FILE --as NAME``.

A replayed federate joins under its recorded name and does again what it did in the recording, in the same
order: its declarations, time management (the same lookahead, the same requests with the same times),
registrations under the same names, and every update, interaction and deletion with its recorded values,
tags and timestamps. Before each request it waits, as the recorded federate did, until it has received the
callbacks it had received by then that a federate waits for (grants, enabled regulation or constraint,
synchronization points, registration advice, saves and restores), so the live federates run against it as
they ran against the original. Handles are matched by name: the FOM comes from the recording.

- :func:`script` — what one federate of a recording did, as :class:`Step` s;
- :class:`Replayer` — plays a script back against a gateway;
- :mod:`.diff` — the first divergence between two recordings (``python -m hlacore.replay diff A B``).
"""

from __future__ import annotations

import collections
import os
import tempfile
import time
from dataclasses import dataclass
from typing import Any, Callable, Iterable, Optional

from hlacore import fed as fedfile
from hlacore import rti
from hlacore.recording import Event, decode_text

__all__ = ["ReplayError", "Step", "Script", "script", "Replayer", "WAITED_CALLBACKS"]

#: The callbacks a replayed federate waits for (the wire message's name -> the callbacks that count as it).
WAITED_CALLBACKS: dict[str, tuple[str, ...]] = {
    "TimeAdvanceGrant": ("timeAdvanceGrant",),
    "TimeRegulationEnabled": ("timeRegulationEnabled",),
    "TimeConstrainedEnabled": ("timeConstrainedEnabled",),
    "AnnounceSyncPoint": ("announceSynchronizationPoint",),
    "FederationSynchronized": ("federationSynchronized",),
    "StartRegistration": ("startRegistrationForObjectClass",),
    "InitiateFederateSave": ("initiateFederateSave",),
    "FederationSaved": ("federationSaved", "federationNotSaved"),
    "InitiateFederateRestore": ("initiateFederateRestore",),
    "FederationRestored": ("federationRestored", "federationNotRestored"),
}

# The requests a replay makes again, by wire message (what the recording's requests topic holds). Anything
# else in a replayed federate's recording is refused before joining (ReplayError), never skipped.
_ADVANCES = {1: "timeAdvanceRequest", 2: "timeAdvanceRequestAvailable", 3: "nextEventRequest",
             4: "nextEventRequestAvailable", 5: "flushQueueRequest"}
_SWITCHES = {1: "ClassRelevanceAdvisorySwitch", 2: "AttributeRelevanceAdvisorySwitch",
             3: "AttributeScopeAdvisorySwitch", 4: "InteractionRelevanceAdvisorySwitch"}
_REPLAYED_REQUESTS = {
    "PublishObjectClass", "UnpublishObjectClass", "SubscribeObjectClass", "UnsubscribeObjectClass",
    "PublishInteractionClass", "UnpublishInteractionClass", "SubscribeInteractionClass",
    "UnsubscribeInteractionClass", "EnableTimeRegulation", "DisableTimeRegulation", "EnableTimeConstrained",
    "DisableTimeConstrained", "TimeAdvance", "ModifyLookahead", "SetAsynchronousDelivery", "RegisterSyncPoint",
    "SyncPointAchieved", "FederateSaveComplete", "FederateRestoreComplete", "ResignFederation",
    "SetAdvisorySwitch", "LocalDeleteObject",
}


class ReplayError(Exception):
    """A recording that cannot be replayed as asked, or a replay that went differently from it."""


@dataclass(frozen=True)
class Step:
    """One thing the federate did, and the callbacks it had received before it."""

    event: Event
    waits: dict[str, int]
    """Per wire callback name (a key of :data:`WAITED_CALLBACKS`): how many it had received by then."""


@dataclass
class Script:
    """What one federate of a recording did."""

    federate: str
    federation: str
    fed_name: str
    fed_text: str
    steps: list[Step]
    resigned: bool = False


def script(events: Iterable[Event], federate: str, federation: Optional[str] = None) -> Script:
    """The steps of ``federate`` in the recorded ``events`` (of ``federation``: needed only when the recording
    holds several federations with a federate of that name)."""
    created: dict[str, Event] = {}
    joined: set[str] = set()
    by_federation: dict[str, list[Event]] = collections.defaultdict(list)
    names: dict[str, dict[int, str]] = collections.defaultdict(dict)
    for event in events:
        if event.kind == "created":
            created[event.federation] = event
        elif event.kind == "joined":
            names[event.federation][int(event.data["handle"])] = str(event.data["federate"])
            if event.federate == federate:
                joined.add(event.federation)
        if event.federate == federate and (federation is None or event.federation == federation):
            by_federation[event.federation].append(event)
    candidates = sorted(joined if federation is None else joined & {federation})
    if not candidates:
        known = sorted({name for fed in names.values() for name in fed.values()})
        raise ReplayError(f"no federate named {federate!r} joined "
                          f"{'a federation' if federation is None else repr(federation)} in the recording "
                          f"(it has {', '.join(map(repr, known)) or 'none'})")
    if len(candidates) > 1:
        raise ReplayError(f"federate {federate!r} joined several federations in the recording "
                          f"({', '.join(candidates)}): name one with --federation")
    chosen = candidates[0]
    if chosen not in created:
        raise ReplayError(f"the recording does not hold the creation of federation {chosen!r} (its FOM): it "
                          f"was started after the federation was created")
    # Requests the gateway refused (an exception at the call): not made again.
    refused = {int(e.data["fields"]["request"]) for e in by_federation[chosen] if e.kind == "refusal"}
    counts: collections.Counter[str] = collections.Counter()
    steps: list[Step] = []
    resigned = False
    for event in by_federation[chosen]:
        if event.kind == "request" and int(event.data["fields"].get("request", 0)) in refused:
            continue
        kind = event.kind
        if kind == "callback" or kind == "grant":
            name = "TimeAdvanceGrant" if kind == "grant" else str(event.message)
            if name in WAITED_CALLBACKS:
                counts[name] += 1
            continue
        if kind in ("joined", "dropped", "refusal"):
            continue
        if kind == "request":
            if event.message not in _REPLAYED_REQUESTS:
                raise ReplayError(f"{federate!r} made a {event.message} request (recording sequence "
                                  f"{event.sequence}), which replay does not support yet")
            if event.message == "RegisterSyncPoint" and not event.data["fields"]["whole_federation"]:
                raise ReplayError(f"{federate!r} registered a synchronization point for a set of federates "
                                  f"(recording sequence {event.sequence}), which replay does not support yet")
            resigned |= event.message == "ResignFederation"
        steps.append(Step(event, dict(counts)))
    created_event = created[chosen]
    return Script(federate, chosen, str(created_event.data["fed_name"]), str(created_event.data["fed_text"]),
                  steps, resigned)


class _Counter(rti.FederateAmbassador):
    """Counts the callbacks the replayed federate receives."""

    def __init__(self) -> None:
        self.received: collections.Counter[str] = collections.Counter()

    def __getattr__(self, name: str) -> Callable[..., None]:
        if name.startswith("_"):
            raise AttributeError(name)

        def count(*args: Any) -> None:
            self.received[name] += 1

        return count


class Replayer:
    """Plays ``script`` back as a federate joined through the gateway at ``address`` (None: the default one,
    as :class:`hlacore.rti.RTIAmbassador` finds it).

    ``speed``: replay on the wall clock, each step no earlier than its recorded distance from the first
    divided by ``speed`` (for federations without time management); None goes as fast as the callbacks come.
    ``timeout``: seconds to wait for one expected callback before :class:`ReplayError`.
    """

    def __init__(self, script: Script, address: Optional[str] = None, speed: Optional[float] = None,
                 timeout: float = 60.0, federation: Optional[str] = None) -> None:
        if speed is not None and not speed > 0:
            raise ValueError(f"speed must be > 0, not {speed}")
        self.script = script
        self.address = address
        self.speed = speed
        self.timeout = timeout
        self.federation = federation or script.federation
        self.fom = fedfile.parse_text(script.fed_text, script.fed_name)
        self.ambassador = _Counter()
        self.rtia: Optional[rti.RTIAmbassador] = None
        self._objects: dict[int, rti.ObjectHandle] = {}
        #: Steps done so far.
        self.done = 0

    def run(self) -> None:
        """Join, do every step, resign (with the recorded action, or the default one if the recorded federate
        never resigned)."""
        rtia = self.rtia = rti.RTIAmbassador(self.address)
        with tempfile.TemporaryDirectory(prefix="hlacore-replay-") as folder:
            fed_path = os.path.join(folder, os.path.basename(self.script.fed_name) or "recorded.fed")
            with open(fed_path, "w", encoding="utf-8") as f:
                f.write(self.script.fed_text)
            rtia.create_or_join(self.script.federate, self.federation, fed_path, self.ambassador)
        try:
            origin = time.monotonic()
            first_ns = self.script.steps[0].event.wall_ns if self.script.steps else 0
            for step in self.script.steps:
                if self.speed is not None:
                    delay = origin + (step.event.wall_ns - first_ns) / 1e9 / self.speed - time.monotonic()
                    if delay > 0:
                        rtia.tick(delay, delay)
                self._wait(step)
                self._do(step.event)
                rtia.tick()
                self.done += 1
            if not self.script.resigned:
                rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        except BaseException:
            # Leave the federation as a federate that vanished would (its objects deleted), then re-raise.
            try:
                rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
            except rti.RTIexception:
                pass
            raise

    def _wait(self, step: Step) -> None:
        assert self.rtia is not None
        deadline = time.monotonic() + self.timeout
        for name, count in step.waits.items():
            while sum(self.ambassador.received[c] for c in WAITED_CALLBACKS[name]) < count:
                if time.monotonic() > deadline:
                    got = sum(self.ambassador.received[c] for c in WAITED_CALLBACKS[name])
                    raise ReplayError(
                        f"replay of {self.script.federate!r}: {self.timeout} s without {name} number {count} (got "
                        f"{got}), which the recorded federate had before its {_describe(step.event)}")
                self.rtia.tick(0.05, 0.05)

    def _object(self, event: Event) -> rti.ObjectHandle:
        assert self.rtia is not None
        handle = self._objects.get(int(event.data["object_handle"]))
        return handle if handle is not None else self.rtia.getObjectInstanceHandle(str(event.data["object"]))

    def _do(self, event: Event) -> None:
        rtia = self.rtia
        assert rtia is not None
        kind = event.kind
        stamp = event.data.get("time")
        if kind in ("register", "update", "delete"):
            cls_name = str(event.class_name)
            if kind == "register":
                cls = rtia.getObjectClassHandle(cls_name)
                self._objects[int(event.data["object_handle"])] = rtia.registerObjectInstance(cls, str(event.data["object"]))
            elif kind == "update":
                cls = rtia.getObjectClassHandle(cls_name)
                values = {rtia.getAttributeHandle(name, cls): value for name, value in event.values().items()}
                rtia.updateAttributeValues(self._object(event), values, event.tag(), stamp)
            else:
                rtia.deleteObjectInstance(self._object(event), event.tag(), stamp)
            return
        if kind == "interaction":
            interaction = rtia.getInteractionClassHandle(str(event.class_name))
            parameters = {rtia.getParameterHandle(name, interaction): value for name, value in event.values().items()}
            rtia.sendInteraction(interaction, parameters, event.tag(), stamp)
            return
        self._request(str(event.message), event.data["fields"])

    def _object_class(self, handle: int) -> tuple[rti.ObjectClassHandle, fedfile.ObjectClass]:
        assert self.rtia is not None
        cls = self.fom.object_class(handle)
        return self.rtia.getObjectClassHandle(cls.qualified_name), cls

    def _interaction_class(self, handle: int) -> rti.InteractionClassHandle:
        assert self.rtia is not None
        return self.rtia.getInteractionClassHandle(self.fom.interaction_class(handle).qualified_name)

    def _attributes(self, cls_handle: rti.ObjectClassHandle, cls: fedfile.ObjectClass,
                    handles: list[int]) -> list[rti.AttributeHandle]:
        assert self.rtia is not None
        return [self.rtia.getAttributeHandle(cls.attribute(h).name, cls_handle) for h in handles]

    def _request(self, name: str, f: dict[str, Any]) -> None:
        rtia = self.rtia
        assert rtia is not None
        if name in ("PublishObjectClass", "SubscribeObjectClass"):
            handle, cls = self._object_class(int(f["object_class"]))
            attributes = self._attributes(handle, cls, f["attributes"])
            if name == "PublishObjectClass":
                rtia.publishObjectClass(handle, attributes)
            else:
                rtia.subscribeObjectClassAttributes(handle, attributes, bool(f["active"]))
        elif name in ("UnpublishObjectClass", "UnsubscribeObjectClass"):
            handle, _ = self._object_class(int(f["object_class"]))
            getattr(rtia, "unpublishObjectClass" if name.startswith("Unpublish") else "unsubscribeObjectClass")(handle)
        elif name == "PublishInteractionClass":
            rtia.publishInteractionClass(self._interaction_class(int(f["interaction_class"])))
        elif name == "SubscribeInteractionClass":
            rtia.subscribeInteractionClass(self._interaction_class(int(f["interaction_class"])), bool(f["active"]))
        elif name in ("UnpublishInteractionClass", "UnsubscribeInteractionClass"):
            method = "unpublishInteractionClass" if name.startswith("Unpublish") else "unsubscribeInteractionClass"
            getattr(rtia, method)(self._interaction_class(int(f["interaction_class"])))
        elif name == "EnableTimeRegulation":
            rtia.enableTimeRegulation(float(f["time"]), float(f["lookahead"]))
        elif name == "EnableTimeConstrained":
            rtia.enableTimeConstrained()
        elif name == "DisableTimeRegulation":
            rtia.disableTimeRegulation()
        elif name == "DisableTimeConstrained":
            rtia.disableTimeConstrained()
        elif name == "TimeAdvance":
            getattr(rtia, _ADVANCES[int(f["kind"])])(float(f["time"]))
        elif name == "ModifyLookahead":
            rtia.modifyLookahead(float(f["lookahead"]))
        elif name == "SetAsynchronousDelivery":
            (rtia.enableAsynchronousDelivery if f["on"] else rtia.disableAsynchronousDelivery)()
        elif name == "RegisterSyncPoint":  # for the whole federation: script() refuses the others
            rtia.registerFederationSynchronizationPoint(decode_text(f["label"]).decode(), decode_text(f["tag"]))
        elif name == "SyncPointAchieved":
            rtia.synchronizationPointAchieved(decode_text(f["label"]).decode())
        elif name == "FederateSaveComplete":
            rtia.federateSaveBegun()  # not a request of its own: the recording has only the outcome
            (rtia.federateSaveComplete if f["success"] else rtia.federateSaveNotComplete)()
        elif name == "FederateRestoreComplete":
            (rtia.federateRestoreComplete if f["success"] else rtia.federateRestoreNotComplete)()
        elif name == "ResignFederation":
            rtia.resignFederationExecution(int(f["action"]))
        elif name == "SetAdvisorySwitch":
            switch = _SWITCHES[int(f["which"])]
            getattr(rtia, ("enable" if f["on"] else "disable") + switch)()
        elif name == "LocalDeleteObject":
            rtia.localDeleteObjectInstance(self._objects[int(f["object"])])
        else:  # script() refuses the others
            raise AssertionError(name)


def _describe(event: Event) -> str:
    if event.kind == "request":
        return f"{event.message} request (recording sequence {event.sequence})"
    what = f"{event.kind} of {event.class_name}"
    if "object" in event.data:
        what += f" {event.data['object']!r}"
    if event.data.get("time") is not None:
        what += f" at time {event.data['time']}"
    return f"{what} (recording sequence {event.sequence})"
