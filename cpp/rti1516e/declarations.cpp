// Declaration management (IEEE 1516.1-2010 §5). Publications and subscriptions add up in 1516-2010 and
// replace each other in the core: the class's attributes after the change go to the core (none: withdrawn).
#include "ambassador.hpp"

namespace hlacore::rti1516e {

void Ambassador::declare(Declared& table, ObjectClassHandle cls, AttributeHandleSet const& attributes, bool adding,
                         bool publishing, bool active) {
    std::lock_guard<std::recursive_mutex> lock(mu_);
    const std::uint32_t c = core(cls);
    std::set<std::uint32_t> now = table.count(c) ? table[c] : std::set<std::uint32_t>{};
    for (const auto& a : attributes) {
        if (adding) now.insert(core(a));
        else now.erase(core(a));
    }
    Client& client = this->client();
    if (now.empty()) {
        if (publishing) client.unpublish_object_class(c);
        else client.request(wire::UnsubscribeObjectClass{c});
        table.erase(c);
        return;
    }
    const wire::Handles list(now.begin(), now.end());
    if (publishing) client.publish_object_class(c, list);
    else client.request(wire::SubscribeObjectClass{c, list, active});
    table[c] = std::move(now);
}

void Ambassador::publishObjectClassAttributes(ObjectClassHandle cls, AttributeHandleSet const& attributes) {
    guarded([&] { declare(published_, cls, attributes, true, true); });
}

void Ambassador::unpublishObjectClass(ObjectClassHandle cls) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        client().unpublish_object_class(core(cls));
        published_.erase(core(cls));
    });
}

void Ambassador::unpublishObjectClassAttributes(ObjectClassHandle cls, AttributeHandleSet const& attributes) {
    guarded([&] { declare(published_, cls, attributes, false, true); });
}

void Ambassador::publishInteractionClass(InteractionClassHandle cls) {
    guarded([&] { client().request(wire::PublishInteractionClass{core(cls)}); });
}

void Ambassador::unpublishInteractionClass(InteractionClassHandle cls) {
    guarded([&] { client().request(wire::UnpublishInteractionClass{core(cls)}); });
}

void Ambassador::subscribeObjectClassAttributes(ObjectClassHandle cls, AttributeHandleSet const& attributes,
                                                bool active, std::wstring const& rate) {
    guarded([&] {
        client().request(wire::SubscriptionRate{core(cls), utf8(rate)});
        declare(subscribed_, cls, attributes, true, false, active);
    });
}

void Ambassador::unsubscribeObjectClass(ObjectClassHandle cls) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        client().request(wire::UnsubscribeObjectClass{core(cls)});
        subscribed_.erase(core(cls));
    });
}

void Ambassador::unsubscribeObjectClassAttributes(ObjectClassHandle cls, AttributeHandleSet const& attributes) {
    guarded([&] { declare(subscribed_, cls, attributes, false, false); });
}

void Ambassador::subscribeInteractionClass(InteractionClassHandle cls, bool active) {
    guarded([&] { client().request(wire::SubscribeInteractionClass{core(cls), active}); });
}

void Ambassador::unsubscribeInteractionClass(InteractionClassHandle cls) {
    guarded([&] { client().request(wire::UnsubscribeInteractionClass{core(cls)}); });
}

}  // namespace hlacore::rti1516e
