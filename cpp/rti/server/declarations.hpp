// Declaration management (HLA 1.3 §5) of one federate at the gateway: what it publishes and subscribes to
// without regions (through regions: FederateRegions, regions.hpp), its advisory switches and the
// advisories it was last sent. Pure state; the Federation's handlers in server/declarations.cpp change it
// and send the advisories, object management routes by it (server/objects.cpp).
#pragma once

#include <map>
#include <set>

#include "fed_parser/fom.hpp"

namespace hlacore {

struct FederateDeclarations {
    std::map<fom::Handle, std::set<fom::Handle>> published;   // object class -> attributes
    std::map<fom::Handle, std::set<fom::Handle>> subscribed;  // object class -> attributes
    std::set<fom::Handle> published_interactions;
    std::set<fom::Handle> subscribed_interactions;
    // HLA 4's directed interactions (server/directed.cpp): object class -> interaction classes.
    std::map<fom::Handle, std::set<fom::Handle>> published_directed;
    std::map<fom::Handle, std::set<fom::Handle>> subscribed_directed;              // when owning an attribute
    std::map<fom::Handle, std::set<fom::Handle>> subscribed_directed_universally;  // whenever knowing the instance
    std::set<fom::Handle> registration_started;    // classes told startRegistrationForObjectClass
    std::set<fom::Handle> interactions_turned_on;  // classes told turnInteractionsOn
    bool class_relevance = true;                   // HLA 1.3 advisory switch defaults
    bool interaction_relevance = true;
    bool attribute_relevance = false;
    bool attribute_scope = false;
};

}  // namespace hlacore
