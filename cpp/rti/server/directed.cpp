// HLA 4's directed interactions (IEEE 1516.1-2025 §5.6-5.13, §6.14-6.15): an interaction sent to one object
// instance. A federate receives it when it knows the instance and subscribed to the interaction class (or a
// superclass, as which it receives it) directed at the instance's class (or a superclass): universally, or while
// it owns an attribute of the instance, the privilege to delete included.
#include "rti/server/federation.hpp"

namespace hlacore {

using wire::WireError;

namespace {

using Directed = std::map<fom::Handle, std::set<fom::Handle>>;

void replace(Directed& declared, fom::Handle object_class, const wire::Handles& interaction_classes) {
    if (interaction_classes.empty()) {
        declared.erase(object_class);
    } else {
        declared[object_class] = std::set<fom::Handle>(interaction_classes.begin(), interaction_classes.end());
    }
}

bool declares(const Directed& declared, fom::Handle object_class, fom::Handle interaction_class) {
    auto it = declared.find(object_class);
    return it != declared.end() && it->second.count(interaction_class);
}

}  // namespace

void Federation::on(FederateHandle from, const wire::PublishDirectedInteractions& m) {
    auto& f = federate(from);
    object_class(m.object_class);
    for (auto ic : m.interaction_classes) interaction_class(ic);
    replace(f.declarations.published_directed, m.object_class, m.interaction_classes);
}

void Federation::on(FederateHandle from, const wire::SubscribeDirectedInteractions& m) {
    auto& f = federate(from);
    object_class(m.object_class);
    for (auto ic : m.owned) interaction_class(ic);
    for (auto ic : m.universally) interaction_class(ic);
    replace(f.declarations.subscribed_directed, m.object_class, m.owned);
    replace(f.declarations.subscribed_directed_universally, m.object_class, m.universally);
}

fom::Handle Federation::directed_receiver(FederateHandle gh, const FederateState& g, fom::Handle cls,
                                          const ObjectInstance& obj) const {
    const auto& d = g.declarations;
    if (d.subscribed_directed.empty() && d.subscribed_directed_universally.empty()) return 0;
    bool owns = false;
    for (const auto& [attribute, owner] : obj.ownership.owners) owns = owns || owner == gh;
    for (fom::Handle ic = cls; ic != 0; ic = fom_.interaction_class(ic)->parent) {
        for (fom::Handle oc = obj.object_class; oc != 0; oc = fom_.object_class(oc)->parent) {
            if (declares(d.subscribed_directed_universally, oc, ic) || (owns && declares(d.subscribed_directed, oc, ic)))
                return ic;
        }
    }
    return 0;
}

void Federation::on(FederateHandle from, const wire::SendDirectedInteraction& m) {
    auto& sender = federate(from);
    ++sender.interactions_sent;
    if (m.time) check_timestamp(from, *m.time, "directed interaction");
    const auto& sent_class = interaction_class(m.interaction_class);
    const wire::HandleValueViews values = wire::views_of(m.values);
    check_parameters(sent_class, values);
    auto it = objects_.find(m.object);
    if (it == objects_.end()) return;  // deleted meanwhile
    const ObjectInstance& obj = it->second;
    bool published = false;
    for (fom::Handle oc = obj.object_class; oc != 0 && !published; oc = fom_.object_class(oc)->parent)
        published = declares(sender.declarations.published_directed, oc, m.interaction_class);
    if (!published)  // the sender's client checked it against the class it knows the instance as
        throw WireError("interaction class '" + sent_class.qualified_name + "' is not published directed at object '" +
                        obj.name + "'");
    wire::ForwardedDirectedInteraction receive;
    receive.object = m.object;
    receive.tag = m.tag;
    receive.sender = from;
    receive.serial = m.serial;
    const auto [transport, order] = interaction_delivery(sender, sent_class);
    receive.transport = static_cast<std::uint8_t>(transport);
    const bool timestamped = m.time && order == fom::Order::Timestamp;
    Routed* routed = nullptr;
    for (auto& [gh, g] : federates_) {
        if (gh == from || !g.known.count(m.object)) continue;
        const fom::Handle as = directed_receiver(gh, g, m.interaction_class, obj);
        if (as == 0) continue;
        const bool tso = timestamped && time_.is_tso(from, gh);
        forward_interaction(gh, receive, values, as, tso ? m.time : std::nullopt, routed);
    }
    if (m.time) release_time();  // only a timestamped message can have been queued for a grant
}

}  // namespace hlacore
