// Object management (HLA 1.3 §6) at the gateway: a registered object instance. The federation keeps them
// by handle and by name; its handlers in server/objects.cpp register, route updates and delete.
#pragma once

#include <map>
#include <string>

#include "fed_parser/fom.hpp"
#include "rti/server/ownership.hpp"

namespace hlacore {

struct ObjectInstance {
    fom::Handle object_class = 0;
    std::string name;
    AttributeOwnership ownership;  // ownership management (HLA 1.3 §7, server/ownership.hpp)
    // changeAttributeOrderType / changeAttributeTransportationType (HLA 1.3 §6.19, §6.21) by the
    // attribute's owner; forgotten when the attribute changes owner.
    std::map<fom::Handle, fom::Order> order;
    std::map<fom::Handle, fom::Transport> transport;
};

}  // namespace hlacore
