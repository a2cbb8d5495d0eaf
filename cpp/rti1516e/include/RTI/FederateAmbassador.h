// The callbacks of IEEE 1516.1-2010 (HLA Evolved): a federate derives from FederateAmbassador (or from
// NullFederateAmbassador, which ignores what it does not override) and hands it to RTIambassador::connect.
//
// RTI1516E_CALLBACKS lists every callback once, X(return type, name, (parameters), nothing), in the
// standard's order.
#ifndef RTI_FederateAmbassador_h
#define RTI_FederateAmbassador_h

#include <RTI/Enums.h>
#include <RTI/Exception.h>
#include <RTI/Handle.h>
#include <RTI/LogicalTime.h>
#include <RTI/SpecificConfig.h>
#include <RTI/Typedefs.h>

#include <set>
#include <string>

namespace rti1516e {

// The three overloads of a callback that delivers values (reflectAttributeValues, receiveInteraction): in
// receive order, and timestamped without and with a retraction handle.
#define RTI1516E_VALUES_CALLBACKS(X, name, target, Values, Info) \
    X(void, name, (target, Values const& values, VariableLengthData const& tag, OrderType sentOrder, \
          TransportationType type, Info info), ) \
    X(void, name, (target, Values const& values, VariableLengthData const& tag, OrderType sentOrder, \
          TransportationType type, LogicalTime const& time, OrderType receivedOrder, Info info), ) \
    X(void, name, (target, Values const& values, VariableLengthData const& tag, OrderType sentOrder, \
          TransportationType type, LogicalTime const& time, OrderType receivedOrder, MessageRetractionHandle handle, \
          Info info), )

#define RTI1516E_CALLBACKS(X) \
    X(void, connectionLost, (std::wstring const& fault), ) \
    X(void, reportFederationExecutions, (FederationExecutionInformationVector const& federations), ) \
    X(void, synchronizationPointRegistrationSucceeded, (std::wstring const& label), ) \
    X(void, synchronizationPointRegistrationFailed, (std::wstring const& label, \
          SynchronizationPointFailureReason reason), ) \
    X(void, announceSynchronizationPoint, (std::wstring const& label, VariableLengthData const& tag), ) \
    X(void, federationSynchronized, (std::wstring const& label, FederateHandleSet const& failed), ) \
    X(void, initiateFederateSave, (std::wstring const& label), ) \
    X(void, initiateFederateSave, (std::wstring const& label, LogicalTime const& time), ) \
    X(void, federationSaved, (), ) \
    X(void, federationNotSaved, (SaveFailureReason reason), ) \
    X(void, federationSaveStatusResponse, (FederateHandleSaveStatusPairVector const& statuses), ) \
    X(void, requestFederationRestoreSucceeded, (std::wstring const& label), ) \
    X(void, requestFederationRestoreFailed, (std::wstring const& label), ) \
    X(void, federationRestoreBegun, (), ) \
    X(void, initiateFederateRestore, (std::wstring const& label, std::wstring const& name, FederateHandle handle), ) \
    X(void, federationRestored, (), ) \
    X(void, federationNotRestored, (RestoreFailureReason reason), ) \
    X(void, federationRestoreStatusResponse, (FederateRestoreStatusVector const& statuses), ) \
    X(void, startRegistrationForObjectClass, (ObjectClassHandle cls), ) \
    X(void, stopRegistrationForObjectClass, (ObjectClassHandle cls), ) \
    X(void, turnInteractionsOn, (InteractionClassHandle handle), ) \
    X(void, turnInteractionsOff, (InteractionClassHandle handle), ) \
    X(void, objectInstanceNameReservationSucceeded, (std::wstring const& name), ) \
    X(void, objectInstanceNameReservationFailed, (std::wstring const& name), ) \
    X(void, multipleObjectInstanceNameReservationSucceeded, (std::set<std::wstring> const& names), ) \
    X(void, multipleObjectInstanceNameReservationFailed, (std::set<std::wstring> const& names), ) \
    X(void, discoverObjectInstance, (ObjectInstanceHandle object, ObjectClassHandle cls, std::wstring const& name), \
          ) \
    X(void, discoverObjectInstance, (ObjectInstanceHandle object, ObjectClassHandle cls, std::wstring const& name, \
          FederateHandle producer), ) \
    RTI1516E_VALUES_CALLBACKS(X, reflectAttributeValues, ObjectInstanceHandle object, AttributeHandleValueMap, \
                              SupplementalReflectInfo) \
    RTI1516E_VALUES_CALLBACKS(X, receiveInteraction, InteractionClassHandle cls, ParameterHandleValueMap, \
                              SupplementalReceiveInfo) \
    X(void, removeObjectInstance, (ObjectInstanceHandle object, VariableLengthData const& tag, OrderType sentOrder, \
          SupplementalRemoveInfo info), ) \
    X(void, removeObjectInstance, (ObjectInstanceHandle object, VariableLengthData const& tag, OrderType sentOrder, \
          LogicalTime const& time, OrderType receivedOrder, SupplementalRemoveInfo info), ) \
    X(void, removeObjectInstance, (ObjectInstanceHandle object, VariableLengthData const& tag, OrderType sentOrder, \
          LogicalTime const& time, OrderType receivedOrder, MessageRetractionHandle handle, \
          SupplementalRemoveInfo info), ) \
    X(void, attributesInScope, (ObjectInstanceHandle object, AttributeHandleSet const& attributes), ) \
    X(void, attributesOutOfScope, (ObjectInstanceHandle object, AttributeHandleSet const& attributes), ) \
    X(void, provideAttributeValueUpdate, (ObjectInstanceHandle object, AttributeHandleSet const& attributes, \
          VariableLengthData const& tag), ) \
    X(void, turnUpdatesOnForObjectInstance, (ObjectInstanceHandle object, AttributeHandleSet const& attributes), ) \
    X(void, turnUpdatesOnForObjectInstance, (ObjectInstanceHandle object, AttributeHandleSet const& attributes, \
          std::wstring const& rate), ) \
    X(void, turnUpdatesOffForObjectInstance, (ObjectInstanceHandle object, AttributeHandleSet const& attributes), ) \
    X(void, confirmAttributeTransportationTypeChange, (ObjectInstanceHandle object, AttributeHandleSet attributes, \
          TransportationType type), ) \
    X(void, reportAttributeTransportationType, (ObjectInstanceHandle object, AttributeHandle attribute, \
          TransportationType type), ) \
    X(void, confirmInteractionTransportationTypeChange, (InteractionClassHandle cls, TransportationType type), ) \
    X(void, reportInteractionTransportationType, (FederateHandle federate, InteractionClassHandle cls, \
          TransportationType type), ) \
    X(void, requestAttributeOwnershipAssumption, (ObjectInstanceHandle object, \
          AttributeHandleSet const& attributes, VariableLengthData const& tag), ) \
    X(void, requestDivestitureConfirmation, (ObjectInstanceHandle object, AttributeHandleSet const& attributes), ) \
    X(void, attributeOwnershipAcquisitionNotification, (ObjectInstanceHandle object, \
          AttributeHandleSet const& attributes, VariableLengthData const& tag), ) \
    X(void, attributeOwnershipUnavailable, (ObjectInstanceHandle object, AttributeHandleSet const& attributes), ) \
    X(void, requestAttributeOwnershipRelease, (ObjectInstanceHandle object, AttributeHandleSet const& attributes, \
          VariableLengthData const& tag), ) \
    X(void, confirmAttributeOwnershipAcquisitionCancellation, (ObjectInstanceHandle object, \
          AttributeHandleSet const& attributes), ) \
    X(void, informAttributeOwnership, (ObjectInstanceHandle object, AttributeHandle attribute, \
          FederateHandle owner), ) \
    X(void, attributeIsNotOwned, (ObjectInstanceHandle object, AttributeHandle attribute), ) \
    X(void, attributeIsOwnedByRTI, (ObjectInstanceHandle object, AttributeHandle attribute), ) \
    X(void, timeRegulationEnabled, (LogicalTime const& time), ) \
    X(void, timeConstrainedEnabled, (LogicalTime const& time), ) \
    X(void, timeAdvanceGrant, (LogicalTime const& time), ) \
    X(void, requestRetraction, (MessageRetractionHandle handle), )

class RTI_EXPORT FederateAmbassador {
public:
    virtual ~FederateAmbassador() = 0;
#define RTI1516E_PURE(ret, name, params, qualifier) virtual ret name params qualifier = 0;
    RTI1516E_CALLBACKS(RTI1516E_PURE)
#undef RTI1516E_PURE

protected:
    FederateAmbassador() = default;
};

}  // namespace rti1516e

#endif
