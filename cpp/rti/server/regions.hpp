// Data distribution management (HLA 1.3 §9) at the gateway: a federate's regions, its subscriptions and
// update associations through them, and the overlap test that decides who receives what. Pure state, no
// I/O; the Federation's handlers in server/regions.cpp route with it (docs/ddm.md has the contract).
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "fed_parser/fom.hpp"
#include "rti/erase_nested.hpp"
#include "rti/server/outbox.hpp"

namespace hlacore {

// A region belongs to the federate that created it; its handle is chosen by that federate's client.
using RegionHandle = std::uint32_t;

// One or more extents, each a closed range (lower <= value <= upper) per dimension of the routing space, in
// the FOM's order. The default region (a plain subscription, an unassociated attribute, an interaction sent
// without region) is the whole space: it has no Region, and overlaps every region.
struct Region {
    using Range = std::pair<std::uint32_t, std::uint32_t>;
    fom::Handle space = 0;
    std::vector<std::vector<Range>> extents;

    // From the wire's bounds (lower and upper of each dimension, extent after extent); wire::WireError when
    // the space is unknown or the bounds do not fit its dimensions.
    static Region from_bounds(const fom::Fom& fom, fom::Handle space, const wire::Handles& bounds);
    // Some extent of each overlaps in every dimension.
    bool overlaps(const Region& other) const;
};

// One federate's DDM state. Subscriptions through a region live here; the plain ones (the default region)
// stay with the federate's declarations.
struct FederateRegions {
    std::map<RegionHandle, Region> regions;
    std::map<fom::Handle, std::map<RegionHandle, std::set<fom::Handle>>> object_subscriptions;  // class -> region -> attributes
    std::map<fom::Handle, std::set<RegionHandle>> interaction_subscriptions;
    // The update regions: object -> attribute -> region (absent: the default region).
    std::map<ObjectHandle, std::map<fom::Handle, RegionHandle>> update_regions;
    // The attributes last reported in scope, while the attribute scope advisory switch is on.
    std::map<ObjectHandle, std::set<fom::Handle>> in_scope;
    // Owned attributes last reported relevant (turnUpdatesOn), while the relevance switch is on.
    std::map<ObjectHandle, std::set<fom::Handle>> relevant;
    // The highest region number the federate created: saved, so that a restored client never numbers a new
    // region like one the federate had before the save (server/save_restore.cpp).
    RegionHandle last_region = 0;

    const Region& at(RegionHandle r) const;  // wire::WireError when unknown
    void create(RegionHandle r, Region region);  // wire::WireError for 0 or a handle in use
    // The region and whatever refers to it: subscriptions through it, update associations.
    void erase(RegionHandle r);
    // The subscription of class `cls` through region `r` (in object_ or interaction_subscriptions) goes;
    // false when there was none, wire::WireError for an unknown region.
    template <class Subscriptions>
    bool unsubscribe(Subscriptions& subscriptions, fom::Handle cls, RegionHandle r) {
        at(r);
        return erase_nested(subscriptions, cls, r);
    }
    // The region the object's attribute is updated in, null for the default region.
    const Region* update_region(ObjectHandle object, fom::Handle attribute) const;
    // Is the attribute subscribed at class `known` through a region overlapping `updated_in` (null: the
    // default region)?
    bool subscribed(fom::Handle known, fom::Handle attribute, const Region* updated_in) const;
    // Is interaction class `cls` subscribed through a region overlapping `sent_in` (null: the default region)?
    bool subscribed_interaction(fom::Handle cls, const Region* sent_in) const;
};

}  // namespace hlacore
