// Support services (HLA 1.3 §10): names and handles, answered from the FOM without asking the gateway.
#include "rti/client/client.hpp"

namespace hlacore {

fom::Handle Client::object_class_handle(const std::string& name) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    const auto* c = fom_->find_object_class(name);
    if (!c) raise(ErrorCode::NameNotFound, "no object class named '" + name + "'");
    return c->handle;
}

std::string Client::object_class_name(fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    return defined_object_class(cls).qualified_name;
}

fom::Handle Client::attribute_handle(const std::string& name, fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto& c = defined_object_class(cls);
    const auto* a = c.attribute(name);
    if (!a) raise(ErrorCode::NameNotFound, "class '" + c.qualified_name + "' has no attribute named '" + name + "'");
    return a->handle;
}

std::string Client::attribute_name(fom::Handle attribute, fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto& c = defined_object_class(cls);
    const auto* a = c.attribute(attribute);
    if (!a)
        raise(ErrorCode::AttributeNotDefined,
              "attribute handle " + std::to_string(attribute) + " is not defined for class '" + c.qualified_name + "'");
    return a->name;
}

fom::Handle Client::interaction_class_handle(const std::string& name) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    const auto* c = fom_->find_interaction_class(name);
    if (!c) raise(ErrorCode::NameNotFound, "no interaction class named '" + name + "'");
    return c->handle;
}

std::string Client::interaction_class_name(fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    return defined_interaction_class(cls).qualified_name;
}

fom::Handle Client::parameter_handle(const std::string& name, fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto& c = defined_interaction_class(cls);
    const auto* p = c.parameter(name);
    if (!p) raise(ErrorCode::NameNotFound, "interaction '" + c.qualified_name + "' has no parameter named '" + name + "'");
    return p->handle;
}

std::string Client::parameter_name(fom::Handle parameter, fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto& c = defined_interaction_class(cls);
    const auto* p = c.parameter(parameter);
    if (!p)
        raise(ErrorCode::InteractionParameterNotDefined, "parameter handle " + std::to_string(parameter) +
                                                             " is not defined for interaction '" + c.qualified_name + "'");
    return p->name;
}

std::uint32_t Client::object_instance_handle(const std::string& name) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    for (const auto& [h, obj] : objects_) {
        if (obj.name == name) return h;
    }
    raise(ErrorCode::ObjectNotKnown, "no object named '" + name + "' is known to this federate");
}

std::string Client::object_instance_name(std::uint32_t object) const {
    std::lock_guard<std::mutex> lock(mu_);
    return known_object(object).name;
}

fom::Handle Client::object_class_of(std::uint32_t object) const {
    std::lock_guard<std::mutex> lock(mu_);
    return known_object(object).object_class;
}

fom::Handle Client::routing_space_handle(const std::string& name) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    const auto* s = fom_->find_space(name);
    if (!s) raise(ErrorCode::NameNotFound, "no routing space named '" + name + "'");
    return s->handle;
}

std::string Client::routing_space_name(fom::Handle space) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    const auto* s = fom_->space(space);
    if (!s) raise(ErrorCode::SpaceNotDefined, "routing space handle " + std::to_string(space) + " is not defined");
    return s->name;
}

fom::Handle Client::dimension_handle(const std::string& name, fom::Handle space) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    const auto* s = fom_->space(space);
    if (!s) raise(ErrorCode::SpaceNotDefined, "routing space handle " + std::to_string(space) + " is not defined");
    if (const auto* d = s->dimension(name)) return d->handle;
    raise(ErrorCode::NameNotFound, "routing space '" + s->name + "' has no dimension named '" + name + "'");
}

const fom::Dimension& Client::defined_dimension(fom::Handle dimension, fom::Handle space) const {
    require_joined();
    const auto* s = fom_->space(space);
    if (!s) raise(ErrorCode::SpaceNotDefined, "routing space handle " + std::to_string(space) + " is not defined");
    if (const auto* d = s->dimension(dimension)) return *d;
    raise(ErrorCode::DimensionNotDefined, "dimension handle " + std::to_string(dimension) + " is not defined in '" +
                                              s->name + "'");
}

std::string Client::dimension_name(fom::Handle dimension, fom::Handle space) const {
    std::lock_guard<std::mutex> lock(mu_);
    return defined_dimension(dimension, space).name;
}

std::uint64_t Client::dimension_upper_bound(fom::Handle dimension, fom::Handle space) const {
    std::lock_guard<std::mutex> lock(mu_);
    return defined_dimension(dimension, space).upper_bound;
}

fom::Handle Client::attribute_routing_space(fom::Handle attribute, fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto& c = defined_object_class(cls);
    const auto* a = c.attribute(attribute);
    if (!a) raise(ErrorCode::AttributeNotDefined, "attribute handle " + std::to_string(attribute) + " is not defined");
    const auto* s = a->space.empty() ? nullptr : fom_->find_space(a->space);
    return s ? s->handle : 0;
}

std::set<fom::Handle> Client::attribute_routing_spaces(fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    std::set<fom::Handle> spaces;
    for (const auto& a : defined_object_class(cls).attributes) {
        const auto* s = a.space.empty() ? nullptr : fom_->find_space(a.space);
        if (s) spaces.insert(s->handle);
    }
    return spaces;
}

fom::Handle Client::interaction_routing_space(fom::Handle cls) const {
    std::lock_guard<std::mutex> lock(mu_);
    const auto& c = defined_interaction_class(cls);
    const auto* s = c.space.empty() ? nullptr : fom_->find_space(c.space);
    return s ? s->handle : 0;
}

std::uint32_t Client::federate_handle() const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    return federate_;
}

TimeType Client::time_type() const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    return time_type_;
}

namespace {

// HLA 1.3's names of the transportation and ordering types, and the messages for a name or handle it lacks.
struct NamedTypes {
    const char* what;
    std::pair<const char*, std::uint8_t> types[2];
    ErrorCode bad_handle;

    std::uint8_t handle(const std::string& name) const {
        for (const auto& [n, h] : types)
            if (name == n) return h;
        raise(ErrorCode::NameNotFound, std::string("no ") + what + " type " + name + " (" + types[0].first + ", " +
                                           types[1].first + ")");
    }
    std::string name(std::uint64_t handle) const {
        for (const auto& [n, h] : types)
            if (handle == h) return n;
        raise(bad_handle, std::string(what) + " handle " + std::to_string(handle));
    }
};

const NamedTypes kTransportations{"transportation",
                                  {{"HLAreliable", static_cast<std::uint8_t>(fom::Transport::Reliable)},
                                   {"HLAbestEffort", static_cast<std::uint8_t>(fom::Transport::BestEffort)}},
                                  ErrorCode::InvalidTransportationHandle};
const NamedTypes kOrderings{"ordering",
                            {{"Receive", static_cast<std::uint8_t>(fom::Order::Receive)},
                             {"Timestamp", static_cast<std::uint8_t>(fom::Order::Timestamp)}},
                            ErrorCode::InvalidOrderingHandle};

}  // namespace

std::uint8_t Client::transportation_handle(const std::string& name) { return kTransportations.handle(name); }
std::string Client::transportation_name(std::uint64_t handle) { return kTransportations.name(handle); }
std::uint8_t Client::ordering_handle(const std::string& name) { return kOrderings.handle(name); }
std::string Client::ordering_name(std::uint64_t handle) { return kOrderings.name(handle); }

const fom::UpdateRate& Client::find_update_rate(const std::string& designator) const {
    const fom::UpdateRate* rate = fom_->find_update_rate(designator);
    if (!rate) raise(ErrorCode::InvalidUpdateRateDesignator, "no FOM module declares the update rate '" + designator + "'");
    return *rate;
}

double Client::update_rate(const std::string& designator) const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    return find_update_rate(designator).rate;
}

double Client::update_rate_for(std::uint32_t object, fom::Handle attribute) const {
    std::lock_guard<std::mutex> lock(mu_);
    const LocalObject& obj = known_object(object);
    check_attributes(defined_object_class(obj.object_class), {attribute});
    const auto rate = declarations_.rates.find(obj.object_class);
    return rate == declarations_.rates.end() ? 0 : rate->second;
}

}  // namespace hlacore
