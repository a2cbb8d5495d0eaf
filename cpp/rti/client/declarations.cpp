// Declaration management (HLA 1.3 §5), the federate side.
#include "rti/client/client.hpp"

namespace hlacore {

void Client::publish_object_class(fom::Handle cls, const std::vector<fom::Handle>& attributes) {
    std::vector<wire::UnconditionalDivestiture> divested;
    {
        std::lock_guard<std::mutex> lock(mu_);
        check_attributes(defined_object_class(cls), attributes);
        if (attributes.empty()) {
            published_.erase(cls);
        } else {
            published_[cls] = std::set<fom::Handle>(attributes.begin(), attributes.end());
        }
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
        if (attributes.empty()) {
            subscribed_.erase(cls);
        } else {
            subscribed_[cls] = std::set<fom::Handle>(attributes.begin(), attributes.end());
        }
    }
    send(wire::SubscribeObjectClass{cls, attributes, active});
}

void Client::unsubscribe_object_class(fom::Handle cls) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_object_class(cls);
        if (!subscribed_.erase(cls))
            raise(ErrorCode::ObjectClassNotSubscribed, "object class '" + c.qualified_name + "' is not subscribed");
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

void Client::unpublish_interaction_class(fom::Handle cls) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_interaction_class(cls);
        if (!published_interactions_.erase(cls))
            raise(ErrorCode::InteractionClassNotPublished,
                  "interaction class '" + c.qualified_name + "' is not published");
    }
    send(wire::UnpublishInteractionClass{cls});
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
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_interaction_class(cls);
        if (!subscribed_interactions_.erase(cls))
            raise(ErrorCode::InteractionClassNotSubscribed,
                  "interaction class '" + c.qualified_name + "' is not subscribed");
    }
    send(wire::UnsubscribeInteractionClass{cls});
}

void Client::set_advisory_switch(wire::AdvisorySwitch which, bool on) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    send(wire::SetAdvisorySwitch{static_cast<std::uint8_t>(which), on});
}

}  // namespace hlacore
