// HLA 4's directed interactions (IEEE 1516.1-2025 §5.6-5.13, §6.14), the federate side: the declarations add up
// here and go to the gateway whole, per object class (server/directed.cpp routes by them).
#include "rti/client/client.hpp"

namespace hlacore {

namespace {

using Directed = std::map<fom::Handle, std::set<fom::Handle>>;

// Adds the interaction classes to those of the object class, or removes them (all of them when none are named).
void change(Directed& declared, fom::Handle object_class, const std::vector<fom::Handle>& interactions, bool adding) {
    auto& set = declared[object_class];
    if (adding) {
        set.insert(interactions.begin(), interactions.end());
    } else if (interactions.empty()) {
        set.clear();
    } else {
        for (auto ic : interactions) set.erase(ic);
    }
    if (set.empty()) declared.erase(object_class);
}

wire::Handles handles_of(const Directed& declared, fom::Handle object_class) {
    auto it = declared.find(object_class);
    return it == declared.end() ? wire::Handles{} : wire::Handles(it->second.begin(), it->second.end());
}

}  // namespace

void Client::check_directed(fom::Handle object_class, const std::vector<fom::Handle>& interactions) const {
    require_idle("a directed interaction declaration");
    defined_object_class(object_class);
    for (auto ic : interactions) defined_interaction_class(ic);
}

void Client::check_directed_declaration(fom::Handle object_class) const {
    std::lock_guard<std::mutex> lock(mu_);
    check_directed(object_class, {});
}

void Client::publish_directed(fom::Handle object_class, const std::vector<fom::Handle>& interactions, bool adding) {
    wire::PublishDirectedInteractions m{object_class, {}};
    {
        std::lock_guard<std::mutex> lock(mu_);
        check_directed(object_class, interactions);
        change(declarations_.published_directed, object_class, interactions, adding);
        m.interaction_classes = handles_of(declarations_.published_directed, object_class);
    }
    send(m);
}

void Client::subscribe_directed(fom::Handle object_class, const std::vector<fom::Handle>& interactions,
                                DirectedReceipt receipt) {
    wire::SubscribeDirectedInteractions m{object_class, {}, {}};
    {
        std::lock_guard<std::mutex> lock(mu_);
        check_directed(object_class, interactions);
        auto& owned = declarations_.subscribed_directed;
        auto& universally = declarations_.subscribed_directed_universally;
        // An interaction class is subscribed one way at a time: the later subscription decides.
        if (receipt == DirectedReceipt::None || !interactions.empty()) {
            change(owned, object_class, interactions, receipt == DirectedReceipt::Owned);
            change(universally, object_class, interactions, receipt == DirectedReceipt::Universally);
        }
        m.owned = handles_of(owned, object_class);
        m.universally = handles_of(universally, object_class);
    }
    send(m);
}

std::uint64_t Client::send_directed_interaction(fom::Handle cls, std::uint32_t object, wire::HandleValues values,
                                                const std::string& tag, wire::OptionalTime time) {
    wire::SendDirectedInteraction m{cls, object, std::move(values), tag, time, 0};
    {
        std::lock_guard<std::mutex> lock(mu_);
        check_not_saving_or_restoring("sendDirectedInteraction");
        const auto& c = defined_interaction_class(cls);
        const LocalObject& obj = known_object(object);
        bool published = false;
        for (fom::Handle oc = obj.object_class; oc != 0 && !published; oc = fom_->object_class(oc)->parent) {
            auto it = declarations_.published_directed.find(oc);
            published = it != declarations_.published_directed.end() && it->second.count(cls);
        }
        if (!published)
            raise(ErrorCode::InteractionClassNotPublished, "interaction class '" + c.qualified_name +
                                                               "' is not published directed at object class '" +
                                                               fom_->object_class(obj.object_class)->qualified_name + "'");
        check_sendable_parameters(c, m.values);
        check_forwardable(m, "sendDirectedInteraction");
        m.serial = next_serial(time);
    }
    send(m);
    return m.serial;
}

}  // namespace hlacore
