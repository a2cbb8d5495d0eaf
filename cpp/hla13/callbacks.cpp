// The callbacks: each message from the gateway becomes one call of the federate's FederateAmbassador
// (RTIambassador::tick delivers them), the HLA 1.3 counterpart of cpp/bindings/callbacks.cpp.
#include <type_traits>

#include "ambassador.hpp"
#include "fedtime.hh"
#include "rti/wire/callbacks.hpp"

using namespace hlacore;
using namespace hlacore::hla13;

namespace {

// Received values, with how they came.
template <class M>
Pairs received(M& m) {
    return Pairs{std::move(m.values), true, m.order, m.transport};
}

// Each callback message as the call of the federate's ambassador it is: one overload per message of
// HLACORE_CALLBACK_MESSAGES (wire/callbacks.hpp checks that none is missing).
struct Deliver {
    RTI::FederateAmbassador& fa;
    void operator()(wire::SyncPointRegistrationSucceeded& m) {
        fa.synchronizationPointRegistrationSucceeded(m.label.c_str());
    }
    void operator()(wire::SyncPointRegistrationFailed& m) {
        fa.synchronizationPointRegistrationFailed(m.label.c_str());
    }
    void operator()(wire::AnnounceSyncPoint& m) { fa.announceSynchronizationPoint(m.label.c_str(), m.tag.c_str()); }
    void operator()(wire::FederationSynchronized& m) { fa.federationSynchronized(m.label.c_str()); }
    void operator()(wire::StartRegistration& m) { fa.startRegistrationForObjectClass(m.object_class); }
    void operator()(wire::StopRegistration& m) { fa.stopRegistrationForObjectClass(m.object_class); }
    void operator()(wire::TurnInteractionsOn& m) { fa.turnInteractionsOn(m.interaction_class); }
    void operator()(wire::TurnInteractionsOff& m) { fa.turnInteractionsOff(m.interaction_class); }
    void operator()(wire::DiscoverObject& m) { fa.discoverObjectInstance(m.object, m.object_class, m.name.c_str()); }
    void operator()(wire::ReflectAttributes& m) {
        const AttributeValues values(received(m));
        if (m.time)
            fa.reflectAttributeValues(m.object, values, RTIfedTime(*m.time), m.tag.c_str(), retraction(m.sender, m.serial));
        else
            fa.reflectAttributeValues(m.object, values, m.tag.c_str());
    }
    void operator()(wire::ReceiveInteraction& m) {
        const ParameterValues values(received(m));
        if (m.time)
            fa.receiveInteraction(m.interaction_class, values, RTIfedTime(*m.time), m.tag.c_str(),
                                  retraction(m.sender, m.serial));
        else
            fa.receiveInteraction(m.interaction_class, values, m.tag.c_str());
    }
    void operator()(wire::RemoveObject& m) {
        if (m.time)
            fa.removeObjectInstance(m.object, RTIfedTime(*m.time), m.tag.c_str(), retraction(m.sender, m.serial));
        else
            fa.removeObjectInstance(m.object, m.tag.c_str());
    }
    void operator()(wire::TimeRegulationEnabled& m) { fa.timeRegulationEnabled(RTIfedTime(m.time)); }
    void operator()(wire::TimeConstrainedEnabled& m) { fa.timeConstrainedEnabled(RTIfedTime(m.time)); }
    void operator()(wire::TimeAdvanceGrant& m) { fa.timeAdvanceGrant(RTIfedTime(m.time)); }
    void operator()(wire::RequestRetraction& m) { fa.requestRetraction(retraction(m.sender, m.serial)); }
    // HLA 1.3 has no name reservation nor transportation queries: never asked for.
    void operator()(wire::ObjectNamesReserved&) {}
    void operator()(wire::AttributeTransportationReported&) {}
    void operator()(wire::InteractionTransportationReported&) {}
#define HLACORE_X(message, callback) \
    void operator()(wire::message& m) { fa.callback(m.object, AttributeHandles(std::move(m.attributes))); }
    HLACORE_OBJECT_ATTRIBUTE_CALLBACKS(HLACORE_X)
#undef HLACORE_X
    void operator()(wire::RequestOwnershipAssumption& m) {
        fa.requestAttributeOwnershipAssumption(m.object, AttributeHandles(std::move(m.attributes)), m.tag.c_str());
    }
    void operator()(wire::RequestOwnershipRelease& m) {
        fa.requestAttributeOwnershipRelease(m.object, AttributeHandles(std::move(m.attributes)), m.tag.c_str());
    }
    void operator()(wire::OwnershipInformation& m) {
        switch (static_cast<wire::OwnershipKind>(m.kind)) {
            case wire::OwnershipKind::OwnedByFederate: fa.informAttributeOwnership(m.object, m.attribute, m.owner); break;
            case wire::OwnershipKind::OwnedByRti: fa.attributeOwnedByRTI(m.object, m.attribute); break;
            default: fa.attributeIsNotOwned(m.object, m.attribute); break;
        }
    }
    void operator()(wire::InitiateFederateSave& m) { fa.initiateFederateSave(m.label.c_str()); }
    void operator()(wire::FederationSaved& m) {
        if (m.success) fa.federationSaved();
        else fa.federationNotSaved();
    }
    void operator()(wire::RestoreRequestAnswer& m) {
        if (m.succeeded) fa.requestFederationRestoreSucceeded(m.label.c_str());
        else fa.requestFederationRestoreFailed(m.label.c_str(), m.reason.c_str());
    }
    void operator()(wire::FederationRestoreBegun&) { fa.federationRestoreBegun(); }
    void operator()(wire::InitiateFederateRestore& m) { fa.initiateFederateRestore(m.label.c_str(), m.federate); }
    void operator()(wire::FederationRestored& m) {
        if (m.success) fa.federationRestored();
        else fa.federationNotRestored();
    }
    void unexpected() { throw RTI::RTIinternalError("unexpected message from the gateway"); }
};

}  // namespace

void RTIambPrivateRefs::deliver(wire::Message& message) {
    if (!federate) return;  // not joined (or joined without an ambassador): nobody to tell
    Deliver deliver{*federate};
    wire::dispatch_callback<void>(message, deliver);
}
