// Ownership management (HLA 1.3 §7) of one object instance at the gateway: who owns each attribute, who
// may delete the object, and the transfers in progress. Pure state; the Federation's handlers in
// server/ownership.cpp move ownership and send the notifications.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "fed_parser/fom.hpp"
#include "rti/server/outbox.hpp"

namespace hlacore {

struct AttributeOwnership {
    std::map<fom::Handle, FederateHandle> owners;  // attribute -> owner, absent = unowned
    // With a privilegeToDelete attribute in the FOM, its owner may delete the object (HLA 1.3 §6.8);
    // without one, the registrant may (privilege_holder, 0 once released).
    fom::Handle privilege_attribute = 0;
    FederateHandle privilege_holder = 0;
    // Transfers in progress: attributes their owner offers by negotiated divestiture (with its tag), and the
    // federates waiting for an attribute (attributeOwnershipAcquisition), in request order.
    std::map<fom::Handle, std::string> divesting;
    std::map<fom::Handle, std::vector<FederateHandle>> acquirers;

    // The attribute's owner, 0 when unowned.
    FederateHandle owner(fom::Handle attribute) const {
        auto it = owners.find(attribute);
        return it == owners.end() ? 0 : it->second;
    }
    // Who may delete the object: the owner of privilegeToDelete, else the privilege holder (0: nobody).
    FederateHandle deleter() const { return privilege_attribute == 0 ? privilege_holder : owner(privilege_attribute); }
};

}  // namespace hlacore
