// RTIambassador: connecting, federation management (§4: create, join, resign, synchronization points,
// save and restore), declaration management (§5), the support services (§10) and tick. The other groups
// are in objects.cpp, time.cpp and regions.cpp; the callbacks in callbacks.cpp.
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>

#include "ambassador.hpp"
#include "fed_parser/omt.hpp"

using namespace hlacore;
using hlacore::hla13::guarded;
using hlacore::hla13::h32;
using hlacore::hla13::text;

namespace {

// A new[]'d copy of a name, as the support services return it.
char* name_copy(const std::string& name) {
    char* copy = new char[name.size() + 1];
    std::memcpy(copy, name.c_str(), name.size() + 1);
    return copy;
}

}  // namespace

RTI::RTIambassador::RTIambassador() : privateData(nullptr), privateRefs(nullptr) {
    guarded([&] {
        // The environment hlacore.rti.RTIAmbassador reads too (client/options.hpp).
        ClientSettings c = client_settings({});
        privateRefs = new RTIambPrivateRefs(std::move(c.options), c.host, c.port);
    });
}

RTI::RTIambassador::~RTIambassador() {
    for (auto& [handle, region] : privateRefs->regions) delete region;
    delete privateRefs;
}

// ---- federation management ----

void RTI::RTIambassador::createFederationExecution(const char* executionName, const char* FED) {
    guarded([&] {
        const std::string fed = text(FED);
        std::string fed_text;
        // A file this process can read is sent, checked here first for its FILE:LINE:COL; another name
        // is looked up by the gateway in its --fom-path directories.
        if (std::ifstream file{fed, std::ios::binary}) {
            std::ostringstream contents;
            contents << file.rdbuf();
            fed_text = contents.str();
            try {
                fom::parse_fom(fed_text, fed);
            } catch (const fom::FedError& e) {
                throw RTI::ErrorReadingFED(e.what());
            }
        }
        privateRefs->client.create_federation(text(executionName), fed, fed_text);
    });
}

void RTI::RTIambassador::destroyFederationExecution(const char* executionName) {
    guarded([&] { privateRefs->client.destroy_federation(text(executionName)); });
}

RTI::FederateHandle RTI::RTIambassador::joinFederationExecution(const char* yourName, const char* executionName,
                                                                FederateAmbassadorPtr federateAmbassador) {
    return guarded([&] {
        const FederateHandle handle = privateRefs->client.join(text(yourName), text(executionName));
        privateRefs->federate = federateAmbassador;
        return handle;
    });
}

void RTI::RTIambassador::resignFederationExecution(ResignAction theAction) {
    guarded([&] {
        if (theAction < RELEASE_ATTRIBUTES || theAction > NO_ACTION)
            throw RTI::InvalidResignAction(("resign action " + std::to_string(static_cast<int>(theAction))).c_str());
        privateRefs->client.resign(static_cast<std::uint8_t>(theAction));
        privateRefs->federate = nullptr;
    });
}

void RTI::RTIambassador::registerFederationSynchronizationPoint(const char* label, const char* tag) {
    guarded([&] { privateRefs->client.request(wire::RegisterSyncPoint{text(label), text(tag), true, {}}); });
}

void RTI::RTIambassador::registerFederationSynchronizationPoint(const char* label, const char* tag,
                                                                const FederateHandleSet& synchronizationSet) {
    guarded([&] {
        privateRefs->client.request(
            wire::RegisterSyncPoint{text(label), text(tag), false, hla13::handles_of(synchronizationSet)});
    });
}

void RTI::RTIambassador::synchronizationPointAchieved(const char* label) {
    guarded([&] { privateRefs->client.request(wire::SyncPointAchieved{text(label)}); });
}

void RTI::RTIambassador::requestFederationSave(const char* label, const FedTime& theTime) {
    guarded([&] { privateRefs->client.request_federation_save(text(label), hla13::time_of(theTime)); });
}

void RTI::RTIambassador::requestFederationSave(const char* label) {
    guarded([&] { privateRefs->client.request_federation_save(text(label), std::nullopt); });
}

void RTI::RTIambassador::federateSaveBegun() {
    guarded([&] { privateRefs->client.federate_save_begun(); });
}

void RTI::RTIambassador::federateSaveComplete() {
    guarded([&] { privateRefs->client.federate_save_complete(true); });
}

void RTI::RTIambassador::federateSaveNotComplete() {
    guarded([&] { privateRefs->client.federate_save_complete(false); });
}

void RTI::RTIambassador::requestFederationRestore(const char* label) {
    guarded([&] { privateRefs->client.request_federation_restore(text(label)); });
}

void RTI::RTIambassador::federateRestoreComplete() {
    guarded([&] { privateRefs->client.federate_restore_complete(true); });
}

void RTI::RTIambassador::federateRestoreNotComplete() {
    guarded([&] { privateRefs->client.federate_restore_complete(false); });
}

// ---- declaration management ----

void RTI::RTIambassador::publishObjectClass(ObjectClassHandle theClass, const AttributeHandleSet& attributeList) {
    guarded([&] { privateRefs->client.publish_object_class(h32(theClass), hla13::handles_of(attributeList)); });
}

void RTI::RTIambassador::unpublishObjectClass(ObjectClassHandle theClass) {
    guarded([&] { privateRefs->client.unpublish_object_class(h32(theClass)); });
}

void RTI::RTIambassador::publishInteractionClass(InteractionClassHandle theInteraction) {
    guarded([&] { privateRefs->client.request(wire::PublishInteractionClass{h32(theInteraction)}); });
}

void RTI::RTIambassador::unpublishInteractionClass(InteractionClassHandle theInteraction) {
    guarded([&] { privateRefs->client.request(wire::UnpublishInteractionClass{h32(theInteraction)}); });
}

void RTI::RTIambassador::subscribeObjectClassAttributes(ObjectClassHandle theClass,
                                                        const AttributeHandleSet& attributeList, Boolean active) {
    guarded([&] {
        privateRefs->client.request(
            wire::SubscribeObjectClass{h32(theClass), hla13::handles_of(attributeList), active != RTI_FALSE});
    });
}

void RTI::RTIambassador::unsubscribeObjectClass(ObjectClassHandle theClass) {
    guarded([&] { privateRefs->client.request(wire::UnsubscribeObjectClass{h32(theClass)}); });
}

void RTI::RTIambassador::subscribeInteractionClass(InteractionClassHandle theClass, Boolean active) {
    guarded([&] { privateRefs->client.request(wire::SubscribeInteractionClass{h32(theClass), active != RTI_FALSE}); });
}

void RTI::RTIambassador::unsubscribeInteractionClass(InteractionClassHandle theClass) {
    guarded([&] { privateRefs->client.request(wire::UnsubscribeInteractionClass{h32(theClass)}); });
}

// ---- support services ----

RTI::ObjectClassHandle RTI::RTIambassador::getObjectClassHandle(const char* theName) {
    return guarded([&] { return ObjectClassHandle{privateRefs->client.object_class_handle(text(theName))}; });
}

char* RTI::RTIambassador::getObjectClassName(ObjectClassHandle theHandle) {
    return guarded([&] { return name_copy(privateRefs->client.object_class_name(h32(theHandle))); });
}

RTI::AttributeHandle RTI::RTIambassador::getAttributeHandle(const char* theName, ObjectClassHandle whichClass) {
    return guarded([&] { return AttributeHandle{privateRefs->client.attribute_handle(text(theName), h32(whichClass))}; });
}

char* RTI::RTIambassador::getAttributeName(AttributeHandle theHandle, ObjectClassHandle whichClass) {
    return guarded([&] { return name_copy(privateRefs->client.attribute_name(h32(theHandle), h32(whichClass))); });
}

RTI::InteractionClassHandle RTI::RTIambassador::getInteractionClassHandle(const char* theName) {
    return guarded([&] { return InteractionClassHandle{privateRefs->client.interaction_class_handle(text(theName))}; });
}

char* RTI::RTIambassador::getInteractionClassName(InteractionClassHandle theHandle) {
    return guarded([&] { return name_copy(privateRefs->client.interaction_class_name(h32(theHandle))); });
}

RTI::ParameterHandle RTI::RTIambassador::getParameterHandle(const char* theName, InteractionClassHandle whichClass) {
    return guarded([&] { return ParameterHandle{privateRefs->client.parameter_handle(text(theName), h32(whichClass))}; });
}

char* RTI::RTIambassador::getParameterName(ParameterHandle theHandle, InteractionClassHandle whichClass) {
    return guarded([&] { return name_copy(privateRefs->client.parameter_name(h32(theHandle), h32(whichClass))); });
}

RTI::ObjectHandle RTI::RTIambassador::getObjectInstanceHandle(const char* theName) {
    return guarded([&] { return ObjectHandle{privateRefs->client.object_instance_handle(text(theName))}; });
}

char* RTI::RTIambassador::getObjectInstanceName(ObjectHandle theHandle) {
    return guarded([&] { return name_copy(privateRefs->client.object_instance_name(h32(theHandle))); });
}

RTI::SpaceHandle RTI::RTIambassador::getRoutingSpaceHandle(const char* theName) {
    return guarded([&] { return static_cast<SpaceHandle>(privateRefs->client.routing_space_handle(text(theName))); });
}

char* RTI::RTIambassador::getRoutingSpaceName(SpaceHandle theHandle) {
    return guarded([&] { return name_copy(privateRefs->client.routing_space_name(h32(static_cast<ULong>(theHandle)))); });
}

RTI::DimensionHandle RTI::RTIambassador::getDimensionHandle(const char* theName, SpaceHandle whichSpace) {
    return guarded([&] {
        return DimensionHandle{privateRefs->client.dimension_handle(text(theName), h32(static_cast<ULong>(whichSpace)))};
    });
}

char* RTI::RTIambassador::getDimensionName(DimensionHandle theHandle, SpaceHandle whichSpace) {
    return guarded([&] {
        return name_copy(privateRefs->client.dimension_name(h32(theHandle), h32(static_cast<ULong>(whichSpace))));
    });
}

RTI::SpaceHandle RTI::RTIambassador::getAttributeRoutingSpaceHandle(AttributeHandle theHandle, ObjectClassHandle whichClass) {
    return guarded([&] {
        return static_cast<SpaceHandle>(privateRefs->client.attribute_routing_space(h32(theHandle), h32(whichClass)));
    });
}

RTI::ObjectClassHandle RTI::RTIambassador::getObjectClass(ObjectHandle theObject) {
    return guarded([&] { return ObjectClassHandle{privateRefs->client.object_class_of(h32(theObject))}; });
}

RTI::SpaceHandle RTI::RTIambassador::getInteractionRoutingSpaceHandle(InteractionClassHandle theHandle) {
    return guarded([&] { return static_cast<SpaceHandle>(privateRefs->client.interaction_routing_space(h32(theHandle))); });
}

// Transportation and ordering: the names hlacore.rti answers, with CERTI's handles (Client's support services).
RTI::TransportationHandle RTI::RTIambassador::getTransportationHandle(const char* theName) {
    return guarded([&] { return TransportationHandle{Client::transportation_handle(text(theName))}; });
}

char* RTI::RTIambassador::getTransportationName(TransportationHandle theHandle) {
    return guarded([&] { return name_copy(Client::transportation_name(theHandle)); });
}

RTI::OrderingHandle RTI::RTIambassador::getOrderingHandle(const char* theName) {
    return guarded([&] { return OrderingHandle{Client::ordering_handle(text(theName))}; });
}

char* RTI::RTIambassador::getOrderingName(OrderingHandle theHandle) {
    return guarded([&] { return name_copy(Client::ordering_name(theHandle)); });
}

namespace {
void set_switch(Client& client, wire::AdvisorySwitch which, bool on) {
    guarded([&] { client.request(wire::SetAdvisorySwitch{static_cast<std::uint8_t>(which), on}); });
}
}  // namespace

void RTI::RTIambassador::enableClassRelevanceAdvisorySwitch() { set_switch(privateRefs->client, wire::AdvisorySwitch::ClassRelevance, true); }
void RTI::RTIambassador::disableClassRelevanceAdvisorySwitch() { set_switch(privateRefs->client, wire::AdvisorySwitch::ClassRelevance, false); }
void RTI::RTIambassador::enableAttributeRelevanceAdvisorySwitch() { set_switch(privateRefs->client, wire::AdvisorySwitch::AttributeRelevance, true); }
void RTI::RTIambassador::disableAttributeRelevanceAdvisorySwitch() { set_switch(privateRefs->client, wire::AdvisorySwitch::AttributeRelevance, false); }
void RTI::RTIambassador::enableAttributeScopeAdvisorySwitch() { set_switch(privateRefs->client, wire::AdvisorySwitch::AttributeScope, true); }
void RTI::RTIambassador::disableAttributeScopeAdvisorySwitch() { set_switch(privateRefs->client, wire::AdvisorySwitch::AttributeScope, false); }
void RTI::RTIambassador::enableInteractionRelevanceAdvisorySwitch() { set_switch(privateRefs->client, wire::AdvisorySwitch::InteractionRelevance, true); }
void RTI::RTIambassador::disableInteractionRelevanceAdvisorySwitch() { set_switch(privateRefs->client, wire::AdvisorySwitch::InteractionRelevance, false); }

// ---- tick ----

namespace {
// Delivers what is queued, until `deadline` (max(): all of it).
void deliver_queued(RTIambPrivateRefs& refs, Client::Clock::time_point deadline) {
    while (auto m = refs.client.pop_callback()) {
        refs.deliver(*m);
        if (deadline != Client::Clock::time_point::max() && Client::Clock::now() >= deadline) break;
    }
}
}  // namespace

RTI::Boolean RTI::RTIambassador::tick() {
    return guarded([&] {
        privateRefs->client.poll_now();
        deliver_queued(*privateRefs, Client::Clock::time_point::max());
        return hla13::boolean(privateRefs->client.has_callbacks());
    });
}

RTI::Boolean RTI::RTIambassador::tick(TickTime minimum, TickTime maximum) {
    return guarded([&] {
        using Seconds = std::chrono::duration<double>;
        Client& c = privateRefs->client;
        const double lo = minimum > 0 ? minimum : 0.0;
        const double hi = maximum > lo ? maximum : lo;
        const auto start = Client::Clock::now();
        const auto after = [&](double s) { return start + std::chrono::duration_cast<Client::Clock::duration>(Seconds(s)); };
        if (c.wait_for_callback(after(lo)) != Client::WaitStatus::Ready) return hla13::boolean(c.has_callbacks());
        const auto deadline = after(hi);
        for (;;) {
            deliver_queued(*privateRefs, deadline);
            if (Client::Clock::now() >= deadline) break;
            c.poll_now();  // more may have come meanwhile: delivered within the same tick
            if (!c.has_callbacks()) break;
        }
        return hla13::boolean(c.has_callbacks());
    });
}

RTI::RegionToken RTI::RTIambassador::getRegionToken(Region* theRegion) {
    return guarded([&] { return RegionToken{privateRefs->known(*theRegion).handle()}; });
}

RTI::Region* RTI::RTIambassador::getRegion(RegionToken theToken) {
    return guarded([&]() -> Region* {
        const auto it = privateRefs->regions.find(h32(theToken));
        if (it == privateRefs->regions.end())
            throw RTI::RegionNotKnown(("region token " + std::to_string(theToken)).c_str());
        return it->second;
    });
}
