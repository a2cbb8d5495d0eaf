// Object instance names reserved ahead of registration (IEEE 1516-2010 §6.2-6.7).
#include "rti/server/name_reservations.hpp"

#include "rti/exceptions.hpp"

namespace hlacore {

void NameReservations::on(FederateHandle from, const wire::ReserveObjectNames& m, const ObjectNames& objects) {
    // Names beginning with HLA are the RTI's (IEEE 1516-2010 §6.2; the gateway names objects HLAobject_<n>).
    auto taken = [&](const std::string& name) {
        return name.empty() || name.compare(0, 3, "HLA") == 0 || objects.count(name) || reserved_.count(name);
    };
    if (m.multiple) {
        bool free = !m.names.empty();
        for (const auto& name : m.names) free = free && !taken(name);
        if (free)
            for (const auto& name : m.names) reserved_[name] = from;
        outbox_.send(from, wire::ObjectNamesReserved{true, free, m.names});
        return;
    }
    for (const auto& name : m.names) {  // one each, as reserveObjectInstanceName asks
        const bool free = !taken(name);
        if (free) reserved_[name] = from;
        outbox_.send(from, wire::ObjectNamesReserved{false, free, {name}});
    }
}

void NameReservations::on(FederateHandle from, const wire::ReleaseObjectNames& m) {
    for (const auto& name : m.names) {
        auto it = reserved_.find(name);
        if (it != reserved_.end() && it->second == from) reserved_.erase(it);
    }
}

void NameReservations::registering(FederateHandle h, const std::string& name) {
    auto it = reserved_.find(name);
    if (it == reserved_.end()) return;
    if (it->second != h)
        throw RtiError(ErrorCode::ObjectAlreadyRegistered,
                       "the name '" + name + "' is reserved by federate " + std::to_string(it->second));
    reserved_.erase(it);
}

void NameReservations::departed(FederateHandle h) {
    for (auto it = reserved_.begin(); it != reserved_.end();) it = it->second == h ? reserved_.erase(it) : std::next(it);
}

}  // namespace hlacore
