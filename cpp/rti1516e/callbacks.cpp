// The callbacks: each message from the gateway becomes one call of the federate's FederateAmbassador with
// IEEE 1516-2010's arguments (the fourth front end of wire::dispatch_callback, beside cpp/bindings,
// cpp/hla13 and cpp/certi), delivered by evokeCallback / evokeMultipleCallbacks, or by the ambassador's own
// thread under HLA_IMMEDIATE.
#include <iostream>

#include "ambassador.hpp"
#include "rti/wire/callbacks.hpp"

namespace hlacore::rti1516e {

namespace {

// Received values as the callback's map: views of the message's bytes, which outlive the call.
template <class H>
std::map<H, VariableLengthData> received(wire::HandleValues& values) {
    std::map<H, VariableLengthData> out;
    for (auto& [h, v] : values) out[handle<H>(h)].setDataPointer(const_cast<char*>(v.data()), v.size());
    return out;
}

VariableLengthData tag_of(std::string const& tag) {
    VariableLengthData d;
    d.setDataPointer(const_cast<char*>(tag.data()), tag.size());
    return d;
}

}  // namespace

struct Deliver {
    FederateAmbassador& fa;
    std::map<std::string, bool>& sync_sets;
    std::set<std::wstring>& reserved;
    std::map<std::uint32_t, std::set<std::uint32_t>>& divesting;
    std::map<std::uint32_t, std::set<std::uint32_t>>& release_asked;
    std::string const& federate_name;
    bool integer_time;
    DirectedInteractionReceiver* directed;  // HLA 4's, when the federate ambassador is one
    // A timestamped callback's time, made only where there is one.
    TimeOut time() const { return TimeOut(integer_time); }

    static AttributeHandleSet attrs(wire::Handles const& a) { return handles<AttributeHandle>(a); }
    // A reflection or an interaction: `call` gets the values, the tag, how they were sent, and with a timestamp
    // the time, the order received and the retraction handle, then the supplemental information.
    template <class ValueHandle, class Info, class M, class Call>
    void values_to(M& m, Call call) {
        const auto values = received<ValueHandle>(m.values);
        const Info info(handle<FederateHandle>(m.sender));
        const auto order = static_cast<OrderType>(m.order);
        const auto transport = static_cast<TransportationType>(m.transport);
        if (m.time)
            call(values, tag_of(m.tag), order, transport, time()(*m.time), order, retraction(m.sender, m.serial), info);
        else
            call(values, tag_of(m.tag), order, transport, info);
    }

    void operator()(wire::SyncPointRegistrationSucceeded& m) {
        sync_sets.erase(m.label);
        fa.synchronizationPointRegistrationSucceeded(wide(m.label));
    }
    void operator()(wire::SyncPointRegistrationFailed& m) {
        // The core fails a label in use, or a set naming a federate that is not joined.
        const bool with_set = sync_sets.count(m.label) && sync_sets[m.label];
        sync_sets.erase(m.label);
        fa.synchronizationPointRegistrationFailed(
            wide(m.label), with_set ? SYNCHRONIZATION_SET_MEMBER_NOT_JOINED : SYNCHRONIZATION_POINT_LABEL_NOT_UNIQUE);
    }
    void operator()(wire::AnnounceSyncPoint& m) { fa.announceSynchronizationPoint(wide(m.label), tag_of(m.tag)); }
    void operator()(wire::FederationSynchronized& m) { fa.federationSynchronized(wide(m.label), FederateHandleSet{}); }
    void operator()(wire::InitiateFederateSave& m) { fa.initiateFederateSave(wide(m.label)); }
    void operator()(wire::FederationSaved& m) {
        if (m.success) fa.federationSaved();
        else fa.federationNotSaved(static_cast<SaveFailureReason>(m.reason));  // numbered alike (wire/messages.hpp)
    }
    void operator()(wire::RestoreRequestAnswer& m) {
        if (m.succeeded) fa.requestFederationRestoreSucceeded(wide(m.label));
        else fa.requestFederationRestoreFailed(wide(m.label));
    }
    void operator()(wire::FederationRestoreBegun&) { fa.federationRestoreBegun(); }
    void operator()(wire::InitiateFederateRestore& m) {  // the restore keeps each federate's name
        fa.initiateFederateRestore(wide(m.label), wide(federate_name), handle<FederateHandle>(m.federate));
    }
    void operator()(wire::FederationRestored& m) {
        if (m.success) fa.federationRestored();
        else fa.federationNotRestored(static_cast<RestoreFailureReason>(m.reason));
    }
    void operator()(wire::StartRegistration& m) { fa.startRegistrationForObjectClass(handle<ObjectClassHandle>(m.object_class)); }
    void operator()(wire::StopRegistration& m) { fa.stopRegistrationForObjectClass(handle<ObjectClassHandle>(m.object_class)); }
    void operator()(wire::TurnInteractionsOn& m) { fa.turnInteractionsOn(handle<InteractionClassHandle>(m.interaction_class)); }
    void operator()(wire::TurnInteractionsOff& m) { fa.turnInteractionsOff(handle<InteractionClassHandle>(m.interaction_class)); }
    void operator()(wire::DiscoverObject& m) {
        fa.discoverObjectInstance(handle<ObjectInstanceHandle>(m.object), handle<ObjectClassHandle>(m.object_class),
                                  wide(m.name));
    }
    void operator()(wire::ReflectAttributes& m) {
        const auto object = handle<ObjectInstanceHandle>(m.object);
        values_to<AttributeHandle, SupplementalReflectInfo>(m, [&](auto const&... a) { fa.reflectAttributeValues(object, a...); });
    }
    void operator()(wire::ReceiveInteraction& m) {
        const auto cls = handle<InteractionClassHandle>(m.interaction_class);
        values_to<ParameterHandle, SupplementalReceiveInfo>(m, [&](auto const&... a) { fa.receiveInteraction(cls, a...); });
    }
    void operator()(wire::ReceiveDirectedInteraction& m) {
        if (!directed) unexpected();
        const auto values = received<ParameterHandle>(m.values);
        const auto cls = handle<InteractionClassHandle>(m.interaction_class);
        const auto object = handle<ObjectInstanceHandle>(m.object);
        const auto transport = static_cast<TransportationType>(m.transport);
        const auto producer = handle<FederateHandle>(m.sender);
        if (m.time) {
            const auto retraction_handle = retraction(m.sender, m.serial);
            directed->receiveDirectedInteraction(cls, object, values, tag_of(m.tag), transport, producer, time()(*m.time),
                                                 TIMESTAMP, TIMESTAMP, &retraction_handle);
        } else {
            directed->receiveDirectedInteraction(cls, object, values, tag_of(m.tag), transport, producer);
        }
    }
    void operator()(wire::RemoveObject& m) {
        const auto object = handle<ObjectInstanceHandle>(m.object);
        const SupplementalRemoveInfo info(handle<FederateHandle>(m.sender));
        if (m.time)
            fa.removeObjectInstance(object, tag_of(m.tag), TIMESTAMP, time()(*m.time), TIMESTAMP,
                                    retraction(m.sender, m.serial), info);
        else
            fa.removeObjectInstance(object, tag_of(m.tag), RECEIVE, info);
    }
    void operator()(wire::AttributesInScope& m) { fa.attributesInScope(handle<ObjectInstanceHandle>(m.object), attrs(m.attributes)); }
    void operator()(wire::AttributesOutOfScope& m) {
        fa.attributesOutOfScope(handle<ObjectInstanceHandle>(m.object), attrs(m.attributes));
    }
    void operator()(wire::ProvideAttributeValueUpdate& m) {  // the core's request carries no tag
        fa.provideAttributeValueUpdate(handle<ObjectInstanceHandle>(m.object), attrs(m.attributes), VariableLengthData());
    }
    void operator()(wire::TurnUpdatesOn& m) {
        fa.turnUpdatesOnForObjectInstance(handle<ObjectInstanceHandle>(m.object), attrs(m.attributes));
    }
    void operator()(wire::TurnUpdatesOff& m) {
        fa.turnUpdatesOffForObjectInstance(handle<ObjectInstanceHandle>(m.object), attrs(m.attributes));
    }
    void operator()(wire::AttributeTransportationReported& m) {
        fa.reportAttributeTransportationType(handle<ObjectInstanceHandle>(m.object), handle<AttributeHandle>(m.attribute),
                                             static_cast<TransportationType>(m.transport));
    }
    void operator()(wire::InteractionTransportationReported& m) {
        fa.reportInteractionTransportationType(handle<FederateHandle>(m.federate),
                                               handle<InteractionClassHandle>(m.interaction_class),
                                               static_cast<TransportationType>(m.transport));
    }
    void operator()(wire::ObjectNamesReserved& m) {
        std::set<std::wstring> names;
        for (const auto& n : m.names) names.insert(wide(n));
        if (m.success) reserved.insert(names.begin(), names.end());
        if (m.multiple) {
            if (m.success) fa.multipleObjectInstanceNameReservationSucceeded(names);
            else fa.multipleObjectInstanceNameReservationFailed(names);
        } else if (!names.empty()) {
            if (m.success) fa.objectInstanceNameReservationSucceeded(*names.begin());
            else fa.objectInstanceNameReservationFailed(*names.begin());
        }
    }
    void operator()(wire::RequestOwnershipAssumption& m) {
        fa.requestAttributeOwnershipAssumption(handle<ObjectInstanceHandle>(m.object), attrs(m.attributes), tag_of(m.tag));
    }
    void operator()(wire::DivestitureNotification& m) {  // confirmDivestiture checks it was asked
        divesting[m.object].insert(m.attributes.begin(), m.attributes.end());
        fa.requestDivestitureConfirmation(handle<ObjectInstanceHandle>(m.object), attrs(m.attributes));
    }
    void operator()(wire::AcquisitionNotification& m) {
        fa.attributeOwnershipAcquisitionNotification(handle<ObjectInstanceHandle>(m.object), attrs(m.attributes),
                                                     VariableLengthData());
    }
    void operator()(wire::OwnershipUnavailable& m) {
        fa.attributeOwnershipUnavailable(handle<ObjectInstanceHandle>(m.object), attrs(m.attributes));
    }
    void operator()(wire::RequestOwnershipRelease& m) {  // attributeOwnershipDivestitureIfWanted gives these
        release_asked[m.object].insert(m.attributes.begin(), m.attributes.end());
        fa.requestAttributeOwnershipRelease(handle<ObjectInstanceHandle>(m.object), attrs(m.attributes), tag_of(m.tag));
    }
    void operator()(wire::ConfirmAcquisitionCancellation& m) {
        fa.confirmAttributeOwnershipAcquisitionCancellation(handle<ObjectInstanceHandle>(m.object), attrs(m.attributes));
    }
    void operator()(wire::OwnershipInformation& m) {
        const auto object = handle<ObjectInstanceHandle>(m.object);
        const auto attribute = handle<AttributeHandle>(m.attribute);
        switch (static_cast<wire::OwnershipKind>(m.kind)) {
            case wire::OwnershipKind::OwnedByFederate:
                fa.informAttributeOwnership(object, attribute, handle<FederateHandle>(m.owner));
                break;
            case wire::OwnershipKind::OwnedByRti: fa.attributeIsOwnedByRTI(object, attribute); break;
            default: fa.attributeIsNotOwned(object, attribute); break;
        }
    }
    void operator()(wire::TimeRegulationEnabled& m) { fa.timeRegulationEnabled(time()(m.time)); }
    void operator()(wire::TimeConstrainedEnabled& m) { fa.timeConstrainedEnabled(time()(m.time)); }
    void operator()(wire::TimeAdvanceGrant& m) { fa.timeAdvanceGrant(time()(m.time)); }
    void operator()(wire::RequestRetraction& m) { fa.requestRetraction(retraction(m.sender, m.serial)); }
    void unexpected() { raise("RTIinternalError", "unexpected message from the gateway"); }
};

void Ambassador::deliver(wire::Message& message) {
    Deliver d{*federate_, sync_sets_, reserved_, divesting_, release_asked_, federate_name_,
              integer_time_, directed_};
    wire::dispatch_callback<void>(message, d);
}

bool Ambassador::deliver_one() {
    std::lock_guard<std::recursive_mutex> lock(mu_);
    if (!callbacks_enabled_ || !client_ || !federate_) return false;
    if (!local_.empty()) {
        auto call = std::move(local_.front());
        local_.pop_front();
        call(*federate_);
        return true;
    }
    auto m = client_->pop_callback();
    if (!m) return false;
    try {
        deliver(*m);
    } catch (const Exception& e) {
        if (!immediate_) throw;
        std::wcerr << L"hlacore rti1516e: a callback raised " << e.what() << std::endl;  // the thread goes on
    }
    return true;
}

namespace {
Client::Clock::time_point after(Client::Clock::time_point start, double seconds) {
    using Seconds = std::chrono::duration<double>;
    return start + std::chrono::duration_cast<Client::Clock::duration>(Seconds(seconds > 0 ? seconds : 0));
}
}  // namespace

bool Ambassador::evokeCallback(double minimumSeconds) {
    return guarded([&] {
        Client& c = client();
        if (!immediate_ && callbacks_enabled_) {
            c.poll_now();
            if (!deliver_one() && c.wait_for_callback(after(Client::Clock::now(), minimumSeconds)) == Client::WaitStatus::Ready)
                deliver_one();
        }
        std::lock_guard<std::recursive_mutex> lock(mu_);
        return !local_.empty() || c.has_callbacks();
    });
}

bool Ambassador::evokeMultipleCallbacks(double minimumSeconds, double maximumSeconds) {
    return guarded([&] {
        Client& c = client();
        const auto start = Client::Clock::now();
        if (!immediate_ && callbacks_enabled_) {
            c.poll_now();
            bool any = deliver_one();
            if (!any && c.wait_for_callback(after(start, minimumSeconds)) == Client::WaitStatus::Ready) any = deliver_one();
            const auto deadline = after(start, std::max(minimumSeconds, maximumSeconds));
            while (any && Client::Clock::now() < deadline) {
                any = deliver_one();
                if (!any) {
                    c.poll_now();  // more may have come meanwhile: delivered within the same call
                    any = deliver_one();
                }
            }
        }
        std::lock_guard<std::recursive_mutex> lock(mu_);
        return !local_.empty() || c.has_callbacks();
    });
}

void Ambassador::enableCallbacks() {
    guarded([&] {
        client();
        std::lock_guard<std::recursive_mutex> lock(mu_);
        callbacks_enabled_ = true;
    });
}

void Ambassador::disableCallbacks() {
    guarded([&] {
        client();
        std::lock_guard<std::recursive_mutex> lock(mu_);  // once this returns, no callback is being delivered
        callbacks_enabled_ = false;
    });
}

}  // namespace hlacore::rti1516e
