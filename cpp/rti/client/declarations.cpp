// Declaration management (HLA 1.3 §5), the federate side.
#include "rti/client/client.hpp"

namespace hlacore {

namespace {

// publish/subscribe of an object class: its attributes replace those declared before (none: no longer declared).
void declare(std::map<fom::Handle, std::set<fom::Handle>>& declared, fom::Handle cls,
             const std::vector<fom::Handle>& attributes) {
    if (attributes.empty()) {
        declared.erase(cls);
    } else {
        declared[cls] = std::set<fom::Handle>(attributes.begin(), attributes.end());
    }
}

// unpublish/unsubscribe: the class leaves `declared`, refused with `code` when it was not in it.
template <class Declared, class Class>
void undeclare(Declared& declared, const Class& cls, const char* kind, ErrorCode code, const char* declared_as) {
    if (!declared.erase(cls.handle))
        raise(code, std::string(kind) + " '" + cls.qualified_name + "' is not " + declared_as);
}

}  // namespace

void Client::publish_object_class(fom::Handle cls, const std::vector<fom::Handle>& attributes) {
    std::vector<wire::UnconditionalDivestiture> divested;
    {
        std::lock_guard<std::mutex> lock(mu_);
        check_attributes(defined_object_class(cls), attributes);
        declare(declarations_.published, cls, attributes);
        divested = divest_unpublished(cls);
    }
    for (const auto& m : divested) send(m);
    send(wire::PublishObjectClass{cls, attributes});
}

void Client::unpublish_object_class(fom::Handle cls) {
    std::vector<wire::UnconditionalDivestiture> divested;
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_object_class(cls);
        if (!declarations_.published.count(cls))
            raise(ErrorCode::ObjectClassNotPublished, "object class '" + c.qualified_name + "' is not published");
        // HLA 1.3 §5.3: not while this federate waits to acquire attributes of an instance of the class.
        for (const auto& [h, obj] : objects_) {
            if (obj.object_class == cls && (!obj.acquiring.empty() || !obj.acquiring_if_available.empty()))
                raise(ErrorCode::OwnershipAcquisitionPending,
                      "an ownership acquisition is pending for object '" + obj.name + "' of class '" +
                          c.qualified_name + "'");
        }
        declarations_.published.erase(cls);
        divested = divest_unpublished(cls);
    }
    for (const auto& m : divested) send(m);
    send(wire::UnpublishObjectClass{cls});
}

void Client::check(const wire::SubscribeObjectClass& m) {
    // Passive subscriptions (m.active false) only change advisories, which follow any subscription here.
    check_attributes(defined_object_class(m.object_class), m.attributes);
    declare(declarations_.subscribed, m.object_class, m.attributes);
}

void Client::check(const wire::SubscriptionRate& m) {
    defined_object_class(m.object_class);
    declarations_.rates[m.object_class] = m.designator.empty() ? 0 : find_update_rate(m.designator).rate;
}

void Client::check(const wire::UnsubscribeObjectClass& m) {
    undeclare(declarations_.subscribed, defined_object_class(m.object_class), "object class", ErrorCode::ObjectClassNotSubscribed,
              "subscribed");
}

void Client::check(const wire::PublishInteractionClass& m) {
    defined_interaction_class(m.interaction_class);
    declarations_.published_interactions.insert(m.interaction_class);
}

void Client::check(const wire::UnpublishInteractionClass& m) {
    undeclare(declarations_.published_interactions, defined_interaction_class(m.interaction_class), "interaction class",
              ErrorCode::InteractionClassNotPublished, "published");
    interaction_transport_.erase(m.interaction_class);  // the gateway forgets the class's transport change too
}

void Client::check(const wire::SubscribeInteractionClass& m) {
    defined_interaction_class(m.interaction_class);
    declarations_.subscribed_interactions.insert(m.interaction_class);
}

void Client::check(const wire::UnsubscribeInteractionClass& m) {
    undeclare(declarations_.subscribed_interactions, defined_interaction_class(m.interaction_class), "interaction class",
              ErrorCode::InteractionClassNotSubscribed, "subscribed");
}

void Client::check(const wire::SetAdvisorySwitch&) { require_joined(); }

}  // namespace hlacore
