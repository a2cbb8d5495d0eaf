// The services of IEEE 1516.1-2010 (HLA Evolved) as a federate calls them. RTIambassadorFactory makes
// hlacore's, which serves them over hlacore's federate side (docs/rti1516e.md, "C++").
//
// RTI1516E_SERVICES lists every service once, X(return type, name, (parameters), const or nothing), in the
// standard's order; the interface declares each pure virtual, an implementation overrides each.
#ifndef RTI_RTIambassador_h
#define RTI_RTIambassador_h

#include <RTI/Enums.h>
#include <RTI/Exception.h>
#include <RTI/Handle.h>
#include <RTI/LogicalTimeFactory.h>
#include <RTI/RangeBounds.h>
#include <RTI/SpecificConfig.h>
#include <RTI/Typedefs.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace rti1516e {

class FederateAmbassador;
class LogicalTime;
class LogicalTimeInterval;

#define RTI1516E_SERVICES(X) \
    X(void, connect, (FederateAmbassador& federate, CallbackModel model, std::wstring const& settings = L""), ) \
    X(void, disconnect, (), ) \
    X(void, createFederationExecution, (std::wstring const& federation, std::wstring const& module, \
          std::wstring const& timeType = L""), ) \
    X(void, createFederationExecution, (std::wstring const& federation, std::vector<std::wstring> const& modules, \
          std::wstring const& timeType = L""), ) \
    X(void, createFederationExecutionWithMIM, (std::wstring const& federation, \
          std::vector<std::wstring> const& modules, std::wstring const& mim, std::wstring const& timeType = L""), ) \
    X(void, destroyFederationExecution, (std::wstring const& federation), ) \
    X(void, listFederationExecutions, (), ) \
    X(FederateHandle, joinFederationExecution, (std::wstring const& type, std::wstring const& federation, \
          std::vector<std::wstring> const& modules = std::vector<std::wstring>()), ) \
    X(FederateHandle, joinFederationExecution, (std::wstring const& name, std::wstring const& type, \
          std::wstring const& federation, std::vector<std::wstring> const& modules = std::vector<std::wstring>()), ) \
    X(void, resignFederationExecution, (ResignAction action), ) \
    X(void, registerFederationSynchronizationPoint, (std::wstring const& label, VariableLengthData const& tag), ) \
    X(void, registerFederationSynchronizationPoint, (std::wstring const& label, VariableLengthData const& tag, \
          FederateHandleSet const& set), ) \
    X(void, synchronizationPointAchieved, (std::wstring const& label, bool successfully = true), ) \
    X(void, requestFederationSave, (std::wstring const& label), ) \
    X(void, requestFederationSave, (std::wstring const& label, LogicalTime const& time), ) \
    X(void, federateSaveBegun, (), ) \
    X(void, federateSaveComplete, (), ) \
    X(void, federateSaveNotComplete, (), ) \
    X(void, abortFederationSave, (), ) \
    X(void, queryFederationSaveStatus, (), ) \
    X(void, requestFederationRestore, (std::wstring const& label), ) \
    X(void, federateRestoreComplete, (), ) \
    X(void, federateRestoreNotComplete, (), ) \
    X(void, abortFederationRestore, (), ) \
    X(void, queryFederationRestoreStatus, (), ) \
    X(void, publishObjectClassAttributes, (ObjectClassHandle cls, AttributeHandleSet const& attributes), ) \
    X(void, unpublishObjectClass, (ObjectClassHandle cls), ) \
    X(void, unpublishObjectClassAttributes, (ObjectClassHandle cls, AttributeHandleSet const& attributes), ) \
    X(void, publishInteractionClass, (InteractionClassHandle cls), ) \
    X(void, unpublishInteractionClass, (InteractionClassHandle cls), ) \
    X(void, subscribeObjectClassAttributes, (ObjectClassHandle cls, AttributeHandleSet const& attributes, \
          bool active = true, std::wstring const& rate = L""), ) \
    X(void, unsubscribeObjectClass, (ObjectClassHandle cls), ) \
    X(void, unsubscribeObjectClassAttributes, (ObjectClassHandle cls, AttributeHandleSet const& attributes), ) \
    X(void, subscribeInteractionClass, (InteractionClassHandle cls, bool active = true), ) \
    X(void, unsubscribeInteractionClass, (InteractionClassHandle cls), ) \
    X(void, reserveObjectInstanceName, (std::wstring const& name), ) \
    X(void, releaseObjectInstanceName, (std::wstring const& name), ) \
    X(void, reserveMultipleObjectInstanceName, (std::set<std::wstring> const& names), ) \
    X(void, releaseMultipleObjectInstanceName, (std::set<std::wstring> const& names), ) \
    X(ObjectInstanceHandle, registerObjectInstance, (ObjectClassHandle cls), ) \
    X(ObjectInstanceHandle, registerObjectInstance, (ObjectClassHandle cls, std::wstring const& name), ) \
    X(void, updateAttributeValues, (ObjectInstanceHandle object, AttributeHandleValueMap const& values, \
          VariableLengthData const& tag), ) \
    X(MessageRetractionHandle, updateAttributeValues, (ObjectInstanceHandle object, \
          AttributeHandleValueMap const& values, VariableLengthData const& tag, LogicalTime const& time), ) \
    X(void, sendInteraction, (InteractionClassHandle cls, ParameterHandleValueMap const& values, \
          VariableLengthData const& tag), ) \
    X(MessageRetractionHandle, sendInteraction, (InteractionClassHandle cls, ParameterHandleValueMap const& values, \
          VariableLengthData const& tag, LogicalTime const& time), ) \
    X(void, deleteObjectInstance, (ObjectInstanceHandle object, VariableLengthData const& tag), ) \
    X(MessageRetractionHandle, deleteObjectInstance, (ObjectInstanceHandle object, VariableLengthData const& tag, \
          LogicalTime const& time), ) \
    X(void, localDeleteObjectInstance, (ObjectInstanceHandle object), ) \
    X(void, requestAttributeValueUpdate, (ObjectInstanceHandle object, AttributeHandleSet const& attributes, \
          VariableLengthData const& tag), ) \
    X(void, requestAttributeValueUpdate, (ObjectClassHandle cls, AttributeHandleSet const& attributes, \
          VariableLengthData const& tag), ) \
    X(void, requestAttributeTransportationTypeChange, (ObjectInstanceHandle object, \
          AttributeHandleSet const& attributes, TransportationType type), ) \
    X(void, queryAttributeTransportationType, (ObjectInstanceHandle object, AttributeHandle attribute), ) \
    X(void, requestInteractionTransportationTypeChange, (InteractionClassHandle cls, TransportationType type), ) \
    X(void, queryInteractionTransportationType, (FederateHandle federate, InteractionClassHandle cls), ) \
    X(void, unconditionalAttributeOwnershipDivestiture, (ObjectInstanceHandle object, \
          AttributeHandleSet const& attributes), ) \
    X(void, negotiatedAttributeOwnershipDivestiture, (ObjectInstanceHandle object, \
          AttributeHandleSet const& attributes, VariableLengthData const& tag), ) \
    X(void, confirmDivestiture, (ObjectInstanceHandle object, AttributeHandleSet const& attributes, \
          VariableLengthData const& tag), ) \
    X(void, attributeOwnershipAcquisition, (ObjectInstanceHandle object, AttributeHandleSet const& attributes, \
          VariableLengthData const& tag), ) \
    X(void, attributeOwnershipAcquisitionIfAvailable, (ObjectInstanceHandle object, \
          AttributeHandleSet const& attributes), ) \
    X(void, attributeOwnershipReleaseDenied, (ObjectInstanceHandle object, AttributeHandleSet const& attributes), ) \
    X(void, attributeOwnershipDivestitureIfWanted, (ObjectInstanceHandle object, \
          AttributeHandleSet const& attributes, AttributeHandleSet& divested), ) \
    X(void, cancelNegotiatedAttributeOwnershipDivestiture, (ObjectInstanceHandle object, \
          AttributeHandleSet const& attributes), ) \
    X(void, cancelAttributeOwnershipAcquisition, (ObjectInstanceHandle object, \
          AttributeHandleSet const& attributes), ) \
    X(void, queryAttributeOwnership, (ObjectInstanceHandle object, AttributeHandle attribute), ) \
    X(bool, isAttributeOwnedByFederate, (ObjectInstanceHandle object, AttributeHandle attribute), ) \
    X(void, enableTimeRegulation, (LogicalTimeInterval const& lookahead), ) \
    X(void, disableTimeRegulation, (), ) \
    X(void, enableTimeConstrained, (), ) \
    X(void, disableTimeConstrained, (), ) \
    X(void, timeAdvanceRequest, (LogicalTime const& time), ) \
    X(void, timeAdvanceRequestAvailable, (LogicalTime const& time), ) \
    X(void, nextMessageRequest, (LogicalTime const& time), ) \
    X(void, nextMessageRequestAvailable, (LogicalTime const& time), ) \
    X(void, flushQueueRequest, (LogicalTime const& time), ) \
    X(void, enableAsynchronousDelivery, (), ) \
    X(void, disableAsynchronousDelivery, (), ) \
    X(bool, queryGALT, (LogicalTime& time), ) \
    X(void, queryLogicalTime, (LogicalTime& time), ) \
    X(bool, queryLITS, (LogicalTime& time), ) \
    X(void, modifyLookahead, (LogicalTimeInterval const& lookahead), ) \
    X(void, queryLookahead, (LogicalTimeInterval& lookahead), ) \
    X(void, retract, (MessageRetractionHandle handle), ) \
    X(void, changeAttributeOrderType, (ObjectInstanceHandle object, AttributeHandleSet const& attributes, \
          OrderType type), ) \
    X(void, changeInteractionOrderType, (InteractionClassHandle cls, OrderType type), ) \
    X(RegionHandle, createRegion, (DimensionHandleSet const& dimensions), ) \
    X(void, commitRegionModifications, (RegionHandleSet const& regions), ) \
    X(void, deleteRegion, (RegionHandle const& region), ) \
    X(ObjectInstanceHandle, registerObjectInstanceWithRegions, (ObjectClassHandle cls, \
          AttributeHandleSetRegionHandleSetPairVector const& regions), ) \
    X(ObjectInstanceHandle, registerObjectInstanceWithRegions, (ObjectClassHandle cls, \
          AttributeHandleSetRegionHandleSetPairVector const& regions, std::wstring const& name), ) \
    X(void, associateRegionsForUpdates, (ObjectInstanceHandle object, \
          AttributeHandleSetRegionHandleSetPairVector const& regions), ) \
    X(void, unassociateRegionsForUpdates, (ObjectInstanceHandle object, \
          AttributeHandleSetRegionHandleSetPairVector const& regions), ) \
    X(void, subscribeObjectClassAttributesWithRegions, (ObjectClassHandle cls, \
          AttributeHandleSetRegionHandleSetPairVector const& regions, bool active = true, \
          std::wstring const& rate = L""), ) \
    X(void, unsubscribeObjectClassAttributesWithRegions, (ObjectClassHandle cls, \
          AttributeHandleSetRegionHandleSetPairVector const& regions), ) \
    X(void, subscribeInteractionClassWithRegions, (InteractionClassHandle cls, RegionHandleSet const& regions, \
          bool active = true), ) \
    X(void, unsubscribeInteractionClassWithRegions, (InteractionClassHandle cls, RegionHandleSet const& regions), ) \
    X(void, sendInteractionWithRegions, (InteractionClassHandle cls, ParameterHandleValueMap const& values, \
          RegionHandleSet const& regions, VariableLengthData const& tag), ) \
    X(MessageRetractionHandle, sendInteractionWithRegions, (InteractionClassHandle cls, \
          ParameterHandleValueMap const& values, RegionHandleSet const& regions, VariableLengthData const& tag, \
          LogicalTime const& time), ) \
    X(void, requestAttributeValueUpdateWithRegions, (ObjectClassHandle cls, \
          AttributeHandleSetRegionHandleSetPairVector const& regions, VariableLengthData const& tag), ) \
    X(ResignAction, getAutomaticResignDirective, (), ) \
    X(void, setAutomaticResignDirective, (ResignAction action), ) \
    X(FederateHandle, getFederateHandle, (std::wstring const& name), ) \
    X(std::wstring, getFederateName, (FederateHandle handle), ) \
    X(ObjectClassHandle, getObjectClassHandle, (std::wstring const& name), ) \
    X(std::wstring, getObjectClassName, (ObjectClassHandle handle), ) \
    X(ObjectClassHandle, getKnownObjectClassHandle, (ObjectInstanceHandle object), ) \
    X(ObjectInstanceHandle, getObjectInstanceHandle, (std::wstring const& name), ) \
    X(std::wstring, getObjectInstanceName, (ObjectInstanceHandle handle), ) \
    X(AttributeHandle, getAttributeHandle, (ObjectClassHandle cls, std::wstring const& name), ) \
    X(std::wstring, getAttributeName, (ObjectClassHandle cls, AttributeHandle handle), ) \
    X(double, getUpdateRateValue, (std::wstring const& rate), ) \
    X(double, getUpdateRateValueForAttribute, (ObjectInstanceHandle object, AttributeHandle attribute), ) \
    X(InteractionClassHandle, getInteractionClassHandle, (std::wstring const& name), ) \
    X(std::wstring, getInteractionClassName, (InteractionClassHandle handle), ) \
    X(ParameterHandle, getParameterHandle, (InteractionClassHandle cls, std::wstring const& name), ) \
    X(std::wstring, getParameterName, (InteractionClassHandle cls, ParameterHandle handle), ) \
    X(OrderType, getOrderType, (std::wstring const& name), ) \
    X(std::wstring, getOrderName, (OrderType type), ) \
    X(TransportationType, getTransportationType, (std::wstring const& name), ) \
    X(std::wstring, getTransportationName, (TransportationType type), ) \
    X(DimensionHandleSet, getAvailableDimensionsForClassAttribute, (ObjectClassHandle cls, AttributeHandle handle), \
          ) \
    X(DimensionHandleSet, getAvailableDimensionsForInteractionClass, (InteractionClassHandle cls), ) \
    X(DimensionHandle, getDimensionHandle, (std::wstring const& name), ) \
    X(std::wstring, getDimensionName, (DimensionHandle handle), ) \
    X(unsigned long, getDimensionUpperBound, (DimensionHandle handle), ) \
    X(DimensionHandleSet, getDimensionHandleSet, (RegionHandle region), ) \
    X(RangeBounds, getRangeBounds, (RegionHandle region, DimensionHandle dimension), ) \
    X(void, setRangeBounds, (RegionHandle region, DimensionHandle dimension, RangeBounds const& bounds), ) \
    X(unsigned long, normalizeFederateHandle, (FederateHandle federate), ) \
    X(unsigned long, normalizeServiceGroup, (ServiceGroup group), ) \
    X(void, enableObjectClassRelevanceAdvisorySwitch, (), ) \
    X(void, disableObjectClassRelevanceAdvisorySwitch, (), ) \
    X(void, enableAttributeRelevanceAdvisorySwitch, (), ) \
    X(void, disableAttributeRelevanceAdvisorySwitch, (), ) \
    X(void, enableAttributeScopeAdvisorySwitch, (), ) \
    X(void, disableAttributeScopeAdvisorySwitch, (), ) \
    X(void, enableInteractionRelevanceAdvisorySwitch, (), ) \
    X(void, disableInteractionRelevanceAdvisorySwitch, (), ) \
    X(bool, evokeCallback, (double minimumSeconds), ) \
    X(bool, evokeMultipleCallbacks, (double minimumSeconds, double maximumSeconds), ) \
    X(void, enableCallbacks, (), ) \
    X(void, disableCallbacks, (), ) \
    X(RTI_UNIQUE_PTR<LogicalTimeFactory>, getTimeFactory, (), const) \
    X(FederateHandle, decodeFederateHandle, (VariableLengthData const& encoded), const) \
    X(ObjectClassHandle, decodeObjectClassHandle, (VariableLengthData const& encoded), const) \
    X(InteractionClassHandle, decodeInteractionClassHandle, (VariableLengthData const& encoded), const) \
    X(ObjectInstanceHandle, decodeObjectInstanceHandle, (VariableLengthData const& encoded), const) \
    X(AttributeHandle, decodeAttributeHandle, (VariableLengthData const& encoded), const) \
    X(ParameterHandle, decodeParameterHandle, (VariableLengthData const& encoded), const) \
    X(DimensionHandle, decodeDimensionHandle, (VariableLengthData const& encoded), const) \
    X(MessageRetractionHandle, decodeMessageRetractionHandle, (VariableLengthData const& encoded), const) \
    X(RegionHandle, decodeRegionHandle, (VariableLengthData const& encoded), const)

class RTI_EXPORT RTIambassador {
public:
    virtual ~RTIambassador();
#define RTI1516E_PURE(ret, name, params, qualifier) virtual ret name params qualifier = 0;
    RTI1516E_SERVICES(RTI1516E_PURE)
#undef RTI1516E_PURE

protected:
    RTIambassador() = default;
};

}  // namespace rti1516e

#endif
