// RTIambassador: object management (§6, with the transport and order changes) and ownership management (§7).
#include "ambassador.hpp"

using namespace hlacore;
using hlacore::hla13::guarded;
using hlacore::hla13::h32;
using hlacore::hla13::handles_of;
using hlacore::hla13::text;

namespace {
// The retraction handle of a timestamped message this federate sent.
RTI::EventRetractionHandle retraction(const Client& c, std::uint64_t serial) {
    return hla13::retraction(c.federate_handle(), serial);
}

// A timestamped message's event retraction handle: `send(client, time)` sends it and returns its serial.
template <class Send>
RTI::EventRetractionHandle timed(RTIambPrivateRefs& refs, const RTI::FedTime& time, Send send) {
    return guarded([&] {
        Client& c = refs.client;
        return retraction(c, send(c, hla13::time_of(time)));
    });
}

// An update or an interaction, its values as the client takes them; the message's serial.
std::uint64_t update(Client& c, RTI::ObjectHandle object, const RTI::AttributeHandleValuePairSet& set, const char* tag,
                     wire::OptionalTime time) {
    const wire::HandleValues values = hla13::values_of(set);
    return c.update_attributes(h32(object), wire::views_of(values), text(tag), time);
}
std::uint64_t interact(Client& c, RTI::InteractionClassHandle cls, const RTI::ParameterHandleValuePairSet& set,
                       const char* tag, wire::OptionalTime time) {
    const wire::HandleValues values = hla13::values_of(set);
    return c.send_interaction(h32(cls), wire::views_of(values), text(tag), time);
}
}  // namespace

RTI::ObjectHandle RTI::RTIambassador::registerObjectInstance(ObjectClassHandle theClass, const char* theObject) {
    return guarded([&] { return ObjectHandle{privateRefs->client.register_object(h32(theClass), text(theObject))}; });
}

RTI::ObjectHandle RTI::RTIambassador::registerObjectInstance(ObjectClassHandle theClass) {
    return registerObjectInstance(theClass, nullptr);
}

RTI::EventRetractionHandle RTI::RTIambassador::updateAttributeValues(ObjectHandle theObject,
                                                                     const AttributeHandleValuePairSet& theAttributes,
                                                                     const FedTime& theTime, const char* theTag) {
    return timed(*privateRefs, theTime, [&](Client& c, wire::OptionalTime time) {
        return update(c, theObject, theAttributes, theTag, time);
    });
}

void RTI::RTIambassador::updateAttributeValues(ObjectHandle theObject, const AttributeHandleValuePairSet& theAttributes,
                                               const char* theTag) {
    guarded([&] { update(privateRefs->client, theObject, theAttributes, theTag, std::nullopt); });
}

RTI::EventRetractionHandle RTI::RTIambassador::sendInteraction(InteractionClassHandle theInteraction,
                                                               const ParameterHandleValuePairSet& theParameters,
                                                               const FedTime& theTime, const char* theTag) {
    return timed(*privateRefs, theTime, [&](Client& c, wire::OptionalTime time) {
        return interact(c, theInteraction, theParameters, theTag, time);
    });
}

void RTI::RTIambassador::sendInteraction(InteractionClassHandle theInteraction,
                                         const ParameterHandleValuePairSet& theParameters, const char* theTag) {
    guarded([&] { interact(privateRefs->client, theInteraction, theParameters, theTag, std::nullopt); });
}

RTI::EventRetractionHandle RTI::RTIambassador::deleteObjectInstance(ObjectHandle theObject, const FedTime& theTime,
                                                                    const char* theTag) {
    return timed(*privateRefs, theTime, [&](Client& c, wire::OptionalTime time) {
        return c.delete_object(h32(theObject), text(theTag), time);
    });
}

void RTI::RTIambassador::deleteObjectInstance(ObjectHandle theObject, const char* theTag) {
    guarded([&] { privateRefs->client.delete_object(h32(theObject), text(theTag), std::nullopt); });
}

void RTI::RTIambassador::localDeleteObjectInstance(ObjectHandle theObject) {
    guarded([&] { privateRefs->client.request(wire::LocalDeleteObject{h32(theObject)}); });
}

void RTI::RTIambassador::changeAttributeTransportationType(ObjectHandle theObject, const AttributeHandleSet& theAttributes,
                                                           TransportationHandle theType) {
    guarded([&] {
        privateRefs->client.change_attribute_transportation(h32(theObject), handles_of(theAttributes), h32(theType));
    });
}

void RTI::RTIambassador::changeInteractionTransportationType(InteractionClassHandle theClass, TransportationHandle theType) {
    guarded([&] { privateRefs->client.change_interaction_transportation(h32(theClass), h32(theType)); });
}

void RTI::RTIambassador::changeAttributeOrderType(ObjectHandle theObject, const AttributeHandleSet& theAttributes,
                                                  OrderingHandle theType) {
    guarded([&] { privateRefs->client.change_attribute_order(h32(theObject), handles_of(theAttributes), h32(theType)); });
}

void RTI::RTIambassador::changeInteractionOrderType(InteractionClassHandle theClass, OrderingHandle theType) {
    guarded([&] { privateRefs->client.change_interaction_order(h32(theClass), h32(theType)); });
}

void RTI::RTIambassador::requestObjectAttributeValueUpdate(ObjectHandle theObject, const AttributeHandleSet& theAttributes) {
    guarded([&] { privateRefs->client.request(wire::RequestObjectUpdate{h32(theObject), handles_of(theAttributes)}); });
}

void RTI::RTIambassador::requestClassAttributeValueUpdate(ObjectClassHandle theClass, const AttributeHandleSet& theAttributes) {
    guarded([&] { privateRefs->client.request(wire::RequestClassUpdate{h32(theClass), handles_of(theAttributes)}); });
}

// ---- ownership management ----

void RTI::RTIambassador::unconditionalAttributeOwnershipDivestiture(ObjectHandle theObject,
                                                                    const AttributeHandleSet& theAttributes) {
    guarded([&] { privateRefs->client.unconditional_divestiture(h32(theObject), handles_of(theAttributes)); });
}

void RTI::RTIambassador::negotiatedAttributeOwnershipDivestiture(ObjectHandle theObject,
                                                                 const AttributeHandleSet& theAttributes,
                                                                 const char* theTag) {
    guarded([&] { privateRefs->client.negotiated_divestiture(h32(theObject), handles_of(theAttributes), text(theTag)); });
}

void RTI::RTIambassador::attributeOwnershipAcquisition(ObjectHandle theObject, const AttributeHandleSet& desiredAttributes,
                                                       const char* theTag) {
    guarded([&] { privateRefs->client.ownership_acquisition(h32(theObject), handles_of(desiredAttributes), text(theTag)); });
}

void RTI::RTIambassador::attributeOwnershipAcquisitionIfAvailable(ObjectHandle theObject,
                                                                  const AttributeHandleSet& desiredAttributes) {
    guarded([&] { privateRefs->client.ownership_acquisition_if_available(h32(theObject), handles_of(desiredAttributes)); });
}

RTI::AttributeHandleSet* RTI::RTIambassador::attributeOwnershipReleaseResponse(ObjectHandle theObject,
                                                                              const AttributeHandleSet& theAttributes) {
    return guarded([&]() -> AttributeHandleSet* {
        return new hla13::AttributeHandles(privateRefs->client.release_response(h32(theObject), handles_of(theAttributes)));
    });
}

void RTI::RTIambassador::cancelNegotiatedAttributeOwnershipDivestiture(ObjectHandle theObject,
                                                                       const AttributeHandleSet& theAttributes) {
    guarded([&] { privateRefs->client.request(wire::CancelNegotiatedDivestiture{h32(theObject), handles_of(theAttributes)}); });
}

void RTI::RTIambassador::cancelAttributeOwnershipAcquisition(ObjectHandle theObject, const AttributeHandleSet& theAttributes) {
    guarded([&] { privateRefs->client.request(wire::CancelOwnershipAcquisition{h32(theObject), handles_of(theAttributes)}); });
}

void RTI::RTIambassador::queryAttributeOwnership(ObjectHandle theObject, AttributeHandle theAttribute) {
    guarded([&] { privateRefs->client.request(wire::QueryOwnership{h32(theObject), h32(theAttribute)}); });
}

RTI::Boolean RTI::RTIambassador::isAttributeOwnedByFederate(ObjectHandle theObject, AttributeHandle theAttribute) {
    return guarded([&] { return hla13::boolean(privateRefs->client.is_owned(h32(theObject), h32(theAttribute))); });
}
