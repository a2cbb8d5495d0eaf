// The callbacks: each message from the gateway as the CERTI message the federate's libRTI turns into the call
// of its FederateAmbassador (the counterpart of cpp/hla13/callbacks.cpp).
#include "certi/rtia.hpp"
#include "rti/wire/callbacks.hpp"

namespace hlacore::certi {

namespace {

// A received update or interaction: its values, and when timestamped its date and retraction handle.
template <class M>
void received(Message& out, M& m) {
    out.handles.reserve(m.values.size());
    out.values.reserve(m.values.size());
    for (auto& [handle, value] : m.values) {
        out.handles.push_back(handle);
        out.values.emplace_back(value.view());
    }
    out.tag = m.tag;
    if (m.time) {
        out.date = *m.time;
        out.retraction = EventRetraction{m.sender, m.serial};
    }
}

Message labelled(Type type, const std::string& label) {
    Message out(type);
    out.label = label;
    return out;
}

Message timed(Type type, double time) {
    Message out(type);
    out.date = time;
    return out;
}

// One overload per message of HLACORE_CALLBACK_MESSAGES (wire/callbacks.hpp checks that none is missing).
struct ToMessage {
    Message operator()(wire::SyncPointRegistrationSucceeded& m) {
        return labelled(Type::SYNCHRONIZATION_POINT_REGISTRATION_SUCCEEDED, m.label);
    }
    Message operator()(wire::SyncPointRegistrationFailed& m) {
        return labelled(Type::SYNCHRONIZATION_POINT_REGISTRATION_FAILED, m.label);
    }
    Message operator()(wire::AnnounceSyncPoint& m) {
        Message out = labelled(Type::ANNOUNCE_SYNCHRONIZATION_POINT, m.label);
        out.tag = m.tag;
        return out;
    }
    Message operator()(wire::FederationSynchronized& m) { return labelled(Type::FEDERATION_SYNCHRONIZED, m.label); }
    Message operator()(wire::InitiateFederateSave& m) { return labelled(Type::INITIATE_FEDERATE_SAVE, m.label); }
    Message operator()(wire::FederationSaved& m) {
        return Message(m.success ? Type::FEDERATION_SAVED : Type::FEDERATION_NOT_SAVED);
    }
    Message operator()(wire::RestoreRequestAnswer& m) {
        if (m.succeeded) return labelled(Type::REQUEST_FEDERATION_RESTORE_SUCCEEDED, m.label);
        Message out = labelled(Type::REQUEST_FEDERATION_RESTORE_FAILED, m.label);
        out.restore_reason = m.reason;
        out.tag = m.reason;  // where CERTI's libRTI reads the reason
        return out;
    }
    Message operator()(wire::FederationRestoreBegun&) { return Message(Type::FEDERATION_RESTORE_BEGUN); }
    Message operator()(wire::InitiateFederateRestore& m) {
        Message out = labelled(Type::INITIATE_FEDERATE_RESTORE, m.label);
        out.federate = m.federate;
        return out;
    }
    Message operator()(wire::FederationRestored& m) {
        return Message(m.success ? Type::FEDERATION_RESTORED : Type::FEDERATION_NOT_RESTORED);
    }
    Message operator()(wire::StartRegistration& m) { return with_class(Type::START_REGISTRATION_FOR_OBJECT_CLASS, m.object_class); }
    Message operator()(wire::StopRegistration& m) { return with_class(Type::STOP_REGISTRATION_FOR_OBJECT_CLASS, m.object_class); }
    Message operator()(wire::TurnInteractionsOn& m) { return with_interaction(Type::TURN_INTERACTIONS_ON, m.interaction_class); }
    Message operator()(wire::TurnInteractionsOff& m) { return with_interaction(Type::TURN_INTERACTIONS_OFF, m.interaction_class); }
    Message operator()(wire::DiscoverObject& m) {
        Message out = with_class(Type::DISCOVER_OBJECT_INSTANCE, m.object_class);
        out.object = m.object;
        out.name = m.name;
        return out;
    }
    Message operator()(wire::ReflectAttributes& m) {
        Message out(Type::REFLECT_ATTRIBUTE_VALUES);
        out.object = m.object;
        received(out, m);
        return out;
    }
    Message operator()(wire::ReceiveInteraction& m) {
        Message out = with_interaction(Type::RECEIVE_INTERACTION, m.interaction_class);
        received(out, m);
        return out;
    }
    Message operator()(wire::RemoveObject& m) {
        Message out(Type::REMOVE_OBJECT_INSTANCE);
        out.object = m.object;
        out.tag = m.tag;
        if (m.time) {
            out.date = *m.time;
            out.retraction = EventRetraction{m.sender, m.serial};
        }
        return out;
    }
#define HLACORE_X(message, type)                         \
    Message operator()(wire::message& m) {               \
        Message out(Type::type);                         \
        out.object = m.object;                           \
        out.handles.assign(m.attributes.begin(), m.attributes.end()); \
        return out;                                      \
    }
    HLACORE_X(ProvideAttributeValueUpdate, PROVIDE_ATTRIBUTE_VALUE_UPDATE)
    HLACORE_X(DivestitureNotification, ATTRIBUTE_OWNERSHIP_DIVESTITURE_NOTIFICATION)
    HLACORE_X(AcquisitionNotification, ATTRIBUTE_OWNERSHIP_ACQUISITION_NOTIFICATION)
    HLACORE_X(OwnershipUnavailable, ATTRIBUTE_OWNERSHIP_UNAVAILABLE)
    HLACORE_X(ConfirmAcquisitionCancellation, CONFIRM_ATTRIBUTE_OWNERSHIP_ACQUISITION_CANCELLATION)
    HLACORE_X(AttributesInScope, ATTRIBUTES_IN_SCOPE)
    HLACORE_X(AttributesOutOfScope, ATTRIBUTES_OUT_OF_SCOPE)
    HLACORE_X(TurnUpdatesOn, TURN_UPDATES_ON_FOR_OBJECT_INSTANCE)
    HLACORE_X(TurnUpdatesOff, TURN_UPDATES_OFF_FOR_OBJECT_INSTANCE)
#undef HLACORE_X
    Message operator()(wire::RequestOwnershipAssumption& m) {
        return tagged_attributes(Type::REQUEST_ATTRIBUTE_OWNERSHIP_ASSUMPTION, m);
    }
    Message operator()(wire::RequestOwnershipRelease& m) {
        return tagged_attributes(Type::REQUEST_ATTRIBUTE_OWNERSHIP_RELEASE, m);
    }
    Message operator()(wire::OwnershipInformation& m) {
        Message out;
        switch (static_cast<wire::OwnershipKind>(m.kind)) {
            case wire::OwnershipKind::OwnedByFederate: out.type = Type::INFORM_ATTRIBUTE_OWNERSHIP; break;
            case wire::OwnershipKind::OwnedByRti: out.type = Type::ATTRIBUTE_OWNED_BY_RTI; break;
            default: out.type = Type::ATTRIBUTE_IS_NOT_OWNED; break;
        }
        out.object = m.object;
        out.attribute = m.attribute;
        out.federate = m.owner;
        return out;
    }
    Message operator()(wire::TimeRegulationEnabled& m) { return timed(Type::TIME_REGULATION_ENABLED, m.time); }
    Message operator()(wire::TimeConstrainedEnabled& m) { return timed(Type::TIME_CONSTRAINED_ENABLED, m.time); }
    Message operator()(wire::TimeAdvanceGrant& m) { return timed(Type::TIME_ADVANCE_GRANT, m.time); }
    Message operator()(wire::ObjectNamesReserved& m) {  // the rtia asks for one name at a time
        Message out(m.success ? Type::RESERVE_OBJECT_INSTANCE_NAME_SUCCEEDED : Type::RESERVE_OBJECT_INSTANCE_NAME_FAILED);
        out.name = m.names.empty() ? std::string() : m.names.front();
        return out;
    }
    Message operator()(wire::RequestRetraction& m) {
        Message out(Type::REQUEST_RETRACTION);
        out.retraction = EventRetraction{m.sender, m.serial};
        return out;
    }
    // CERTI's protocol has no transportation queries: the rtia never asks.
    Message operator()(wire::AttributeTransportationReported&) { return unexpected(); }
    Message operator()(wire::InteractionTransportationReported&) { return unexpected(); }
    Message unexpected() { raise(ErrorCode::RTIinternalError, "unexpected message from the gateway"); }

private:
    static Message with_class(Type type, std::uint32_t cls) {
        Message out(type);
        out.object_class = cls;
        return out;
    }
    static Message with_interaction(Type type, std::uint32_t cls) {
        Message out(type);
        out.interaction_class = cls;
        return out;
    }
    template <class M>
    static Message tagged_attributes(Type type, M& m) {
        Message out(type);
        out.object = m.object;
        out.handles.assign(m.attributes.begin(), m.attributes.end());
        out.tag = m.tag;
        return out;
    }
};

}  // namespace

Message Rtia::message_of(wire::Message& callback) {
    ToMessage to;
    return wire::dispatch_callback<Message>(callback, to);
}

}  // namespace hlacore::certi
