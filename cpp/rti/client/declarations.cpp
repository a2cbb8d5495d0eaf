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
        declare(published_, cls, attributes);
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
        if (!published_.count(cls))
            raise(ErrorCode::ObjectClassNotPublished, "object class '" + c.qualified_name + "' is not published");
        // HLA 1.3 §5.3: not while this federate waits to acquire attributes of an instance of the class.
        for (const auto& [h, obj] : objects_) {
            if (obj.object_class == cls && (!obj.acquiring.empty() || !obj.acquiring_if_available.empty()))
                raise(ErrorCode::OwnershipAcquisitionPending,
                      "an ownership acquisition is pending for object '" + obj.name + "' of class '" +
                          c.qualified_name + "'");
        }
        published_.erase(cls);
        divested = divest_unpublished(cls);
    }
    for (const auto& m : divested) send(m);
    send(wire::UnpublishObjectClass{cls});
}

void Client::subscribe_object_class(fom::Handle cls, const std::vector<fom::Handle>& attributes, bool active) {
    (void)active;  // passive subscriptions only change advisories, which follow any subscription here
    {
        std::lock_guard<std::mutex> lock(mu_);
        check_attributes(defined_object_class(cls), attributes);
        declare(subscribed_, cls, attributes);
    }
    send(wire::SubscribeObjectClass{cls, attributes, active});
}

void Client::unsubscribe_object_class(fom::Handle cls) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        undeclare(subscribed_, defined_object_class(cls), "object class", ErrorCode::ObjectClassNotSubscribed, "subscribed");
    }
    send(wire::UnsubscribeObjectClass{cls});
}

void Client::publish_interaction_class(fom::Handle cls) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        defined_interaction_class(cls);
        published_interactions_.insert(cls);
    }
    send(wire::PublishInteractionClass{cls});
}

template <class Message>
void Client::undeclare_interaction(std::set<fom::Handle>& declared, fom::Handle cls, ErrorCode code,
                                   const char* declared_as) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        undeclare(declared, defined_interaction_class(cls), "interaction class", code, declared_as);
    }
    send(Message{cls});
}

void Client::unpublish_interaction_class(fom::Handle cls) {
    undeclare_interaction<wire::UnpublishInteractionClass>(published_interactions_, cls,
                                                           ErrorCode::InteractionClassNotPublished, "published");
    std::lock_guard<std::mutex> lock(mu_);
    interaction_transport_.erase(cls);  // the gateway forgets the class's transport change too
}

void Client::subscribe_interaction_class(fom::Handle cls, bool active) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        defined_interaction_class(cls);
        subscribed_interactions_.insert(cls);
    }
    send(wire::SubscribeInteractionClass{cls, active});
}

void Client::unsubscribe_interaction_class(fom::Handle cls) {
    undeclare_interaction<wire::UnsubscribeInteractionClass>(subscribed_interactions_, cls,
                                                             ErrorCode::InteractionClassNotSubscribed, "subscribed");
}

void Client::set_advisory_switch(wire::AdvisorySwitch which, bool on) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    send(wire::SetAdvisorySwitch{static_cast<std::uint8_t>(which), on});
}

}  // namespace hlacore
