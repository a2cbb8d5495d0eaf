// Object management (HLA 1.3 §6), the federate side: the checks against this federate's view, then the send.
#include "rti/client/client.hpp"

namespace hlacore {

std::uint32_t Client::register_object(fom::Handle cls, const std::string& name) {
    std::set<fom::Handle> owned;
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_object_class(cls);
        check_not_saving_or_restoring("registerObjectInstance");
        auto it = declarations_.published.find(cls);
        if (it == declarations_.published.end())
            raise(ErrorCode::ObjectClassNotPublished, "object class '" + c.qualified_name + "' is not published");
        owned = it->second;
    }
    const auto id = next_request();
    auto registered = call<wire::ObjectRegistered>(wire::RegisterObject{id, cls, name}, id);
    std::lock_guard<std::mutex> lock(mu_);
    add_registered(registered.object, cls, registered.name, std::move(owned));
    return registered.object;
}

void Client::add_registered(std::uint32_t object, fom::Handle cls, const std::string& name, std::set<fom::Handle> owned) {
    LocalObject obj = make_local_object(cls, name);
    obj.owned = std::move(owned);
    // The registrant holds the privilege to delete (HLA 1.3 §6.2), the privilegeToDelete attribute if any.
    if (obj.privilege_attribute) obj.owned.insert(obj.privilege_attribute);
    obj.privilege_to_delete = true;
    objects_[object] = std::move(obj);
}

std::uint64_t Client::update_attributes(std::uint32_t object, wire::HandleValueViews values, const std::string& tag,
                                        wire::OptionalTime time) {
    wire::UpdateAttributesView update{object, std::move(values), tag, time, 0};
    bool datagram = false;
    {
        std::lock_guard<std::mutex> lock(mu_);
        const LocalObject& obj = known_object(object);
        check_not_saving_or_restoring("updateAttributeValues");
        const auto& cls = *fom_->object_class(obj.object_class);
        for (const auto& [attr, value] : update.values) {
            if (!cls.attribute(attr))
                raise(ErrorCode::AttributeNotDefined, "attribute handle " + std::to_string(attr) +
                                                          " is not defined for class '" + cls.qualified_name + "'");
            if (!obj.owned.count(attr))
                raise(ErrorCode::AttributeNotOwned, "attribute '" + cls.attribute(attr)->name + "' of object '" +
                                                        obj.name + "' is not owned by this federate");
        }
        check_forwardable(update, "updateAttributeValues");
        update.serial = next_serial(time);
        datagram = !time && best_effort(obj, update.values);
    }
    if (datagram) {
        send_best_effort(update);
    } else {
        send(update);
    }
    return update.serial;
}

std::uint64_t Client::send_interaction(fom::Handle cls, wire::HandleValueViews values, const std::string& tag,
                                       wire::OptionalTime time) {
    wire::SendInteractionView interaction{cls, std::move(values), tag, time, 0};
    bool datagram = false;
    {
        std::lock_guard<std::mutex> lock(mu_);
        check_not_saving_or_restoring("sendInteraction");
        check_sendable(cls, interaction.values);
        check_forwardable(interaction, "sendInteraction");
        interaction.serial = next_serial(time);
        datagram = !time && best_effort(cls);
    }
    if (datagram) {
        send_best_effort(interaction);
    } else {
        send(interaction);
    }
    return interaction.serial;
}

std::uint64_t Client::delete_object(std::uint32_t object, const std::string& tag, wire::OptionalTime time) {
    std::uint64_t serial;
    {
        std::lock_guard<std::mutex> lock(mu_);
        const LocalObject& obj = known_object(object);
        check_not_saving_or_restoring("deleteObjectInstance");
        if (!obj.privilege_to_delete)
            raise(ErrorCode::DeletePrivilegeNotHeld, "this federate may not delete object '" + obj.name + "'");
        serial = next_serial(time);
        objects_.erase(object);
    }
    send(wire::DeleteObject{object, tag, time, serial});
    return serial;
}

void Client::check(const wire::LocalDeleteObject& m) {
    const LocalObject& obj = known_object(m.object);
    if (!obj.owned.empty())
        raise(ErrorCode::FederateOwnsAttributes,
              "this federate owns attributes of object '" + obj.name + "' and cannot delete it locally");
    objects_.erase(m.object);
}

void Client::check(const wire::RequestObjectUpdate& m) {
    const LocalObject& obj = known_object(m.object);
    check_attributes(*fom_->object_class(obj.object_class), m.attributes);
}

void Client::check(const wire::RequestClassUpdate& m) {
    check_attributes(defined_object_class(m.object_class), m.attributes);
}

// ---- object instance names (IEEE 1516-2010 §6.2-6.7): the gateway answers the reservation ----

void Client::check(const wire::ReserveObjectNames& m) {
    require_joined();
    if (m.names.empty()) raise(ErrorCode::NameNotFound, "no name to reserve");
}

void Client::check(const wire::ReleaseObjectNames&) { require_joined(); }

// ---- transport and order changes (HLA 1.3 §6.19-6.22) ----

namespace {

std::uint8_t transport_value(std::uint32_t transport) {
    if (transport != static_cast<std::uint32_t>(fom::Transport::Reliable) &&
        transport != static_cast<std::uint32_t>(fom::Transport::BestEffort))
        raise(ErrorCode::InvalidTransportationHandle,
              "transportation handle " + std::to_string(transport) + " is not a transportation type");
    return static_cast<std::uint8_t>(transport);
}

std::uint8_t order_value(std::uint32_t order) {
    if (order != static_cast<std::uint32_t>(fom::Order::Receive) &&
        order != static_cast<std::uint32_t>(fom::Order::Timestamp))
        raise(ErrorCode::InvalidOrderingHandle, "ordering handle " + std::to_string(order) + " is not an ordering type");
    return static_cast<std::uint8_t>(order);
}

}  // namespace

void Client::change_attribute_transportation(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                                             std::uint32_t transport) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    change_attribute_delivery(object, attributes, 0, transport_value(transport));
}

void Client::change_attribute_order(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                                    std::uint32_t order) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    change_attribute_delivery(object, attributes, order_value(order), 0);
}

void Client::change_interaction_transportation(fom::Handle cls, std::uint32_t transport) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    change_interaction_delivery(cls, 0, transport_value(transport));
}

void Client::change_interaction_order(fom::Handle cls, std::uint32_t order) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    change_interaction_delivery(cls, order_value(order), 0);
}

// §6.19, §6.21: only the owner of every named attribute may change them.
void Client::change_attribute_delivery(std::uint32_t object, const std::vector<fom::Handle>& attributes,
                                       std::uint8_t order, std::uint8_t transport) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const LocalObject& obj = known_object(object);
        const auto& cls = *fom_->object_class(obj.object_class);
        check_attributes(cls, attributes);
        for (auto a : attributes) {
            if (!obj.owned.count(a))
                raise(ErrorCode::AttributeNotOwned, "attribute '" + cls.attribute(a)->name + "' of object '" +
                                                        obj.name + "' is not owned by this federate");
        }
        // Known here too: whether an update may go as a datagram (client/datagrams.cpp).
        if (transport)
            for (auto a : attributes) known_object(object).transport[a] = static_cast<fom::Transport>(transport);
    }
    send(wire::ChangeAttributeDelivery{object, attributes, order, transport});
}

// §6.20, §6.22: only a publisher of the class may change it.
void Client::change_interaction_delivery(fom::Handle cls, std::uint8_t order, std::uint8_t transport) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        const auto& c = defined_interaction_class(cls);
        if (!declarations_.published_interactions.count(cls))
            raise(ErrorCode::InteractionClassNotPublished,
                  "interaction class '" + c.qualified_name + "' is not published");
        if (transport) interaction_transport_[cls] = static_cast<fom::Transport>(transport);
    }
    send(wire::ChangeInteractionDelivery{cls, order, transport});
}

// IEEE 1516-2010's transportation queries, answered by a report callback.
void Client::check(const wire::QueryAttributeTransportation& m) { ownership_object(m.object, {m.attribute}); }
void Client::check(const wire::QueryInteractionTransportation& m) { defined_interaction_class(m.interaction_class); }

// Discoveries and removals count at once, before tick() delivers them: later calls check against them.
bool Client::arrived(wire::DiscoverObject& d) {
    objects_[d.object] = make_local_object(d.object_class, d.name);
    return true;
}

bool Client::arrived(wire::RemoveObject& r) {
    objects_.erase(r.object);
    return true;
}

}  // namespace hlacore
