#include "rti/server/federation.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>

namespace hlacore {

using wire::WireError;

std::string time_text(double t) {
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, t);
    return std::string(buf, result.ptr);
}

Federation::Federation(std::string name, fom::Fom fom, std::string fed_name, std::string fed_text, Outbox& outbox)
    : name_(std::move(name)),
      fom_(std::move(fom)),
      fed_name_(std::move(fed_name)),
      fed_text_(std::move(fed_text)),
      outbox_(outbox) {}

const std::string& Federation::federate_name(FederateHandle federate) const {
    static const std::string none;
    auto it = federates_.find(federate);
    return it == federates_.end() ? none : it->second.name;
}

std::vector<FederateHandle> Federation::federates() const {
    std::vector<FederateHandle> handles;
    for (const auto& [handle, state] : federates_) handles.push_back(handle);
    return handles;
}

const ObjectInstance* Federation::object(ObjectHandle object) const {
    auto it = objects_.find(object);
    return it == objects_.end() ? nullptr : &it->second;
}

double Federation::federate_time(FederateHandle federate) const {
    return federates_.count(federate) ? time_.federate_time(federate) : std::numeric_limits<double>::quiet_NaN();
}

FederateHandle Federation::join(const std::string& federate_name, const std::string& federate_type) {
    for (const auto& [h, f] : federates_) {
        if (f.name == federate_name)
            throw RtiError(ErrorCode::FederateAlreadyExecutionMember,
                           "a federate named '" + federate_name + "' is already joined to '" + name_ + "'");
    }
    const FederateHandle h = next_federate_++;
    federates_[h].name = federate_name;
    federates_[h].type = federate_type;
    time_.add_federate(h);
    return h;
}

void Federation::announce_pending(FederateHandle h) { sync_points_.joined(h); }

void Federation::extend_fom(fom::ExtendedFom extended, FederateHandle joining) {
    fom_ = std::move(extended.fom);
    fed_text_ = std::move(extended.text);
    widen_regions();
    for (const auto& [h, f] : federates_)
        if (h != joining) outbox_.send(h, wire::FomExtended{fed_text_, fed_name_});
}

void Federation::resign(FederateHandle h, wire::ResignAction action) {
    using wire::ResignAction;
    if (action < ResignAction::ReleaseAttributes || action > ResignAction::NoAction)
        throw RtiError(ErrorCode::InvalidResignAction, "unknown resign action " + std::to_string(int(action)));
    const bool deletes = action == ResignAction::DeleteObjects || action == ResignAction::DeleteObjectsAndReleaseAttributes;
    const bool releases =
        action == ResignAction::ReleaseAttributes || action == ResignAction::DeleteObjectsAndReleaseAttributes;

    // HLA 1.3 §4.5: the federate may not leave attributes owned behind unless the action disposes of them.
    if (!releases) {
        for (const auto& [oh, obj] : objects_) {
            if (deletes && obj.ownership.deleter() == h) continue;
            for (const auto& [attr, owner] : obj.ownership.owners) {
                if (owner == h)
                    throw RtiError(ErrorCode::FederateOwnsAttributes,
                                   "federate owns attributes of object '" + obj.name + "'; resign with an action "
                                   "that deletes objects or releases attributes");
            }
        }
    }
    if (deletes) {
        std::vector<ObjectHandle> doomed;
        for (const auto& [oh, obj] : objects_)
            if (obj.ownership.deleter() == h) doomed.push_back(oh);
        for (ObjectHandle oh : doomed) remove_object(oh, h, "", std::nullopt, 0);
    }
    // Released attributes become unowned, or go to a federate waiting to acquire them (HLA 1.3 §7.7);
    // the departing federate's own acquisitions and divestitures end with it.
    for (auto& [oh, obj] : objects_) {
        if (obj.ownership.privilege_holder == h) obj.ownership.privilege_holder = 0;
        for (auto it = obj.ownership.acquirers.begin(); it != obj.ownership.acquirers.end();) {
            auto& waiting = it->second;
            waiting.erase(std::remove(waiting.begin(), waiting.end(), h), waiting.end());
            it = waiting.empty() ? obj.ownership.acquirers.erase(it) : std::next(it);
        }
        std::vector<fom::Handle> released;
        for (const auto& [attr, owner] : obj.ownership.owners)
            if (owner == h) released.push_back(attr);
        OwnershipNotices notices;
        for (fom::Handle attr : released) release_attribute(obj, attr, notices);
        send_notices(oh, notices);
    }
    federates_.erase(h);
    time_.remove_federate(h);
    routed_.erase(h);
    sync_points_.departed(h);
    reservations_.departed(h);
    save_restore_departed(h);
    update_advisories();
    count_scope_watchers();
    refresh_scope();
    release_time();  // those blocked on the departed federate may advance now
}

void Federation::on(FederateHandle from, const wire::RegisterSyncPoint& m) {
    federate(from);
    std::vector<FederateHandle> joined;
    for (const auto& [h, f] : federates_) joined.push_back(h);
    sync_points_.on(from, m, joined);
}

void Federation::on(FederateHandle from, const wire::SyncPointAchieved& m) {
    federate(from);
    sync_points_.on(from, m);
}

template <class M>
void Federation::handle(FederateHandle from, const M& message) {
    if (!std::is_same_v<M, wire::FederateRestoreComplete> && save_restore_.restoring(from)) return;
    on(from, message);
    if (scope_watchers_ != 0) refresh_scope();  // an attribute scope or relevance advisory switch is on
}
template void Federation::handle(FederateHandle, const std::monostate&);
#define HLACORE_X(name) template void Federation::handle(FederateHandle, const wire::name&);
HLACORE_MESSAGES(HLACORE_X)
#undef HLACORE_X
template void Federation::handle(FederateHandle, const wire::UpdateAttributesView&);
template void Federation::handle(FederateHandle, const wire::SendInteractionView&);

template <class M>
void Federation::on(FederateHandle, const M&) {
    if constexpr (std::is_same_v<M, std::monostate>) {
        throw WireError("empty message");
    } else {
        throw WireError(std::string(wire::message_name(M::kType)) + " is not a federation service message");
    }
}

// ---- lookups ----

Federation::FederateState& Federation::federate(FederateHandle h) {
    auto it = federates_.find(h);
    if (it == federates_.end()) throw RtiError(ErrorCode::FederateNotExecutionMember, "federate is not joined");
    return it->second;
}

const fom::ObjectClass& Federation::object_class(fom::Handle h) const {
    const auto* cls = fom_.object_class(h);
    if (!cls) throw WireError("object class handle " + std::to_string(h) + " is not defined in the FOM");
    return *cls;
}

const fom::InteractionClass& Federation::interaction_class(fom::Handle h) const {
    const auto* cls = fom_.interaction_class(h);
    if (!cls) throw WireError("interaction class handle " + std::to_string(h) + " is not defined in the FOM");
    return *cls;
}

void Federation::check_attributes(const fom::ObjectClass& cls, const wire::Handles& attributes) const {
    for (auto a : attributes) {
        if (!cls.attribute(a))
            throw WireError("attribute handle " + std::to_string(a) + " is not defined for class '" +
                            cls.qualified_name + "'");
    }
}

}  // namespace hlacore
