// The HLA 1.3 exceptions, declared once: the same names and codes in C++, on the wire and in Python
// (where each becomes a subclass of rti.RTIexception). Append only: the position is the wire code.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "rti/list_codes.hpp"

#define HLACORE_EXCEPTIONS(X)                   \
    X(ArrayIndexOutOfBounds)                    \
    X(AsynchronousDeliveryAlreadyDisabled)      \
    X(AsynchronousDeliveryAlreadyEnabled)       \
    X(AttributeAcquisitionWasNotRequested)      \
    X(AttributeAcquisitionWasNotCanceled)       \
    X(AttributeAlreadyBeingAcquired)            \
    X(AttributeAlreadyBeingDivested)            \
    X(AttributeAlreadyOwned)                    \
    X(AttributeDivestitureWasNotRequested)      \
    X(AttributeNotDefined)                      \
    X(AttributeNotKnown)                        \
    X(AttributeNotOwned)                        \
    X(AttributeNotPublished)                    \
    X(ConcurrentAccessAttempted)                \
    X(CouldNotDiscover)                         \
    X(CouldNotOpenFED)                          \
    X(CouldNotRestore)                          \
    X(DeletePrivilegeNotHeld)                   \
    X(DimensionNotDefined)                      \
    X(EnableTimeConstrainedPending)             \
    X(EnableTimeConstrainedWasNotPending)       \
    X(EnableTimeRegulationPending)              \
    X(EnableTimeRegulationWasNotPending)        \
    X(ErrorReadingFED)                          \
    X(EventNotKnown)                            \
    X(FederateAlreadyExecutionMember)           \
    X(FederateInternalError)                    \
    X(FederateLoggingServiceCalls)              \
    X(FederateNotExecutionMember)               \
    X(FederateOwnsAttributes)                   \
    X(FederateWasNotAskedToReleaseAttribute)    \
    X(FederatesCurrentlyJoined)                 \
    X(FederationExecutionAlreadyExists)         \
    X(FederationExecutionDoesNotExist)          \
    X(FederationTimeAlreadyPassed)              \
    X(HandleValuePairMaximumExceeded)           \
    X(InteractionClassNotDefined)               \
    X(InteractionClassNotKnown)                 \
    X(InteractionClassNotPublished)             \
    X(InteractionClassNotSubscribed)            \
    X(InteractionParameterNotDefined)           \
    X(InteractionParameterNotKnown)             \
    X(InvalidExtents)                           \
    X(InvalidFederationTime)                    \
    X(InvalidHandleValuePairSetContext)         \
    X(InvalidLookahead)                         \
    X(InvalidOrderingHandle)                    \
    X(InvalidRegionContext)                     \
    X(InvalidResignAction)                      \
    X(InvalidRetractionHandle)                  \
    X(InvalidTransportationHandle)              \
    X(MemoryExhausted)                          \
    X(NameNotFound)                             \
    X(ObjectClassNotDefined)                    \
    X(ObjectClassNotKnown)                      \
    X(ObjectClassNotPublished)                  \
    X(ObjectClassNotSubscribed)                 \
    X(ObjectNotKnown)                           \
    X(ObjectAlreadyRegistered)                  \
    X(OwnershipAcquisitionPending)              \
    X(RegionInUse)                              \
    X(RegionNotKnown)                           \
    X(RestoreInProgress)                        \
    X(RestoreNotRequested)                      \
    X(RTIinternalError)                         \
    X(SpaceNotDefined)                          \
    X(SaveInProgress)                           \
    X(SaveNotInitiated)                         \
    X(SpecifiedSaveLabelDoesNotExist)           \
    X(SynchronizationPointLabelWasNotAnnounced) \
    X(TimeAdvanceAlreadyInProgress)             \
    X(TimeAdvanceWasNotInProgress)              \
    X(TimeConstrainedAlreadyEnabled)            \
    X(TimeConstrainedWasNotEnabled)             \
    X(TimeRegulationAlreadyEnabled)             \
    X(TimeRegulationWasNotEnabled)              \
    X(UnableToPerformSave)                      \
    X(ValueCountExceeded)                       \
    X(ValueLengthExceeded)                      \
    /* hlacore's own, each a subclass of RTIinternalError in Python (PyHLA code catching that still works) */ \
    X(GatewayNotResponding)                     \
    X(AuthenticationFailed)                     \
    /* IEEE 1516-2010's aborts with no save or restore under way */ \
    X(SaveNotInProgress)                        \
    X(RestoreNotInProgress)                     \
    /* IEEE 1516-2010's update rate named by no FOM module */ \
    X(InvalidUpdateRateDesignator)              \
    /* FOM modules added at join that contradict the federation's (IEEE 1516-2010's InconsistentFDD) */ \
    X(InconsistentFDD)

namespace hlacore {

enum class ErrorCode : std::uint16_t { HLACORE_LIST_CODES(None, HLACORE_EXCEPTIONS) };

// The code whose Python class is `code`'s base: RTIinternalError for hlacore's own, None (RTIexception) otherwise.
constexpr ErrorCode base_of(ErrorCode code) {
    return code > ErrorCode::ValueLengthExceeded && code < ErrorCode::Count ? ErrorCode::RTIinternalError : ErrorCode::None;
}

// Name of the exception, "" for None or an unknown code.
const char* error_name(ErrorCode code);

// An HLA exception raised by a service, carried as-is across the wire.
class RtiError : public std::runtime_error {
public:
    RtiError(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
    ErrorCode code() const { return code_; }

private:
    ErrorCode code_;
};

// Throws the RtiError that becomes the HLA exception `code` at the Python call.
[[noreturn]] inline void raise(ErrorCode code, const std::string& message) { throw RtiError(code, message); }
// A refusal's code off the wire; one this side does not know is an RTIinternalError.
constexpr ErrorCode error_code(std::uint16_t code) {
    return code < static_cast<std::uint16_t>(ErrorCode::Count) ? static_cast<ErrorCode>(code) : ErrorCode::RTIinternalError;
}

}  // namespace hlacore
