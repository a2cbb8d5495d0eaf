#include "rti/federation.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

namespace hlacore {

using wire::WireError;

namespace {

// Shortest text that reads back as the same double, for error messages.
std::string time_text(double t) {
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, t);
    return std::string(buf, result.ptr);
}

// The attribute that carries the privilege to delete (CERTI/Portico and OpenRTI spellings), or null.
const fom::Attribute* privilege_to_delete(const fom::ObjectClass& cls) {
    const auto* a = cls.attribute("privilegeToDelete");
    return a ? a : cls.attribute("HLAprivilegeToDeleteObject");
}


}  // namespace

Federation::Federation(std::string name, fom::Fom fom, std::string fed_name, std::string fed_text, Outbox& outbox)
    : name_(std::move(name)),
      fom_(std::move(fom)),
      fed_name_(std::move(fed_name)),
      fed_text_(std::move(fed_text)),
      outbox_(outbox) {}

FederateHandle Federation::join(const std::string& federate_name) {
    for (const auto& [h, f] : federates_) {
        if (f.name == federate_name)
            throw RtiError(ErrorCode::FederateAlreadyExecutionMember,
                           "a federate named '" + federate_name + "' is already joined to '" + name_ + "'");
    }
    const FederateHandle h = next_federate_++;
    federates_[h].name = federate_name;
    time_.add_federate(h);
    return h;
}

void Federation::announce_pending(FederateHandle h) {
    // A pending synchronization point for the whole federation includes late joiners (HLA 1.3 §4.6).
    for (auto& [label, point] : sync_points_) {
        if (!point.whole_federation) continue;
        point.members.insert(h);
        outbox_.send(h, wire::AnnounceSyncPoint{label, point.tag});
    }
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
            if (deletes && deleter(obj) == h) continue;
            for (const auto& [attr, owner] : obj.owners) {
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
            if (deleter(obj) == h) doomed.push_back(oh);
        for (ObjectHandle oh : doomed) remove_object(oh, h, "", std::nullopt, 0);
    }
    // Released attributes become unowned, or go to a federate waiting to acquire them (HLA 1.3 §7.7);
    // the departing federate's own acquisitions and divestitures end with it.
    for (auto& [oh, obj] : objects_) {
        if (obj.privilege_holder == h) obj.privilege_holder = 0;
        for (auto it = obj.acquirers.begin(); it != obj.acquirers.end();) {
            auto& waiting = it->second;
            waiting.erase(std::remove(waiting.begin(), waiting.end(), h), waiting.end());
            it = waiting.empty() ? obj.acquirers.erase(it) : std::next(it);
        }
        std::vector<fom::Handle> released;
        for (const auto& [attr, owner] : obj.owners)
            if (owner == h) released.push_back(attr);
        OwnershipNotices notices;
        for (fom::Handle attr : released) release_attribute(obj, attr, notices);
        send_notices(oh, notices);
    }
    federates_.erase(h);
    time_.remove_federate(h);
    routed_.erase(h);
    std::vector<std::string> labels;
    for (auto& [label, point] : sync_points_) {
        point.members.erase(h);
        point.achieved.erase(h);
        labels.push_back(label);
    }
    for (const auto& label : labels) check_sync_point(label);
    save_restore_departed(h);
    update_advisories();
    count_scope_watchers();
    refresh_scope();
    release_time();  // those blocked on the departed federate may advance now
}

std::pair<ObjectHandle, std::string> Federation::register_object(FederateHandle h, fom::Handle cls_handle,
                                                                 const std::string& requested_name) {
    const auto& cls = object_class(cls_handle);
    auto& f = federate(h);
    check_not_restoring(h);
    auto pub = f.published.find(cls_handle);
    if (pub == f.published.end())
        throw RtiError(ErrorCode::ObjectClassNotPublished, "object class '" + cls.qualified_name + "' is not published");
    std::string name = requested_name;
    const ObjectHandle oh = next_object_;
    if (name.empty()) {
        name = "HLAobject_" + std::to_string(oh);
        for (int suffix = 1; object_names_.count(name); ++suffix)
            name = "HLAobject_" + std::to_string(oh) + "_" + std::to_string(suffix);
    } else if (object_names_.count(name)) {
        throw RtiError(ErrorCode::ObjectAlreadyRegistered, "an object named '" + name + "' already exists");
    }
    ++next_object_;
    ObjectInstance& obj = objects_[oh];
    obj.object_class = cls_handle;
    obj.name = name;
    obj.privilege_holder = h;
    for (fom::Handle attr : pub->second) obj.owners[attr] = h;
    // The registrant holds the privilege to delete, as an attribute that transfers like the others.
    if (const auto* privilege = privilege_to_delete(cls)) {
        obj.privilege_attribute = privilege->handle;
        obj.owners[privilege->handle] = h;
    }
    object_names_[name] = oh;
    f.known.insert(oh);
    for (auto& [gh, g] : federates_) {
        if (gh != h && discovers(gh, g, oh, obj)) discover(gh, g, oh, obj);
    }
    refresh_scope();
    return {oh, name};
}

template <class M>
void Federation::handle(FederateHandle from, const M& message) {
    if (!std::is_same_v<M, wire::FederateRestoreComplete> && restoring(from)) return;
    on(from, message);
    refresh_scope();
}
template void Federation::handle(FederateHandle, const std::monostate&);
#define HLACORE_X(name) template void Federation::handle(FederateHandle, const wire::name&);
HLACORE_MESSAGES(HLACORE_X)
#undef HLACORE_X

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

fom::Handle Federation::known_class(const FederateState& f, fom::Handle cls) const {
    for (fom::Handle c = cls; c != 0; c = fom_.object_class(c)->parent) {
        if (f.subscribed.count(c) || f.ddm.object_subscriptions.count(c)) return c;
    }
    return 0;
}

fom::Handle Federation::receiving_interaction_class(const FederateState& f, fom::Handle cls) const {
    for (fom::Handle c = cls; c != 0; c = fom_.interaction_class(c)->parent) {
        if (f.subscribed_interactions.count(c) || f.ddm.interaction_subscriptions.count(c)) return c;
    }
    return 0;
}

void Federation::discover(FederateHandle to, FederateState& f, ObjectHandle oh, const ObjectInstance& obj) {
    f.known.insert(oh);
    outbox_.send(to, wire::DiscoverObject{oh, known_class(f, obj.object_class), obj.name});
}

void Federation::discover_all_for(FederateHandle h) {
    auto& f = federates_.at(h);
    for (const auto& [oh, obj] : objects_) {
        if (!f.known.count(oh) && discovers(h, f, oh, obj)) discover(h, f, oh, obj);
    }
}

void Federation::remove_object(ObjectHandle oh, FederateHandle by, const std::string& tag,
                               const wire::OptionalTime& time, std::uint64_t serial) {
    auto it = objects_.find(oh);
    if (it == objects_.end()) return;
    for (auto& [gh, g] : federates_) {
        if (!g.known.erase(oh) || gh == by) continue;
        if (time && time_.is_tso(by, gh)) {
            deliver_timestamp_order(gh, wire::RemoveObject{oh, tag, time, by, serial}, by, serial, *time);
        } else {
            deliver_receive_order(gh, wire::RemoveObject{oh, tag, std::nullopt, by, serial});
        }
    }
    object_names_.erase(it->second.name);
    objects_.erase(it);
    forget_update_regions(oh);
}

// HLA 1.3 §8.1.1: receivers were granted on the regulating sender's bound, so a timestamp below it could
// land in their past. Clients check this first (InvalidFederationTime); here it is a protocol violation.
void Federation::check_timestamp(FederateHandle from, const wire::OptionalTime& time, const char* what) const {
    if (!time || time_.may_send(from, *time)) return;
    throw WireError(std::string(what) + " at timestamp " + time_text(*time) +
                    " is below the sender's output bound " + time_text(time_.promise(from)) +
                    " (lowest timestamp it may still send)");
}

template <class M>
void Federation::deliver_receive_order(FederateHandle to, const M& message) {
    if (!time_.holds_receive_order(to)) {
        outbox_.send(to, message);
        return;
    }
    std::string frame;
    wire::encode(frame, message);
    time_.enqueue_receive_order(to, std::move(frame));
}

template <class M>
void Federation::deliver_timestamp_order(FederateHandle to, const M& message, FederateHandle sender,
                                         std::uint64_t serial, double time) {
    TsoMessage queued{time, sender, serial, {}};
    wire::encode(queued.frame, message);
    time_.enqueue_tso(to, std::move(queued));
    Routed& routed = routed_[sender][serial];
    routed.time = time;
    routed.receivers.push_back(to);
}

void Federation::release_time() {
    if (time_frozen()) return;  // every federate is saving or restoring
    if (save_.active && save_.time) cap_requests_at_save_time();
    // A message at or below the sender's time can no longer be retracted (HLA 1.3 §8.21).
    auto forget_retractable = [&](FederateHandle sender, double time) {
        auto routed = routed_.find(sender);
        if (routed == routed_.end()) return;
        for (auto it = routed->second.begin(); it != routed->second.end();)
            it = it->second.time <= time ? routed->second.erase(it) : std::next(it);
    };
    // In the order of TimeManager::Release: messages below a new time precede the callback announcing it.
    for (auto& r : time_.release()) {
        if (!federates_.count(r.federate)) continue;
        std::string& out = outbox_.buffer(r.federate);
        if (r.constrained_enabled) wire::encode(out, wire::TimeConstrainedEnabled{*r.constrained_enabled});
        for (const auto& frame : r.frames) out.append(frame);
        if (r.regulation_enabled) {
            wire::encode(out, wire::TimeRegulationEnabled{*r.regulation_enabled});
            forget_retractable(r.federate, *r.regulation_enabled);
        }
        if (r.grant) {
            wire::encode(out, wire::TimeAdvanceGrant{*r.grant});
            forget_retractable(r.federate, *r.grant);
        }
    }
    if (save_.active && save_.time) tell_savers();  // a timed save starts at the grants reaching its time
}

double Federation::query_time(FederateHandle f, wire::TimeQuery which) {
    federate(f);
    return which == wire::TimeQuery::Lbts ? time_.lbts(f) : time_.min_next_event_time(f);
}

// Start/stop registration and turn interactions on/off follow real subscriber changes (HLA 1.3 §5.10-5.13):
// a published class is relevant when another federate would discover (receive) its instances (interactions).
void Federation::update_advisories() {
    for (auto& [ph, p] : federates_) {
        std::set<fom::Handle> relevant;
        for (const auto& [cls, attrs] : p.published) {
            for (const auto& [gh, g] : federates_) {
                if (gh != ph && known_class(g, cls) != 0) {
                    relevant.insert(cls);
                    break;
                }
            }
        }
        if (p.class_relevance) {
            for (fom::Handle cls : relevant)
                if (!p.registration_started.count(cls)) outbox_.send(ph, wire::StartRegistration{cls});
            for (fom::Handle cls : p.registration_started)
                if (!relevant.count(cls) && p.published.count(cls)) outbox_.send(ph, wire::StopRegistration{cls});
            p.registration_started = std::move(relevant);
        }

        std::set<fom::Handle> wanted;
        for (fom::Handle ic : p.published_interactions) {
            for (const auto& [gh, g] : federates_) {
                if (gh != ph && receiving_interaction_class(g, ic) != 0) {
                    wanted.insert(ic);
                    break;
                }
            }
        }
        if (p.interaction_relevance) {
            for (fom::Handle ic : wanted)
                if (!p.interactions_turned_on.count(ic)) outbox_.send(ph, wire::TurnInteractionsOn{ic});
            for (fom::Handle ic : p.interactions_turned_on)
                if (!wanted.count(ic) && p.published_interactions.count(ic))
                    outbox_.send(ph, wire::TurnInteractionsOff{ic});
            p.interactions_turned_on = std::move(wanted);
        }
    }
}

// ---- synchronization points (HLA 1.3 §4.6-4.10) ----

void Federation::on(FederateHandle from, const wire::RegisterSyncPoint& m) {
    federate(from);
    if (sync_points_.count(m.label)) {
        outbox_.send(from, wire::SyncPointRegistrationFailed{m.label});
        return;
    }
    SyncPoint point;
    point.tag = m.tag;
    point.whole_federation = m.whole_federation;
    if (m.whole_federation) {
        for (const auto& [h, f] : federates_) point.members.insert(h);
    } else {
        for (auto h : m.federates) {
            if (!federates_.count(h)) {
                outbox_.send(from, wire::SyncPointRegistrationFailed{m.label});
                return;
            }
            point.members.insert(h);
        }
    }
    outbox_.send(from, wire::SyncPointRegistrationSucceeded{m.label});
    for (auto h : point.members) outbox_.send(h, wire::AnnounceSyncPoint{m.label, m.tag});
    sync_points_.emplace(m.label, std::move(point));
    check_sync_point(m.label);  // an explicit empty set is synchronized at once
}

void Federation::on(FederateHandle from, const wire::SyncPointAchieved& m) {
    federate(from);
    auto it = sync_points_.find(m.label);
    if (it == sync_points_.end() || !it->second.members.count(from)) return;
    it->second.achieved.insert(from);
    check_sync_point(m.label);
}

void Federation::check_sync_point(const std::string& label) {
    auto it = sync_points_.find(label);
    if (it == sync_points_.end() || it->second.achieved.size() < it->second.members.size()) return;
    const SyncPoint point = std::move(it->second);
    sync_points_.erase(it);
    for (auto h : point.members) outbox_.send(h, wire::FederationSynchronized{label});
}

// ---- declaration management (HLA 1.3 §5) ----

void Federation::on(FederateHandle from, const wire::PublishObjectClass& m) {
    auto& f = federate(from);
    check_attributes(object_class(m.object_class), m.attributes);
    if (m.attributes.empty()) {
        f.published.erase(m.object_class);
    } else {
        f.published[m.object_class] = std::set<fom::Handle>(m.attributes.begin(), m.attributes.end());
    }
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::UnpublishObjectClass& m) {
    object_class(m.object_class);
    federate(from).published.erase(m.object_class);
    federate(from).registration_started.erase(m.object_class);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::SubscribeObjectClass& m) {
    auto& f = federate(from);
    check_attributes(object_class(m.object_class), m.attributes);
    if (m.attributes.empty()) {
        f.subscribed.erase(m.object_class);
    } else {
        f.subscribed[m.object_class] = std::set<fom::Handle>(m.attributes.begin(), m.attributes.end());
        discover_all_for(from);
    }
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::UnsubscribeObjectClass& m) {
    object_class(m.object_class);
    federate(from).subscribed.erase(m.object_class);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::PublishInteractionClass& m) {
    interaction_class(m.interaction_class);
    federate(from).published_interactions.insert(m.interaction_class);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::UnpublishInteractionClass& m) {
    interaction_class(m.interaction_class);
    auto& f = federate(from);
    f.published_interactions.erase(m.interaction_class);
    f.interactions_turned_on.erase(m.interaction_class);
    f.interaction_order.erase(m.interaction_class);
    f.interaction_transport.erase(m.interaction_class);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::SubscribeInteractionClass& m) {
    interaction_class(m.interaction_class);
    federate(from).subscribed_interactions.insert(m.interaction_class);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::UnsubscribeInteractionClass& m) {
    interaction_class(m.interaction_class);
    federate(from).subscribed_interactions.erase(m.interaction_class);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::SetAdvisorySwitch& m) {
    auto& f = federate(from);
    switch (static_cast<wire::AdvisorySwitch>(m.which)) {
        case wire::AdvisorySwitch::ClassRelevance:
            f.class_relevance = m.on;
            if (!m.on) f.registration_started.clear();
            break;
        case wire::AdvisorySwitch::InteractionRelevance:
            f.interaction_relevance = m.on;
            if (!m.on) f.interactions_turned_on.clear();
            break;
        case wire::AdvisorySwitch::AttributeRelevance: f.attribute_relevance = m.on; break;
        case wire::AdvisorySwitch::AttributeScope: f.attribute_scope = m.on; break;
        default: throw WireError("unknown advisory switch " + std::to_string(m.which));
    }
    count_scope_watchers();
    update_advisories();
}

// ---- object management (HLA 1.3 §6) ----

void Federation::on(FederateHandle from, const wire::UpdateAttributes& m) {
    federate(from);
    check_timestamp(from, m.time, "attribute update");
    auto it = objects_.find(m.object);
    if (it == objects_.end()) return;  // deleted meanwhile
    const ObjectInstance& obj = it->second;
    const auto& cls = object_class(obj.object_class);
    for (const auto& [attr, value] : m.values) {
        if (!cls.attribute(attr))
            throw WireError("attribute handle " + std::to_string(attr) + " is not defined for class '" +
                            cls.qualified_name + "'");
    }
    // Each attribute's order and transport: its owner's change (HLA 1.3 §6.19, §6.21), else the FOM's.
    // Only the sender's own attributes are reflected, so only its changes matter.
    auto order_of = [&](fom::Handle attr) {
        auto it = obj.order.find(attr);
        return it != obj.order.end() ? it->second : cls.attribute(attr)->order;
    };
    auto transport_of = [&](fom::Handle attr) {
        auto it = obj.transport.find(attr);
        return it != obj.transport.end() ? it->second : cls.attribute(attr)->transport;
    };
    // out[tso][transport - 1]: one reflection per order and transport actually used.
    wire::ReflectAttributes out[2][2];
    for (int tso = 0; tso < 2; ++tso) {
        for (int tr = 0; tr < 2; ++tr) {
            auto& r = out[tso][tr];
            r.object = m.object;
            r.tag = m.tag;
            r.sender = from;
            r.serial = m.serial;
            r.order = static_cast<std::uint8_t>(tso ? fom::Order::Timestamp : fom::Order::Receive);
            r.transport = static_cast<std::uint8_t>(tr + 1);
            if (tso) r.time = m.time;
        }
    }
    for (auto& [gh, g] : federates_) {
        if (gh == from) continue;
        const fom::Handle known = known_class(g, obj.object_class);
        if (known == 0) continue;
        // A plain subscription (the default region) wants every subscribed attribute; a subscription
        // region only those whose update region overlaps it (HLA 1.3 §9).
        const auto plain = g.subscribed.find(known);
        // HLA 1.3 §8.1.1: timestamp order needs a time, a regulating sender, a constrained receiver and
        // `timestamp` as the attribute's order; each attribute goes its own way, so one update may split.
        const bool tso = m.time && time_.is_tso(from, gh);
        for (auto& row : out)
            for (auto& r : row) r.values.clear();
        for (const auto& pair : m.values) {
            // Values of attributes the sender does not own are not reflected (clients check this first).
            auto owner = obj.owners.find(pair.first);
            if (owner == obj.owners.end() || owner->second != from) continue;
            if (!(plain != g.subscribed.end() && plain->second.count(pair.first)) &&
                !region_wanted(g, known, from, m.object, pair.first))
                continue;
            const bool timed = tso && order_of(pair.first) == fom::Order::Timestamp;
            const int tr = transport_of(pair.first) == fom::Transport::BestEffort ? 1 : 0;
            out[timed][tr].values.push_back(pair);
        }
        if (!g.known.count(m.object)) {
            // Discovered when an attribute comes into scope; a plain subscriber as before DDM.
            bool in_scope = plain != g.subscribed.end();
            for (const auto& row : out)
                for (const auto& r : row) in_scope = in_scope || !r.values.empty();
            if (!in_scope) continue;
            discover(gh, g, m.object, obj);
        }
        for (auto& r : out[1])
            if (!r.values.empty()) deliver_timestamp_order(gh, r, from, m.serial, *m.time);
        for (auto& r : out[0])
            if (!r.values.empty()) deliver_receive_order(gh, r);
    }
    release_time();
}

void Federation::on(FederateHandle from, const wire::SendInteraction& m) {
    federate(from);
    route_interaction(from, m, nullptr);
}

// `region`: the region the interaction was sent with (sendInteractionWithRegion), null for the default
// region, which reaches every subscriber of the class.
void Federation::route_interaction(FederateHandle from, const wire::SendInteraction& m, const Region* region) {
    check_timestamp(from, m.time, "interaction");
    const auto& sent_class = interaction_class(m.interaction_class);
    for (const auto& [param, value] : m.values) {
        if (!sent_class.parameter(param))
            throw WireError("parameter handle " + std::to_string(param) + " is not defined for interaction '" +
                            sent_class.qualified_name + "'");
    }
    wire::ReceiveInteraction receive;
    receive.tag = m.tag;
    receive.sender = from;
    receive.serial = m.serial;
    // The sender's change of the class's transport or order (HLA 1.3 §6.20, §6.22), else the FOM's.
    const auto& sender = federates_.at(from);
    auto changed_transport = sender.interaction_transport.find(m.interaction_class);
    auto changed_order = sender.interaction_order.find(m.interaction_class);
    const fom::Transport transport =
        changed_transport != sender.interaction_transport.end() ? changed_transport->second : sent_class.transport;
    const fom::Order order = changed_order != sender.interaction_order.end() ? changed_order->second : sent_class.order;
    receive.transport = static_cast<std::uint8_t>(transport);
    const bool timestamped = m.time && order == fom::Order::Timestamp;
    for (auto& [gh, g] : federates_) {
        if (gh == from) continue;
        const fom::Handle as = interaction_receiver(g, m.interaction_class, region);
        if (as == 0) continue;
        // Received as the subscribed superclass: only the parameters that class defines.
        const auto* received_class = fom_.interaction_class(as);
        receive.interaction_class = as;
        receive.values.clear();
        for (const auto& pair : m.values)
            if (received_class->parameter(pair.first)) receive.values.push_back(pair);
        if (timestamped && time_.is_tso(from, gh)) {
            receive.order = static_cast<std::uint8_t>(fom::Order::Timestamp);
            receive.time = m.time;
            deliver_timestamp_order(gh, receive, from, m.serial, *m.time);
        } else {
            receive.order = static_cast<std::uint8_t>(fom::Order::Receive);
            receive.time.reset();
            deliver_receive_order(gh, receive);
        }
    }
    release_time();
}

void Federation::on(FederateHandle from, const wire::DeleteObject& m) {
    federate(from);
    check_timestamp(from, m.time, "object deletion");
    auto it = objects_.find(m.object);
    if (it == objects_.end() || deleter(it->second) != from) return;  // checked by the client
    remove_object(m.object, from, m.tag, m.time, m.serial);
    release_time();
}

// ---- time management (HLA 1.3 §8); the rules are in time_manager.hpp and docs/time-management.md ----

void Federation::on(FederateHandle from, const wire::EnableTimeRegulation& m) {
    federate(from);
    if (!(m.lookahead >= 0) || !std::isfinite(m.time)) throw WireError("invalid time or lookahead");
    // HLA 1.3 §8.2: the client refuses these (TimeRegulationAlreadyEnabled, EnableTimeRegulationPending,
    // TimeAdvanceAlreadyInProgress); re-enabling could also lower a bound others were granted on.
    if (time_.enabling_regulation(from)) throw WireError("enable time regulation while an enable is pending");
    if (time_.regulating(from)) throw WireError("enable time regulation while regulation is enabled");
    if (time_.advancing(from)) throw WireError("enable time regulation while a time advance is pending");
    time_.enable_regulation(from, m.time, m.lookahead);
    release_time();  // timeRegulationEnabled comes from there, at once unless constrained messages must go first
}

void Federation::on(FederateHandle from, const wire::DisableTimeRegulation&) {
    federate(from);
    time_.disable_regulation(from);
    release_time();
}

void Federation::on(FederateHandle from, const wire::EnableTimeConstrained&) {
    federate(from);
    time_.enable_constrained(from);
    release_time();
}

void Federation::on(FederateHandle from, const wire::DisableTimeConstrained&) {
    federate(from);
    for (const auto& frame : time_.disable_constrained(from)) outbox_.send_frame(from, frame);
    release_time();
}

void Federation::on(FederateHandle from, const wire::TimeAdvance& m) {
    federate(from);
    if (m.kind < 1 || m.kind > 5 || std::isnan(m.time)) throw WireError("invalid time advance request");
    if (m.time < time_.federate_time(from)) throw WireError("time advance request into the past");
    // HLA 1.3 §8.2: refused by the client too (EnableTimeRegulationPending).
    if (time_.enabling_regulation(from))
        throw WireError("time advance request while a regulation enable is pending");
    time_.request(from, static_cast<AdvanceKind>(m.kind), m.time);
    release_time();
}

void Federation::on(FederateHandle from, const wire::ModifyLookahead& m) {
    federate(from);
    if (!(m.lookahead >= 0)) throw WireError("invalid lookahead");
    time_.modify_lookahead(from, m.lookahead);
    release_time();
}

void Federation::on(FederateHandle from, const wire::SetAsynchronousDelivery& m) {
    federate(from);
    time_.set_asynchronous_delivery(from, m.on);
    release_time();
}

void Federation::on(FederateHandle from, const wire::Retract& m) {
    federate(from);
    auto sender = routed_.find(from);
    if (sender == routed_.end()) return;
    auto it = sender->second.find(m.serial);
    if (it == sender->second.end()) return;  // never routed TSO, or already in the past
    const auto removed = time_.retract(from, m.serial);
    for (FederateHandle to : it->second.receivers) {
        // Those who already got it are asked to retract it themselves (HLA 1.3 §8.22).
        if (federates_.count(to) && std::find(removed.begin(), removed.end(), to) == removed.end())
            outbox_.send(to, wire::RequestRetraction{from, m.serial});
    }
    sender->second.erase(it);
}

void Federation::on(FederateHandle from, const wire::LocalDeleteObject& m) {
    federate(from).known.erase(m.object);
    // A federate that forgot the object no longer waits to acquire its attributes (HLA 1.3 §7.7), and
    // releases any it was given while its client still thought it owned none.
    auto it = objects_.find(m.object);
    if (it == objects_.end()) return;
    ObjectInstance& obj = it->second;
    for (auto w = obj.acquirers.begin(); w != obj.acquirers.end();) {
        w->second.erase(std::remove(w->second.begin(), w->second.end(), from), w->second.end());
        w = w->second.empty() ? obj.acquirers.erase(w) : std::next(w);
    }
    std::vector<fom::Handle> owned;
    for (const auto& [attr, owner] : obj.owners)
        if (owner == from) owned.push_back(attr);
    OwnershipNotices notices;
    for (fom::Handle attr : owned) release_attribute(obj, attr, notices);
    send_notices(m.object, notices);
}

void Federation::on(FederateHandle from, const wire::RequestObjectUpdate& m) {
    federate(from);
    auto it = objects_.find(m.object);
    if (it == objects_.end()) return;
    check_attributes(object_class(it->second.object_class), m.attributes);
    std::map<FederateHandle, wire::Handles> by_owner;
    for (auto attr : m.attributes) {
        auto owner = it->second.owners.find(attr);
        if (owner != it->second.owners.end() && owner->second != from) by_owner[owner->second].push_back(attr);
    }
    for (auto& [owner, attrs] : by_owner) outbox_.send(owner, wire::ProvideAttributeValueUpdate{m.object, attrs});
}

void Federation::on(FederateHandle from, const wire::RequestClassUpdate& m) {
    federate(from);
    check_attributes(object_class(m.object_class), m.attributes);
    for (const auto& [oh, obj] : objects_) {
        if (!fom_.is_object_subclass(obj.object_class, m.object_class)) continue;
        std::map<FederateHandle, wire::Handles> by_owner;
        for (auto attr : m.attributes) {
            auto owner = obj.owners.find(attr);
            if (owner != obj.owners.end() && owner->second != from) by_owner[owner->second].push_back(attr);
        }
        for (auto& [owner, attrs] : by_owner) outbox_.send(owner, wire::ProvideAttributeValueUpdate{oh, attrs});
    }
}

// ---- ownership management (HLA 1.3 §7) ----
// The client raises the exceptions (AttributeNotOwned, AttributeNotPublished, ...) from its own view; here
// each request acts only on the attributes whose state agrees, since a transfer may already be on its way
// to a federate that has not evoked the notification yet.


FederateHandle Federation::deleter(const ObjectInstance& obj) const {
    if (obj.privilege_attribute == 0) return obj.privilege_holder;
    auto owner = obj.owners.find(obj.privilege_attribute);
    return owner == obj.owners.end() ? 0 : owner->second;
}

// privilegeToDelete counts as published with its class (the registrant holds it without naming it).
bool Federation::publishes(const FederateState& f, const ObjectInstance& obj, fom::Handle attribute) const {
    for (fom::Handle c = obj.object_class; c != 0; c = fom_.object_class(c)->parent) {
        auto pub = f.published.find(c);
        if (pub != f.published.end() && (pub->second.count(attribute) || attribute == obj.privilege_attribute))
            return true;
    }
    return false;
}

void Federation::transfer(ObjectInstance& obj, fom::Handle attr, FederateHandle to, OwnershipNotices& notices) {
    auto owner = obj.owners.find(attr);
    // §7.5: a negotiated divestiture completes with attributeOwnershipDivestitureNotification.
    if (owner != obj.owners.end() && owner->second != to && obj.divesting.count(attr))
        notices.divested[owner->second].push_back(attr);
    obj.divesting.erase(attr);
    if (owner == obj.owners.end() || owner->second != to) forget_delivery(obj, attr);
    obj.owners[attr] = to;
    auto waiting = obj.acquirers.find(attr);
    if (waiting != obj.acquirers.end()) {
        auto& list = waiting->second;
        list.erase(std::remove(list.begin(), list.end(), to), list.end());
        if (list.empty()) obj.acquirers.erase(waiting);
    }
    // §7.6: attributeOwnershipAcquisitionNotification.
    notices.acquired[to].push_back(attr);
}

void Federation::release_attribute(ObjectInstance& obj, fom::Handle attr, OwnershipNotices& notices) {
    obj.owners.erase(attr);
    forget_delivery(obj, attr);
    obj.divesting.erase(attr);
    auto waiting = obj.acquirers.find(attr);
    if (waiting != obj.acquirers.end() && !waiting->second.empty())
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
}

Federation::ObjectInstance* Federation::owned_object(ObjectHandle oh, const wire::Handles& attributes) {
    auto it = objects_.find(oh);
    if (it == objects_.end()) return nullptr;  // deleted meanwhile
    check_attributes(object_class(it->second.object_class), attributes);
    return &it->second;
}

// §7.2: the attributes become unowned at once (or go to a federate waiting to acquire them).
void Federation::on(FederateHandle from, const wire::UnconditionalDivestiture& m) {
    federate(from);
    ObjectInstance* obj = owned_object(m.object, m.attributes);
    if (!obj) return;
    OwnershipNotices notices;
    for (auto attr : m.attributes) {
        auto owner = obj->owners.find(attr);
        if (owner != obj->owners.end() && owner->second == from) release_attribute(*obj, attr, notices);
    }
    send_notices(m.object, notices);
}

// §7.3: the owner keeps the attributes until someone takes them. A federate already waiting to acquire
// one gets it at once; otherwise the publishers that know the object are asked (§7.4,
// requestAttributeOwnershipAssumption).
void Federation::on(FederateHandle from, const wire::NegotiatedDivestiture& m) {
    federate(from);
    ObjectInstance* obj = owned_object(m.object, m.attributes);
    if (!obj) return;
    OwnershipNotices notices;
    std::map<FederateHandle, wire::Handles> ask;
    for (auto attr : m.attributes) {
        auto owner = obj->owners.find(attr);
        if (owner == obj->owners.end() || owner->second != from) continue;
        obj->divesting[attr] = m.tag;
        auto waiting = obj->acquirers.find(attr);
        if (waiting != obj->acquirers.end() && !waiting->second.empty()) {
            transfer(*obj, attr, waiting->second.front(), notices);
            continue;
        }
        for (const auto& [gh, g] : federates_) {
            if (gh != from && g.known.count(m.object) && publishes(g, *obj, attr)) ask[gh].push_back(attr);
        }
    }
    send_notices(m.object, notices);
    for (auto& [to, attrs] : ask) outbox_.send(to, wire::RequestOwnershipAssumption{m.object, std::move(attrs), m.tag});
}

// §7.12.
void Federation::on(FederateHandle from, const wire::CancelNegotiatedDivestiture& m) {
    federate(from);
    ObjectInstance* obj = owned_object(m.object, m.attributes);
    if (!obj) return;
    for (auto attr : m.attributes) {
        auto owner = obj->owners.find(attr);
        if (owner != obj->owners.end() && owner->second == from) obj->divesting.erase(attr);
    }
}

// §7.7: an unowned attribute, or one its owner is divesting, is transferred at once; for the others the
// federate waits and their owners are asked to release them (§7.10, requestAttributeOwnershipRelease).
void Federation::on(FederateHandle from, const wire::OwnershipAcquisition& m) {
    const auto& f = federate(from);
    ObjectInstance* obj = owned_object(m.object, m.attributes);
    if (!obj || !f.known.count(m.object)) return;
    OwnershipNotices notices;
    std::map<FederateHandle, wire::Handles> ask;
    for (auto attr : m.attributes) {
        if (!publishes(f, *obj, attr)) continue;  // AttributeNotPublished at the client
        auto owner = obj->owners.find(attr);
        if (owner == obj->owners.end() || (owner->second != from && obj->divesting.count(attr))) {
            transfer(*obj, attr, from, notices);
        } else if (owner->second != from) {
            auto& waiting = obj->acquirers[attr];
            if (std::find(waiting.begin(), waiting.end(), from) == waiting.end()) waiting.push_back(from);
            ask[owner->second].push_back(attr);
        }
    }
    send_notices(m.object, notices);
    for (auto& [to, attrs] : ask) outbox_.send(to, wire::RequestOwnershipRelease{m.object, std::move(attrs), m.tag});
}

// §7.8: granted when unowned or being divested, else attributeOwnershipUnavailable (§7.9).
void Federation::on(FederateHandle from, const wire::OwnershipAcquisitionIfAvailable& m) {
    const auto& f = federate(from);
    ObjectInstance* obj = owned_object(m.object, m.attributes);
    if (!obj || !f.known.count(m.object)) return;
    OwnershipNotices notices;
    for (auto attr : m.attributes) {
        if (!publishes(f, *obj, attr)) continue;
        auto owner = obj->owners.find(attr);
        if (owner == obj->owners.end() || (owner->second != from && obj->divesting.count(attr))) {
            transfer(*obj, attr, from, notices);
        } else if (owner->second != from) {
            notices.unavailable[from].push_back(attr);
        }
    }
    send_notices(m.object, notices);
}

// §7.13: what is still awaited is cancelled (§7.14, confirmAttributeOwnershipAcquisitionCancellation);
// an attribute transferred meanwhile stays acquired (its notification was sent first).
void Federation::on(FederateHandle from, const wire::CancelOwnershipAcquisition& m) {
    federate(from);
    ObjectInstance* obj = owned_object(m.object, m.attributes);
    if (!obj) return;
    OwnershipNotices notices;
    for (auto attr : m.attributes) {
        auto waiting = obj->acquirers.find(attr);
        if (waiting == obj->acquirers.end()) continue;
        auto& list = waiting->second;
        auto it = std::find(list.begin(), list.end(), from);
        if (it == list.end()) continue;
        list.erase(it);
        if (list.empty()) obj->acquirers.erase(waiting);
        notices.cancelled[from].push_back(attr);
    }
    send_notices(m.object, notices);
}

// §7.11: the attributes some federate waits for go to the first of them; the others stay owned.
wire::Handles Federation::release_response(FederateHandle from, const wire::ReleaseResponse& m) {
    federate(from);
    wire::Handles released;
    ObjectInstance* obj = owned_object(m.object, m.attributes);
    if (!obj) return released;
    OwnershipNotices notices;
    for (auto attr : m.attributes) {
        auto owner = obj->owners.find(attr);
        auto waiting = obj->acquirers.find(attr);
        if (owner == obj->owners.end() || owner->second != from || waiting == obj->acquirers.end()) continue;
        obj->divesting.erase(attr);  // the release response itself tells the releasing federate
        transfer(*obj, attr, waiting->second.front(), notices);
        released.push_back(attr);
    }
    send_notices(m.object, notices);
    refresh_scope();
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
    auto owner = obj->owners.find(m.attribute);
    if (owner == obj->owners.end()) {
        info.kind = static_cast<std::uint8_t>(wire::OwnershipKind::NotOwned);
    } else {
        info.kind = static_cast<std::uint8_t>(wire::OwnershipKind::OwnedByFederate);
        info.owner = owner->second;
    }
    outbox_.send(from, info);
}

// ---- transport and order changes (HLA 1.3 §6.19-6.22) ----
// The client raises the exceptions; here a change applies to the attributes the sender still owns (an
// ownership transfer may be on its way) and to classes it still publishes.

namespace {

template <class E>
std::optional<E> delivery_value(std::uint8_t v, const char* what) {
    if (v == 0) return std::nullopt;
    if (v > 2) throw WireError(std::string("invalid ") + what + " " + std::to_string(v));
    return static_cast<E>(v);
}

}  // namespace

void Federation::forget_delivery(ObjectInstance& obj, fom::Handle attr) {
    obj.order.erase(attr);
    obj.transport.erase(attr);
}

void Federation::on(FederateHandle from, const wire::ChangeAttributeDelivery& m) {
    federate(from);
    const auto order = delivery_value<fom::Order>(m.order, "ordering handle");
    const auto transport = delivery_value<fom::Transport>(m.transport, "transportation handle");
    ObjectInstance* obj = owned_object(m.object, m.attributes);
    if (!obj) return;
    for (auto attr : m.attributes) {
        auto owner = obj->owners.find(attr);
        if (owner == obj->owners.end() || owner->second != from) continue;
        if (order) obj->order[attr] = *order;
        if (transport) obj->transport[attr] = *transport;
    }
}

void Federation::on(FederateHandle from, const wire::ChangeInteractionDelivery& m) {
    auto& f = federate(from);
    interaction_class(m.interaction_class);
    const auto order = delivery_value<fom::Order>(m.order, "ordering handle");
    const auto transport = delivery_value<fom::Transport>(m.transport, "transportation handle");
    if (!f.published_interactions.count(m.interaction_class)) return;
    if (order) f.interaction_order[m.interaction_class] = *order;
    if (transport) f.interaction_transport[m.interaction_class] = *transport;
}

}  // namespace hlacore
