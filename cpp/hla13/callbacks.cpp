// The callbacks: each message from the gateway becomes one call of the federate's FederateAmbassador
// (RTIambassador::tick delivers them), the HLA 1.3 counterpart of cpp/bindings/callbacks.cpp.
#include <type_traits>

#include "ambassador.hpp"
#include "fedtime.hh"

using namespace hlacore;
using hlacore::hla13::AttributeHandles;
using hlacore::hla13::AttributeValues;
using hlacore::hla13::Pairs;
using hlacore::hla13::ParameterValues;
using hlacore::hla13::retraction;

namespace {

// Received values, with how they came.
template <class M>
Pairs received(M& m) {
    return Pairs{std::move(m.values), true, m.order, m.transport};
}

}  // namespace

void RTIambPrivateRefs::deliver(wire::Message& message) {
    if (!federate) return;  // not joined (or joined without an ambassador): nobody to tell
    RTI::FederateAmbassador& fa = *federate;
    std::visit(
        [&fa](auto& m) {
            using M = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<M, wire::SyncPointRegistrationSucceeded>) {
                fa.synchronizationPointRegistrationSucceeded(m.label.c_str());
            } else if constexpr (std::is_same_v<M, wire::SyncPointRegistrationFailed>) {
                fa.synchronizationPointRegistrationFailed(m.label.c_str());
            } else if constexpr (std::is_same_v<M, wire::AnnounceSyncPoint>) {
                fa.announceSynchronizationPoint(m.label.c_str(), m.tag.c_str());
            } else if constexpr (std::is_same_v<M, wire::FederationSynchronized>) {
                fa.federationSynchronized(m.label.c_str());
            } else if constexpr (std::is_same_v<M, wire::StartRegistration>) {
                fa.startRegistrationForObjectClass(m.object_class);
            } else if constexpr (std::is_same_v<M, wire::StopRegistration>) {
                fa.stopRegistrationForObjectClass(m.object_class);
            } else if constexpr (std::is_same_v<M, wire::TurnInteractionsOn>) {
                fa.turnInteractionsOn(m.interaction_class);
            } else if constexpr (std::is_same_v<M, wire::TurnInteractionsOff>) {
                fa.turnInteractionsOff(m.interaction_class);
            } else if constexpr (std::is_same_v<M, wire::DiscoverObject>) {
                fa.discoverObjectInstance(m.object, m.object_class, m.name.c_str());
            } else if constexpr (std::is_same_v<M, wire::ReflectAttributes>) {
                const AttributeValues values(received(m));
                if (m.time)
                    fa.reflectAttributeValues(m.object, values, RTIfedTime(*m.time), m.tag.c_str(), retraction(m.sender, m.serial));
                else
                    fa.reflectAttributeValues(m.object, values, m.tag.c_str());
            } else if constexpr (std::is_same_v<M, wire::ReceiveInteraction>) {
                const ParameterValues values(received(m));
                if (m.time)
                    fa.receiveInteraction(m.interaction_class, values, RTIfedTime(*m.time), m.tag.c_str(),
                                          retraction(m.sender, m.serial));
                else
                    fa.receiveInteraction(m.interaction_class, values, m.tag.c_str());
            } else if constexpr (std::is_same_v<M, wire::RemoveObject>) {
                if (m.time)
                    fa.removeObjectInstance(m.object, RTIfedTime(*m.time), m.tag.c_str(), retraction(m.sender, m.serial));
                else
                    fa.removeObjectInstance(m.object, m.tag.c_str());
            } else if constexpr (std::is_same_v<M, wire::TimeRegulationEnabled>) {
                fa.timeRegulationEnabled(RTIfedTime(m.time));
            } else if constexpr (std::is_same_v<M, wire::TimeConstrainedEnabled>) {
                fa.timeConstrainedEnabled(RTIfedTime(m.time));
            } else if constexpr (std::is_same_v<M, wire::TimeAdvanceGrant>) {
                fa.timeAdvanceGrant(RTIfedTime(m.time));
            } else if constexpr (std::is_same_v<M, wire::RequestRetraction>) {
                fa.requestRetraction(retraction(m.sender, m.serial));
            } else if constexpr (std::is_same_v<M, wire::ProvideAttributeValueUpdate>) {
                fa.provideAttributeValueUpdate(m.object, AttributeHandles(std::move(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::RequestOwnershipAssumption>) {
                fa.requestAttributeOwnershipAssumption(m.object, AttributeHandles(std::move(m.attributes)), m.tag.c_str());
            } else if constexpr (std::is_same_v<M, wire::DivestitureNotification>) {
                fa.attributeOwnershipDivestitureNotification(m.object, AttributeHandles(std::move(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::AcquisitionNotification>) {
                fa.attributeOwnershipAcquisitionNotification(m.object, AttributeHandles(std::move(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::OwnershipUnavailable>) {
                fa.attributeOwnershipUnavailable(m.object, AttributeHandles(std::move(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::RequestOwnershipRelease>) {
                fa.requestAttributeOwnershipRelease(m.object, AttributeHandles(std::move(m.attributes)), m.tag.c_str());
            } else if constexpr (std::is_same_v<M, wire::ConfirmAcquisitionCancellation>) {
                fa.confirmAttributeOwnershipAcquisitionCancellation(m.object, AttributeHandles(std::move(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::AttributesInScope>) {
                fa.attributesInScope(m.object, AttributeHandles(std::move(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::AttributesOutOfScope>) {
                fa.attributesOutOfScope(m.object, AttributeHandles(std::move(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::TurnUpdatesOn>) {
                fa.turnUpdatesOnForObjectInstance(m.object, AttributeHandles(std::move(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::TurnUpdatesOff>) {
                fa.turnUpdatesOffForObjectInstance(m.object, AttributeHandles(std::move(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::OwnershipInformation>) {
                switch (static_cast<wire::OwnershipKind>(m.kind)) {
                    case wire::OwnershipKind::OwnedByFederate: fa.informAttributeOwnership(m.object, m.attribute, m.owner); break;
                    case wire::OwnershipKind::OwnedByRti: fa.attributeOwnedByRTI(m.object, m.attribute); break;
                    default: fa.attributeIsNotOwned(m.object, m.attribute); break;
                }
            } else if constexpr (std::is_same_v<M, wire::InitiateFederateSave>) {
                fa.initiateFederateSave(m.label.c_str());
            } else if constexpr (std::is_same_v<M, wire::FederationSaved>) {
                if (m.success) fa.federationSaved();
                else fa.federationNotSaved();
            } else if constexpr (std::is_same_v<M, wire::RestoreRequestAnswer>) {
                if (m.succeeded) fa.requestFederationRestoreSucceeded(m.label.c_str());
                else fa.requestFederationRestoreFailed(m.label.c_str(), m.reason.c_str());
            } else if constexpr (std::is_same_v<M, wire::FederationRestoreBegun>) {
                fa.federationRestoreBegun();
            } else if constexpr (std::is_same_v<M, wire::InitiateFederateRestore>) {
                fa.initiateFederateRestore(m.label.c_str(), m.federate);
            } else if constexpr (std::is_same_v<M, wire::FederationRestored>) {
                if (m.success) fa.federationRestored();
                else fa.federationNotRestored();
            } else {
                throw RTI::RTIinternalError("unexpected message from the gateway");
            }
        },
        message);
}
