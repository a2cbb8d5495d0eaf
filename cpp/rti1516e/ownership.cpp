// Ownership management (IEEE 1516.1-2010 §7) on the core's HLA 1.3 ownership: its negotiated divestiture
// gives the attributes to the acquirer at once, so confirmDivestiture only checks that it was asked for, and a
// release is answered by attributeOwnershipDivestitureIfWanted with what another federate asked for.
#include "ambassador.hpp"

namespace hlacore::rti1516e {

void Ambassador::unconditionalAttributeOwnershipDivestiture(ObjectInstanceHandle object,
                                                            AttributeHandleSet const& attributes) {
    guarded([&] { client().unconditional_divestiture(core(object), cores(attributes)); });
}

void Ambassador::negotiatedAttributeOwnershipDivestiture(ObjectInstanceHandle object,
                                                         AttributeHandleSet const& attributes,
                                                         VariableLengthData const& tag) {
    guarded([&] { client().negotiated_divestiture(core(object), cores(attributes), bytes(tag)); });
}

void Ambassador::confirmDivestiture(ObjectInstanceHandle object, AttributeHandleSet const& attributes,
                                    VariableLengthData const&) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        client();
        auto& asked = divesting_[core(object)];
        for (const auto& a : attributes)
            if (!asked.count(core(a)))
                raise("AttributeDivestitureWasNotRequested", "no confirmation was asked for " + utf8(a.toString()));
        for (const auto& a : attributes) asked.erase(core(a));
    });
}

void Ambassador::attributeOwnershipAcquisition(ObjectInstanceHandle object, AttributeHandleSet const& attributes,
                                               VariableLengthData const& tag) {
    guarded([&] { client().ownership_acquisition(core(object), cores(attributes), bytes(tag)); });
}

void Ambassador::attributeOwnershipAcquisitionIfAvailable(ObjectInstanceHandle object,
                                                          AttributeHandleSet const& attributes) {
    guarded([&] { client().ownership_acquisition_if_available(core(object), cores(attributes)); });
}

// The core keeps an unanswered release request open: denying it needs no message.
void Ambassador::attributeOwnershipReleaseDenied(ObjectInstanceHandle, AttributeHandleSet const&) {
    guarded([&] { client(); });
}

void Ambassador::attributeOwnershipDivestitureIfWanted(ObjectInstanceHandle object,
                                                       AttributeHandleSet const& attributes,
                                                       AttributeHandleSet& divested) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        auto& asked = release_asked_[core(object)];
        wire::Handles wanted;
        for (const auto& a : attributes)
            if (asked.count(core(a))) wanted.push_back(core(a));
        divested.clear();
        if (wanted.empty()) return;
        for (auto a : client().release_response(core(object), wanted)) divested.insert(handle<AttributeHandle>(a));
        for (auto a : wanted) asked.erase(a);
    });
}

void Ambassador::cancelNegotiatedAttributeOwnershipDivestiture(ObjectInstanceHandle object,
                                                               AttributeHandleSet const& attributes) {
    guarded([&] { client().request(wire::CancelNegotiatedDivestiture{core(object), cores(attributes)}); });
}

void Ambassador::cancelAttributeOwnershipAcquisition(ObjectInstanceHandle object, AttributeHandleSet const& attributes) {
    guarded([&] { client().request(wire::CancelOwnershipAcquisition{core(object), cores(attributes)}); });
}

void Ambassador::queryAttributeOwnership(ObjectInstanceHandle object, AttributeHandle attribute) {
    guarded([&] { client().request(wire::QueryOwnership{core(object), core(attribute)}); });
}

bool Ambassador::isAttributeOwnedByFederate(ObjectInstanceHandle object, AttributeHandle attribute) {
    return guarded([&] { return client().is_owned(core(object), core(attribute)); });
}

}  // namespace hlacore::rti1516e
