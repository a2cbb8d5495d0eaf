"""The HLA 1.3 core's callbacks as IEEE 1516-2010 delivers them: an adapter the inner HLA 1.3 ambassador
calls, which calls the user's federate ambassador by the 1516-2010 name with the 1516-2010 arguments (the
shape of OpenRTI's Python module: fixed positional arguments, None where a slot does not apply). A callback
the user's object does not define is not called."""

from __future__ import annotations

from collections import deque
from typing import Any, Callable, Deque, Dict, Optional, Sequence, Set, Tuple

from .. import _core
from . import _enums as e
from ._handles import (AttributeHandle, FederateHandle, InteractionClassHandle, MessageRetractionHandle,
                       ObjectClassHandle, ObjectInstanceHandle, ParameterHandle, wrap_set)

Convert = Callable[["Adapter", Any], Any]


def _tag(tag: Any) -> bytes:
    return tag if isinstance(tag, bytes) else str(tag).encode("utf-8", "surrogateescape")


def _info(retraction: Any) -> Dict[str, Any]:
    """The supplemental information: the producing federate is known from a retraction handle."""
    sender = None if retraction is None else FederateHandle.wrap(_core._federate_handle_of(int(retraction.sendingFederate)))
    return {"hasProducingFederate": sender is not None, "producingFederate": sender or FederateHandle(),
            "hasSentRegions": False, "sentRegions": set()}


# Argument converters: the core's value -> the 1516-2010 one.
_SAME: Convert = lambda a, v: v  # noqa: E731
_OBJ: Convert = lambda a, v: ObjectInstanceHandle.wrap(v)  # noqa: E731
_CLASS: Convert = lambda a, v: ObjectClassHandle.wrap(v)  # noqa: E731
_INTERACTION: Convert = lambda a, v: InteractionClassHandle.wrap(v)  # noqa: E731
_ATTR: Convert = lambda a, v: AttributeHandle.wrap(v)  # noqa: E731
_ATTRS: Convert = lambda a, v: wrap_set(AttributeHandle, v)  # noqa: E731
_FED: Convert = lambda a, v: FederateHandle.wrap(v)  # noqa: E731
_TAG: Convert = lambda a, v: _tag(v)  # noqa: E731
_TIME: Convert = lambda a, v: a.convert_time(v)  # noqa: E731
_RETRACTION: Convert = lambda a, v: MessageRetractionHandle.wrap(v)  # noqa: E731
_INT: Convert = lambda a, v: int(v)  # noqa: E731

# The callbacks that are HLA 1.3's with other handles: HLA 1.3 name -> (the 1516-2010 name, a converter per
# argument kept (the others are dropped), the arguments 1516-2010 adds after them).
_PLAIN: Dict[str, Tuple[str, Sequence[Convert], Tuple[Any, ...]]] = {
    "announceSynchronizationPoint": ("announceSynchronizationPoint", (_SAME, _TAG), ()),
    "federationSynchronized": ("federationSynchronized", (_SAME,), (frozenset(),)),  # no failed set in the core
    "federationSaved": ("federationSaved", (), ()),
    "requestFederationRestoreSucceeded": ("requestFederationRestoreSucceeded", (_SAME,), ()),
    "requestFederationRestoreFailed": ("requestFederationRestoreFailed", (_SAME,), ()),
    "federationRestoreBegun": ("federationRestoreBegun", (), ()),
    "federationRestored": ("federationRestored", (), ()),
    "startRegistrationForObjectClass": ("startRegistrationForObjectClass", (_CLASS,), ()),
    "stopRegistrationForObjectClass": ("stopRegistrationForObjectClass", (_CLASS,), ()),
    "turnInteractionsOn": ("turnInteractionsOn", (_INTERACTION,), ()),
    "turnInteractionsOff": ("turnInteractionsOff", (_INTERACTION,), ()),
    "discoverObjectInstance": ("discoverObjectInstance", (_OBJ, _CLASS, _SAME), ()),
    "objectInstanceNameReservationFailed": ("objectInstanceNameReservationFailed", (_SAME,), ()),
    "provideAttributeValueUpdate": ("provideAttributeValueUpdate", (_OBJ, _ATTRS), (b"",)),
    "attributesInScope": ("attributesInScope", (_OBJ, _ATTRS), ()),
    "attributesOutOfScope": ("attributesOutOfScope", (_OBJ, _ATTRS), ()),
    "turnUpdatesOnForObjectInstance": ("turnUpdatesOnForObjectInstance", (_OBJ, _ATTRS), (None,)),
    "turnUpdatesOffForObjectInstance": ("turnUpdatesOffForObjectInstance", (_OBJ, _ATTRS), ()),
    "requestAttributeOwnershipAssumption": ("requestAttributeOwnershipAssumption", (_OBJ, _ATTRS, _TAG), ()),
    "attributeOwnershipAcquisitionNotification": ("attributeOwnershipAcquisitionNotification", (_OBJ, _ATTRS), (b"",)),
    "attributeOwnershipUnavailable": ("attributeOwnershipUnavailable", (_OBJ, _ATTRS), ()),
    "confirmAttributeOwnershipAcquisitionCancellation": ("confirmAttributeOwnershipAcquisitionCancellation",
                                                         (_OBJ, _ATTRS), ()),
    "reportAttributeTransportationType": ("reportAttributeTransportationType", (_OBJ, _ATTR, _INT), ()),
    "reportInteractionTransportationType": ("reportInteractionTransportationType", (_FED, _INTERACTION, _INT), ()),
    "informAttributeOwnership": ("informAttributeOwnership", (_OBJ, _ATTR, _FED), ()),
    "attributeIsNotOwned": ("attributeIsNotOwned", (_OBJ, _ATTR), ()),
    "attributeOwnedByRTI": ("attributeIsOwnedByRTI", (_OBJ, _ATTR), ()),
    "timeRegulationEnabled": ("timeRegulationEnabled", (_TIME,), ()),
    "timeConstrainedEnabled": ("timeConstrainedEnabled", (_TIME,), ()),
    "timeAdvanceGrant": ("timeAdvanceGrant", (_TIME,), ()),
    "requestRetraction": ("requestRetraction", (_RETRACTION,), ()),
}


class Adapter:
    """The inner ambassador's federate ambassador. ``user`` is the 1516-2010 federate ambassador (any object);
    ``time_out`` turns the core's float time into the federation's time type; ``failure_reason`` says why the
    last save or restore delivered failed; ``local`` holds callbacks the 1516-2010 layer makes itself
    (confirmations, reports), delivered before the core's."""

    def __init__(self, user: Any, time_out: Callable[[float], Any], failure_reason: Callable[[], int]) -> None:
        self.user = user
        self.time_out = time_out
        self.failure_reason = failure_reason
        self.local: Deque[Tuple[str, Tuple[Any, ...]]] = deque()
        self.divesting: Dict[Any, Set[Any]] = {}  # object -> attributes told to confirm their divestiture
        self.sync_sets: Dict[str, bool] = {}      # label -> registered with a federate set
        self.reserved: Set[str] = set()           # object instance names reserved and not used yet
        self.release_asked: Dict[Any, Set[Any]] = {}  # object -> attributes another federate asked for
        self.federate_name = ""

    def convert_time(self, time: float) -> Any:
        """The core's time in the federation's time type."""
        return self.time_out(time)

    def call(self, name: str, *args: Any) -> None:
        """Calls the user's callback `name`, when it has one."""
        method = getattr(self.user, name, None)
        if method is not None:
            method(*args)

    def __getattr__(self, name: str) -> Callable[..., None]:
        if name not in _PLAIN:
            raise AttributeError(name)
        target, converters, extra = _PLAIN[name]
        return lambda *args: self.call(target, *(c(self, v) for c, v in zip(converters, args)), *extra)

    def deliver_local(self) -> bool:
        """Delivers one of the layer's own callbacks; False when there was none."""
        if not self.local:
            return False
        name, args = self.local.popleft()
        self.call(name, *args)
        return True

    def federationNotSaved(self) -> None:
        """With the reason the gateway gave (SaveFailureReason)."""
        self.call("federationNotSaved", self.failure_reason())

    def federationNotRestored(self) -> None:
        """With the reason the gateway gave (RestoreFailureReason)."""
        self.call("federationNotRestored", self.failure_reason())

    def synchronizationPointRegistrationSucceeded(self, label: str) -> None:
        """As 1516-2010's."""
        self.sync_sets.pop(label, None)
        self.call("synchronizationPointRegistrationSucceeded", label)

    def synchronizationPointRegistrationFailed(self, label: str) -> None:
        """With the reason: the core fails a label in use, or a set naming a federate not joined."""
        with_set = self.sync_sets.pop(label, False)
        self.call("synchronizationPointRegistrationFailed", label,
                  e.SYNCHRONIZATION_SET_MEMBER_NOT_JOINED if with_set else e.SYNCHRONIZATION_POINT_LABEL_NOT_UNIQUE)

    def objectInstanceNameReservationSucceeded(self, name: str) -> None:
        """The name is this federate's to register an object with."""
        self.reserved.add(name)
        self.call("objectInstanceNameReservationSucceeded", name)

    def multipleObjectInstanceNameReservationSucceeded(self, names: Tuple[str, ...]) -> None:
        """The names are this federate's, a set."""
        self.reserved.update(names)
        self.call("multipleObjectInstanceNameReservationSucceeded", set(names))

    def multipleObjectInstanceNameReservationFailed(self, names: Tuple[str, ...]) -> None:
        """None of the names was reserved, a set."""
        self.call("multipleObjectInstanceNameReservationFailed", set(names))

    def initiateFederateSave(self, label: str, time: Optional[float] = None) -> None:
        """With the save's time when it has one."""
        self.call("initiateFederateSave", label, *(() if time is None else (self.time_out(time),)))

    def initiateFederateRestore(self, label: str, federate: Any) -> None:
        """With the federate's name, which the restore keeps."""
        self.call("initiateFederateRestore", label, self.federate_name, FederateHandle.wrap(federate))

    def _timed(self, time: Optional[float], order: Any, retraction: Any) -> Tuple[Any, Any, Any]:
        if time is None:
            return None, None, None
        handle = None if retraction is None else MessageRetractionHandle.wrap(retraction)
        return self.time_out(time), int(order), handle

    def reflectAttributeValues(self, obj: Any, attributes: Dict[Any, bytes], tag: Any, order: Any, transport: Any,
                               time: Optional[float] = None, retraction: Any = None) -> None:
        """Nine arguments: object, values, tag, sent order, transportation, time, received order, retraction
        handle, supplemental information."""
        values = {AttributeHandle.wrap(a): v for a, v in attributes.items()}
        self.call("reflectAttributeValues", ObjectInstanceHandle.wrap(obj), values, _tag(tag), int(order),
                  int(transport), *self._timed(time, order, retraction), _info(retraction))

    def receiveInteraction(self, interaction_class: Any, parameters: Dict[Any, bytes], tag: Any, order: Any,
                           transport: Any, time: Optional[float] = None, retraction: Any = None) -> None:
        """Nine arguments, as reflectAttributeValues's."""
        values = {ParameterHandle.wrap(p): v for p, v in parameters.items()}
        self.call("receiveInteraction", InteractionClassHandle.wrap(interaction_class), values, _tag(tag),
                  int(order), int(transport), *self._timed(time, order, retraction), _info(retraction))

    def removeObjectInstance(self, obj: Any, tag: Any, time: Optional[float] = None, retraction: Any = None) -> None:
        """Seven arguments: object, tag, sent order, time, received order, retraction handle, information."""
        order = e.RECEIVE if time is None else e.TIMESTAMP
        info = _info(retraction)
        del info["hasSentRegions"], info["sentRegions"]
        self.call("removeObjectInstance", ObjectInstanceHandle.wrap(obj), _tag(tag), order,
                  *self._timed(time, order, retraction), info)

    def requestAttributeOwnershipRelease(self, obj: Any, attributes: Any, tag: Any) -> None:
        """As 1516-2010's; attributeOwnershipDivestitureIfWanted gives what was asked for."""
        self.release_asked.setdefault(obj, set()).update(attributes)
        self.call("requestAttributeOwnershipRelease", ObjectInstanceHandle.wrap(obj), wrap_set(AttributeHandle, attributes),
                  _tag(tag))

    def attributeOwnershipDivestitureNotification(self, obj: Any, attributes: Any) -> None:
        """requestDivestitureConfirmation: the core has already given the attributes to the acquirer (HLA
        1.3's negotiated divestiture); confirmDivestiture checks that the federate was asked."""
        self.divesting.setdefault(obj, set()).update(attributes)
        self.call("requestDivestitureConfirmation", ObjectInstanceHandle.wrap(obj), wrap_set(AttributeHandle, attributes))
