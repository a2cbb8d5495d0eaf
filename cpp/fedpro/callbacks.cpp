// The callbacks: each 1516-2010 callback of the session's ambassador (on its HLA_IMMEDIATE thread) becomes the
// protocol's CallbackRequest for the session's federate. Every callback is overridden (FederateAmbassador's are
// pure): none is dropped.
#include "fedpro/hla_federate.hpp"

namespace hlacore::fedpro {

using namespace ::rti1516e;

namespace {

template <class Info>
void put_producer(Info const& info, pb::FederateHandle* out) {
    if (info.hasProducingFederate) put(out, info.producingFederate);
}

}  // namespace

void HlaFederate::send(pb::CallbackRequest const& request) { send_callback_(request.SerializeAsString()); }

void HlaFederate::connectionLost(std::wstring const& fault) {
    HLACORE_FEDPRO_CALLBACK(connectionlost, m->set_faultdescription(utf8(fault)));
}
void HlaFederate::reportFederationExecutions(FederationExecutionInformationVector const& federations) {
    HLACORE_FEDPRO_CALLBACK(reportfederationexecutions, for (auto const& f : federations) {
        auto* i = m->mutable_report()->add_federationexecutioninformation();
        i->set_federationexecutionname(utf8(f.federationExecutionName));
        i->set_logicaltimeimplementationname(utf8(f.logicalTimeImplementationName));
    });
}
void HlaFederate::synchronizationPointRegistrationSucceeded(std::wstring const& label) {
    HLACORE_FEDPRO_CALLBACK(synchronizationpointregistrationsucceeded, m->set_synchronizationpointlabel(utf8(label)));
}
void HlaFederate::synchronizationPointRegistrationFailed(std::wstring const& label, SynchronizationPointFailureReason reason) {
    HLACORE_FEDPRO_CALLBACK(synchronizationpointregistrationfailed, {
        m->set_synchronizationpointlabel(utf8(label));
        m->set_reason(static_cast<pb::SynchronizationPointFailureReason>(reason));
    });
}
void HlaFederate::announceSynchronizationPoint(std::wstring const& label, VariableLengthData const& tag) {
    HLACORE_FEDPRO_CALLBACK(announcesynchronizationpoint, {
        m->set_synchronizationpointlabel(utf8(label));
        m->set_usersuppliedtag(bytes(tag));
    });
}
void HlaFederate::federationSynchronized(std::wstring const& label, FederateHandleSet const& failed) {
    HLACORE_FEDPRO_CALLBACK(federationsynchronized, {
        m->set_synchronizationpointlabel(utf8(label));
        put(m->mutable_failedtosyncset(), failed);
    });
}
void HlaFederate::initiateFederateSave(std::wstring const& label) {
    HLACORE_FEDPRO_CALLBACK(initiatefederatesave, m->set_label(utf8(label)));
}
void HlaFederate::initiateFederateSave(std::wstring const& label, LogicalTime const& time) {
    HLACORE_FEDPRO_CALLBACK(initiatefederatesavewithtime, {
        m->set_label(utf8(label));
        put(m->mutable_time(), time);
    });
}
void HlaFederate::federationSaved() { HLACORE_FEDPRO_CALLBACK(federationsaved, ); }
void HlaFederate::federationNotSaved(SaveFailureReason reason) {
    HLACORE_FEDPRO_CALLBACK(federationnotsaved, m->set_reason(static_cast<pb::SaveFailureReason>(reason)));
}
void HlaFederate::federationSaveStatusResponse(FederateHandleSaveStatusPairVector const& statuses) {
    HLACORE_FEDPRO_CALLBACK(federationsavestatusresponse, for (auto const& [federate, status] : statuses) {
        auto* p = m->mutable_response()->add_federatehandlesavestatuspair();
        put(p->mutable_federatehandle(), federate);
        p->set_savestatus(static_cast<pb::SaveStatus>(status));
    });
}
void HlaFederate::requestFederationRestoreSucceeded(std::wstring const& label) {
    HLACORE_FEDPRO_CALLBACK(requestfederationrestoresucceeded, m->set_label(utf8(label)));
}
void HlaFederate::requestFederationRestoreFailed(std::wstring const& label) {
    HLACORE_FEDPRO_CALLBACK(requestfederationrestorefailed, m->set_label(utf8(label)));
}
void HlaFederate::federationRestoreBegun() { HLACORE_FEDPRO_CALLBACK(federationrestorebegun, ); }
void HlaFederate::initiateFederateRestore(std::wstring const& label, std::wstring const& name, FederateHandle handle) {
    HLACORE_FEDPRO_CALLBACK(initiatefederaterestore, {
        m->set_label(utf8(label));
        m->set_federatename(utf8(name));
        put(m->mutable_postrestorefederatehandle(), handle);
    });
}
void HlaFederate::federationRestored() { HLACORE_FEDPRO_CALLBACK(federationrestored, ); }
void HlaFederate::federationNotRestored(RestoreFailureReason reason) {
    HLACORE_FEDPRO_CALLBACK(federationnotrestored, m->set_reason(static_cast<pb::RestoreFailureReason>(reason)));
}
void HlaFederate::federationRestoreStatusResponse(FederateRestoreStatusVector const& statuses) {
    HLACORE_FEDPRO_CALLBACK(federationrestorestatusresponse, for (auto const& s : statuses) {
        auto* p = m->mutable_response()->add_federaterestorestatus();
        put(p->mutable_prerestorehandle(), s.preRestoreHandle);
        put(p->mutable_postrestorehandle(), s.postRestoreHandle);
        p->set_restorestatus(static_cast<pb::RestoreStatus>(s.status));
    });
}
void HlaFederate::startRegistrationForObjectClass(ObjectClassHandle cls) {
    HLACORE_FEDPRO_CALLBACK(startregistrationforobjectclass, put(m->mutable_objectclass(), cls));
}
void HlaFederate::stopRegistrationForObjectClass(ObjectClassHandle cls) {
    HLACORE_FEDPRO_CALLBACK(stopregistrationforobjectclass, put(m->mutable_objectclass(), cls));
}
void HlaFederate::turnInteractionsOn(InteractionClassHandle cls) {
    HLACORE_FEDPRO_CALLBACK(turninteractionson, put(m->mutable_interactionclass(), cls));
}
void HlaFederate::turnInteractionsOff(InteractionClassHandle cls) {
    HLACORE_FEDPRO_CALLBACK(turninteractionsoff, put(m->mutable_interactionclass(), cls));
}
void HlaFederate::objectInstanceNameReservationSucceeded(std::wstring const& name) {
    HLACORE_FEDPRO_CALLBACK(objectinstancenamereservationsucceeded, m->set_objectinstancename(utf8(name)));
}
void HlaFederate::objectInstanceNameReservationFailed(std::wstring const& name) {
    HLACORE_FEDPRO_CALLBACK(objectinstancenamereservationfailed, m->set_objectinstancename(utf8(name)));
}
void HlaFederate::multipleObjectInstanceNameReservationSucceeded(std::set<std::wstring> const& names) {
    HLACORE_FEDPRO_CALLBACK(multipleobjectinstancenamereservationsucceeded, for (auto const& n : names) m->add_objectinstancenames(utf8(n)));
}
void HlaFederate::multipleObjectInstanceNameReservationFailed(std::set<std::wstring> const& names) {
    HLACORE_FEDPRO_CALLBACK(multipleobjectinstancenamereservationfailed, for (auto const& n : names) m->add_objectinstancenames(utf8(n)));
}
void HlaFederate::discoverObjectInstance(ObjectInstanceHandle object, ObjectClassHandle cls, std::wstring const& name) {
    HLACORE_FEDPRO_CALLBACK(discoverobjectinstance, {
        put(m->mutable_objectinstance(), object);
        put(m->mutable_objectclass(), cls);
        m->set_objectinstancename(utf8(name));
    });
}
void HlaFederate::discoverObjectInstance(ObjectInstanceHandle object, ObjectClassHandle cls, std::wstring const& name,
                                         FederateHandle producer) {
    HLACORE_FEDPRO_CALLBACK(discoverobjectinstance, {
        put(m->mutable_objectinstance(), object);
        put(m->mutable_objectclass(), cls);
        m->set_objectinstancename(utf8(name));
        put(m->mutable_producingfederate(), producer);
    });
}
namespace {

// What a reflection, an interaction or a removal carries beside its target and values: the tag and who sent it;
// and when timestamped, the time and the orders.
template <class M, class Info>
void sent(M* m, VariableLengthData const& tag, Info const& info) {
    m->set_usersuppliedtag(bytes(tag));
    put_producer(info, m->mutable_producingfederate());
}
template <class M>
void timed(M* m, LogicalTime const& time, OrderType sent_order, OrderType received_order) {
    put(m->mutable_time(), time);
    m->set_sentordertype(order(sent_order));
    m->set_receivedordertype(order(received_order));
}

}  // namespace

void HlaFederate::reflectAttributeValues(ObjectInstanceHandle object, AttributeHandleValueMap const& values, VariableLengthData const& tag,
                                         OrderType, TransportationType type, SupplementalReflectInfo info) {
    HLACORE_FEDPRO_CALLBACK(reflectattributevalues, put(m->mutable_objectinstance(), object);
                            put(m->mutable_attributevalues(), values); put(m->mutable_transportationtype(), type);
                            sent(m, tag, info));
}
void HlaFederate::reflectAttributeValues(ObjectInstanceHandle object, AttributeHandleValueMap const& values, VariableLengthData const& tag,
                                         OrderType sent_order, TransportationType type, LogicalTime const& time,
                                         OrderType received_order, SupplementalReflectInfo info) {
    HLACORE_FEDPRO_CALLBACK(reflectattributevalueswithtime, put(m->mutable_objectinstance(), object);
                            put(m->mutable_attributevalues(), values); put(m->mutable_transportationtype(), type);
                            sent(m, tag, info); timed(m, time, sent_order, received_order));
}
void HlaFederate::reflectAttributeValues(ObjectInstanceHandle object, AttributeHandleValueMap const& values, VariableLengthData const& tag,
                                         OrderType sent_order, TransportationType type, LogicalTime const& time,
                                         OrderType received_order, MessageRetractionHandle handle, SupplementalReflectInfo info) {
    HLACORE_FEDPRO_CALLBACK(reflectattributevalueswithtime, put(m->mutable_objectinstance(), object);
                            put(m->mutable_attributevalues(), values); put(m->mutable_transportationtype(), type);
                            sent(m, tag, info); timed(m, time, sent_order, received_order);
                            put(m->mutable_optionalretraction(), handle));
}
void HlaFederate::receiveInteraction(InteractionClassHandle cls, ParameterHandleValueMap const& values, VariableLengthData const& tag,
                                     OrderType, TransportationType type, SupplementalReceiveInfo info) {
    HLACORE_FEDPRO_CALLBACK(receiveinteraction, put(m->mutable_interactionclass(), cls);
                            put(m->mutable_parametervalues(), values); put(m->mutable_transportationtype(), type);
                            sent(m, tag, info));
}
void HlaFederate::receiveInteraction(InteractionClassHandle cls, ParameterHandleValueMap const& values, VariableLengthData const& tag,
                                     OrderType sent_order, TransportationType type, LogicalTime const& time,
                                     OrderType received_order, SupplementalReceiveInfo info) {
    HLACORE_FEDPRO_CALLBACK(receiveinteractionwithtime, put(m->mutable_interactionclass(), cls);
                            put(m->mutable_parametervalues(), values); put(m->mutable_transportationtype(), type);
                            sent(m, tag, info); timed(m, time, sent_order, received_order));
}
void HlaFederate::receiveInteraction(InteractionClassHandle cls, ParameterHandleValueMap const& values, VariableLengthData const& tag,
                                     OrderType sent_order, TransportationType type, LogicalTime const& time,
                                     OrderType received_order, MessageRetractionHandle handle, SupplementalReceiveInfo info) {
    HLACORE_FEDPRO_CALLBACK(receiveinteractionwithtime, put(m->mutable_interactionclass(), cls);
                            put(m->mutable_parametervalues(), values); put(m->mutable_transportationtype(), type);
                            sent(m, tag, info); timed(m, time, sent_order, received_order);
                            put(m->mutable_optionalretraction(), handle));
}
void HlaFederate::receiveDirectedInteraction(InteractionClassHandle cls, ObjectInstanceHandle object,
                                             ParameterHandleValueMap const& values, VariableLengthData const& tag,
                                             TransportationType transport, FederateHandle producer) {
    HLACORE_FEDPRO_CALLBACK(receivedirectedinteraction, put(m->mutable_interactionclass(), cls);
                            put(m->mutable_objectinstance(), object); put(m->mutable_parametervalues(), values);
                            m->set_usersuppliedtag(bytes(tag)); put(m->mutable_transportationtype(), transport);
                            put(m->mutable_producingfederate(), producer));
}
void HlaFederate::receiveDirectedInteraction(InteractionClassHandle cls, ObjectInstanceHandle object,
                                             ParameterHandleValueMap const& values, VariableLengthData const& tag,
                                             TransportationType transport, FederateHandle producer, LogicalTime const& time,
                                             OrderType sent_order, OrderType received_order,
                                             MessageRetractionHandle const* retraction) {
    HLACORE_FEDPRO_CALLBACK(receivedirectedinteractionwithtime, put(m->mutable_interactionclass(), cls);
                            put(m->mutable_objectinstance(), object); put(m->mutable_parametervalues(), values);
                            m->set_usersuppliedtag(bytes(tag)); put(m->mutable_transportationtype(), transport);
                            put(m->mutable_producingfederate(), producer); timed(m, time, sent_order, received_order);
                            if (retraction) put(m->mutable_optionalretraction(), *retraction));
}
void HlaFederate::removeObjectInstance(ObjectInstanceHandle object, VariableLengthData const& tag, OrderType, SupplementalRemoveInfo info) {
    HLACORE_FEDPRO_CALLBACK(removeobjectinstance, put(m->mutable_objectinstance(), object); sent(m, tag, info));
}
void HlaFederate::removeObjectInstance(ObjectInstanceHandle object, VariableLengthData const& tag, OrderType sent_order,
                                       LogicalTime const& time, OrderType received_order, SupplementalRemoveInfo info) {
    HLACORE_FEDPRO_CALLBACK(removeobjectinstancewithtime, put(m->mutable_objectinstance(), object); sent(m, tag, info);
                            timed(m, time, sent_order, received_order));
}
void HlaFederate::removeObjectInstance(ObjectInstanceHandle object, VariableLengthData const& tag, OrderType sent_order,
                                       LogicalTime const& time, OrderType received_order, MessageRetractionHandle handle,
                                       SupplementalRemoveInfo info) {
    HLACORE_FEDPRO_CALLBACK(removeobjectinstancewithtime, put(m->mutable_objectinstance(), object); sent(m, tag, info);
                            timed(m, time, sent_order, received_order); put(m->mutable_optionalretraction(), handle));
}

// The callbacks of an object instance and a set of its attributes, alike in both APIs.
#define HLACORE_FEDPRO_OBJECT_ATTRIBUTES(Name, field, member)                                           \
    void HlaFederate::Name(ObjectInstanceHandle object, AttributeHandleSet const& attributes) {         \
        HLACORE_FEDPRO_CALLBACK(field, {                                                                 \
            put(m->mutable_objectinstance(), object);                                                    \
            put(m->mutable_##member(), attributes);                                                      \
        });                                                                                              \
    }
HLACORE_FEDPRO_OBJECT_ATTRIBUTES(attributesInScope, attributesinscope, attributes)
HLACORE_FEDPRO_OBJECT_ATTRIBUTES(attributesOutOfScope, attributesoutofscope, attributes)
HLACORE_FEDPRO_OBJECT_ATTRIBUTES(turnUpdatesOnForObjectInstance, turnupdatesonforobjectinstance, attributes)
HLACORE_FEDPRO_OBJECT_ATTRIBUTES(turnUpdatesOffForObjectInstance, turnupdatesoffforobjectinstance, attributes)
HLACORE_FEDPRO_OBJECT_ATTRIBUTES(requestDivestitureConfirmation, requestdivestitureconfirmation, releasedattributes)
HLACORE_FEDPRO_OBJECT_ATTRIBUTES(attributeOwnershipUnavailable, attributeownershipunavailable, attributes)
HLACORE_FEDPRO_OBJECT_ATTRIBUTES(confirmAttributeOwnershipAcquisitionCancellation, confirmattributeownershipacquisitioncancellation,
                                 attributes)
#undef HLACORE_FEDPRO_OBJECT_ATTRIBUTES

// ... and with a tag.
#define HLACORE_FEDPRO_OBJECT_ATTRIBUTES_TAG(Name, field, member)                                                   \
    void HlaFederate::Name(ObjectInstanceHandle object, AttributeHandleSet const& attributes, VariableLengthData const& tag) { \
        HLACORE_FEDPRO_CALLBACK(field, {                                                                             \
            put(m->mutable_objectinstance(), object);                                                                \
            put(m->mutable_##member(), attributes);                                                                  \
            m->set_usersuppliedtag(bytes(tag));                                                                      \
        });                                                                                                          \
    }
HLACORE_FEDPRO_OBJECT_ATTRIBUTES_TAG(provideAttributeValueUpdate, provideattributevalueupdate, attributes)
HLACORE_FEDPRO_OBJECT_ATTRIBUTES_TAG(requestAttributeOwnershipAssumption, requestattributeownershipassumption, offeredattributes)
HLACORE_FEDPRO_OBJECT_ATTRIBUTES_TAG(attributeOwnershipAcquisitionNotification, attributeownershipacquisitionnotification, securedattributes)
HLACORE_FEDPRO_OBJECT_ATTRIBUTES_TAG(requestAttributeOwnershipRelease, requestattributeownershiprelease, candidateattributes)
#undef HLACORE_FEDPRO_OBJECT_ATTRIBUTES_TAG

void HlaFederate::turnUpdatesOnForObjectInstance(ObjectInstanceHandle object, AttributeHandleSet const& attributes,
                                                 std::wstring const& rate) {
    HLACORE_FEDPRO_CALLBACK(turnupdatesonforobjectinstancewithrate, {
        put(m->mutable_objectinstance(), object);
        put(m->mutable_attributes(), attributes);
        m->set_updateratedesignator(utf8(rate));
    });
}
void HlaFederate::confirmAttributeTransportationTypeChange(ObjectInstanceHandle object, AttributeHandleSet attributes,
                                                           TransportationType type) {
    HLACORE_FEDPRO_CALLBACK(confirmattributetransportationtypechange, {
        put(m->mutable_objectinstance(), object);
        put(m->mutable_attributes(), attributes);
        put(m->mutable_transportationtype(), type);
    });
}
void HlaFederate::reportAttributeTransportationType(ObjectInstanceHandle object, AttributeHandle attribute, TransportationType type) {
    HLACORE_FEDPRO_CALLBACK(reportattributetransportationtype, {
        put(m->mutable_objectinstance(), object);
        put(m->mutable_attribute(), attribute);
        put(m->mutable_transportationtype(), type);
    });
}
void HlaFederate::confirmInteractionTransportationTypeChange(InteractionClassHandle cls, TransportationType type) {
    HLACORE_FEDPRO_CALLBACK(confirminteractiontransportationtypechange, {
        put(m->mutable_interactionclass(), cls);
        put(m->mutable_transportationtype(), type);
    });
}
void HlaFederate::reportInteractionTransportationType(FederateHandle federate, InteractionClassHandle cls, TransportationType type) {
    HLACORE_FEDPRO_CALLBACK(reportinteractiontransportationtype, {
        put(m->mutable_federate(), federate);
        put(m->mutable_interactionclass(), cls);
        put(m->mutable_transportationtype(), type);
    });
}
// HLA 4 reports ownership per set of attributes; 1516-2010 per attribute: one callback each.
void HlaFederate::informAttributeOwnership(ObjectInstanceHandle object, AttributeHandle attribute, FederateHandle owner) {
    HLACORE_FEDPRO_CALLBACK(informattributeownership, {
        put(m->mutable_objectinstance(), object);
        put(m->mutable_attributes()->add_attributehandle(), attribute);
        put(m->mutable_federate(), owner);
    });
}
void HlaFederate::attributeIsNotOwned(ObjectInstanceHandle object, AttributeHandle attribute) {
    HLACORE_FEDPRO_CALLBACK(attributeisnotowned, {
        put(m->mutable_objectinstance(), object);
        put(m->mutable_attributes()->add_attributehandle(), attribute);
    });
}
void HlaFederate::attributeIsOwnedByRTI(ObjectInstanceHandle object, AttributeHandle attribute) {
    HLACORE_FEDPRO_CALLBACK(attributeisownedbyrti, {
        put(m->mutable_objectinstance(), object);
        put(m->mutable_attributes()->add_attributehandle(), attribute);
    });
}
void HlaFederate::timeRegulationEnabled(LogicalTime const& time) {
    HLACORE_FEDPRO_CALLBACK(timeregulationenabled, put(m->mutable_time(), time));
}
void HlaFederate::timeConstrainedEnabled(LogicalTime const& time) {
    HLACORE_FEDPRO_CALLBACK(timeconstrainedenabled, put(m->mutable_time(), time));
}
void HlaFederate::timeAdvanceGrant(LogicalTime const& time) {
    HLACORE_FEDPRO_CALLBACK(timeadvancegrant, put(m->mutable_time(), time));
}
void HlaFederate::requestRetraction(MessageRetractionHandle handle) {
    HLACORE_FEDPRO_CALLBACK(requestretraction, put(m->mutable_retraction(), handle));
}

}  // namespace hlacore::fedpro
