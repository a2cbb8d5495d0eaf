// Object management (IEEE 1516.1-2010 §6): name reservation, registering, updates, interactions, deletion,
// update requests, transportation and order changes.
#include "ambassador.hpp"

namespace hlacore::rti1516e {

namespace {

// The values as the client takes them: views of the caller's bytes, encoded before the call returns.
template <class Map>
wire::HandleValueViews views(Map const& values) {
    wire::HandleValueViews out;
    out.reserve(values.size());
    for (const auto& [h, v] : values)
        out.emplace_back(core(h), std::string_view(static_cast<const char*>(v.data()), v.size()));
    return out;
}

std::vector<std::string> names_of(std::set<std::wstring> const& names) {
    if (names.empty()) raise("NameSetWasEmpty", "no name given");
    std::vector<std::string> out;
    for (const auto& n : names) out.push_back(utf8(n));
    return out;
}

std::uint8_t transport_of(TransportationType const& type) {  // by reference: see raw()
    if (raw(type) != RELIABLE && raw(type) != BEST_EFFORT) raise("InvalidTransportationType", std::to_string(raw(type)));
    return static_cast<std::uint8_t>(raw(type));  // HLAreliable 1, HLAbestEffort 2: the core's numbers too
}

std::uint8_t order_of(OrderType const& type) {
    if (raw(type) != RECEIVE && raw(type) != TIMESTAMP) raise("InvalidOrderType", std::to_string(raw(type)));
    return static_cast<std::uint8_t>(raw(type));
}

}  // namespace

wire::HandleValues copies(ParameterHandleValueMap const& values) {
    wire::HandleValues out;
    for (const auto& [p, v] : values) out.emplace_back(core(p), std::string(static_cast<const char*>(v.data()), v.size()));
    return out;
}

void Ambassador::require_reserved(std::wstring const& name) const {
    if (!reserved_.count(name)) raise("ObjectInstanceNameNotReserved", "'" + utf8(name) + "' (reserve it first)");
}

void Ambassador::reserveObjectInstanceName(std::wstring const& name) {
    guarded([&] { client().request(wire::ReserveObjectNames{false, {utf8(name)}}); });
}

void Ambassador::releaseObjectInstanceName(std::wstring const& name) {
    releaseMultipleObjectInstanceName({name});
}

void Ambassador::reserveMultipleObjectInstanceName(std::set<std::wstring> const& names) {
    guarded([&] { client().request(wire::ReserveObjectNames{true, names_of(names)}); });
}

void Ambassador::releaseMultipleObjectInstanceName(std::set<std::wstring> const& names) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        for (const auto& n : names) require_reserved(n);
        client().request(wire::ReleaseObjectNames{names_of(names)});
        for (const auto& n : names) reserved_.erase(n);
    });
}

ObjectInstanceHandle Ambassador::registerObjectInstance(ObjectClassHandle cls) {
    return guarded([&] { return handle<ObjectInstanceHandle>(client().register_object(core(cls), "")); });
}

ObjectInstanceHandle Ambassador::registerObjectInstance(ObjectClassHandle cls, std::wstring const& name) {
    return guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        require_reserved(name);
        const auto object = client().register_object(core(cls), utf8(name));
        reserved_.erase(name);
        return handle<ObjectInstanceHandle>(object);
    });
}

void Ambassador::updateAttributeValues(ObjectInstanceHandle object, AttributeHandleValueMap const& values,
                                       VariableLengthData const& tag) {
    guarded([&] { client().update_attributes(core(object), views(values), bytes(tag), std::nullopt); });
}

MessageRetractionHandle Ambassador::updateAttributeValues(ObjectInstanceHandle object,
                                                          AttributeHandleValueMap const& values,
                                                          VariableLengthData const& tag, LogicalTime const& time) {
    return guarded([&] {
        Client& c = client();
        return retraction(c.federate_handle(), c.update_attributes(core(object), views(values), bytes(tag), time_in(time)));
    });
}

void Ambassador::sendInteraction(InteractionClassHandle cls, ParameterHandleValueMap const& values,
                                 VariableLengthData const& tag) {
    guarded([&] { client().send_interaction(core(cls), views(values), bytes(tag), std::nullopt); });
}

MessageRetractionHandle Ambassador::sendInteraction(InteractionClassHandle cls, ParameterHandleValueMap const& values,
                                                    VariableLengthData const& tag, LogicalTime const& time) {
    return guarded([&] {
        Client& c = client();
        return retraction(c.federate_handle(), c.send_interaction(core(cls), views(values), bytes(tag), time_in(time)));
    });
}

void Ambassador::deleteObjectInstance(ObjectInstanceHandle object, VariableLengthData const& tag) {
    guarded([&] { client().delete_object(core(object), bytes(tag), std::nullopt); });
}

MessageRetractionHandle Ambassador::deleteObjectInstance(ObjectInstanceHandle object, VariableLengthData const& tag,
                                                         LogicalTime const& time) {
    return guarded([&] {
        Client& c = client();
        return retraction(c.federate_handle(), c.delete_object(core(object), bytes(tag), time_in(time)));
    });
}

void Ambassador::localDeleteObjectInstance(ObjectInstanceHandle object) {
    guarded([&] { client().request(wire::LocalDeleteObject{core(object)}); });
}

// The core's update requests carry no tag.
void Ambassador::requestAttributeValueUpdate(ObjectInstanceHandle object, AttributeHandleSet const& attributes,
                                             VariableLengthData const&) {
    guarded([&] { client().request(wire::RequestObjectUpdate{core(object), cores(attributes)}); });
}

void Ambassador::requestAttributeValueUpdate(ObjectClassHandle cls, AttributeHandleSet const& attributes,
                                             VariableLengthData const&) {
    guarded([&] { client().request(wire::RequestClassUpdate{core(cls), cores(attributes)}); });
}

void Ambassador::requestAttributeTransportationTypeChange(ObjectInstanceHandle object,
                                                          AttributeHandleSet const& attributes,
                                                          TransportationType type) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        client().change_attribute_transportation(core(object), cores(attributes), transport_of(type));
        local_.push_back([=](FederateAmbassador& fa) { fa.confirmAttributeTransportationTypeChange(object, attributes, type); });
    });
}

void Ambassador::requestInteractionTransportationTypeChange(InteractionClassHandle cls, TransportationType type) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        client().change_interaction_transportation(core(cls), transport_of(type));
        local_.push_back([=](FederateAmbassador& fa) { fa.confirmInteractionTransportationTypeChange(cls, type); });
    });
}

void Ambassador::queryAttributeTransportationType(ObjectInstanceHandle object, AttributeHandle attribute) {
    guarded([&] { client().request(wire::QueryAttributeTransportation{core(object), core(attribute)}); });
}

void Ambassador::queryInteractionTransportationType(FederateHandle federate, InteractionClassHandle cls) {
    guarded([&] { client().request(wire::QueryInteractionTransportation{core(federate), core(cls)}); });
}

void Ambassador::changeAttributeOrderType(ObjectInstanceHandle object, AttributeHandleSet const& attributes,
                                          OrderType type) {
    guarded([&] { client().change_attribute_order(core(object), cores(attributes), order_of(type)); });
}

void Ambassador::changeInteractionOrderType(InteractionClassHandle cls, OrderType type) {
    guarded([&] { client().change_interaction_order(core(cls), order_of(type)); });
}

}  // namespace hlacore::rti1516e
