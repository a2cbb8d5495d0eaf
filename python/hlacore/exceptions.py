"""The HLA 1.3 exceptions, one class each, with the standard's names verbatim, and hlacore's own.

Every class is a subclass of :class:`~hlacore.rti.RTIexception`; the services of :mod:`hlacore.rti` raise
them and the same classes are reachable as ``hlacore.rti.<Name>``. The list is declared once in C++
(``HLACORE_EXCEPTIONS`` in ``cpp/rti/exceptions.hpp``, where the position is the wire code); this module
names the classes statically so that type checkers and readers see them (tests/rti/test_exceptions.py checks
that it matches the C++ list exactly). ``ErrorReadingFED`` carries ``file``, ``line`` and ``column`` of a
``.fed`` error. hlacore's own exceptions (``GatewayNotResponding``, ``AuthenticationFailed``, and
``SaveNotInProgress``, ``RestoreNotInProgress`` and ``InvalidUpdateRateDesignator`` of IEEE 1516-2010, and
``InconsistentFDD`` for FOM modules added at join that contradict the federation's) are subclasses of
:class:`~hlacore.rti.RTIinternalError`, so code written for PyHLA that catches that still catches them.
"""

from __future__ import annotations

from . import _core

RTIexception = _core.RTIexception

ArrayIndexOutOfBounds = _core.ArrayIndexOutOfBounds
AsynchronousDeliveryAlreadyDisabled = _core.AsynchronousDeliveryAlreadyDisabled
AsynchronousDeliveryAlreadyEnabled = _core.AsynchronousDeliveryAlreadyEnabled
AttributeAcquisitionWasNotRequested = _core.AttributeAcquisitionWasNotRequested
AttributeAcquisitionWasNotCanceled = _core.AttributeAcquisitionWasNotCanceled
AttributeAlreadyBeingAcquired = _core.AttributeAlreadyBeingAcquired
AttributeAlreadyBeingDivested = _core.AttributeAlreadyBeingDivested
AttributeAlreadyOwned = _core.AttributeAlreadyOwned
AttributeDivestitureWasNotRequested = _core.AttributeDivestitureWasNotRequested
AttributeNotDefined = _core.AttributeNotDefined
AttributeNotKnown = _core.AttributeNotKnown
AttributeNotOwned = _core.AttributeNotOwned
AttributeNotPublished = _core.AttributeNotPublished
ConcurrentAccessAttempted = _core.ConcurrentAccessAttempted
CouldNotDiscover = _core.CouldNotDiscover
CouldNotOpenFED = _core.CouldNotOpenFED
CouldNotRestore = _core.CouldNotRestore
DeletePrivilegeNotHeld = _core.DeletePrivilegeNotHeld
DimensionNotDefined = _core.DimensionNotDefined
EnableTimeConstrainedPending = _core.EnableTimeConstrainedPending
EnableTimeConstrainedWasNotPending = _core.EnableTimeConstrainedWasNotPending
EnableTimeRegulationPending = _core.EnableTimeRegulationPending
EnableTimeRegulationWasNotPending = _core.EnableTimeRegulationWasNotPending
ErrorReadingFED = _core.ErrorReadingFED
EventNotKnown = _core.EventNotKnown
FederateAlreadyExecutionMember = _core.FederateAlreadyExecutionMember
FederateInternalError = _core.FederateInternalError
FederateLoggingServiceCalls = _core.FederateLoggingServiceCalls
FederateNotExecutionMember = _core.FederateNotExecutionMember
FederateOwnsAttributes = _core.FederateOwnsAttributes
FederateWasNotAskedToReleaseAttribute = _core.FederateWasNotAskedToReleaseAttribute
FederatesCurrentlyJoined = _core.FederatesCurrentlyJoined
FederationExecutionAlreadyExists = _core.FederationExecutionAlreadyExists
FederationExecutionDoesNotExist = _core.FederationExecutionDoesNotExist
FederationTimeAlreadyPassed = _core.FederationTimeAlreadyPassed
HandleValuePairMaximumExceeded = _core.HandleValuePairMaximumExceeded
InteractionClassNotDefined = _core.InteractionClassNotDefined
InteractionClassNotKnown = _core.InteractionClassNotKnown
InteractionClassNotPublished = _core.InteractionClassNotPublished
InteractionClassNotSubscribed = _core.InteractionClassNotSubscribed
InteractionParameterNotDefined = _core.InteractionParameterNotDefined
InteractionParameterNotKnown = _core.InteractionParameterNotKnown
InvalidExtents = _core.InvalidExtents
InvalidFederationTime = _core.InvalidFederationTime
InvalidHandleValuePairSetContext = _core.InvalidHandleValuePairSetContext
InvalidLookahead = _core.InvalidLookahead
InvalidOrderingHandle = _core.InvalidOrderingHandle
InvalidRegionContext = _core.InvalidRegionContext
InvalidResignAction = _core.InvalidResignAction
InvalidRetractionHandle = _core.InvalidRetractionHandle
InvalidTransportationHandle = _core.InvalidTransportationHandle
MemoryExhausted = _core.MemoryExhausted
NameNotFound = _core.NameNotFound
ObjectClassNotDefined = _core.ObjectClassNotDefined
ObjectClassNotKnown = _core.ObjectClassNotKnown
ObjectClassNotPublished = _core.ObjectClassNotPublished
ObjectClassNotSubscribed = _core.ObjectClassNotSubscribed
ObjectNotKnown = _core.ObjectNotKnown
ObjectAlreadyRegistered = _core.ObjectAlreadyRegistered
OwnershipAcquisitionPending = _core.OwnershipAcquisitionPending
RegionInUse = _core.RegionInUse
RegionNotKnown = _core.RegionNotKnown
RestoreInProgress = _core.RestoreInProgress
RestoreNotRequested = _core.RestoreNotRequested
RTIinternalError = _core.RTIinternalError
SpaceNotDefined = _core.SpaceNotDefined
SaveInProgress = _core.SaveInProgress
SaveNotInitiated = _core.SaveNotInitiated
SpecifiedSaveLabelDoesNotExist = _core.SpecifiedSaveLabelDoesNotExist
SynchronizationPointLabelWasNotAnnounced = _core.SynchronizationPointLabelWasNotAnnounced
TimeAdvanceAlreadyInProgress = _core.TimeAdvanceAlreadyInProgress
TimeAdvanceWasNotInProgress = _core.TimeAdvanceWasNotInProgress
TimeConstrainedAlreadyEnabled = _core.TimeConstrainedAlreadyEnabled
TimeConstrainedWasNotEnabled = _core.TimeConstrainedWasNotEnabled
TimeRegulationAlreadyEnabled = _core.TimeRegulationAlreadyEnabled
TimeRegulationWasNotEnabled = _core.TimeRegulationWasNotEnabled
UnableToPerformSave = _core.UnableToPerformSave
ValueCountExceeded = _core.ValueCountExceeded
ValueLengthExceeded = _core.ValueLengthExceeded
# hlacore's own, each a subclass of RTIinternalError
GatewayNotResponding = _core.GatewayNotResponding
AuthenticationFailed = _core.AuthenticationFailed
SaveNotInProgress = _core.SaveNotInProgress
RestoreNotInProgress = _core.RestoreNotInProgress
InvalidUpdateRateDesignator = _core.InvalidUpdateRateDesignator
InconsistentFDD = _core.InconsistentFDD

__all__ = [
    "RTIexception",
    "ArrayIndexOutOfBounds",
    "AsynchronousDeliveryAlreadyDisabled",
    "AsynchronousDeliveryAlreadyEnabled",
    "AttributeAcquisitionWasNotRequested",
    "AttributeAcquisitionWasNotCanceled",
    "AttributeAlreadyBeingAcquired",
    "AttributeAlreadyBeingDivested",
    "AttributeAlreadyOwned",
    "AttributeDivestitureWasNotRequested",
    "AttributeNotDefined",
    "AttributeNotKnown",
    "AttributeNotOwned",
    "AttributeNotPublished",
    "ConcurrentAccessAttempted",
    "CouldNotDiscover",
    "CouldNotOpenFED",
    "CouldNotRestore",
    "DeletePrivilegeNotHeld",
    "DimensionNotDefined",
    "EnableTimeConstrainedPending",
    "EnableTimeConstrainedWasNotPending",
    "EnableTimeRegulationPending",
    "EnableTimeRegulationWasNotPending",
    "ErrorReadingFED",
    "EventNotKnown",
    "FederateAlreadyExecutionMember",
    "FederateInternalError",
    "FederateLoggingServiceCalls",
    "FederateNotExecutionMember",
    "FederateOwnsAttributes",
    "FederateWasNotAskedToReleaseAttribute",
    "FederatesCurrentlyJoined",
    "FederationExecutionAlreadyExists",
    "FederationExecutionDoesNotExist",
    "FederationTimeAlreadyPassed",
    "HandleValuePairMaximumExceeded",
    "InteractionClassNotDefined",
    "InteractionClassNotKnown",
    "InteractionClassNotPublished",
    "InteractionClassNotSubscribed",
    "InteractionParameterNotDefined",
    "InteractionParameterNotKnown",
    "InvalidExtents",
    "InvalidFederationTime",
    "InvalidHandleValuePairSetContext",
    "InvalidLookahead",
    "InvalidOrderingHandle",
    "InvalidRegionContext",
    "InvalidResignAction",
    "InvalidRetractionHandle",
    "InvalidTransportationHandle",
    "MemoryExhausted",
    "NameNotFound",
    "ObjectClassNotDefined",
    "ObjectClassNotKnown",
    "ObjectClassNotPublished",
    "ObjectClassNotSubscribed",
    "ObjectNotKnown",
    "ObjectAlreadyRegistered",
    "OwnershipAcquisitionPending",
    "RegionInUse",
    "RegionNotKnown",
    "RestoreInProgress",
    "RestoreNotRequested",
    "RTIinternalError",
    "SpaceNotDefined",
    "SaveInProgress",
    "SaveNotInitiated",
    "SpecifiedSaveLabelDoesNotExist",
    "SynchronizationPointLabelWasNotAnnounced",
    "TimeAdvanceAlreadyInProgress",
    "TimeAdvanceWasNotInProgress",
    "TimeConstrainedAlreadyEnabled",
    "TimeConstrainedWasNotEnabled",
    "TimeRegulationAlreadyEnabled",
    "TimeRegulationWasNotEnabled",
    "UnableToPerformSave",
    "ValueCountExceeded",
    "ValueLengthExceeded",
    "GatewayNotResponding",
    "AuthenticationFailed",
    "SaveNotInProgress",
    "RestoreNotInProgress",
    "InvalidUpdateRateDesignator",
    "InconsistentFDD",
]
