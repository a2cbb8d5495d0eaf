// Object management (HLA 1.3 §6): registration, discovery, updates, interactions, deletion, and the
// transport and order changes (§6.19-6.22).
#include "rti/server/federation.hpp"

#include <algorithm>
#include <optional>

namespace hlacore {

using wire::WireError;

namespace {
// A frame kept for long (held for a federate): encoded into a string of its exact size (as a copy of it is),
// so that it holds what flow control counts and the heap is not left with the holes of a growing string.
template <class M>
std::string held_frame(const M& message) {
    std::string frame;
    const std::size_t length = wire::frame_length(message);
    frame.reserve(4 + length);
    wire::encode(frame, message, length);
    return frame;
}
template <class M>
wire::SharedFrame shared_frame(const M& message) {
    return std::make_shared<std::string>(held_frame(message));
}
}  // namespace

std::pair<ObjectHandle, std::string> Federation::register_object(FederateHandle h, fom::Handle cls_handle,
                                                                 const std::string& requested_name) {
    const auto& cls = object_class(cls_handle);
    auto& f = federate(h);
    save_restore_.check_not_restoring();
    auto pub = f.declarations.published.find(cls_handle);
    if (pub == f.declarations.published.end())
        throw RtiError(ErrorCode::ObjectClassNotPublished, "object class '" + cls.qualified_name + "' is not published");
    std::string name = requested_name;
    const ObjectHandle oh = next_object_;
    if (name.empty()) {
        name = "HLAobject_" + std::to_string(oh);
        for (int suffix = 1; object_names_.count(name); ++suffix)
            name = "HLAobject_" + std::to_string(oh) + "_" + std::to_string(suffix);
    } else if (object_names_.count(name)) {
        throw RtiError(ErrorCode::ObjectAlreadyRegistered, "an object named '" + name + "' already exists");
    } else {
        reservations_.registering(h, name);
    }
    ++next_object_;
    ObjectInstance& obj = objects_[oh];
    obj.object_class = cls_handle;
    obj.name = name;
    obj.ownership.privilege_holder = h;
    for (fom::Handle attr : pub->second) obj.ownership.owners[attr] = h;
    // The registrant holds the privilege to delete, as an attribute that transfers like the others.
    if (const auto* privilege = cls.privilege_to_delete()) {
        obj.ownership.privilege_attribute = privilege->handle;
        obj.ownership.owners[privilege->handle] = h;
    }
    object_names_[name] = oh;
    f.known.insert(oh);
    for (auto& [gh, g] : federates_) {
        if (gh != h && discovers(gh, g, oh, obj)) discover(gh, g, oh, obj);
    }
    refresh_scope();
    return {oh, name};
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
    Routed* routed = nullptr;
    for (auto& [gh, g] : federates_) {
        if (!g.known.erase(oh)) continue;
        if (g.rates) g.rates->forget(oh);
        if (gh == by) continue;
        if (time && time_.is_tso(by, gh)) {
            const wire::RemoveObject removal{oh, tag, time, by, serial};
            deliver_timestamp_order(gh, removal, by, serial, *time, routed, shared_frame(removal));
        } else {
            deliver_receive_order(gh, wire::RemoveObject{oh, tag, std::nullopt, by, serial});
        }
    }
    object_names_.erase(it->second.name);
    objects_.erase(it);
    forget_update_regions(oh);
}

// ---- delivery: receive order, or timestamp order queued in TimeManager (time.cpp releases it) ----

template <class M>
void Federation::deliver_receive_order(FederateHandle to, const M& message) {
    if (!time_.holds_receive_order(to)) {
        if constexpr (M::kType == wire::MessageType::ReflectAttributes || M::kType == wire::MessageType::ReceiveInteraction) {
            if (message.transport == static_cast<std::uint8_t>(fom::Transport::BestEffort) &&
                outbox_.send_best_effort(to, message))
                return;
        }
        outbox_.send(to, message);
        return;
    }
    outbox_.record(to, message);
    time_.enqueue_receive_order(to, held_frame(message));
    outbox_.held(to);
}

template <class M>
void Federation::deliver_timestamp_order(FederateHandle to, const M& message, FederateHandle sender,
                                         std::uint64_t serial, double time, Routed*& routed, wire::SharedFrame frame) {
    outbox_.record(to, message);
    time_.enqueue_tso(to, time, sender, serial, std::move(frame));
    outbox_.held(to);
    if (!routed) {
        routed = &routed_[sender][serial];
        routed->time = time;
    }
    routed->receivers.push_back(to);
}

// ---- object management (HLA 1.3 §6) ----

// The class a federate knows an instance of `cls` as (HLA 1.3 §6.3: discovered as the nearest subscribed
// class), and the class it receives an interaction of `cls` as (§6.6); 0 when it subscribes to neither.
fom::Handle Federation::known_class(const FederateState& f, fom::Handle cls) const {
    for (fom::Handle c = cls; c != 0; c = fom_.object_class(c)->parent) {
        if (f.declarations.subscribed.count(c) || f.ddm.object_subscriptions.count(c)) return c;
    }
    return 0;
}

fom::Handle Federation::receiving_interaction_class(const FederateState& f, fom::Handle cls) const {
    for (fom::Handle c = cls; c != 0; c = fom_.interaction_class(c)->parent) {
        if (f.declarations.subscribed_interactions.count(c) || f.ddm.interaction_subscriptions.count(c)) return c;
    }
    return 0;
}


void Federation::on(FederateHandle from, const wire::UpdateAttributes& m) {
    on(from, wire::UpdateAttributesView{m.object, wire::views_of(m.values), m.tag, m.time, m.serial});
}

void Federation::on(FederateHandle from, const wire::UpdateAttributesView& m) {
    ++federate(from).updates_sent;
    if (m.time) check_timestamp(from, *m.time, "attribute update");
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
    wire::ForwardedReflection out[2][2];
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
    Routed* routed = nullptr;
    // The timestamped reflection last encoded for each transport, and the values it holds: the receivers that
    // get the same attributes share those bytes (encoding each receiver's was 9 % of the rtig's CPU in a
    // 32-federate lockstep).
    wire::SharedFrame tso_frames[2];
    wire::HandleValueRefs tso_framed[2];
    for (auto& [gh, g] : federates_) {
        if (gh == from) continue;
        const fom::Handle known = known_class(g, obj.object_class);
        if (known == 0) continue;
        // A plain subscription (the default region) wants every subscribed attribute; a subscription
        // region only those whose update region overlaps it (HLA 1.3 §9).
        const auto plain = g.declarations.subscribed.find(known);
        // HLA 1.3 §8.1.1: timestamp order needs a time, a regulating sender, a constrained receiver and
        // `timestamp` as the attribute's order; each attribute goes its own way, so one update may split.
        const bool tso = m.time && time_.is_tso(from, gh);
        for (auto& row : out)
            for (auto& r : row) r.values.clear();
        for (const auto& pair : m.values) {
            // Values of attributes the sender does not own are not reflected (clients check this first).
            auto owner = obj.ownership.owners.find(pair.first);
            if (owner == obj.ownership.owners.end() || owner->second != from) continue;
            if (!(plain != g.declarations.subscribed.end() && plain->second.count(pair.first)) &&
                !region_wanted(g, known, from, m.object, pair.first))
                continue;
            const bool timed = tso && order_of(pair.first) == fom::Order::Timestamp;
            if (!timed && g.rates && !g.rates->due(known, m.object, pair.first)) continue;
            const int tr = transport_of(pair.first) == fom::Transport::BestEffort ? 1 : 0;
            out[timed][tr].values.push_back(&pair);
        }
        if (!g.known.count(m.object)) {
            // Discovered when an attribute comes into scope; a plain subscriber as before DDM.
            bool in_scope = plain != g.declarations.subscribed.end();
            for (const auto& row : out)
                for (const auto& r : row) in_scope = in_scope || !r.values.empty();
            if (!in_scope) continue;
            discover(gh, g, m.object, obj);
        }
        for (int tr = 0; tr < 2; ++tr) {
            const auto& r = out[1][tr];
            if (r.values.empty()) continue;
            if (!tso_frames[tr] || r.values != tso_framed[tr]) {
                tso_frames[tr] = shared_frame(r);
                tso_framed[tr] = r.values;
            }
            deliver_timestamp_order(gh, r, from, m.serial, *m.time, routed, tso_frames[tr]);
        }
        for (auto& r : out[0])
            if (!r.values.empty()) deliver_receive_order(gh, r);
    }
    if (m.time) release_time();  // only a timestamped message can have been queued for a grant
}

void Federation::on(FederateHandle from, const wire::SendInteraction& m) {
    on(from, wire::SendInteractionView{m.interaction_class, wire::views_of(m.values), m.tag, m.time, m.serial});
}

void Federation::on(FederateHandle from, const wire::SendInteractionView& m) {
    ++federate(from).interactions_sent;
    route_interaction(from, m, SentRegions{});
}

void Federation::check_parameters(const fom::InteractionClass& cls, const wire::HandleValueViews& values) const {
    for (const auto& [param, value] : values) {
        if (!cls.parameter(param))
            throw WireError("parameter handle " + std::to_string(param) + " is not defined for interaction '" +
                            cls.qualified_name + "'");
    }
}

std::pair<fom::Transport, fom::Order> Federation::interaction_delivery(const FederateState& sender,
                                                                      const fom::InteractionClass& cls) const {
    auto transport = sender.interaction_transport.find(cls.handle);
    auto order = sender.interaction_order.find(cls.handle);
    return {transport != sender.interaction_transport.end() ? transport->second : cls.transport,
            order != sender.interaction_order.end() ? order->second : cls.order};
}

template <class Forwarded>
void Federation::forward_interaction(FederateHandle to, Forwarded& receive, const wire::HandleValueViews& values,
                                     fom::Handle as, const wire::OptionalTime& time, Routed*& routed) {
    // Received as the subscribed superclass: only the parameters that class defines.
    const auto* received_class = fom_.interaction_class(as);
    receive.interaction_class = as;
    receive.values.clear();
    for (const auto& pair : values)
        if (received_class->parameter(pair.first)) receive.values.push_back(&pair);
    if (time) {
        receive.order = static_cast<std::uint8_t>(fom::Order::Timestamp);
        receive.time = time;
        deliver_timestamp_order(to, receive, receive.sender, receive.serial, *time, routed, shared_frame(receive));
    } else {
        receive.order = static_cast<std::uint8_t>(fom::Order::Receive);
        receive.time.reset();
        deliver_receive_order(to, receive);
    }
}
template void Federation::forward_interaction(FederateHandle, wire::ForwardedDirectedInteraction&,
                                              const wire::HandleValueViews&, fom::Handle, const wire::OptionalTime&,
                                              Routed*&);

// `sent_in`: the regions the interaction was sent with (sendInteractionWithRegion), none for the default
// region, which reaches every subscriber of the class.
void Federation::route_interaction(FederateHandle from, const wire::SendInteractionView& m, const SentRegions& sent_in) {
    if (m.time) check_timestamp(from, *m.time, "interaction");
    const auto& sent_class = interaction_class(m.interaction_class);
    check_parameters(sent_class, m.values);
    wire::ForwardedInteraction receive;
    receive.tag = m.tag;
    receive.sender = from;
    receive.serial = m.serial;
    const auto [transport, order] = interaction_delivery(federates_.at(from), sent_class);
    receive.transport = static_cast<std::uint8_t>(transport);
    const bool timestamped = m.time && order == fom::Order::Timestamp;
    Routed* routed = nullptr;
    for (auto& [gh, g] : federates_) {
        if (gh == from) continue;
        const fom::Handle as = interaction_receiver(g, m.interaction_class, sent_in);
        if (as == 0) continue;
        const bool tso = timestamped && time_.is_tso(from, gh);
        forward_interaction(gh, receive, m.values, as, tso ? m.time : std::nullopt, routed);
    }
    if (m.time) release_time();  // only a timestamped message can have been queued for a grant
}

void Federation::on(FederateHandle from, const wire::DeleteObject& m) {
    federate(from);
    if (m.time) check_timestamp(from, *m.time, "object deletion");
    auto it = objects_.find(m.object);
    if (it == objects_.end() || it->second.ownership.deleter() != from) return;  // checked by the client
    remove_object(m.object, from, m.tag, m.time, m.serial);
    if (m.time) release_time();  // only a timestamped message can have been queued for a grant
}

void Federation::on(FederateHandle from, const wire::LocalDeleteObject& m) {
    auto& f = federate(from);
    f.known.erase(m.object);
    if (f.rates) f.rates->forget(m.object);
    // A federate that forgot the object no longer waits to acquire its attributes (HLA 1.3 §7.7), and
    // releases any it was given while its client still thought it owned none.
    auto it = objects_.find(m.object);
    if (it == objects_.end()) return;
    ObjectInstance& obj = it->second;
    for (auto w = obj.ownership.acquirers.begin(); w != obj.ownership.acquirers.end();) {
        w->second.erase(std::remove(w->second.begin(), w->second.end(), from), w->second.end());
        w = w->second.empty() ? obj.ownership.acquirers.erase(w) : std::next(w);
    }
    std::vector<fom::Handle> owned;
    for (const auto& [attr, owner] : obj.ownership.owners)
        if (owner == from) owned.push_back(attr);
    OwnershipNotices notices;
    for (fom::Handle attr : owned) release_attribute(obj, attr, notices);
    send_notices(m.object, notices);
}

void Federation::on(FederateHandle from, const wire::ReserveObjectNames& m) {
    federate(from);
    reservations_.on(from, m, object_names_);
}

void Federation::on(FederateHandle from, const wire::ReleaseObjectNames& m) {
    federate(from);
    reservations_.on(from, m);
}

void Federation::on(FederateHandle from, const wire::RequestObjectUpdate& m) {
    federate(from);
    auto it = objects_.find(m.object);
    if (it == objects_.end()) return;
    check_attributes(object_class(it->second.object_class), m.attributes);
    std::map<FederateHandle, wire::Handles> by_owner;
    for (auto attr : m.attributes) {
        auto owner = it->second.ownership.owners.find(attr);
        if (owner != it->second.ownership.owners.end() && owner->second != from) by_owner[owner->second].push_back(attr);
    }
    for (auto& [owner, attrs] : by_owner) outbox_.send(owner, wire::ProvideAttributeValueUpdate{m.object, attrs});
}

void Federation::on(FederateHandle from, const wire::RequestClassUpdate& m) {
    federate(from);
    request_class_update(from, m.object_class, m.attributes, nullptr);
}

// HLA 1.3 §6.16, §9.13: the owners of the attributes of the class's instances are asked to provide them;
// with a `region`, only the owners with an update region for the attribute that overlaps it.
void Federation::request_class_update(FederateHandle from, fom::Handle cls, const wire::Handles& attributes,
                                      const Region* region) {
    check_attributes(object_class(cls), attributes);
    for (const auto& [oh, obj] : objects_) {
        if (!fom_.is_object_subclass(obj.object_class, cls)) continue;
        std::map<FederateHandle, wire::Handles> by_owner;
        for (auto attr : attributes) {
            auto owner = obj.ownership.owners.find(attr);
            if (owner == obj.ownership.owners.end() || owner->second == from) continue;
            const bool in_region = !region || update_regions_of(owner->second, oh, attr).any([&](const Region* in) {
                return !in || region->overlaps(*in);
            });
            if (in_region) by_owner[owner->second].push_back(attr);
        }
        for (auto& [owner, attrs] : by_owner) outbox_.send(owner, wire::ProvideAttributeValueUpdate{oh, attrs});
    }
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
        auto owner = obj->ownership.owners.find(attr);
        if (owner == obj->ownership.owners.end() || owner->second != from) continue;
        if (order) obj->order[attr] = *order;
        if (transport) obj->transport[attr] = *transport;
    }
}

void Federation::on(FederateHandle from, const wire::ChangeInteractionDelivery& m) {
    auto& f = federate(from);
    interaction_class(m.interaction_class);
    const auto order = delivery_value<fom::Order>(m.order, "ordering handle");
    const auto transport = delivery_value<fom::Transport>(m.transport, "transportation handle");
    if (!f.declarations.published_interactions.count(m.interaction_class)) return;
    if (order) f.interaction_order[m.interaction_class] = *order;
    if (transport) f.interaction_transport[m.interaction_class] = *transport;
}

// IEEE 1516-2010's transportation queries: what an attribute's updates travel by (its owner's change, else
// the FOM's), and a federate's interactions of a class (its change, else the FOM's; the FOM's for a federate
// not joined).
void Federation::on(FederateHandle from, const wire::QueryAttributeTransportation& m) {
    federate(from);
    const ObjectInstance* obj = object(m.object);
    if (!obj) return;  // deleted meanwhile
    const auto& cls = object_class(obj->object_class);
    const fom::Attribute* attr = cls.attribute(m.attribute);
    if (!attr)
        throw WireError("attribute handle " + std::to_string(m.attribute) + " is not defined for class '" +
                        cls.qualified_name + "'");
    const auto changed = obj->transport.find(m.attribute);
    const fom::Transport transport = changed != obj->transport.end() ? changed->second : attr->transport;
    outbox_.send(from, wire::AttributeTransportationReported{m.object, m.attribute, static_cast<std::uint8_t>(transport)});
}

void Federation::on(FederateHandle from, const wire::QueryInteractionTransportation& m) {
    federate(from);
    fom::Transport transport = interaction_class(m.interaction_class).transport;
    if (const auto f = federates_.find(m.federate); f != federates_.end()) {
        const auto changed = f->second.interaction_transport.find(m.interaction_class);
        if (changed != f->second.interaction_transport.end()) transport = changed->second;
    }
    outbox_.send(from, wire::InteractionTransportationReported{m.federate, m.interaction_class,
                                                               static_cast<std::uint8_t>(transport)});
}

}  // namespace hlacore
