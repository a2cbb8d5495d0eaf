"""IEEE 1516-2010's RTIambassador over hlacore's core: each service is the HLA 1.3 core's (an inner
:class:`hlacore.rti.RTIAmbassador`) with 1516-2010's names, arguments and exceptions."""

from __future__ import annotations

import json
import uuid
from typing import Any, Callable, Dict, Iterable, List, Mapping, Optional, Set, Tuple, Type

from .. import _core
from .. import rti as _rti13
from . import _enums as e
from . import _exceptions as x
from ._callbacks import Adapter
from ._delivery import Delivery
from ._regions import Regions
from ._support import added_modules, legal_name, module_text, not_served, services, tag_of, translating, values_of
from ._handles import (CORE_TYPES, AttributeHandle, FederateHandle, Handle, InteractionClassHandle,
                       MessageRetractionHandle, ObjectClassHandle, ObjectInstanceHandle, ParameterHandle, core, cores,
                       decode, wrap_set)

TIME_TYPES = {"HLAfloat64Time": 0, "HLAinteger64Time": 1}
# IEEE 1516-2010's resign actions as the core's HLA 1.3 ones (rti.ResignAction). The core cancels a resigning
# federate's pending acquisitions whatever the action.
_RESIGN = {e.UNCONDITIONALLY_DIVEST_ATTRIBUTES: 1, e.DELETE_OBJECTS: 2, e.CANCEL_PENDING_OWNERSHIP_ACQUISITIONS: 4,
           e.DELETE_OBJECTS_THEN_DIVEST: 3, e.CANCEL_THEN_DELETE_THEN_DIVEST: 3, e.NO_ACTION: 4}


@services
class RTIambassador(Regions):
    """A federate's connection to the RTI with IEEE 1516-2010's services (OpenRTI's Python module's shape).

    ``RTIambassador(**settings)``: the keywords of :class:`hlacore.rti.RTIAmbassador` (``timeout``,
    ``secret_file``, ``tls``, ...), used by :meth:`connect`. Arguments are positional, as in C++; handles are
    this module's types; values, tags and user-supplied data are bytes; logical times and lookaheads are
    floats (ints in a federation created with ``"HLAinteger64Time"``); enumerations are this module's integer
    constants or their names. Every service raises this module's exceptions.
    """

    def __init__(self, **settings: Any) -> None:
        self._settings = settings
        self._rti: Optional[_rti13.RTIAmbassador] = None
        self._adapter: Optional[Adapter] = None
        self._integer_time = False
        self._joined = False
        self._delivery: Optional[Delivery] = None
        self._saving = False  # federateSaveBegun called, the save not over (queryFederationSaveStatus)
        self._resign_directive = e.CANCEL_THEN_DELETE_THEN_DIVEST
        self._published: Dict[Any, Set[Any]] = {}   # object class -> attributes (1516-2010 publishes add up)
        self._subscribed: Dict[Any, Set[Any]] = {}
        self._regions: Dict[int, Dict[Any, Tuple[int, int]]] = {}  # region -> dimension -> [lower, upper)

    # ---- the inner ambassador, times and enumerations ----
    def _inner(self) -> _rti13.RTIAmbassador:
        if self._rti is None:
            raise x.NotConnected("NotConnected: call connect first")
        return self._rti

    def _time_in(self, time: Any) -> float:
        return float(int(time)) if self._integer_time else float(time)

    def _time_out(self, time: float) -> Any:
        return int(time) if self._integer_time and time not in (float("inf"), float("-inf")) else time

    @staticmethod
    def _order(order: Any) -> Any:
        return _core._ordering_handle(e.enum_value(order, e.ORDER_TYPES, x.InvalidOrderType, "order type"))

    @staticmethod
    def _transport(transport: Any) -> Any:
        return _core._transportation_handle(e.enum_value(transport, e.TRANSPORTATION_TYPES, x.InvalidTransportationType,
                                                         "transportation type"))

    def _timed(self, result: Any) -> Optional[MessageRetractionHandle]:
        return None if result is None else MessageRetractionHandle.wrap(result)

    # ---- federation management (IEEE 1516.1-2010 §4) ----
    def connect(self, federateAmbassador: Any, callbackModel: Any = "HLA_EVOKED", localSettingsDesignator: str = "") -> None:
        """Connect to the gateway named by ``localSettingsDesignator`` (``"host:port"``, ``"rti://host:port"``,
        ``"rti://host:port/"``; empty: ``$HLACORE_RTIG`` or 127.0.0.1:60400). With ``"HLA_EVOKED"`` callbacks arrive in
        :meth:`evokeCallback` and :meth:`evokeMultipleCallbacks`; with ``"HLA_IMMEDIATE"`` a thread of this
        ambassador's delivers them as they arrive (a callback that raises is reported on stderr)."""
        if self._rti is not None:
            raise x.AlreadyConnected("AlreadyConnected: this ambassador is connected")
        if callbackModel not in ("HLA_EVOKED", "HLA_IMMEDIATE"):
            raise x.UnsupportedCallbackModel(f"UnsupportedCallbackModel: {callbackModel!r} (HLA_EVOKED, HLA_IMMEDIATE)")
        if not isinstance(localSettingsDesignator, str):
            raise TypeError("the local settings designator is a str")
        address = localSettingsDesignator.strip()
        address = address[len("rti://"):] if address.startswith("rti://") else address
        address = address[:-1] if address.endswith("/") else address
        if address:
            try:
                _core.client_settings({"address": address})
            except _core.RTIinternalError as error:  # names no gateway
                raise x.InvalidLocalSettingsDesignator(f"InvalidLocalSettingsDesignator: {error}") from None
        try:
            self._rti = _rti13.RTIAmbassador(address or None, **self._settings)
        except _core.RTIinternalError as error:  # nothing answers, the secret is refused, a setting is wrong
            raise x.ConnectionFailed(f"ConnectionFailed: {error}") from None
        self._adapter = Adapter(federateAmbassador, self._time_out, self._rti._failure_reason)
        self._delivery = Delivery(self._rti, self._adapter, callbackModel == "HLA_IMMEDIATE", self._connection_lost)

    def _connection_lost(self) -> None:
        self._joined = False
        self._rti = None

    def disconnect(self) -> None:
        """Close the connection; raises ``FederateIsExecutionMember`` while joined."""
        if self._joined:
            raise x.FederateIsExecutionMember("FederateIsExecutionMember: resign first")
        if self._delivery is not None:
            self._delivery.stop()
        self._rti = self._adapter = self._delivery = None  # the inner ambassador closes its connection as it goes

    def createFederationExecution(self, federationName: str, fomModules: Any,
                                  logicalTimeImplementationName: str = "HLAfloat64Time") -> None:
        """Create a federation from FOM modules (one path or URL, or a list), merged in order; its time type
        ``"HLAfloat64Time"`` or ``"HLAinteger64Time"``. A module this process cannot read is looked up by the
        gateway in its ``--fom-path`` (one module only)."""
        self._create(federationName, [fomModules] if isinstance(fomModules, (str, bytes)) else list(fomModules),
                     logicalTimeImplementationName)

    def createFederationExecutionWithMIM(self, federationName: str, fomModules: Any, mimModule: Any,
                                         logicalTimeImplementationName: str = "HLAfloat64Time") -> None:
        """As :meth:`createFederationExecution`, the MIM module merged first (hlacore's MIM is always there)."""
        modules = [fomModules] if isinstance(fomModules, (str, bytes)) else list(fomModules)
        self._create(federationName, [mimModule] + modules, logicalTimeImplementationName)

    def _create(self, name: str, modules: List[Any], time_name: str) -> None:
        if time_name not in TIME_TYPES:
            raise x.CouldNotCreateLogicalTimeFactory(f"CouldNotCreateLogicalTimeFactory: {time_name!r} (hlacore serves "
                                                     f"{', '.join(TIME_TYPES)})")
        if not modules:
            raise x.CouldNotOpenFDD("CouldNotOpenFDD: no FOM module given")
        read = [module_text(m) for m in modules]
        unread = [n for n, text in read if not text]
        if unread and len(read) > 1:
            raise x.CouldNotOpenFDD(f"CouldNotOpenFDD: cannot open {unread[0]!r}")
        if unread:
            self._inner()._create(name, read[0][0], "", TIME_TYPES[time_name])
            return
        _core.parse_fom_modules([(text, n) for n, text in read])  # errors at the caller, FILE:LINE:COL
        text = read[0][1] if len(read) == 1 else \
            _core.fom_bundle([(text, n) for n, text in read]).decode("utf-8", "surrogateescape")
        self._inner()._create(name, read[0][0] if len(read) == 1 else ", ".join(n for n, _ in read), text,
                              TIME_TYPES[time_name])

    def destroyFederationExecution(self, federationName: str) -> None:
        """Destroy a federation no federate is joined to."""
        self._inner().destroyFederationExecution(federationName)

    def _report(self) -> Dict[str, Any]:
        """The gateway's status report, asked on this connection: after everything sent before."""
        return dict(json.loads(self._inner()._status(0, False)))

    def listFederationExecutions(self) -> None:
        """Ask for the federations: ``reportFederationExecutions`` with their names and time types."""
        infos = [{"federationExecutionName": f["name"], "logicalTimeImplementationName": f.get("time_type", "")}
                 for f in self._report()["federations"]]
        assert self._adapter is not None
        self._adapter.local.append(("reportFederationExecutions", (infos,)))

    def joinFederationExecution(self, *args: Any) -> FederateHandle:
        """``(federateType, federationName)``, ``(federateName, federateType, federationName)``, either with
        a list of additional FOM modules last (paths or file: URLs, read here). Without a name the federate
        gets a unique one.

        The additional modules are merged into the federation's FOM, which every federate joined before learns
        at once; every handle given out before keeps its meaning (docs/fom-modules.md). Raises
        ``CouldNotOpenFDD`` for a module this process cannot read, ``ErrorReadingFDD`` for one that does not
        read, ``InconsistentFDD`` for one that contradicts the federation's FOM (``FILE:LINE:COL`` naming both
        places) or a federation created from an HLA 1.3 ``.fed``."""
        fom_modules = ""
        if len(args) == 4 or (len(args) == 3 and not isinstance(args[2], (str, bytes))):
            fom_modules = added_modules(args[-1])
            args = args[:-1]
        if len(args) == 2:
            federate_type, federation = args
            name = f"{federate_type}-{uuid.uuid4().hex[:12]}"
        elif len(args) == 3:
            name, federate_type, federation = args
        else:
            raise TypeError(f"joinFederationExecution takes 2 to 4 arguments, not {len(args)}")
        inner, adapter = self._inner(), self._adapter
        assert adapter is not None
        try:
            handle = inner._join_with(name, federation, adapter, fom_modules, federate_type)
        except _core.FederateAlreadyExecutionMember as error:
            if self._joined:
                raise x.FederateAlreadyExecutionMember(f"FederateAlreadyExecutionMember: {error}") from None
            raise x.FederateNameAlreadyInUse(f"FederateNameAlreadyInUse: {error}") from None
        self._joined = True
        self._integer_time = inner._time_type() == TIME_TYPES["HLAinteger64Time"]
        adapter.federate_name = name
        return FederateHandle.wrap(handle)

    def resignFederationExecution(self, resignAction: Any) -> None:
        """Resign with one of the ResignAction constants."""
        action = e.enum_value(resignAction, e.RESIGN_ACTIONS, x.InvalidResignAction, "resign action")
        self._inner().resignFederationExecution(_RESIGN[action])
        self._joined = False
        assert self._adapter is not None
        self._adapter.reserved.clear()  # the gateway dropped them
        self._published.clear()
        self._subscribed.clear()
        self._regions.clear()  # the gateway deleted them

    def registerFederationSynchronizationPoint(self, synchronizationPointLabel: str, userSuppliedTag: Any,
                                               synchronizationSet: Optional[Iterable[Any]] = None) -> None:
        """Register a synchronization point for every federate, or for those of ``synchronizationSet``."""
        federates = cores(FederateHandle, synchronizationSet) if synchronizationSet else None
        assert self._adapter is not None
        self._adapter.sync_sets[synchronizationPointLabel] = bool(federates)
        self._inner().registerFederationSynchronizationPoint(synchronizationPointLabel, tag_of(userSuppliedTag), federates)

    def synchronizationPointAchieved(self, synchronizationPointLabel: str, successful: Any = True) -> None:
        """This federate reached the point (``successful=False`` is not served: the core has no failed set)."""
        if not successful:
            raise not_served("an unsuccessful synchronizationPointAchieved", "the core has no failed set")
        self._inner().synchronizationPointAchieved(synchronizationPointLabel)

    def requestFederationSave(self, label: str, time: Any = None) -> None:
        """Save the federation now, or at ``time``."""
        self._inner().requestFederationSave(label, None if time is None else self._time_in(time))

    def federateSaveBegun(self) -> None:
        """This federate began saving its state."""
        self._inner().federateSaveBegun()
        self._saving = True

    def federateSaveComplete(self) -> None:
        """This federate saved its state."""
        self._inner().federateSaveComplete()
        self._saving = False

    def federateSaveNotComplete(self) -> None:
        """This federate could not save its state."""
        self._inner().federateSaveNotComplete()
        self._saving = False

    def abortFederationSave(self) -> None:
        """End the save under way: every federate gets ``federationNotSaved(SAVE_ABORTED)``."""
        self._inner()._abort_save()

    def requestFederationRestore(self, label: str) -> None:
        """Restore the federation saved as ``label``."""
        self._inner().requestFederationRestore(label)

    def abortFederationRestore(self) -> None:
        """End the restore under way: every federate gets ``federationNotRestored(RESTORE_ABORTED)``."""
        self._inner()._abort_restore()

    # ---- declaration management (§5) ----
    def _declare(self, table: Dict[Any, Set[Any]], theClass: Any, attributeList: Iterable[Any], adding: bool,
                 declare: Callable[[Any, List[Any]], None], withdraw: Callable[[Any], None]) -> None:
        """Publications and subscriptions add up in 1516-2010 and replace each other in the core: the class's
        attributes after the change go to the core (none: the class is withdrawn)."""
        cls = core(ObjectClassHandle, theClass)
        attributes = set(cores(AttributeHandle, attributeList))
        now = table.get(cls, set()) | attributes if adding else table.get(cls, set()) - attributes
        if now:
            declare(cls, sorted(now, key=int))
            table[cls] = now
        else:
            self._withdraw(table, theClass, withdraw)

    def _withdraw(self, table: Dict[Any, Set[Any]], theClass: Any, withdraw: Callable[[Any], None]) -> None:
        cls = core(ObjectClassHandle, theClass)
        withdraw(cls)
        table.pop(cls, None)

    def publishObjectClassAttributes(self, theClass: Any, attributeList: Iterable[Any]) -> None:
        """Publish these attributes of the class (added to those published before)."""
        inner = self._inner()
        self._declare(self._published, theClass, attributeList, True, inner.publishObjectClass, inner.unpublishObjectClass)

    def unpublishObjectClass(self, theClass: Any) -> None:
        """Publish none of the class's attributes."""
        self._withdraw(self._published, theClass, self._inner().unpublishObjectClass)

    def unpublishObjectClassAttributes(self, theClass: Any, attributeList: Iterable[Any]) -> None:
        """Stop publishing these attributes of the class."""
        inner = self._inner()
        self._declare(self._published, theClass, attributeList, False, inner.publishObjectClass, inner.unpublishObjectClass)

    def publishInteractionClass(self, theInteraction: Any) -> None:
        """Publish the interaction class."""
        self._inner().publishInteractionClass(core(InteractionClassHandle, theInteraction))

    def unpublishInteractionClass(self, theInteraction: Any) -> None:
        """Stop publishing the interaction class."""
        self._inner().unpublishInteractionClass(core(InteractionClassHandle, theInteraction))

    def subscribeObjectClassAttributes(self, theClass: Any, attributeList: Iterable[Any], active: Any = True,
                                       updateRateDesignator: str = "") -> None:
        """Subscribe to these attributes of the class (added to those subscribed before); with an update rate
        designator, receive-order values of the class's attributes come at most at that rate."""
        inner = self._inner()
        inner._subscription_rate(core(ObjectClassHandle, theClass), updateRateDesignator)
        self._declare(self._subscribed, theClass, attributeList, True,
                      lambda c, a: inner.subscribeObjectClassAttributes(c, a, bool(active)), inner.unsubscribeObjectClass)

    def unsubscribeObjectClass(self, theClass: Any) -> None:
        """Subscribe to none of the class's attributes."""
        self._withdraw(self._subscribed, theClass, self._inner().unsubscribeObjectClass)

    def unsubscribeObjectClassAttributes(self, theClass: Any, attributeList: Iterable[Any]) -> None:
        """Stop subscribing to these attributes of the class."""
        inner = self._inner()
        self._declare(self._subscribed, theClass, attributeList, False, inner.subscribeObjectClassAttributes,
                      inner.unsubscribeObjectClass)

    def subscribeInteractionClass(self, theClass: Any, active: Any = True) -> None:
        """Subscribe to the interaction class."""
        self._inner().subscribeInteractionClass(core(InteractionClassHandle, theClass), bool(active))

    def unsubscribeInteractionClass(self, theClass: Any) -> None:
        """Stop subscribing to the interaction class."""
        self._inner().unsubscribeInteractionClass(core(InteractionClassHandle, theClass))

    # ---- object management (§6) ----
    def reserveObjectInstanceName(self, theObjectInstanceName: str) -> None:
        """Reserve a name for an object this federate will register: ``objectInstanceNameReservationSucceeded``
        or ``objectInstanceNameReservationFailed`` (the name is held or reserved) follows."""
        self._inner()._reserve_names(False, [legal_name(theObjectInstanceName)])

    def reserveMultipleObjectInstanceName(self, theObjectInstanceNames: Iterable[str]) -> None:
        """Reserve all of these names or none: ``multipleObjectInstanceNameReservationSucceeded`` or
        ``...Failed`` follows with the set."""
        if isinstance(theObjectInstanceNames, (str, bytes)):
            raise TypeError("a collection of names, not one name")
        names = [legal_name(n) for n in theObjectInstanceNames]
        if not names:
            raise x.NameSetWasEmpty("NameSetWasEmpty: no name to reserve")
        self._inner()._reserve_names(True, names)

    def releaseObjectInstanceName(self, theObjectInstanceName: str) -> None:
        """Give back a name this federate reserved and has not used."""
        self._release([theObjectInstanceName])

    def releaseMultipleObjectInstanceName(self, theObjectInstanceNames: Iterable[str]) -> None:
        """Give back names this federate reserved and has not used."""
        self._release(list(theObjectInstanceNames))

    def _release(self, names: List[str]) -> None:
        inner, adapter = self._inner(), self._adapter
        assert adapter is not None
        missing = [n for n in names if n not in adapter.reserved]
        if missing:
            raise x.ObjectInstanceNameNotReserved(f"ObjectInstanceNameNotReserved: {missing[0]!r}")
        inner._release_names(names)
        adapter.reserved.difference_update(names)

    def registerObjectInstance(self, theClass: Any, theObjectName: Optional[str] = None) -> ObjectInstanceHandle:
        """Register an object of the class, with a name this federate reserved or a unique one; returns its
        handle."""
        inner, adapter = self._inner(), self._adapter
        assert adapter is not None
        if theObjectName is not None and theObjectName not in adapter.reserved:
            raise x.ObjectInstanceNameNotReserved(f"ObjectInstanceNameNotReserved: {theObjectName!r} (reserve it first)")
        handle = inner.registerObjectInstance(core(ObjectClassHandle, theClass), theObjectName)
        adapter.reserved.discard(theObjectName or "")
        return ObjectInstanceHandle.wrap(handle)

    def updateAttributeValues(self, theObject: Any, theAttributeValues: Mapping[Any, Any], theUserSuppliedTag: Any,
                              theTime: Any = None) -> Optional[MessageRetractionHandle]:
        """Send new values; with a time, timestamped, returning its retraction handle."""
        return self._timed(self._inner().updateAttributeValues(
            core(ObjectInstanceHandle, theObject), values_of(AttributeHandle, theAttributeValues),
            tag_of(theUserSuppliedTag), None if theTime is None else self._time_in(theTime)))

    def sendInteraction(self, theInteraction: Any, theParameterValues: Mapping[Any, Any], theUserSuppliedTag: Any,
                        theTime: Any = None) -> Optional[MessageRetractionHandle]:
        """Send an interaction; with a time, timestamped, returning its retraction handle."""
        return self._timed(self._inner().sendInteraction(
            core(InteractionClassHandle, theInteraction), values_of(ParameterHandle, theParameterValues),
            tag_of(theUserSuppliedTag), None if theTime is None else self._time_in(theTime)))

    def deleteObjectInstance(self, objectHandle: Any, theUserSuppliedTag: Any,
                             theTime: Any = None) -> Optional[MessageRetractionHandle]:
        """Delete an object; with a time, timestamped, returning its retraction handle."""
        return self._timed(self._inner().deleteObjectInstance(
            core(ObjectInstanceHandle, objectHandle), tag_of(theUserSuppliedTag),
            None if theTime is None else self._time_in(theTime)))

    def localDeleteObjectInstance(self, objectHandle: Any) -> None:
        """Forget an object here only (it may be discovered again)."""
        self._inner().localDeleteObjectInstance(core(ObjectInstanceHandle, objectHandle))

    def requestAttributeValueUpdate(self, theObjectOrClass: Any, theAttributes: Iterable[Any], theUserSuppliedTag: Any) -> None:
        """Ask the owners of an object's attributes, or of every object of a class, to provide them."""
        tag_of(theUserSuppliedTag)  # the core's request carries no tag
        attributes = cores(AttributeHandle, theAttributes)
        if isinstance(theObjectOrClass, ObjectClassHandle):
            self._inner().requestClassAttributeValueUpdate(core(ObjectClassHandle, theObjectOrClass), attributes)
        else:
            self._inner().requestObjectAttributeValueUpdate(core(ObjectInstanceHandle, theObjectOrClass), attributes)

    def requestAttributeTransportationTypeChange(self, theObject: Any, theAttributes: Iterable[Any],
                                                 theType: Any) -> None:
        """Send these attributes of the object with another transportation; confirmed by callback."""
        attributes, transport = cores(AttributeHandle, theAttributes), self._transport(theType)
        self._inner().changeAttributeTransportationType(core(ObjectInstanceHandle, theObject), attributes, transport)
        assert self._adapter is not None
        self._adapter.local.append(("confirmAttributeTransportationTypeChange",
                                    (theObject, wrap_set(AttributeHandle, attributes), int(transport))))

    def requestInteractionTransportationTypeChange(self, theClass: Any, theType: Any) -> None:
        """Send the interaction class with another transportation; confirmed by callback."""
        transport = self._transport(theType)
        self._inner().changeInteractionTransportationType(core(InteractionClassHandle, theClass), transport)
        assert self._adapter is not None
        self._adapter.local.append(("confirmInteractionTransportationTypeChange", (theClass, int(transport))))

    def queryAttributeTransportationType(self, theObject: Any, theAttribute: Any) -> None:
        """Ask how the attribute's updates travel: ``reportAttributeTransportationType`` answers."""
        self._inner()._query_attribute_transportation(core(ObjectInstanceHandle, theObject), core(AttributeHandle, theAttribute))

    def queryInteractionTransportationType(self, theFederate: Any, theInteraction: Any) -> None:
        """Ask how that federate's interactions of the class travel: ``reportInteractionTransportationType``
        answers."""
        self._inner()._query_interaction_transportation(core(FederateHandle, theFederate),
                                                        core(InteractionClassHandle, theInteraction))

    # ---- ownership management (§7) ----
    def unconditionalAttributeOwnershipDivestiture(self, theObject: Any, theAttributes: Iterable[Any]) -> None:
        """Give up these attributes now (to a federate acquiring them, or to none)."""
        self._inner().unconditionalAttributeOwnershipDivestiture(core(ObjectInstanceHandle, theObject),
                                                                 cores(AttributeHandle, theAttributes))

    def negotiatedAttributeOwnershipDivestiture(self, theObject: Any, theAttributes: Iterable[Any], theUserSuppliedTag: Any) -> None:
        """Offer these attributes to a federate that takes them (``requestDivestitureConfirmation`` then)."""
        self._inner().negotiatedAttributeOwnershipDivestiture(core(ObjectInstanceHandle, theObject),
                                                              cores(AttributeHandle, theAttributes), tag_of(theUserSuppliedTag))

    def confirmDivestiture(self, theObject: Any, theAttributes: Iterable[Any], theUserSuppliedTag: Any) -> None:
        """Confirm the divestiture ``requestDivestitureConfirmation`` asked for. The core, following HLA 1.3,
        has already moved the attributes by then; this checks that they were asked for."""
        assert self._adapter is not None
        obj, attributes = core(ObjectInstanceHandle, theObject), set(cores(AttributeHandle, theAttributes))
        asked = self._adapter.divesting.get(obj, set())
        if not attributes <= asked:
            raise x.AttributeDivestitureWasNotRequested("AttributeDivestitureWasNotRequested: no confirmation was asked "
                                                        "for some of these attributes")
        asked -= attributes

    def attributeOwnershipAcquisition(self, theObject: Any, desiredAttributes: Iterable[Any], theUserSuppliedTag: Any) -> None:
        """Acquire these attributes, asking their owners to release them."""
        self._inner().attributeOwnershipAcquisition(core(ObjectInstanceHandle, theObject),
                                                    cores(AttributeHandle, desiredAttributes), tag_of(theUserSuppliedTag))

    def attributeOwnershipAcquisitionIfAvailable(self, theObject: Any, desiredAttributes: Iterable[Any]) -> None:
        """Acquire those of these attributes nobody owns."""
        self._inner().attributeOwnershipAcquisitionIfAvailable(core(ObjectInstanceHandle, theObject),
                                                               cores(AttributeHandle, desiredAttributes))

    def attributeOwnershipReleaseDenied(self, theObject: Any, theAttributes: Iterable[Any]) -> None:
        """Keep attributes another federate asked for (the request simply goes unanswered)."""
        core(ObjectInstanceHandle, theObject)
        cores(AttributeHandle, theAttributes)

    def attributeOwnershipDivestitureIfWanted(self, theObject: Any, theAttributes: Iterable[Any]) -> Set[AttributeHandle]:
        """Give those of these attributes another federate asked for; returns them."""
        assert self._adapter is not None
        obj = core(ObjectInstanceHandle, theObject)
        asked = self._adapter.release_asked.get(obj, set())
        wanted = [a for a in cores(AttributeHandle, theAttributes) if a in asked]
        if not wanted:
            return set()
        given = self._inner().attributeOwnershipReleaseResponse(obj, wanted)
        asked.difference_update(wanted)
        return wrap_set(AttributeHandle, given)

    def cancelNegotiatedAttributeOwnershipDivestiture(self, theObject: Any, theAttributes: Iterable[Any]) -> None:
        """Withdraw the offer of these attributes."""
        self._inner().cancelNegotiatedAttributeOwnershipDivestiture(core(ObjectInstanceHandle, theObject),
                                                                    cores(AttributeHandle, theAttributes))

    def cancelAttributeOwnershipAcquisition(self, theObject: Any, theAttributes: Iterable[Any]) -> None:
        """Withdraw the acquisition of these attributes."""
        self._inner().cancelAttributeOwnershipAcquisition(core(ObjectInstanceHandle, theObject),
                                                          cores(AttributeHandle, theAttributes))

    def queryAttributeOwnership(self, theObject: Any, theAttribute: Any) -> None:
        """Ask who owns the attribute (``informAttributeOwnership`` or ``attributeIsNotOwned``)."""
        self._inner().queryAttributeOwnership(core(ObjectInstanceHandle, theObject), core(AttributeHandle, theAttribute))

    def isAttributeOwnedByFederate(self, theObject: Any, theAttribute: Any) -> bool:
        """Whether this federate owns the attribute."""
        return bool(self._inner().isAttributeOwnedByFederate(core(ObjectInstanceHandle, theObject),
                                                             core(AttributeHandle, theAttribute)))

    # ---- time management (§8) ----
    def enableTimeRegulation(self, theLookahead: Any) -> None:
        """Become time-regulating with this lookahead (``timeRegulationEnabled`` then)."""
        inner = self._inner()
        inner.enableTimeRegulation(inner.queryFederateTime(), self._time_in(theLookahead))

    def timeAdvanceRequest(self, theTime: Any) -> None:
        """Advance to ``theTime`` (``timeAdvanceGrant`` then)."""
        self._inner().timeAdvanceRequest(self._time_in(theTime))

    def timeAdvanceRequestAvailable(self, theTime: Any) -> None:
        """Advance to ``theTime``, others' messages at that time still to come."""
        self._inner().timeAdvanceRequestAvailable(self._time_in(theTime))

    def nextMessageRequest(self, theTime: Any) -> None:
        """Advance to the next message's time, at most ``theTime``."""
        self._inner().nextEventRequest(self._time_in(theTime))

    def nextMessageRequestAvailable(self, theTime: Any) -> None:
        """As :meth:`nextMessageRequest`, others' messages at the granted time still to come."""
        self._inner().nextEventRequestAvailable(self._time_in(theTime))

    def flushQueueRequest(self, theTime: Any) -> None:
        """Deliver every queued message and advance as far as it can, at most to ``theTime``."""
        self._inner().flushQueueRequest(self._time_in(theTime))

    def queryGALT(self) -> Any:
        """The greatest time this federate may be granted now; None when nothing holds it back."""
        galt = self._inner().queryLBTS()
        return None if galt == float("inf") else self._time_out(galt)

    def queryLogicalTime(self) -> Any:
        """This federate's logical time."""
        return self._time_out(self._inner().queryFederateTime())

    def queryLITS(self) -> Any:
        """The least timestamp this federate may still receive; None when none can come."""
        lits = self._inner().queryMinNextEventTime()
        return None if lits == float("inf") else self._time_out(lits)

    def modifyLookahead(self, theLookahead: Any) -> None:
        """Change the lookahead."""
        self._inner().modifyLookahead(self._time_in(theLookahead))

    def queryLookahead(self) -> Any:
        """The lookahead."""
        return self._time_out(self._inner().queryLookahead())

    def retract(self, theHandle: Any) -> None:
        """Retract a timestamped message this federate sent."""
        self._inner().retract(core(MessageRetractionHandle, theHandle))

    def changeAttributeOrderType(self, theObject: Any, theAttributes: Iterable[Any], theType: Any) -> None:
        """Send these attributes of the object in another order."""
        self._inner().changeAttributeOrderType(core(ObjectInstanceHandle, theObject), cores(AttributeHandle, theAttributes),
                                               self._order(theType))

    def changeInteractionOrderType(self, theClass: Any, theType: Any) -> None:
        """Send the interaction class in another order."""
        self._inner().changeInteractionOrderType(core(InteractionClassHandle, theClass), self._order(theType))

    # ---- support services (§10) ----
    def getAutomaticResignDirective(self) -> int:
        """The resign action this federate asked for should its connection be lost."""
        return self._resign_directive

    def setAutomaticResignDirective(self, resignAction: Any) -> None:
        """Only the action the gateway takes for a federate that vanishes is served (it deletes the objects
        the federate may delete and releases the rest: CANCEL_THEN_DELETE_THEN_DIVEST)."""
        action = e.enum_value(resignAction, e.RESIGN_ACTIONS, x.InvalidResignAction, "resign action")
        if action != e.CANCEL_THEN_DELETE_THEN_DIVEST:
            raise not_served("another automatic resign action", "the gateway deletes and divests a vanished federate")
        self._resign_directive = action

    def _federation(self) -> Dict[str, Any]:
        """This federate's federation in the gateway's status report."""
        me = self._inner()._federate_handle()
        for federation in self._report()["federations"]:
            if any(f["handle"] == int(me) and f["name"] == (self._adapter.federate_name if self._adapter else "")
                   for f in federation["federates"]):
                return dict(federation)
        raise x.FederateNotExecutionMember("FederateNotExecutionMember: not in the gateway's report")

    def _federates(self) -> List[Dict[str, Any]]:
        return list(self._federation()["federates"])

    def queryFederationSaveStatus(self) -> None:
        """Ask each federate's save status: ``federationSaveStatusResponse([(FederateHandle, status)])``,
        from the gateway's record: NO_SAVE_IN_PROGRESS, FEDERATE_INSTRUCTED_TO_SAVE (this federate:
        FEDERATE_SAVING after federateSaveBegun), FEDERATE_WAITING_FOR_FEDERATION_TO_SAVE once it completed."""
        federation = self._federation()
        save = federation["save_restore"]
        told, answered = set(save.get("told", ())), set(save.get("answered", ()))
        me = int(self._inner()._federate_handle())
        statuses = []
        for f in federation["federates"]:
            h = f["handle"]
            if save["state"] not in ("saving", "waiting for the save time") or h not in told:
                status = e.NO_SAVE_IN_PROGRESS
            elif h in answered:
                status = e.FEDERATE_WAITING_FOR_FEDERATION_TO_SAVE
            else:
                status = e.FEDERATE_SAVING if h == me and self._saving else e.FEDERATE_INSTRUCTED_TO_SAVE
            statuses.append((FederateHandle.wrap(_core._federate_handle_of(h)), status))
        assert self._adapter is not None
        self._adapter.local.append(("federationSaveStatusResponse", (statuses,)))

    def queryFederationRestoreStatus(self) -> None:
        """Ask each federate's restore status: ``federationRestoreStatusResponse([(handle before, handle
        after, status)])`` (the core keeps each federate's handle): NO_RESTORE_IN_PROGRESS, FEDERATE_RESTORING,
        FEDERATE_WAITING_FOR_FEDERATION_TO_RESTORE once it completed."""
        federation = self._federation()
        restore = federation["save_restore"]
        answered = set(restore.get("answered", ()))
        statuses = []
        for f in federation["federates"]:
            h = FederateHandle.wrap(_core._federate_handle_of(f["handle"]))
            status = (e.NO_RESTORE_IN_PROGRESS if restore["state"] != "restoring" else
                      e.FEDERATE_WAITING_FOR_FEDERATION_TO_RESTORE if f["handle"] in answered else e.FEDERATE_RESTORING)
            statuses.append((h, h, status))
        assert self._adapter is not None
        self._adapter.local.append(("federationRestoreStatusResponse", (statuses,)))

    def getFederateHandle(self, theName: str) -> FederateHandle:
        """The handle of the joined federate named ``theName``."""
        for f in self._federates():
            if f["name"] == theName:
                return FederateHandle.wrap(_core._federate_handle_of(f["handle"]))
        raise x.NameNotFound(f"NameNotFound: no federate named {theName!r} is joined")

    def getFederateName(self, theHandle: Any) -> str:
        """The name of a joined federate."""
        wanted = int(core(FederateHandle, theHandle))
        for f in self._federates():
            if f["handle"] == wanted:
                return str(f["name"])
        raise x.FederateHandleNotKnown(f"FederateHandleNotKnown: no federate {wanted} is joined")

    # ---- the names and handles of classes, objects, attributes and parameters: added after the class ----

    def getTransportationType(self, transportationName: str) -> int:
        """RELIABLE for ``"HLAreliable"``, BEST_EFFORT for ``"HLAbestEffort"``."""
        try:
            return int(self._inner().getTransportationHandle(transportationName))
        except _core.NameNotFound as error:
            raise x.InvalidTransportationName(f"InvalidTransportationName: {error}") from None

    def getUpdateRateValue(self, updateRateDesignator: str) -> float:
        """The rate, in updates a second, of an update rate the FOM modules declare."""
        return float(self._inner()._update_rate(updateRateDesignator))

    def getUpdateRateValueForAttribute(self, theObject: Any, theAttribute: Any) -> float:
        """The update rate this federate's subscription of the object's class asks for (0: none)."""
        return float(self._inner()._update_rate_for(core(ObjectInstanceHandle, theObject), core(AttributeHandle, theAttribute)))

    def getTransportationName(self, transportationType: Any) -> str:
        """``"HLAreliable"`` or ``"HLAbestEffort"``."""
        return self._inner().getTransportationName(self._transport(transportationType))

    def getOrderType(self, orderName: str) -> int:
        """RECEIVE or TIMESTAMP by name (``"Receive"``, ``"TimeStamp"``, any case)."""
        wanted = {"receive": e.RECEIVE, "timestamp": e.TIMESTAMP}.get(str(orderName).lower())
        if wanted is None:
            raise x.InvalidOrderName(f"InvalidOrderName: {orderName!r} (Receive, TimeStamp)")
        return wanted

    def getOrderName(self, orderType: Any) -> str:
        """``"Receive"`` or ``"TimeStamp"``."""
        return {e.RECEIVE: "Receive", e.TIMESTAMP: "TimeStamp"}[e.enum_value(orderType, e.ORDER_TYPES,
                                                                            x.InvalidOrderType, "order type")]

    # ---- the advisory switches: enable<Switch> and disable<Switch>, added after the class ----

    def normalizeFederateHandle(self, theFederateHandle: Any) -> int:
        """The federate handle as an integer."""
        return int(core(FederateHandle, theFederateHandle))

    def normalizeServiceGroup(self, theServiceGroup: Any) -> int:
        """The service group as an integer."""
        return e.enum_value(theServiceGroup, e.SERVICE_GROUPS, x.InvalidServiceGroup, "service group")

    # ---- decoding handles: decode<Kind>Handle for each kind, added after the class ----
    def decodeMessageRetractionHandle(self, encodedValue: Any) -> MessageRetractionHandle:
        """The MessageRetractionHandle ``encode()`` gave these 12 bytes for (the sender's 4, the serial's 8)."""
        raw = bytes(encodedValue)
        if len(raw) != 12:
            raise x.CouldNotDecode(f"CouldNotDecode: a MessageRetractionHandle is 12 bytes, not {len(raw)}")
        sender, serial = int.from_bytes(raw[:4], "big"), int.from_bytes(raw[4:], "big")
        return MessageRetractionHandle.wrap(_core._retraction_handle(sender, serial))

    # ---- callbacks ----
    def _deliveries(self) -> Delivery:
        self._inner()
        assert self._delivery is not None
        return self._delivery

    def evokeCallback(self, approximateMinimumTimeInSeconds: Any) -> bool:
        """Deliver one callback, waiting up to the time given for one; returns whether more are pending
        (HLA_IMMEDIATE: delivers none, the ambassador's thread does)."""
        return self._deliveries().one(float(approximateMinimumTimeInSeconds))

    def evokeMultipleCallbacks(self, approximateMinimumTimeInSeconds: Any, approximateMaximumTimeInSeconds: Any) -> bool:
        """Deliver callbacks: wait up to the minimum time for the first, then deliver for up to the maximum."""
        return self._deliveries().many(float(approximateMinimumTimeInSeconds), float(approximateMaximumTimeInSeconds))

    def enableCallbacks(self) -> None:
        """Deliver callbacks again."""
        self._deliveries().set_enabled(True)

    def disableCallbacks(self) -> None:
        """Hold callbacks back until :meth:`enableCallbacks`."""
        self._deliveries().set_enabled(False)

    def getTimeFactory(self) -> str:
        """The federation's time type's name (``"HLAfloat64Time"`` or ``"HLAinteger64Time"``): times are
        Python floats or ints, so no factory object is needed."""
        self._inner()
        return "HLAinteger64Time" if self._integer_time else "HLAfloat64Time"


def _decoder(kind: Type[Handle]) -> Callable[[RTIambassador, Any], Any]:
    def decode_handle(self: RTIambassador, encodedValue: Any) -> Any:
        return decode(kind, encodedValue, CORE_TYPES[kind])
    decode_handle.__name__ = f"decode{kind.__name__}"
    decode_handle.__doc__ = f"The {kind.__name__} ``encode()`` gave these bytes for; raises ``CouldNotDecode``."
    return translating(decode_handle)


def _switch(switch: str, core_name: str, on: bool) -> Callable[[RTIambassador], None]:
    def set_switch(self: RTIambassador) -> None:
        getattr(self._inner(), ("enable" if on else "disable") + core_name)()
    set_switch.__name__ = ("enable" if on else "disable") + switch
    set_switch.__doc__ = f"Turn the {switch[:-len('AdvisorySwitch')]} advisory switch {'on' if on else 'off'}."
    return translating(set_switch)


def _lookup(core_name: str, result: type, kinds: Tuple[type, ...], doc: str) -> Callable[..., Any]:
    def look_up(self: RTIambassador, *args: Any) -> Any:
        if len(args) != len(kinds):
            raise TypeError(f"{name} takes {len(kinds)} argument(s), not {len(args)}")
        given = [a if kind is str else core(kind, a) for kind, a in zip(kinds, args)]
        found = getattr(self._inner(), core_name)(*reversed(given))  # HLA 1.3 puts the class last
        return found if result is str else result.wrap(found)  # type: ignore[attr-defined]
    name = core_name if core_name != "getObjectClass" else "getKnownObjectClassHandle"
    look_up.__name__, look_up.__doc__ = name, doc
    return translating(look_up)


# 1516-2010's lookups: the core's service (which takes the arguments in the reverse order), what it gives, the
# arguments' kinds (str: a name), the docstring.
_LOOKUPS = (
    ("getObjectClassHandle", ObjectClassHandle, (str,), "The handle of an object class by its name (qualified or "
     "not, with or without ``HLAobjectRoot.``)."),
    ("getObjectClassName", str, (ObjectClassHandle,), "The object class's name."),
    ("getObjectClass", ObjectClassHandle, (ObjectInstanceHandle,), "The class this federate knows the object as."),
    ("getObjectInstanceHandle", ObjectInstanceHandle, (str,), "The handle of a known object by its name."),
    ("getObjectInstanceName", str, (ObjectInstanceHandle,), "A known object's name."),
    ("getAttributeHandle", AttributeHandle, (ObjectClassHandle, str), "The handle of an attribute of the class."),
    ("getAttributeName", str, (ObjectClassHandle, AttributeHandle), "An attribute's name."),
    ("getInteractionClassHandle", InteractionClassHandle, (str,), "The handle of an interaction class by its name."),
    ("getInteractionClassName", str, (InteractionClassHandle,), "The interaction class's name."),
    ("getParameterHandle", ParameterHandle, (InteractionClassHandle, str), "The handle of a parameter of the class."),
    ("getParameterName", str, (InteractionClassHandle, ParameterHandle), "A parameter's name."),
)
for _core_name, _result, _kinds, _doc in _LOOKUPS:
    _method = _lookup(_core_name, _result, _kinds, _doc)
    setattr(RTIambassador, _method.__name__, _method)
for _kind in CORE_TYPES:
    setattr(RTIambassador, f"decode{_kind.__name__}", _decoder(_kind))
for _name, _core_name in (("ObjectClassRelevanceAdvisorySwitch", "ClassRelevanceAdvisorySwitch"),
                          ("AttributeRelevanceAdvisorySwitch", "AttributeRelevanceAdvisorySwitch"),
                          ("AttributeScopeAdvisorySwitch", "AttributeScopeAdvisorySwitch"),
                          ("InteractionRelevanceAdvisorySwitch", "InteractionRelevanceAdvisorySwitch")):
    for _on in (True, False):
        setattr(RTIambassador, ("enable" if _on else "disable") + _name, _switch(_name, _core_name, _on))

def _passed(name: str, doc: str) -> Callable[[RTIambassador], None]:
    def service(self: RTIambassador) -> None:
        getattr(self._inner(), name)()
    service.__name__, service.__doc__ = name, doc
    return translating(service)


# The services without arguments that are the core's own: name -> docstring.
_PASSED = {
    "federateRestoreComplete": "This federate restored its state.",
    "federateRestoreNotComplete": "This federate could not restore its state.",
    "disableTimeRegulation": "Stop being time-regulating.",
    "enableTimeConstrained": "Become time-constrained (``timeConstrainedEnabled`` then).",
    "disableTimeConstrained": "Stop being time-constrained.",
    "enableAsynchronousDelivery": "Deliver receive-order messages while not advancing too.",
    "disableAsynchronousDelivery": "Deliver receive-order messages only while advancing.",
}
for _name, _doc in _PASSED.items():
    setattr(RTIambassador, _name, _passed(_name, _doc))
