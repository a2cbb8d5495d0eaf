"""The HLA 1.3 RTI ambassador with PyHLA's names and argument order.

A PyHLA federate ports by changing its import line::

    import hlacore.rti as rti            # was: import hla.rti as rti

    class Ambassador(rti.FederateAmbassador):
        def reflectAttributeValues(self, obj, attributes, tag, order, transport, time=None, retraction=None):
            ...

    rtia = rti.RTIAmbassador()           # connects to $HLACORE_RTIG ($CERTI_HOST:$CERTI_TCP_PORT) or 127.0.0.1:60400
    rtia.createFederationExecution("uav", "uav.fed")
    rtia.joinFederationExecution("sender", "uav", Ambassador())
    ...
    rtia.tick(1.0, 1.0)

Every service raises the HLA 1.3 exception named in its docstring (all subclasses of
:class:`RTIexception`); wrong handle types raise :class:`TypeError`. Callbacks are evoked by
:meth:`RTIAmbassador.tick` on the ticking thread; sending calls are safe from any thread.
"""

from __future__ import annotations

import os
import time as _time
from typing import Any, Callable, Dict, Optional, Type

from . import _core, _options
from ._core import (  # noqa: F401  (re-exported handle types)
    AttributeHandle,
    DimensionHandle,
    EventRetractionHandle,
    FederateHandle,
    InteractionClassHandle,
    ObjectClassHandle,
    ObjectHandle,
    OrderingHandle,
    ParameterHandle,
    RegionHandle,
    SpaceHandle,
    TransportationHandle,
)

#: Lowest bound of a region's ranges (data distribution management, docs/ddm.md): ranges are closed,
#: ``MIN_EXTENT <= lower <= upper <= MAX_EXTENT``.
MIN_EXTENT: int = _core.MIN_EXTENT
#: Highest bound of a region's ranges (2**32 - 1).
MAX_EXTENT: int = _core.MAX_EXTENT

DEFAULT_ADDRESS = "127.0.0.1:60400"

from . import exceptions as _exceptions
from .exceptions import *  # noqa: F401,F403  (the HLA 1.3 exceptions, PyHLA exposes them here)

_EXCEPTION_NAMES = list(_exceptions.__all__)
# PyHLA's spellings.
#: PyHLA's spelling of :class:`RTIinternalError`, the same class.
RTIInternalError = _core.RTIinternalError
Exception = _core.RTIexception  # noqa: A001  (hla.rti.Exception was PyHLA's base class)


class ResignAction:
    """Actions for :meth:`RTIAmbassador.resignFederationExecution` (PyHLA's values)."""

    #: Leave the attributes this federate owns unowned (or to a federate waiting to acquire them).
    ReleaseAttributes = 1
    #: Delete the objects this federate may delete (``removeObjectInstance`` at the others).
    DeleteObjects = 2
    #: Both: delete the objects this federate may delete, release its other attributes.
    DeleteObjectsAndReleaseAttributes = 3
    #: Neither: raises :class:`FederateOwnsAttributes` while this federate owns attributes.
    NoAction = 4


class FederateAmbassador:
    """Base class for a federate's callbacks.

    Define the callbacks you need with PyHLA's signatures; a callback you do not define is not called.
    :meth:`RTIAmbassador.tick` delivers them on the ticking thread, and an exception a callback raises
    propagates out of ``tick``. ``hlacore._core.CALLBACKS`` lists their names (declared once, in
    ``cpp/rti/wire/callbacks.hpp``). Labels, tags and names arrive as ``str`` (the bytes sent, decoded as
    UTF-8 with ``surrogateescape``); ``attributes`` is a dict ``{AttributeHandle: bytes}`` in
    ``reflectAttributeValues`` and a tuple of :class:`AttributeHandle` in the other callbacks.

    - synchronization points (HLA 1.3 §4.6-4.10): ``synchronizationPointRegistrationSucceeded(label)``,
      ``synchronizationPointRegistrationFailed(label)``, ``announceSynchronizationPoint(label, tag)``,
      ``federationSynchronized(label)``;
    - save and restore (HLA 1.3 §4.11-4.22, docs/save-restore.md): ``initiateFederateSave(label)``,
      ``federationSaved()``, ``federationNotSaved()``, ``requestFederationRestoreSucceeded(label)``,
      ``requestFederationRestoreFailed(label, reason)``, ``federationRestoreBegun()``,
      ``initiateFederateRestore(label, federateHandle)``, ``federationRestored()``,
      ``federationNotRestored()``;
    - declarations (HLA 1.3 §5): ``startRegistrationForObjectClass(objectClass)``,
      ``stopRegistrationForObjectClass(objectClass)``, ``turnInteractionsOn(interactionClass)``,
      ``turnInteractionsOff(interactionClass)``;
    - objects (HLA 1.3 §6): ``discoverObjectInstance(object, objectClass, name)``,
      ``reflectAttributeValues(object, attributes, tag, order, transport[, time, retraction])``,
      ``receiveInteraction(interactionClass, parameters, tag, order, transport[, time, retraction])``,
      ``removeObjectInstance(object, tag[, time, retraction])``,
      ``provideAttributeValueUpdate(object, attributes)``; with the attribute scope advisory switch on
      (HLA 1.3 §6.13-6.14, docs/ddm.md) ``attributesInScope(object, attributes)`` and
      ``attributesOutOfScope(object, attributes)``; with the attribute relevance advisory switch on,
      ``turnUpdatesOnForObjectInstance(object, attributes)`` and
      ``turnUpdatesOffForObjectInstance(object, attributes)``;
    - ownership (HLA 1.3 §7): ``requestAttributeOwnershipAssumption(object, attributes, tag)``,
      ``attributeOwnershipDivestitureNotification(object, attributes)``,
      ``attributeOwnershipAcquisitionNotification(object, attributes)``,
      ``attributeOwnershipUnavailable(object, attributes)``,
      ``requestAttributeOwnershipRelease(object, attributes, tag)``,
      ``confirmAttributeOwnershipAcquisitionCancellation(object, attributes)``,
      ``informAttributeOwnership(object, attribute, owner)``, ``attributeIsNotOwned(object, attribute)``,
      ``attributeOwnedByRTI(object, attribute)``;
    - time (HLA 1.3 §8): ``timeRegulationEnabled(time)``, ``timeConstrainedEnabled(time)``,
      ``timeAdvanceGrant(time)``, ``requestRetraction(retraction)``.

    .. rubric:: Synchronization points (HLA 1.3 §4.6-4.10)

    .. method:: synchronizationPointRegistrationSucceeded(label: str) -> None

       :meth:`RTIAmbassador.registerFederationSynchronizationPoint` registered ``label``.

    .. method:: synchronizationPointRegistrationFailed(label: str) -> None

       :meth:`RTIAmbassador.registerFederationSynchronizationPoint` did not register ``label``: the label
       is in use, or a federate it names is not joined.

    .. method:: announceSynchronizationPoint(label: str, tag: str) -> None

       A federate registered the synchronization point ``label`` for this federate; answer with
       :meth:`RTIAmbassador.synchronizationPointAchieved` once it is reached.

    .. method:: federationSynchronized(label: str) -> None

       Every federate of the synchronization point ``label`` has achieved it.

    .. rubric:: Save and restore (HLA 1.3 §4.11-4.22, docs/save-restore.md)

    .. method:: initiateFederateSave(label: str) -> None

       Save this federate's state under ``label`` now, then call
       :meth:`RTIAmbassador.federateSaveComplete` (or :meth:`RTIAmbassador.federateSaveNotComplete`).

    .. method:: federationSaved() -> None

       Every federate completed the save.

    .. method:: federationNotSaved() -> None

       The save failed: a federate answered :meth:`RTIAmbassador.federateSaveNotComplete`, or the gateway
       could not write the save file.

    .. method:: requestFederationRestoreSucceeded(label: str) -> None

       This federate's :meth:`RTIAmbassador.requestFederationRestore` is accepted; the restore begins.

    .. method:: requestFederationRestoreFailed(label: str, reason: str) -> None

       This federate's :meth:`RTIAmbassador.requestFederationRestore` is refused, for ``reason``: no save
       has that label, it was made with another FOM, or the federates joined are not those saved.

    .. method:: federationRestoreBegun() -> None

       A restore has begun: the services that would cross it raise :class:`RestoreInProgress` until
       :meth:`federationRestored` or :meth:`federationNotRestored`.

    .. method:: initiateFederateRestore(label: str, federateHandle: FederateHandle) -> None

       Restore this federate's state saved under ``label``; from now on it is the federate
       ``federateHandle`` of the save. Then call :meth:`RTIAmbassador.federateRestoreComplete` (or
       :meth:`RTIAmbassador.federateRestoreNotComplete`).

    .. method:: federationRestored() -> None

       Every federate completed the restore.

    .. method:: federationNotRestored() -> None

       The restore failed: a federate answered :meth:`RTIAmbassador.federateRestoreNotComplete`.

    .. rubric:: Declarations (HLA 1.3 §5)

    .. method:: startRegistrationForObjectClass(objectClass: ObjectClassHandle) -> None

       Some federate subscribes to attributes this federate publishes for ``objectClass``: its instances
       are wanted (class relevance advisory switch, on by default).

    .. method:: stopRegistrationForObjectClass(objectClass: ObjectClassHandle) -> None

       No federate subscribes to what this federate publishes for ``objectClass`` any more.

    .. method:: turnInteractionsOn(interactionClass: InteractionClassHandle) -> None

       Some federate subscribes to ``interactionClass``, which this federate publishes (interaction
       relevance advisory switch, on by default).

    .. method:: turnInteractionsOff(interactionClass: InteractionClassHandle) -> None

       No federate subscribes to ``interactionClass`` any more.

    .. rubric:: Objects (HLA 1.3 §6)

    .. method:: discoverObjectInstance(object: ObjectHandle, objectClass: ObjectClassHandle, name: str) -> None

       A new object of a subscribed class: ``objectClass`` is the subscribed class it is known as here
       (the registered class or its closest subscribed superclass).

    .. method:: reflectAttributeValues(object: ObjectHandle, attributes: dict[AttributeHandle, bytes], \
                tag: str, order: OrderingHandle, transport: TransportationHandle, time: float | None = None, \
                retraction: EventRetractionHandle | None = None) -> None

       New values of subscribed attributes of ``object``, as its owner sent them with
       :meth:`RTIAmbassador.updateAttributeValues`. A timestamp-ordered update also passes ``time`` and
       the ``retraction`` handle of the message.

    .. method:: receiveInteraction(interactionClass: InteractionClassHandle, \
                parameters: dict[ParameterHandle, bytes], tag: str, order: OrderingHandle, \
                transport: TransportationHandle, time: float | None = None, \
                retraction: EventRetractionHandle | None = None) -> None

       An interaction of a subscribed class (:meth:`RTIAmbassador.sendInteraction`); ``time`` and
       ``retraction`` as in :meth:`reflectAttributeValues`.

    .. method:: removeObjectInstance(object: ObjectHandle, tag: str, time: float | None = None, \
                retraction: EventRetractionHandle | None = None) -> None

       ``object`` was deleted (:meth:`RTIAmbassador.deleteObjectInstance`, or its owner resigned with
       :attr:`ResignAction.DeleteObjects`); ``time`` and ``retraction`` as in
       :meth:`reflectAttributeValues`.

    .. method:: provideAttributeValueUpdate(object: ObjectHandle, attributes: tuple[AttributeHandle, ...]) -> None

       A federate asked for the current values of ``attributes`` of ``object``, which this federate owns
       (:meth:`RTIAmbassador.requestObjectAttributeValueUpdate` and the like): send them with
       :meth:`RTIAmbassador.updateAttributeValues`.

    .. method:: attributesInScope(object: ObjectHandle, attributes: tuple[AttributeHandle, ...]) -> None

       ``attributes`` of ``object`` came into scope (attribute scope advisory switch,
       :meth:`RTIAmbassador.enableAttributeScopeAdvisorySwitch`).

    .. method:: attributesOutOfScope(object: ObjectHandle, attributes: tuple[AttributeHandle, ...]) -> None

       ``attributes`` of ``object`` went out of scope.

    .. method:: turnUpdatesOnForObjectInstance(object: ObjectHandle, attributes: tuple[AttributeHandle, ...]) -> None

       Some other federate has ``attributes`` of ``object``, owned by this federate, in scope: updates
       of them are wanted (attribute relevance advisory switch,
       :meth:`RTIAmbassador.enableAttributeRelevanceAdvisorySwitch`).

    .. method:: turnUpdatesOffForObjectInstance(object: ObjectHandle, attributes: tuple[AttributeHandle, ...]) -> None

       No other federate has ``attributes`` of ``object`` in scope any more.

    .. rubric:: Ownership (HLA 1.3 §7)

    .. method:: requestAttributeOwnershipAssumption(object: ObjectHandle, \
                attributes: tuple[AttributeHandle, ...], tag: str) -> None

       The owner of ``attributes`` of ``object`` offers them
       (:meth:`RTIAmbassador.negotiatedAttributeOwnershipDivestiture`) to the federates that know the
       object and publish them; take them with :meth:`RTIAmbassador.attributeOwnershipAcquisition` if
       wanted.

    .. method:: attributeOwnershipDivestitureNotification(object: ObjectHandle, \
                attributes: tuple[AttributeHandle, ...]) -> None

       The negotiated divestiture of ``attributes`` of ``object`` is complete: this federate no longer
       owns them.

    .. method:: attributeOwnershipAcquisitionNotification(object: ObjectHandle, \
                attributes: tuple[AttributeHandle, ...]) -> None

       This federate now owns ``attributes`` of ``object``.

    .. method:: attributeOwnershipUnavailable(object: ObjectHandle, attributes: tuple[AttributeHandle, ...]) -> None

       :meth:`RTIAmbassador.attributeOwnershipAcquisitionIfAvailable` could not get ``attributes`` of
       ``object``: another federate owns them or is acquiring them.

    .. method:: requestAttributeOwnershipRelease(object: ObjectHandle, \
                attributes: tuple[AttributeHandle, ...], tag: str) -> None

       Another federate wants ``attributes`` of ``object``, owned by this federate; release them with
       :meth:`RTIAmbassador.attributeOwnershipReleaseResponse` if willing.

    .. method:: confirmAttributeOwnershipAcquisitionCancellation(object: ObjectHandle, \
                attributes: tuple[AttributeHandle, ...]) -> None

       :meth:`RTIAmbassador.cancelAttributeOwnershipAcquisition` succeeded for ``attributes`` of
       ``object``.

    .. method:: informAttributeOwnership(object: ObjectHandle, attribute: AttributeHandle, \
                owner: FederateHandle) -> None

       Answer to :meth:`RTIAmbassador.queryAttributeOwnership`: the federate ``owner`` owns
       ``attribute`` of ``object``.

    .. method:: attributeIsNotOwned(object: ObjectHandle, attribute: AttributeHandle) -> None

       Answer to :meth:`RTIAmbassador.queryAttributeOwnership`: no federate owns ``attribute`` of
       ``object``.

    .. method:: attributeOwnedByRTI(object: ObjectHandle, attribute: AttributeHandle) -> None

       Answer to :meth:`RTIAmbassador.queryAttributeOwnership` for an attribute the RTI owns; never
       called: hlacore has no RTI-owned attributes.

    .. rubric:: Time (HLA 1.3 §8, docs/time-management.md)

    .. method:: timeRegulationEnabled(time: float) -> None

       :meth:`RTIAmbassador.enableTimeRegulation` took effect; ``time`` is the federate's time now.

    .. method:: timeConstrainedEnabled(time: float) -> None

       :meth:`RTIAmbassador.enableTimeConstrained` took effect; ``time`` is the federate's time now.

    .. method:: timeAdvanceGrant(time: float) -> None

       The pending time advance request is granted: the federate's time is now ``time``.

    .. method:: requestRetraction(retraction: EventRetractionHandle) -> None

       The sender retracted (:meth:`RTIAmbassador.retract`) a timestamped message this federate was
       already delivered; ``retraction`` is the handle that came with it.
    """


_TRANSPORTS = {"HLAreliable": 1, "reliable": 1, "HLAbestEffort": 2, "best_effort": 2}
_TRANSPORT_NAMES = {1: "HLAreliable", 2: "HLAbestEffort"}
_ORDERS = {"Receive": 1, "receive": 1, "Timestamp": 2, "timestamp": 2}
_ORDER_NAMES = {1: "Receive", 2: "Timestamp"}


def _code_named(codes: Dict[str, int], name: str, kind: str) -> int:
    if name not in codes:
        raise _core.NameNotFound(f"no {kind} named {name!r}")
    return codes[name]


def _name_of(handle: Any, handle_type: Any, names: Dict[int, str], invalid: Type[Exception], kind: str) -> str:
    if not isinstance(handle, handle_type):
        raise TypeError(f"{handle_type.__name__} object required")
    if int(handle) not in names:
        raise invalid(f"{handle!r} is not {kind}")
    return names[int(handle)]

_SWITCH_CLASS, _SWITCH_ATTRIBUTE, _SWITCH_SCOPE, _SWITCH_INTERACTION = 1, 2, 3, 4



def _client_settings(**values: object) -> _core.ClientSettings:
    """Where and how to connect: the values given (None: not given), else the environment, else the defaults,
    checked by the client's table (``cpp/rti/client/options.cpp``); :class:`RTIinternalError` naming a value
    it refuses."""
    return _core.client_settings(dict(_options.given(_core.client_options(), values)))


class RTIAmbassador(_core.RTIAmbassadorBase):
    """A federate's connection to the RTI (HLA 1.3 RTIambassador).

    ``RTIAmbassador(address=None)`` connects to the gateway; raises :class:`RTIinternalError` naming the address
    if nothing answers. One ambassador joins at most one federation execution at a time. Every blocking call
    releases the GIL and Ctrl-C interrupts it with KeyboardInterrupt; a call interrupted while its reply was
    owed closes the connection (the gateway resigns the federate). Each keyword not given is read from its
    environment variable, as the HLA 1.3 C++ API reads them all (docs/cpp-api.md); a value refused raises
    :class:`RTIinternalError` naming it, a secret file that cannot be used :class:`AuthenticationFailed`. The
    keywords:

"""

    def __init__(self, address: Optional[str] = None, timeout: Optional[float] = None,
                 secret_file: Optional[str | os.PathLike[str]] = None, datagrams: Optional[bool] = None,
                 federation_secret_file: Optional[str | os.PathLike[str]] = None,
                 tls: Optional[bool | str | os.PathLike[str]] = None, busy_poll_us: Optional[int] = None,
                 time_semantics: Optional[str] = None) -> None:
        super().__init__(_client_settings(address=address, timeout=timeout, secret_file=secret_file,
                                          datagrams=datagrams, federation_secret_file=federation_secret_file,
                                          tls=tls, busy_poll_us=busy_poll_us, time_semantics=time_semantics))
        self._federate_ambassador: Any = None

    # ---- federation management ----

    def createFederationExecution(self, executionName: str, FED: str) -> None:
        """Create a federation execution from a ``.fed`` file or an OMT XML FOM module (HLA 1.3 §4.2;
        docs/fom-modules.md).

        The file is read and checked here, so a malformed file raises :class:`ErrorReadingFED` in the
        caller with its ``FILE:LINE:COL:`` position. A path this process cannot open is looked up by
        the gateway in its ``--fom-path`` directories. Raises :class:`FederationExecutionAlreadyExists`,
        :class:`CouldNotOpenFED`, :class:`ErrorReadingFED`.
        """
        text = ""
        if os.path.isfile(FED):
            try:
                with open(FED, "r", encoding="utf-8", errors="surrogateescape") as f:
                    text = f.read()
            except OSError as e:
                raise _core.CouldNotOpenFED(f"cannot read FED file {FED!r}: {e.strerror}") from None
            _core.parse_fed(text, FED)
        self._create(executionName, FED, text)

    def joinFederationExecution(
        self, yourName: str, executionName: str, federateAmbassadorReference: FederateAmbassador
    ) -> FederateHandle:
        """Join a federation execution (HLA 1.3 §4.4); callbacks go to ``federateAmbassadorReference``.

        Returns the federate's :class:`FederateHandle`. Raises :class:`FederateAlreadyExecutionMember`
        (this ambassador is joined, or the name is taken) and :class:`FederationExecutionDoesNotExist`.
        """
        return self._join_with(yourName, executionName, federateAmbassadorReference)

    def _join_with(self, name: str, execution: str, ambassador: Any, fom_modules: str = "",
                   federate_type: str = "") -> FederateHandle:
        """joinFederationExecution, with FOM modules added to the federation's (a bundle) and the federate's type
        (hlacore.rti1516e)."""
        handle = self._join(name, execution, fom_modules, federate_type)
        self._federate_ambassador = ambassador
        return handle

    def resignFederationExecution(self, theAction: int) -> None:
        """Resign from the federation execution (HLA 1.3 §4.5).

        ``theAction`` is a :class:`ResignAction`: ``DeleteObjects`` removes the objects this federate may
        delete (``removeObjectInstance`` at the others), ``ReleaseAttributes`` leaves its attributes
        unowned. Raises :class:`FederateOwnsAttributes` when the action leaves owned attributes behind,
        :class:`InvalidResignAction`, :class:`FederateNotExecutionMember`.
        """
        self._resign(int(theAction))
        self._federate_ambassador = None

    # ---- advisory switches (HLA 1.3 §5.10-5.13, §7.17-7.24) ----

    def enableClassRelevanceAdvisorySwitch(self) -> None:
        """Turn on ``startRegistrationForObjectClass``/``stopRegistrationForObjectClass`` (the default)."""
        self._set_advisory_switch(_SWITCH_CLASS, True)

    def disableClassRelevanceAdvisorySwitch(self) -> None:
        """Turn off ``startRegistrationForObjectClass``/``stopRegistrationForObjectClass``."""
        self._set_advisory_switch(_SWITCH_CLASS, False)

    def enableInteractionRelevanceAdvisorySwitch(self) -> None:
        """Turn on ``turnInteractionsOn``/``turnInteractionsOff`` (the default)."""
        self._set_advisory_switch(_SWITCH_INTERACTION, True)

    def disableInteractionRelevanceAdvisorySwitch(self) -> None:
        """Turn off ``turnInteractionsOn``/``turnInteractionsOff``."""
        self._set_advisory_switch(_SWITCH_INTERACTION, False)

    def enableAttributeRelevanceAdvisorySwitch(self) -> None:
        """Turn on ``turnUpdatesOnForObjectInstance``/``turnUpdatesOffForObjectInstance``: whether some other
        federate has an attribute this federate owns in scope (see :meth:`enableAttributeScopeAdvisorySwitch`)."""
        self._set_advisory_switch(_SWITCH_ATTRIBUTE, True)

    def disableAttributeRelevanceAdvisorySwitch(self) -> None:
        """Turn off ``turnUpdatesOnForObjectInstance``/``turnUpdatesOffForObjectInstance`` (the default)."""
        self._set_advisory_switch(_SWITCH_ATTRIBUTE, False)

    def enableAttributeScopeAdvisorySwitch(self) -> None:
        """Turn on ``attributesInScope``/``attributesOutOfScope`` (HLA 1.3 §6.13-6.14): an attribute of a known
        object is in scope while it is subscribed (through a region overlapping its owner's update region,
        if by region) and owned by another federate."""
        self._set_advisory_switch(_SWITCH_SCOPE, True)

    def disableAttributeScopeAdvisorySwitch(self) -> None:
        """Turn off ``attributesInScope``/``attributesOutOfScope`` (the default)."""
        self._set_advisory_switch(_SWITCH_SCOPE, False)

    # ---- transportation and ordering (answered locally, usable before joining) ----

    def getTransportationHandle(self, name: str) -> TransportationHandle:
        """Handle of ``"HLAreliable"`` or ``"HLAbestEffort"``; raises :class:`NameNotFound`."""
        return _core._transportation_handle(_code_named(_TRANSPORTS, name, "transportation type"))

    def getTransportationName(self, handle: TransportationHandle) -> str:
        """Name of a transportation handle; raises :class:`InvalidTransportationHandle`."""
        return _name_of(handle, TransportationHandle, _TRANSPORT_NAMES, _core.InvalidTransportationHandle, "a transportation type")

    def getOrderingHandle(self, name: str) -> OrderingHandle:
        """Handle of ``"Receive"`` or ``"Timestamp"``; raises :class:`NameNotFound`."""
        return _core._ordering_handle(_code_named(_ORDERS, name, "ordering type"))

    def getOrderingName(self, handle: OrderingHandle) -> str:
        """Name of an ordering handle; raises :class:`InvalidOrderingHandle`."""
        return _name_of(handle, OrderingHandle, _ORDER_NAMES, _core.InvalidOrderingHandle, "an ordering type")

    # ---- conveniences (beyond PyHLA): what every federate writes around the services ----

    def create_or_join(
        self, federate: str, federation: str, fed_file: Optional[str], ambassador: Any
    ) -> FederateHandle:
        """Join ``federation`` as ``federate``, creating it from ``fed_file`` first unless it exists.

        ``createFederationExecution(federation, fed_file)`` (skipped when ``fed_file`` is None; a
        :class:`FederationExecutionAlreadyExists` is ignored: another federate created it), then
        ``joinFederationExecution(federate, federation, ambassador)``. Returns the federate handle and
        raises what those two services raise otherwise.
        """
        if fed_file is not None:
            try:
                self.createFederationExecution(federation, fed_file)
            except _exceptions.FederationExecutionAlreadyExists:
                pass
        return self.joinFederationExecution(federate, federation, ambassador)

    def enable_time_management(
        self,
        lookahead: float,
        timeout: Optional[float] = None,
        *,
        regulating: bool = True,
        constrained: bool = True,
    ) -> float:
        """Become time-regulating and time-constrained and wait until both are enabled; returns the time.

        ``enableTimeRegulation(queryFederateTime(), lookahead)`` and ``enableTimeConstrained()`` (either
        left out with ``regulating=False`` / ``constrained=False``), then tick until
        ``timeRegulationEnabled`` and ``timeConstrainedEnabled`` have been delivered, to the federate
        ambassador as usual (whether or not it defines them). Other callbacks that arrive meanwhile are
        delivered too. Raises what the two services raise, and :class:`TimeoutError` when ``timeout``
        seconds pass first (the requests stay pending). Ctrl-C interrupts the wait.
        """
        watcher = _EnableWatcher(self._federate_ambassador, regulating, constrained)
        if regulating:
            self.enableTimeRegulation(self.queryFederateTime(), lookahead)
        if constrained:
            self.enableTimeConstrained()

        def enabled() -> bool:
            self._dispatch(watcher, False, -1.0)
            return watcher.done()

        self._deliver_until(enabled, timeout, "time management not enabled")
        return float(self.queryFederateTime())

    # ---- recording (beyond PyHLA: the recorder federate, python -m hlacore.record) ----

    def start_recording(self, path: str | os.PathLike[str]) -> None:
        """Record this federate's federation into the MCAP file ``path``, from now until
        :meth:`stop_recording`: the gateway sends the joined federate every record of the federation, the
        same as ``rtig --record`` writes (docs/record-replay.md), beginning with the FOM and the federates
        joined so far, and they are written as they come while the federate ticks or calls services. Raises
        RuntimeError when the file cannot be created, RTIinternalError when this federate records already.
        """
        self._start_recording(os.fspath(path))

    def stop_recording(self) -> int:
        """Close the recording started by :meth:`start_recording` (its summary written, readable by every MCAP
        tool); returns the number of records. Raises RuntimeError with the write error (a full disk, say)
        that stopped the recording, if one did."""
        return int(self._stop_recording())

    # ---- blocking time advance (beyond PyHLA; asyncio forms in hlacore.aio): advance_to, next_event and
    # await_grant are _core's (cpp/bindings/callbacks.cpp), run once per step of every time-managed federate ----

    def _deliver_until(self, delivered: Callable[[], bool], timeout: Optional[float], what: str) -> None:
        """Call `delivered` (it delivers what is ready) until it returns True, waiting for the socket in
        between (GIL released, Ctrl-C interrupts); TimeoutError saying `what` after `timeout` seconds."""
        deadline = None if timeout is None else _time.monotonic() + timeout
        while not delivered():
            remaining = -1.0
            if deadline is not None:
                remaining = deadline - _time.monotonic()
                if remaining <= 0:
                    raise TimeoutError(f"{what} within {timeout} s")
            self._wait(remaining)

    def deliver_until_granted(self, read: bool = True) -> bool:
        """Deliver ready callbacks, stopping after a grant; True once no time advance is pending.

        With ``read`` (the default) it also reads what the socket holds, without blocking."""
        ambassador = self._federate_ambassador
        while self._time_advance_pending():
            if not self._dispatch(ambassador, True, -1.0):
                if not read:
                    return False
                self._poll()
                if not self._dispatch(ambassador, True, -1.0):
                    return False
        return True


RTIAmbassador.__doc__ = f"{RTIAmbassador.__doc__}{_options.document(_core.client_options(), 'else ``${}``')}\n"


class _EnableWatcher:
    """Forwards callbacks to the federate ambassador, noting the two enable callbacks on the way."""

    def __init__(self, ambassador: Any, regulating: bool, constrained: bool) -> None:
        self._ambassador = ambassador
        self.regulation_pending = regulating
        self.constraint_pending = constrained

    def done(self) -> bool:
        """Whether every enable callback asked for has arrived."""
        return not (self.regulation_pending or self.constraint_pending)

    def timeRegulationEnabled(self, time: float) -> None:
        """Note that regulation is enabled, and forward the callback."""
        self.regulation_pending = False
        self._forward("timeRegulationEnabled", time)

    def timeConstrainedEnabled(self, time: float) -> None:
        """Note that the federate is constrained, and forward the callback."""
        self.constraint_pending = False
        self._forward("timeConstrainedEnabled", time)

    def _forward(self, name: str, *args: Any) -> None:
        method = getattr(self._ambassador, name, None)
        if method is not None:
            method(*args)

    def __getattr__(self, name: str) -> Any:  # every other callback goes straight to the ambassador
        return getattr(self._ambassador, name)


__all__ = [
    "RTIAmbassador",
    "FederateAmbassador",
    "ResignAction",
    "RTIexception",
    "RTIInternalError",
    "AttributeHandle",
    "DimensionHandle",
    "EventRetractionHandle",
    "FederateHandle",
    "InteractionClassHandle",
    "ObjectClassHandle",
    "ObjectHandle",
    "OrderingHandle",
    "ParameterHandle",
    "RegionHandle",
    "SpaceHandle",
    "MIN_EXTENT",
    "MAX_EXTENT",
    "TransportationHandle",
    *_EXCEPTION_NAMES,
]

