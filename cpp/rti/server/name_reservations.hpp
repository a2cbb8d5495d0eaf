// Object instance names reserved ahead of registration (IEEE 1516-2010 §6.2-6.7) in one federation: a name is
// reserved by one federate until it registers an object with it, releases it or leaves. Owned by the
// Federation, which checks that the sender is joined and tells it the names the objects hold.
#pragma once

#include <string>
#include <unordered_map>

#include "rti/server/outbox.hpp"

namespace hlacore {

class NameReservations {
public:
    using ObjectNames = std::unordered_map<std::string, ObjectHandle>;

    explicit NameReservations(Outbox& outbox) : outbox_(outbox) {}

    // reserve(Multiple)ObjectInstanceName, answered with ObjectNamesReserved: a name an object holds, one
    // already reserved, or one of the RTI's (beginning with HLA) fails (all the names of a multiple one).
    void on(FederateHandle from, const wire::ReserveObjectNames& m, const ObjectNames& objects);
    // Names this federate reserved go back; others are left alone.
    void on(FederateHandle from, const wire::ReleaseObjectNames& m);
    // registerObjectInstance(name) by `h`: RtiError when another federate reserved the name; the
    // registrant's own reservation is used up.
    void registering(FederateHandle h, const std::string& name);
    void departed(FederateHandle h);
    // A restore renumbers the federates: the reservations go.
    void clear() { reserved_.clear(); }

private:
    Outbox& outbox_;
    std::unordered_map<std::string, FederateHandle> reserved_;
};

}  // namespace hlacore
