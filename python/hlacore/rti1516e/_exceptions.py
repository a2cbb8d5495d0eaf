"""IEEE 1516-2010's exceptions, one class each named as in C++ (``rti1516e::NameNotFound`` is
:class:`NameNotFound`), all direct subclasses of :class:`Exception` (this module's, itself a subclass of
Python's). Every service of :class:`~hlacore.rti1516e.RTIambassador` raises these; the HLA 1.3 core's own
exceptions are translated by :func:`translate` (``ObjectNotKnown`` becomes :class:`ObjectInstanceNotKnown`, ...).
"""

from __future__ import annotations

import builtins
from typing import Dict, Type

from .. import _core


class Exception(builtins.Exception):  # noqa: A001  (rti1516e.Exception is the standard's base class)
    """The base class of every IEEE 1516-2010 exception; its text is ``"<Name>: <reason>"``."""


def _exception(name: str) -> Type[Exception]:
    return type(name, (Exception,), {"__module__": "hlacore.rti1516e",
                                     "__doc__": f"IEEE 1516-2010's {name} (rti1516e::{name})."})


AlreadyConnected = _exception("AlreadyConnected")
AsynchronousDeliveryAlreadyDisabled = _exception("AsynchronousDeliveryAlreadyDisabled")
AsynchronousDeliveryAlreadyEnabled = _exception("AsynchronousDeliveryAlreadyEnabled")
AttributeAcquisitionWasNotCanceled = _exception("AttributeAcquisitionWasNotCanceled")
AttributeAcquisitionWasNotRequested = _exception("AttributeAcquisitionWasNotRequested")
AttributeAlreadyBeingAcquired = _exception("AttributeAlreadyBeingAcquired")
AttributeAlreadyBeingChanged = _exception("AttributeAlreadyBeingChanged")
AttributeAlreadyBeingDivested = _exception("AttributeAlreadyBeingDivested")
AttributeAlreadyOwned = _exception("AttributeAlreadyOwned")
AttributeDivestitureWasNotRequested = _exception("AttributeDivestitureWasNotRequested")
AttributeNotDefined = _exception("AttributeNotDefined")
AttributeNotOwned = _exception("AttributeNotOwned")
AttributeNotPublished = _exception("AttributeNotPublished")
AttributeNotRecognized = _exception("AttributeNotRecognized")
AttributeNotSubscribed = _exception("AttributeNotSubscribed")
AttributeRelevanceAdvisorySwitchIsOff = _exception("AttributeRelevanceAdvisorySwitchIsOff")
AttributeRelevanceAdvisorySwitchIsOn = _exception("AttributeRelevanceAdvisorySwitchIsOn")
AttributeScopeAdvisorySwitchIsOff = _exception("AttributeScopeAdvisorySwitchIsOff")
AttributeScopeAdvisorySwitchIsOn = _exception("AttributeScopeAdvisorySwitchIsOn")
BadInitializationParameter = _exception("BadInitializationParameter")
CallNotAllowedFromWithinCallback = _exception("CallNotAllowedFromWithinCallback")
ConnectionFailed = _exception("ConnectionFailed")
CouldNotCreateLogicalTimeFactory = _exception("CouldNotCreateLogicalTimeFactory")
CouldNotDecode = _exception("CouldNotDecode")
CouldNotDiscover = _exception("CouldNotDiscover")
CouldNotEncode = _exception("CouldNotEncode")
CouldNotOpenFDD = _exception("CouldNotOpenFDD")
CouldNotOpenMIM = _exception("CouldNotOpenMIM")
CouldNotInitiateRestore = _exception("CouldNotInitiateRestore")
DeletePrivilegeNotHeld = _exception("DeletePrivilegeNotHeld")
DesignatorIsHLAstandardMIM = _exception("DesignatorIsHLAstandardMIM")
ErrorReadingMIM = _exception("ErrorReadingMIM")
RequestForTimeConstrainedPending = _exception("RequestForTimeConstrainedPending")
NoRequestToEnableTimeConstrainedWasPending = _exception("NoRequestToEnableTimeConstrainedWasPending")
RequestForTimeRegulationPending = _exception("RequestForTimeRegulationPending")
NoRequestToEnableTimeRegulationWasPending = _exception("NoRequestToEnableTimeRegulationWasPending")
NoFederateWillingToAcquireAttribute = _exception("NoFederateWillingToAcquireAttribute")
ErrorReadingFDD = _exception("ErrorReadingFDD")
FederateAlreadyExecutionMember = _exception("FederateAlreadyExecutionMember")
FederateHasNotBegunSave = _exception("FederateHasNotBegunSave")
FederateInternalError = _exception("FederateInternalError")
FederateIsExecutionMember = _exception("FederateIsExecutionMember")
FederateNameAlreadyInUse = _exception("FederateNameAlreadyInUse")
FederateNotExecutionMember = _exception("FederateNotExecutionMember")
FederateHandleNotKnown = _exception("FederateHandleNotKnown")
FederateOwnsAttributes = _exception("FederateOwnsAttributes")
FederateServiceInvocationsAreBeingReportedViaMOM = _exception("FederateServiceInvocationsAreBeingReportedViaMOM")
FederateUnableToUseTime = _exception("FederateUnableToUseTime")
FederatesCurrentlyJoined = _exception("FederatesCurrentlyJoined")
FederationExecutionAlreadyExists = _exception("FederationExecutionAlreadyExists")
FederationExecutionDoesNotExist = _exception("FederationExecutionDoesNotExist")
IllegalName = _exception("IllegalName")
IllegalTimeArithmetic = _exception("IllegalTimeArithmetic")
InconsistentFDD = _exception("InconsistentFDD")
InteractionClassAlreadyBeingChanged = _exception("InteractionClassAlreadyBeingChanged")
InteractionClassNotDefined = _exception("InteractionClassNotDefined")
InteractionClassNotPublished = _exception("InteractionClassNotPublished")
InteractionClassNotRecognized = _exception("InteractionClassNotRecognized")
InteractionClassNotSubscribed = _exception("InteractionClassNotSubscribed")
InteractionParameterNotDefined = _exception("InteractionParameterNotDefined")
InteractionParameterNotRecognized = _exception("InteractionParameterNotRecognized")
InteractionRelevanceAdvisorySwitchIsOff = _exception("InteractionRelevanceAdvisorySwitchIsOff")
InteractionRelevanceAdvisorySwitchIsOn = _exception("InteractionRelevanceAdvisorySwitchIsOn")
InTimeAdvancingState = _exception("InTimeAdvancingState")
InvalidAttributeHandle = _exception("InvalidAttributeHandle")
InvalidDimensionHandle = _exception("InvalidDimensionHandle")
InvalidFederateHandle = _exception("InvalidFederateHandle")
InvalidInteractionClassHandle = _exception("InvalidInteractionClassHandle")
InvalidLocalSettingsDesignator = _exception("InvalidLocalSettingsDesignator")
InvalidLogicalTime = _exception("InvalidLogicalTime")
InvalidLogicalTimeInterval = _exception("InvalidLogicalTimeInterval")
InvalidLookahead = _exception("InvalidLookahead")
InvalidObjectClassHandle = _exception("InvalidObjectClassHandle")
InvalidOrderName = _exception("InvalidOrderName")
InvalidOrderType = _exception("InvalidOrderType")
InvalidParameterHandle = _exception("InvalidParameterHandle")
InvalidRangeBound = _exception("InvalidRangeBound")
InvalidRegion = _exception("InvalidRegion")
InvalidRegionContext = _exception("InvalidRegionContext")
InvalidResignAction = _exception("InvalidResignAction")
InvalidUpdateRateDesignator = _exception("InvalidUpdateRateDesignator")
InvalidMessageRetractionHandle = _exception("InvalidMessageRetractionHandle")
InvalidServiceGroup = _exception("InvalidServiceGroup")
InvalidTransportationName = _exception("InvalidTransportationName")
InvalidTransportationType = _exception("InvalidTransportationType")
JoinedFederateIsNotInTimeAdvancingState = _exception("JoinedFederateIsNotInTimeAdvancingState")
LogicalTimeAlreadyPassed = _exception("LogicalTimeAlreadyPassed")
MessageCanNoLongerBeRetracted = _exception("MessageCanNoLongerBeRetracted")
NameNotFound = _exception("NameNotFound")
NameSetWasEmpty = _exception("NameSetWasEmpty")
NoAcquisitionPending = _exception("NoAcquisitionPending")
NotConnected = _exception("NotConnected")
ObjectClassNotDefined = _exception("ObjectClassNotDefined")
ObjectClassNotKnown = _exception("ObjectClassNotKnown")
ObjectClassNotPublished = _exception("ObjectClassNotPublished")
ObjectClassRelevanceAdvisorySwitchIsOff = _exception("ObjectClassRelevanceAdvisorySwitchIsOff")
ObjectClassRelevanceAdvisorySwitchIsOn = _exception("ObjectClassRelevanceAdvisorySwitchIsOn")
ObjectInstanceNameInUse = _exception("ObjectInstanceNameInUse")
ObjectInstanceNameNotReserved = _exception("ObjectInstanceNameNotReserved")
ObjectInstanceNotKnown = _exception("ObjectInstanceNotKnown")
OwnershipAcquisitionPending = _exception("OwnershipAcquisitionPending")
RTIinternalError = _exception("RTIinternalError")
RegionDoesNotContainSpecifiedDimension = _exception("RegionDoesNotContainSpecifiedDimension")
RegionInUseForUpdateOrSubscription = _exception("RegionInUseForUpdateOrSubscription")
RegionNotCreatedByThisFederate = _exception("RegionNotCreatedByThisFederate")
RestoreInProgress = _exception("RestoreInProgress")
RestoreNotInProgress = _exception("RestoreNotInProgress")
RestoreNotRequested = _exception("RestoreNotRequested")
SaveInProgress = _exception("SaveInProgress")
SaveNotInProgress = _exception("SaveNotInProgress")
SaveNotInitiated = _exception("SaveNotInitiated")
SpecifiedSaveLabelDoesNotExist = _exception("SpecifiedSaveLabelDoesNotExist")
SynchronizationPointLabelNotAnnounced = _exception("SynchronizationPointLabelNotAnnounced")
TimeConstrainedAlreadyEnabled = _exception("TimeConstrainedAlreadyEnabled")
TimeConstrainedIsNotEnabled = _exception("TimeConstrainedIsNotEnabled")
TimeRegulationAlreadyEnabled = _exception("TimeRegulationAlreadyEnabled")
TimeRegulationIsNotEnabled = _exception("TimeRegulationIsNotEnabled")
UnableToPerformSave = _exception("UnableToPerformSave")
UnknownName = _exception("UnknownName")
UnsupportedCallbackModel = _exception("UnsupportedCallbackModel")
InternalError = _exception("InternalError")

NAMES = tuple("""
AlreadyConnected AsynchronousDeliveryAlreadyDisabled AsynchronousDeliveryAlreadyEnabled
AttributeAcquisitionWasNotCanceled AttributeAcquisitionWasNotRequested AttributeAlreadyBeingAcquired
AttributeAlreadyBeingChanged AttributeAlreadyBeingDivested AttributeAlreadyOwned
AttributeDivestitureWasNotRequested AttributeNotDefined AttributeNotOwned AttributeNotPublished
AttributeNotRecognized AttributeNotSubscribed AttributeRelevanceAdvisorySwitchIsOff
AttributeRelevanceAdvisorySwitchIsOn AttributeScopeAdvisorySwitchIsOff AttributeScopeAdvisorySwitchIsOn
BadInitializationParameter CallNotAllowedFromWithinCallback ConnectionFailed CouldNotCreateLogicalTimeFactory
CouldNotDecode CouldNotDiscover CouldNotEncode CouldNotOpenFDD CouldNotOpenMIM CouldNotInitiateRestore
DeletePrivilegeNotHeld DesignatorIsHLAstandardMIM ErrorReadingMIM RequestForTimeConstrainedPending
NoRequestToEnableTimeConstrainedWasPending RequestForTimeRegulationPending
NoRequestToEnableTimeRegulationWasPending NoFederateWillingToAcquireAttribute ErrorReadingFDD FederateAlreadyExecutionMember FederateHasNotBegunSave
FederateInternalError FederateIsExecutionMember FederateNameAlreadyInUse FederateNotExecutionMember
FederateHandleNotKnown FederateOwnsAttributes FederateServiceInvocationsAreBeingReportedViaMOM
FederateUnableToUseTime FederatesCurrentlyJoined FederationExecutionAlreadyExists
FederationExecutionDoesNotExist IllegalName IllegalTimeArithmetic InconsistentFDD
InteractionClassAlreadyBeingChanged InteractionClassNotDefined InteractionClassNotPublished
InteractionClassNotRecognized InteractionClassNotSubscribed InteractionParameterNotDefined
InteractionParameterNotRecognized InteractionRelevanceAdvisorySwitchIsOff InteractionRelevanceAdvisorySwitchIsOn
InTimeAdvancingState InvalidAttributeHandle InvalidDimensionHandle InvalidFederateHandle
InvalidInteractionClassHandle InvalidLocalSettingsDesignator InvalidLogicalTime InvalidLogicalTimeInterval
InvalidLookahead InvalidObjectClassHandle InvalidOrderName InvalidOrderType InvalidParameterHandle
InvalidRangeBound InvalidRegion InvalidRegionContext InvalidResignAction InvalidUpdateRateDesignator
InvalidMessageRetractionHandle InvalidServiceGroup InvalidTransportationName InvalidTransportationType
JoinedFederateIsNotInTimeAdvancingState LogicalTimeAlreadyPassed MessageCanNoLongerBeRetracted NameNotFound
NameSetWasEmpty NoAcquisitionPending NotConnected ObjectClassNotDefined ObjectClassNotKnown
ObjectClassNotPublished ObjectClassRelevanceAdvisorySwitchIsOff ObjectClassRelevanceAdvisorySwitchIsOn
ObjectInstanceNameInUse ObjectInstanceNameNotReserved ObjectInstanceNotKnown OwnershipAcquisitionPending
RTIinternalError RegionDoesNotContainSpecifiedDimension RegionInUseForUpdateOrSubscription
RegionNotCreatedByThisFederate RestoreInProgress RestoreNotInProgress RestoreNotRequested SaveInProgress
SaveNotInProgress SaveNotInitiated SpecifiedSaveLabelDoesNotExist SynchronizationPointLabelNotAnnounced
TimeConstrainedAlreadyEnabled TimeConstrainedIsNotEnabled TimeRegulationAlreadyEnabled
TimeRegulationIsNotEnabled UnableToPerformSave UnknownName UnsupportedCallbackModel InternalError
""".split())
__all__ = ["Exception", *NAMES]

# The HLA 1.3 core's exceptions that IEEE 1516-2010 names otherwise (the rest keep their names; hlacore's own,
# and those with no 1516-2010 counterpart, become RTIinternalError).
_RENAMED: Dict[str, str] = {
    "AttributeNotKnown": "AttributeNotDefined", "ConcurrentAccessAttempted": "CallNotAllowedFromWithinCallback",
    "CouldNotOpenFED": "CouldNotOpenFDD", "CouldNotRestore": "CouldNotInitiateRestore",
    "DimensionNotDefined": "InvalidDimensionHandle", "EnableTimeConstrainedPending": "RequestForTimeConstrainedPending",
    "EnableTimeConstrainedWasNotPending": "NoRequestToEnableTimeConstrainedWasPending",
    "EnableTimeRegulationPending": "RequestForTimeRegulationPending",
    "EnableTimeRegulationWasNotPending": "NoRequestToEnableTimeRegulationWasPending",
    "ErrorReadingFED": "ErrorReadingFDD", "EventNotKnown": "MessageCanNoLongerBeRetracted",
    "FederateLoggingServiceCalls": "FederateServiceInvocationsAreBeingReportedViaMOM",
    "FederateWasNotAskedToReleaseAttribute": "AttributeDivestitureWasNotRequested",
    "FederationTimeAlreadyPassed": "LogicalTimeAlreadyPassed", "InteractionClassNotKnown": "InteractionClassNotRecognized",
    "InteractionParameterNotKnown": "InteractionParameterNotRecognized", "InvalidExtents": "InvalidRangeBound",
    "InvalidFederationTime": "InvalidLogicalTime", "InvalidOrderingHandle": "InvalidOrderType",
    "InvalidRetractionHandle": "InvalidMessageRetractionHandle", "InvalidTransportationHandle": "InvalidTransportationType",
    "ObjectAlreadyRegistered": "ObjectInstanceNameInUse", "ObjectNotKnown": "ObjectInstanceNotKnown",
    "RegionInUse": "RegionInUseForUpdateOrSubscription", "RegionNotKnown": "InvalidRegion",
    "SpaceNotDefined": "InvalidDimensionHandle", "SynchronizationPointLabelWasNotAnnounced": "SynchronizationPointLabelNotAnnounced",
    "TimeAdvanceAlreadyInProgress": "InTimeAdvancingState",
    "TimeAdvanceWasNotInProgress": "JoinedFederateIsNotInTimeAdvancingState",
    "TimeConstrainedWasNotEnabled": "TimeConstrainedIsNotEnabled", "TimeRegulationWasNotEnabled": "TimeRegulationIsNotEnabled",
    "GatewayNotResponding": "NotConnected",
}


def translate(error: _core.RTIexception) -> Exception:
    """The IEEE 1516-2010 exception for an HLA 1.3 one raised by the core, with the same reason."""
    name = type(error).__name__
    name = "InconsistentFDD" if getattr(error, "inconsistent", False) else _RENAMED.get(name, name)
    cls = globals().get(name) if name in NAMES else None
    if cls is None:
        name, cls = "RTIinternalError", RTIinternalError
    return cls(f"{name}: {error}")
