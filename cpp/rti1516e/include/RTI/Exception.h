// The exceptions of IEEE 1516.1-2010's C++ API: one class per name, each carrying the reason it was raised
// with. RTI1516E_EXCEPTIONS lists them (hlacore.rti1516e raises the same names in Python).
#ifndef RTI_Exception_h
#define RTI_Exception_h

#include <RTI/SpecificConfig.h>

#include <iosfwd>
#include <string>

namespace rti1516e {

class RTI_EXPORT Exception {
public:
    Exception() = default;
    Exception(Exception const&) = default;
    Exception& operator=(Exception const&) = default;
    virtual ~Exception();
    virtual std::wstring what() const noexcept = 0;
};

RTI_EXPORT std::wostream& operator<<(std::wostream& stream, Exception const& e);

#define RTI1516E_EXCEPTIONS(X) \
    X(AlreadyConnected) \
    X(AsynchronousDeliveryAlreadyDisabled) \
    X(AsynchronousDeliveryAlreadyEnabled) \
    X(AttributeAcquisitionWasNotCanceled) \
    X(AttributeAcquisitionWasNotRequested) \
    X(AttributeAlreadyBeingAcquired) \
    X(AttributeAlreadyBeingChanged) \
    X(AttributeAlreadyBeingDivested) \
    X(AttributeAlreadyOwned) \
    X(AttributeDivestitureWasNotRequested) \
    X(AttributeNotDefined) \
    X(AttributeNotOwned) \
    X(AttributeNotPublished) \
    X(AttributeNotRecognized) \
    X(AttributeNotSubscribed) \
    X(AttributeRelevanceAdvisorySwitchIsOff) \
    X(AttributeRelevanceAdvisorySwitchIsOn) \
    X(AttributeScopeAdvisorySwitchIsOff) \
    X(AttributeScopeAdvisorySwitchIsOn) \
    X(BadInitializationParameter) \
    X(CallNotAllowedFromWithinCallback) \
    X(ConnectionFailed) \
    X(CouldNotCreateLogicalTimeFactory) \
    X(CouldNotDecode) \
    X(CouldNotDiscover) \
    X(CouldNotEncode) \
    X(CouldNotOpenFDD) \
    X(CouldNotOpenMIM) \
    X(CouldNotInitiateRestore) \
    X(DeletePrivilegeNotHeld) \
    X(DesignatorIsHLAstandardMIM) \
    X(ErrorReadingMIM) \
    X(RequestForTimeConstrainedPending) \
    X(NoRequestToEnableTimeConstrainedWasPending) \
    X(RequestForTimeRegulationPending) \
    X(NoRequestToEnableTimeRegulationWasPending) \
    X(NoFederateWillingToAcquireAttribute) \
    X(ErrorReadingFDD) \
    X(FederateAlreadyExecutionMember) \
    X(FederateHasNotBegunSave) \
    X(FederateInternalError) \
    X(FederateIsExecutionMember) \
    X(FederateNameAlreadyInUse) \
    X(FederateNotExecutionMember) \
    X(FederateHandleNotKnown) \
    X(FederateOwnsAttributes) \
    X(FederateServiceInvocationsAreBeingReportedViaMOM) \
    X(FederateUnableToUseTime) \
    X(FederatesCurrentlyJoined) \
    X(FederationExecutionAlreadyExists) \
    X(FederationExecutionDoesNotExist) \
    X(IllegalName) \
    X(IllegalTimeArithmetic) \
    X(InconsistentFDD) \
    X(InteractionClassAlreadyBeingChanged) \
    X(InteractionClassNotDefined) \
    X(InteractionClassNotPublished) \
    X(InteractionClassNotRecognized) \
    X(InteractionClassNotSubscribed) \
    X(InteractionParameterNotDefined) \
    X(InteractionParameterNotRecognized) \
    X(InteractionRelevanceAdvisorySwitchIsOff) \
    X(InteractionRelevanceAdvisorySwitchIsOn) \
    X(InTimeAdvancingState) \
    X(InvalidAttributeHandle) \
    X(InvalidDimensionHandle) \
    X(InvalidFederateHandle) \
    X(InvalidInteractionClassHandle) \
    X(InvalidLocalSettingsDesignator) \
    X(InvalidLogicalTime) \
    X(InvalidLogicalTimeInterval) \
    X(InvalidLookahead) \
    X(InvalidObjectClassHandle) \
    X(InvalidOrderName) \
    X(InvalidOrderType) \
    X(InvalidParameterHandle) \
    X(InvalidRangeBound) \
    X(InvalidRegion) \
    X(InvalidRegionContext) \
    X(InvalidResignAction) \
    X(InvalidUpdateRateDesignator) \
    X(InvalidMessageRetractionHandle) \
    X(InvalidServiceGroup) \
    X(InvalidTransportationName) \
    X(InvalidTransportationType) \
    X(JoinedFederateIsNotInTimeAdvancingState) \
    X(LogicalTimeAlreadyPassed) \
    X(MessageCanNoLongerBeRetracted) \
    X(NameNotFound) \
    X(NameSetWasEmpty) \
    X(NoAcquisitionPending) \
    X(NotConnected) \
    X(ObjectClassNotDefined) \
    X(ObjectClassNotKnown) \
    X(ObjectClassNotPublished) \
    X(ObjectClassRelevanceAdvisorySwitchIsOff) \
    X(ObjectClassRelevanceAdvisorySwitchIsOn) \
    X(ObjectInstanceNameInUse) \
    X(ObjectInstanceNameNotReserved) \
    X(ObjectInstanceNotKnown) \
    X(OwnershipAcquisitionPending) \
    X(RTIinternalError) \
    X(RegionDoesNotContainSpecifiedDimension) \
    X(RegionInUseForUpdateOrSubscription) \
    X(RegionNotCreatedByThisFederate) \
    X(RestoreInProgress) \
    X(RestoreNotInProgress) \
    X(RestoreNotRequested) \
    X(SaveInProgress) \
    X(SaveNotInProgress) \
    X(SaveNotInitiated) \
    X(SpecifiedSaveLabelDoesNotExist) \
    X(SynchronizationPointLabelNotAnnounced) \
    X(TimeConstrainedAlreadyEnabled) \
    X(TimeConstrainedIsNotEnabled) \
    X(TimeRegulationAlreadyEnabled) \
    X(TimeRegulationIsNotEnabled) \
    X(UnableToPerformSave) \
    X(UnknownName) \
    X(UnsupportedCallbackModel) \
    X(InternalError)

#define RTI_EXCEPTION(A)                                            \
    class RTI_EXPORT A : public Exception {                          \
    public:                                                         \
        A(std::wstring const& message) noexcept;                    \
        std::wstring what() const noexcept override;                \
                                                                    \
    private:                                                        \
        std::wstring _msg;                                          \
    };
RTI1516E_EXCEPTIONS(RTI_EXCEPTION)
#undef RTI_EXCEPTION

}  // namespace rti1516e

#endif
