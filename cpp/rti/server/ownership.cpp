// Ownership management (HLA 1.3 §7).
#include "rti/server/federation.hpp"

#include <algorithm>

namespace hlacore {

using wire::WireError;

// ---- ownership management (HLA 1.3 §7) ----
// The client raises the exceptions (AttributeNotOwned, AttributeNotPublished, ...) from its own view; here
// each request acts only on the attributes whose state agrees, since a transfer may already be on its way
// to a federate that has not evoked the notification yet.



// privilegeToDelete counts as published with its class (the registrant holds it without naming it).
bool Federation::publishes(const FederateState& f, const ObjectInstance& obj, fom::Handle attribute) const {
    for (fom::Handle c = obj.object_class; c != 0; c = fom_.object_class(c)->parent) {
        auto pub = f.declarations.published.find(c);
        if (pub != f.declarations.published.end() && (pub->second.count(attribute) || attribute == obj.ownership.privilege_attribute))
            return true;
    }
    return false;
}

void Federation::transfer(ObjectInstance& obj, fom::Handle attr, FederateHandle to, OwnershipNotices& notices) {
    auto owner = obj.ownership.owners.find(attr);
    // §7.5: a negotiated divestiture completes with attributeOwnershipDivestitureNotification.
    if (owner != obj.ownership.owners.end() && owner->second != to && obj.ownership.divesting.count(attr))
        notices.divested[owner->second].push_back(attr);
    obj.ownership.divesting.erase(attr);
    if (owner == obj.ownership.owners.end() || owner->second != to) forget_delivery(obj, attr);
    obj.ownership.owners[attr] = to;
    auto waiting = obj.ownership.acquirers.find(attr);
    if (waiting != obj.ownership.acquirers.end()) {
        auto& list = waiting->second;
        list.erase(std::remove(list.begin(), list.end(), to), list.end());
        if (list.empty()) obj.ownership.acquirers.erase(waiting);
    }
    // §7.6: attributeOwnershipAcquisitionNotification.
    notices.acquired[to].push_back(attr);
}

void Federation::release_attribute(ObjectInstance& obj, fom::Handle attr, OwnershipNotices& notices) {
    obj.ownership.owners.erase(attr);
    forget_delivery(obj, attr);
    obj.ownership.divesting.erase(attr);
    auto waiting = obj.ownership.acquirers.find(attr);
    if (waiting != obj.ownership.acquirers.end() && !waiting->second.empty())
        transfer(obj, attr, waiting->second.front(), notices);
}

void Federation::send_notices(ObjectHandle oh, OwnershipNotices& notices) {
    auto send_each = [&](auto message, std::map<FederateHandle, wire::Handles>& by_federate) {
        for (auto& [to, attrs] : by_federate) {
            if (!federates_.count(to)) continue;
            message.object = oh;
            message.attributes = std::move(attrs);
            outbox_.send(to, message);
        }
        by_federate.clear();
    };
    send_each(wire::DivestitureNotification{}, notices.divested);
    send_each(wire::AcquisitionNotification{}, notices.acquired);
    send_each(wire::OwnershipUnavailable{}, notices.unavailable);
    send_each(wire::ConfirmAcquisitionCancellation{}, notices.cancelled);
    // The requests to other federates come after what the request itself settled.
    send_each(wire::RequestOwnershipAssumption{0, {}, notices.tag}, notices.assumption_requested);
    send_each(wire::RequestOwnershipRelease{0, {}, notices.tag}, notices.release_requested);
}

ObjectInstance* Federation::owned_object(ObjectHandle oh, const wire::Handles& attributes) {
    auto it = objects_.find(oh);
    if (it == objects_.end()) return nullptr;  // deleted meanwhile
    check_attributes(object_class(it->second.object_class), attributes);
    return &it->second;
}


// §7.7-7.8: the attributes `from` publishes that are unowned, or that their owner is divesting, go to it at
// once. Returns those another federate owns (and keeps for now), with their owner.
std::vector<std::pair<fom::Handle, FederateHandle>> Federation::acquire_available(
    FederateHandle from, const FederateState& f, ObjectInstance& obj, const wire::Handles& attributes,
    OwnershipNotices& notices) {
    std::vector<std::pair<fom::Handle, FederateHandle>> owned_by_others;
    for (auto attr : attributes) {
        if (!publishes(f, obj, attr)) continue;  // AttributeNotPublished at the client
        const FederateHandle owner = obj.ownership.owner(attr);
        if (owner == 0 || (owner != from && obj.ownership.divesting.count(attr))) {
            transfer(obj, attr, from, notices);
        } else if (owner != from) {
            owned_by_others.emplace_back(attr, owner);
        }
    }
    return owned_by_others;
}

template <class Act>
bool Federation::change_ownership(FederateHandle from, ObjectHandle oh, const wire::Handles& attributes, Act&& act) {
    federate(from);
    ObjectInstance* obj = owned_object(oh, attributes);
    if (!obj) return false;
    OwnershipNotices notices;
    act(*obj, notices);
    send_notices(oh, notices);
    return true;
}

// §7.2: the attributes become unowned at once (or go to a federate waiting to acquire them).
void Federation::on(FederateHandle from, const wire::UnconditionalDivestiture& m) {
    change_ownership(from, m.object, m.attributes, [&](ObjectInstance& obj, OwnershipNotices& notices) {
        for (auto attr : m.attributes)
            if (obj.ownership.owner(attr) == from) release_attribute(obj, attr, notices);
    });
}

// §7.3: the owner keeps the attributes until someone takes them. A federate already waiting to acquire
// one gets it at once; otherwise the publishers that know the object are asked (§7.4,
// requestAttributeOwnershipAssumption).
void Federation::on(FederateHandle from, const wire::NegotiatedDivestiture& m) {
    change_ownership(from, m.object, m.attributes, [&](ObjectInstance& obj, OwnershipNotices& notices) {
        notices.tag = m.tag;
        for (auto attr : m.attributes) {
            if (obj.ownership.owner(attr) != from) continue;
            obj.ownership.divesting[attr] = m.tag;
            auto waiting = obj.ownership.acquirers.find(attr);
            if (waiting != obj.ownership.acquirers.end() && !waiting->second.empty()) {
                transfer(obj, attr, waiting->second.front(), notices);
                continue;
            }
            for (const auto& [gh, g] : federates_) {
                if (gh != from && g.known.count(m.object) && publishes(g, obj, attr))
                    notices.assumption_requested[gh].push_back(attr);
            }
        }
    });
}

// §7.12.
void Federation::on(FederateHandle from, const wire::CancelNegotiatedDivestiture& m) {
    change_ownership(from, m.object, m.attributes, [&](ObjectInstance& obj, OwnershipNotices&) {
        for (auto attr : m.attributes)
            if (obj.ownership.owner(attr) == from) obj.ownership.divesting.erase(attr);
    });
}

// §7.7: an unowned attribute, or one its owner is divesting, is transferred at once; for the others the
// federate waits and their owners are asked to release them (§7.10, requestAttributeOwnershipRelease).
void Federation::on(FederateHandle from, const wire::OwnershipAcquisition& m) {
    const auto& f = federate(from);
    change_ownership(from, m.object, m.attributes, [&](ObjectInstance& obj, OwnershipNotices& notices) {
        if (!f.known.count(m.object)) return;
        notices.tag = m.tag;
        for (const auto& [attr, owner] : acquire_available(from, f, obj, m.attributes, notices)) {
            auto& waiting = obj.ownership.acquirers[attr];
            if (std::find(waiting.begin(), waiting.end(), from) == waiting.end()) waiting.push_back(from);
            notices.release_requested[owner].push_back(attr);
        }
    });
}

// §7.8: granted when unowned or being divested, else attributeOwnershipUnavailable (§7.9).
void Federation::on(FederateHandle from, const wire::OwnershipAcquisitionIfAvailable& m) {
    const auto& f = federate(from);
    change_ownership(from, m.object, m.attributes, [&](ObjectInstance& obj, OwnershipNotices& notices) {
        if (!f.known.count(m.object)) return;
        for (const auto& [attr, owner] : acquire_available(from, f, obj, m.attributes, notices))
            notices.unavailable[from].push_back(attr);
    });
}

// §7.13: what is still awaited is cancelled (§7.14, confirmAttributeOwnershipAcquisitionCancellation);
// an attribute transferred meanwhile stays acquired (its notification was sent first).
void Federation::on(FederateHandle from, const wire::CancelOwnershipAcquisition& m) {
    change_ownership(from, m.object, m.attributes, [&](ObjectInstance& obj, OwnershipNotices& notices) {
        for (auto attr : m.attributes) {
            auto waiting = obj.ownership.acquirers.find(attr);
            if (waiting == obj.ownership.acquirers.end()) continue;
            auto& list = waiting->second;
            auto it = std::find(list.begin(), list.end(), from);
            if (it == list.end()) continue;
            list.erase(it);
            if (list.empty()) obj.ownership.acquirers.erase(waiting);
            notices.cancelled[from].push_back(attr);
        }
    });
}

// §7.11: the attributes some federate waits for go to the first of them; the others stay owned.
wire::Handles Federation::release_response(FederateHandle from, const wire::ReleaseResponse& m) {
    wire::Handles released;
    const bool acted =
        change_ownership(from, m.object, m.attributes, [&](ObjectInstance& obj, OwnershipNotices& notices) {
        for (auto attr : m.attributes) {
            auto waiting = obj.ownership.acquirers.find(attr);
            if (obj.ownership.owner(attr) != from || waiting == obj.ownership.acquirers.end()) continue;
            obj.ownership.divesting.erase(attr);  // the release response itself tells the releasing federate
            transfer(obj, attr, waiting->second.front(), notices);
            released.push_back(attr);
        }
    });
    if (acted) refresh_scope();
    return released;
}

// §7.15-7.16: informAttributeOwnership or attributeIsNotOwned (no attribute is owned by the RTI here:
// hlacore has no management object model).
void Federation::on(FederateHandle from, const wire::QueryOwnership& m) {
    federate(from);
    ObjectInstance* obj = owned_object(m.object, wire::Handles{m.attribute});
    if (!obj) return;
    wire::OwnershipInformation info;
    info.object = m.object;
    info.attribute = m.attribute;
    info.owner = obj->ownership.owner(m.attribute);
    info.kind = static_cast<std::uint8_t>(info.owner ? wire::OwnershipKind::OwnedByFederate : wire::OwnershipKind::NotOwned);
    outbox_.send(from, info);
}

}  // namespace hlacore
