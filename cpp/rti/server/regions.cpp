// Data distribution management (HLA 1.3 §9), the gateway side: regions, subscriptions and update
// associations through regions, and the overlap test that decides who receives what. The filtering is
// done here, so an update or interaction whose region misses a subscriber's never leaves the gateway.
//
// Contract (docs/ddm.md): ranges are closed ([lower, upper] with lower <= upper); two regions overlap when
// some extent of one and some extent of the other overlap in every dimension; the default region (a plain
// subscription, an unassociated attribute, an interaction sent without region) is the whole space and
// overlaps every region.
#include "rti/server/regions.hpp"
#include "rti/server/federation.hpp"
#include "rti/erase_nested.hpp"

#include <algorithm>
#include <limits>

namespace hlacore {

using wire::WireError;

// ---- the state (regions.hpp) ----

bool Region::overlaps(const Region& other) const {
    for (const auto& ea : extents) {
        for (const auto& eb : other.extents) {
            bool all = ea.size() == eb.size();
            for (std::size_t d = 0; all && d < ea.size(); ++d)
                all = ea[d].first <= eb[d].second && eb[d].first <= ea[d].second;
            if (all) return true;
        }
    }
    return false;
}

Region Region::from_bounds(const fom::Fom& fom, fom::Handle space, const wire::Handles& bounds) {
    const auto* s = fom.space(space);
    if (!s) throw WireError("routing space handle " + std::to_string(space) + " is not defined in the FOM");
    const std::size_t per_extent = 2 * s->dimensions.size();
    Region region;
    region.space = space;
    if (per_extent == 0) {
        // A space without dimensions: its one extent covers the whole (empty) space.
        if (!bounds.empty()) throw WireError("routing space '" + s->name + "' has no dimensions");
        region.extents.emplace_back();
        return region;
    }
    if (bounds.empty() || bounds.size() % per_extent != 0)
        throw WireError("region bounds do not match the dimensions of routing space '" + s->name + "'");
    for (std::size_t i = 0; i < bounds.size(); i += per_extent) {
        std::vector<Range> extent;
        for (std::size_t d = 0; d < per_extent; d += 2) {
            if (bounds[i + d] > bounds[i + d + 1]) throw WireError("region range with lower bound above upper bound");
            extent.emplace_back(bounds[i + d], bounds[i + d + 1]);
        }
        region.extents.push_back(std::move(extent));
    }
    return region;
}

const Region& FederateRegions::at(RegionHandle r) const {
    auto it = regions.find(r);
    if (it == regions.end()) throw WireError("region " + std::to_string(r) + " is not known");
    return it->second;
}

void FederateRegions::create(RegionHandle r, Region region) {
    if (r == 0 || regions.count(r)) throw WireError("region handle " + std::to_string(r) + " is 0 or already in use");
    regions[r] = std::move(region);
    last_region = std::max(last_region, r);
}

void FederateRegions::erase(RegionHandle r) {
    regions.erase(r);
    for (auto it = object_subscriptions.begin(); it != object_subscriptions.end();) {
        it->second.erase(r);
        it = it->second.empty() ? object_subscriptions.erase(it) : std::next(it);
    }
    for (auto it = interaction_subscriptions.begin(); it != interaction_subscriptions.end();) {
        it->second.erase(r);
        it = it->second.empty() ? interaction_subscriptions.erase(it) : std::next(it);
    }
    forget_region(update_regions, r);
}

SentRegions FederateRegions::update_regions_of(ObjectHandle object, fom::Handle attribute) const {
    auto obj = update_regions.find(object);
    if (obj == update_regions.end()) return {};
    auto attr = obj->second.find(attribute);
    return attr == obj->second.end() ? SentRegions{} : SentRegions{*this, attr->second};
}

bool FederateRegions::subscribed(fom::Handle known, fom::Handle attribute, const Region* updated_in) const {
    auto by_class = object_subscriptions.find(known);
    if (by_class == object_subscriptions.end()) return false;
    for (const auto& [r, attributes] : by_class->second) {
        if (!attributes.count(attribute)) continue;
        if (!updated_in) return true;  // the default region overlaps every region
        auto region = regions.find(r);
        if (region != regions.end() && region->second.overlaps(*updated_in)) return true;
    }
    return false;
}

bool FederateRegions::subscribed_interaction(fom::Handle cls, const Region* sent_in) const {
    auto by_class = interaction_subscriptions.find(cls);
    if (by_class == interaction_subscriptions.end()) return false;
    if (!sent_in) return true;
    for (RegionHandle r : by_class->second) {
        auto subscribed = regions.find(r);
        if (subscribed != regions.end() && subscribed->second.overlaps(*sent_in)) return true;
    }
    return false;
}

// ---- routing with it ----

void Federation::check_region_space(const fom::ObjectClass& cls, fom::Handle attribute, RegionHandle r,
                                    const Region& region) const {
    const auto* space = fom_.find_space(cls.attribute(attribute)->space);
    if (!space || space->handle != region.space)
        throw WireError("region " + std::to_string(r) + " is not in the routing space of attribute " +
                        std::to_string(attribute));
}

SentRegions Federation::update_regions_of(FederateHandle owner, ObjectHandle object, fom::Handle attribute) const {
    auto f = federates_.find(owner);
    return f == federates_.end() ? SentRegions{} : f->second.ddm.update_regions_of(object, attribute);
}

bool Federation::region_wanted(const FederateState& g, fom::Handle known, FederateHandle owner, ObjectHandle object,
                               fom::Handle attribute) const {
    // Without region subscriptions (no DDM in use) this is one test, and the owner is not looked up.
    if (g.ddm.object_subscriptions.empty()) return false;
    return g.ddm.subscribed(known, attribute, update_regions_of(owner, object, attribute));
}

bool Federation::discovers(FederateHandle gh, const FederateState& g, ObjectHandle object,
                           const ObjectInstance& obj) const {
    const fom::Handle known = known_class(g, obj.object_class);
    if (known == 0) return false;
    if (g.declarations.subscribed.count(known)) return true;
    for (const auto& [attr, owner] : obj.ownership.owners) {
        if (owner != gh && region_wanted(g, known, owner, object, attr)) return true;
    }
    return false;
}

fom::Handle Federation::interaction_receiver(const FederateState& g, fom::Handle cls, const SentRegions& sent_in) const {
    // Received as the nearest class through which it is in scope.
    for (fom::Handle c = cls; c != 0; c = fom_.interaction_class(c)->parent)
        if (g.declarations.subscribed_interactions.count(c) || g.ddm.subscribed_interaction(c, sent_in)) return c;
    return 0;
}

void Federation::widen_regions() {
    for (auto& [h, f] : federates_) {
        for (auto& [r, region] : f.ddm.regions) {
            const auto* space = fom_.space(region.space);
            for (auto& extent : region.extents)  // the whole axis, as the client gives a dimension not named
                while (space && extent.size() < space->dimensions.size())
                    extent.emplace_back(0, std::numeric_limits<std::uint32_t>::max());
        }
    }
}

void Federation::discover_in_scope() {
    for (auto& [h, f] : federates_) discover_all_for(h);
}

std::set<fom::Handle> Federation::scope_of(FederateHandle gh, const FederateState& g, ObjectHandle object,
                                           const ObjectInstance& obj) const {
    std::set<fom::Handle> scope;
    const fom::Handle known = known_class(g, obj.object_class);
    if (known == 0) return scope;
    auto plain = g.declarations.subscribed.find(known);
    for (const auto& [attr, owner] : obj.ownership.owners) {
        if (owner == gh) continue;
        if ((plain != g.declarations.subscribed.end() && plain->second.count(attr)) || region_wanted(g, known, owner, object, attr))
            scope.insert(attr);
    }
    return scope;
}

namespace {

// Sends `M` (AttributesInScope/OutOfScope, TurnUpdatesOn/Off) for each object's attributes in `from`
// missing from `to`, where keep(object, attribute) still allows a notice.
template <class M, class Keep>
void send_difference(Outbox& outbox, FederateHandle federate,
                     const std::map<std::uint32_t, std::set<fom::Handle>>& from,
                     const std::map<std::uint32_t, std::set<fom::Handle>>& to, Keep keep) {
    for (const auto& [object, attrs] : from) {
        auto other = to.find(object);
        M notice;
        notice.object = object;
        for (auto attr : attrs)
            if ((other == to.end() || !other->second.count(attr)) && keep(object, attr)) notice.attributes.push_back(attr);
        if (!notice.attributes.empty()) outbox.send(federate, notice);
    }
}

}  // namespace

// Scope (and so relevance) changes with subscriptions, regions, associations, ownership, discovery and
// deletion; recomputing it for the federates that asked is simpler than following each of those. It runs
// after every message: with no switch on (the default) it returns at once.
void Federation::refresh_scope() {
    if (scope_watchers_ == 0) return;
    bool scope_wanted = false;
    bool relevance_wanted = false;
    for (auto& [h, f] : federates_) {
        if (!f.declarations.attribute_scope) f.ddm.in_scope.clear();
        if (!f.declarations.attribute_relevance) f.ddm.relevant.clear();
        scope_wanted = scope_wanted || f.declarations.attribute_scope;
        relevance_wanted = relevance_wanted || f.declarations.attribute_relevance;
    }
    if (!scope_wanted && !relevance_wanted) return;
    using Scopes = std::map<ObjectHandle, std::set<fom::Handle>>;
    std::map<FederateHandle, Scopes> relevant;  // owner -> what some other federate has in scope
    for (auto& [gh, g] : federates_) {
        if (!g.declarations.attribute_scope && !relevance_wanted) continue;
        Scopes now;
        for (ObjectHandle oh : g.known) {
            auto obj = objects_.find(oh);
            if (obj == objects_.end()) continue;
            auto scope = scope_of(gh, g, oh, obj->second);
            for (auto attr : scope) relevant[obj->second.ownership.owners.at(attr)][oh].insert(attr);
            if (!scope.empty()) now[oh] = std::move(scope);
        }
        if (!g.declarations.attribute_scope) continue;
        // No out-of-scope notice for an object removed or forgotten meanwhile.
        const auto& known = g.known;  // C++17 lambdas cannot capture structured bindings (clang refuses)
        send_difference<wire::AttributesOutOfScope>(outbox_, gh, g.ddm.in_scope, now,
                                                    [&](ObjectHandle oh, fom::Handle) { return known.count(oh) > 0; });
        send_difference<wire::AttributesInScope>(outbox_, gh, now, g.ddm.in_scope,
                                                 [](ObjectHandle, fom::Handle) { return true; });
        g.ddm.in_scope = std::move(now);
    }
    if (!relevance_wanted) return;
    for (auto& [ph, p] : federates_) {
        if (!p.declarations.attribute_relevance) continue;
        Scopes& now = relevant[ph];
        // turnUpdatesOff only for attributes the federate still owns.
        const FederateHandle owner_handle = ph;
        auto owned = [&](ObjectHandle oh, fom::Handle attr) {
            auto obj = objects_.find(oh);
            if (obj == objects_.end()) return false;
            auto owner = obj->second.ownership.owners.find(attr);
            return owner != obj->second.ownership.owners.end() && owner->second == owner_handle;
        };
        send_difference<wire::TurnUpdatesOff>(outbox_, ph, p.ddm.relevant, now, owned);
        send_difference<wire::TurnUpdatesOn>(outbox_, ph, now, p.ddm.relevant,
                                             [](ObjectHandle, fom::Handle) { return true; });
        p.ddm.relevant = std::move(now);
    }
}

void Federation::count_scope_watchers() {
    scope_watchers_ = 0;
    for (auto& [h, f] : federates_) {
        if (!f.declarations.attribute_scope) f.ddm.in_scope.clear();
        if (!f.declarations.attribute_relevance) f.ddm.relevant.clear();
        if (f.declarations.attribute_scope || f.declarations.attribute_relevance) ++scope_watchers_;
    }
}

void Federation::forget_update_regions(ObjectHandle object) {
    for (auto& [h, f] : federates_) f.ddm.update_regions.erase(object);
}

std::pair<ObjectHandle, std::string> Federation::register_object_with_region(FederateHandle h,
                                                                             const wire::RegisterObjectWithRegion& m) {
    auto& f = federate(h);
    const auto& cls = object_class(m.object_class);
    if (m.attributes.size() != m.regions.size()) throw WireError("as many regions as attributes are required");
    check_attributes(cls, m.attributes);
    // An attribute named with several regions has them all (IEEE 1516-2010; HLA 1.3's clients send one).
    AttributeRegions associations;
    for (std::size_t i = 0; i < m.attributes.size(); ++i) {
        check_region_space(cls, m.attributes[i], m.regions[i], f.ddm.at(m.regions[i]));
        associations[m.attributes[i]].insert(m.regions[i]);
    }
    // register_object discovers the instance at once: the associations must be there under the handle it
    // is about to give (handles are never reused), and go if the registration is refused.
    const ObjectHandle next = next_object_;
    if (!associations.empty()) f.ddm.update_regions[next] = std::move(associations);
    try {
        return register_object(h, m.object_class, m.name);
    } catch (...) {
        f.ddm.update_regions.erase(next);
        throw;
    }
}

void Federation::on(FederateHandle from, const wire::CreateRegion& m) {
    federate(from).ddm.create(m.region, Region::from_bounds(fom_, m.space, m.bounds));
}

// §9.3: from now on, routing uses the new extents; instances that come into scope are discovered.
void Federation::on(FederateHandle from, const wire::ModifyRegion& m) {
    auto& f = federate(from);
    const fom::Handle space = f.ddm.at(m.region).space;
    f.ddm.regions[m.region] = Region::from_bounds(fom_, space, m.bounds);
    discover_in_scope();
}

// §9.4: the client refuses a region in use (RegionInUse); here whatever still refers to it goes with it.
void Federation::on(FederateHandle from, const wire::DeleteRegion& m) {
    auto& f = federate(from);
    f.ddm.at(m.region);
    f.ddm.erase(m.region);
    update_advisories();
}

// §9.6: HLA 1.3 gives an attribute one update region per federate, so associating replaces the previous
// one; IEEE 1516-2010 several, so associating adds (`adds`).
void Federation::on(FederateHandle from, const wire::AssociateRegion& m) {
    auto& f = federate(from);
    const Region& region = f.ddm.at(m.region);
    auto obj = objects_.find(m.object);
    if (obj == objects_.end()) return;  // deleted meanwhile
    const auto& cls = object_class(obj->second.object_class);
    check_attributes(cls, m.attributes);
    for (auto attr : m.attributes) check_region_space(cls, attr, m.region, region);
    for (auto attr : m.attributes) associate_region(f.ddm.update_regions, m.object, attr, m.region, m.adds);
    discover_in_scope();
}

// §9.7: the object's attributes (those named, or all: HLA 1.3) are no longer updated in this region; one
// left with no region is back in the default region.
void Federation::on(FederateHandle from, const wire::UnassociateRegion& m) {
    auto& f = federate(from);
    f.ddm.at(m.region);
    if (unassociate_region(f.ddm.update_regions, m.object, m.region, m.attributes)) discover_in_scope();
}

// §9.8: the attribute set replaces the previous one for this class and region; an empty one unsubscribes.
void Federation::on(FederateHandle from, const wire::SubscribeObjectClassWithRegion& m) {
    auto& f = federate(from);
    const Region& region = f.ddm.at(m.region);
    const auto& cls = object_class(m.object_class);
    check_attributes(cls, m.attributes);
    for (auto attr : m.attributes) check_region_space(cls, attr, m.region, region);
    if (m.attributes.empty()) {
        erase_nested(f.ddm.object_subscriptions, m.object_class, m.region);
    } else {
        f.ddm.object_subscriptions[m.object_class][m.region] = std::set<fom::Handle>(m.attributes.begin(), m.attributes.end());
        discover_all_for(from);
    }
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::UnsubscribeObjectClassWithRegion& m) {
    object_class(m.object_class);
    auto& ddm = federate(from).ddm;
    if (ddm.unsubscribe(ddm.object_subscriptions, m.object_class, m.region)) update_advisories();
}

const Region& Federation::interaction_region(const FederateState& f, RegionHandle r,
                                                         fom::Handle cls) const {
    const Region& region = f.ddm.at(r);
    const auto& ic = interaction_class(cls);
    const auto* space = fom_.find_space(ic.space);
    if (!space || space->handle != region.space)
        throw WireError("region " + std::to_string(r) + " is not in the routing space of interaction '" +
                        ic.qualified_name + "'");
    return region;
}

void Federation::on(FederateHandle from, const wire::SubscribeInteractionClassWithRegion& m) {
    auto& f = federate(from);
    interaction_region(f, m.region, m.interaction_class);
    f.ddm.interaction_subscriptions[m.interaction_class].insert(m.region);
    update_advisories();
}

void Federation::on(FederateHandle from, const wire::UnsubscribeInteractionClassWithRegion& m) {
    interaction_class(m.interaction_class);
    auto& ddm = federate(from).ddm;
    if (ddm.unsubscribe(ddm.interaction_subscriptions, m.interaction_class, m.region)) update_advisories();
}

// §9.12: reaches the plain subscribers and, once, those whose subscription regions overlap any of `regions`
// (none: the default region).
void Federation::on(FederateHandle from, const wire::SendInteractionWithRegion& m) {
    FederateState& f = federate(from);
    ++f.interactions_sent;
    for (RegionHandle r : m.regions) interaction_region(f, r, m.interaction_class);
    const std::set<RegionHandle> regions(m.regions.begin(), m.regions.end());
    route_interaction(from, wire::SendInteractionView{m.interaction_class, wire::views_of(m.values), m.tag, m.time, m.serial},
                      SentRegions{f.ddm, regions});
}

// §9.13: the owners of attributes whose update region overlaps `region` are asked to provide them.
void Federation::on(FederateHandle from, const wire::RequestClassUpdateWithRegion& m) {
    request_class_update(from, m.object_class, m.attributes, &federate(from).ddm.at(m.region));
}

}  // namespace hlacore
