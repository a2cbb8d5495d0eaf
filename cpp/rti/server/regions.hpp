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
#include "rti/update_regions.hpp"

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

struct FederateRegions;

// The regions an attribute is updated in or an interaction sent in, all of one federate's: none is the
// default region, which overlaps every region. A view: no copy on a message's path.
class SentRegions {
public:
    SentRegions() = default;  // the default region
    SentRegions(const FederateRegions& owner, const std::set<RegionHandle>& handles) : owner_(&owner), handles_(&handles) {}
    bool is_default() const { return !handles_ || handles_->empty(); }
    // Is f(region) true for some of them? For the default region, f(nullptr).
    template <class F>
    bool any(F f) const;

private:
    const FederateRegions* owner_ = nullptr;
    const std::set<RegionHandle>* handles_ = nullptr;
};

// One federate's DDM state. Subscriptions through a region live here; the plain ones (the default region)
// stay with the federate's declarations.
struct FederateRegions {
    std::map<RegionHandle, Region> regions;
    std::map<fom::Handle, std::map<RegionHandle, std::set<fom::Handle>>> object_subscriptions;  // class -> region -> attributes
    std::map<fom::Handle, std::set<RegionHandle>> interaction_subscriptions;
    // The update regions: object -> attribute -> regions (absent: the default region). HLA 1.3 gives an
    // attribute one, IEEE 1516-2010 several: an update reaches a subscriber when any of them overlaps.
    UpdateRegions update_regions;
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
    // The regions the object's attribute is updated in (none: the default region).
    SentRegions update_regions_of(ObjectHandle object, fom::Handle attribute) const;
    // Is the attribute subscribed at class `known` through a region overlapping some of `updated_in`?
    bool subscribed(fom::Handle known, fom::Handle attribute, const SentRegions& updated_in) const {
        return updated_in.any([&](const Region* in) { return subscribed(known, attribute, in); });
    }
    // Is interaction class `cls` subscribed through a region overlapping some of `sent_in`?
    bool subscribed_interaction(fom::Handle cls, const SentRegions& sent_in) const {
        return sent_in.any([&](const Region* in) { return subscribed_interaction(cls, in); });
    }
    // The same for one region, null for the default region.
    bool subscribed(fom::Handle known, fom::Handle attribute, const Region* updated_in) const;
    bool subscribed_interaction(fom::Handle cls, const Region* sent_in) const;
};

template <class F>
bool SentRegions::any(F f) const {
    if (is_default()) return f(static_cast<const Region*>(nullptr));
    // Counted rather than iterated to end(): the common single region costs no tree step.
    auto it = handles_->begin();
    for (std::size_t left = handles_->size();; ++it) {
        auto region = owner_->regions.find(*it);
        if (region != owner_->regions.end() && f(&region->second)) return true;
        if (--left == 0) return false;
    }
}

}  // namespace hlacore
