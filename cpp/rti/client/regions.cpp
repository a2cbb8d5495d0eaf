// The federate side of data distribution management (HLA 1.3 §9): regions are created and numbered here,
// every service checks HLA 1.3's exceptions against this federate's regions, subscriptions and
// associations, and the gateway does the routing (server/regions.cpp).
#include <algorithm>
#include <atomic>

#include "rti/client/client.hpp"
#include "rti/erase_nested.hpp"

namespace hlacore {

namespace {

std::string region_text(std::uint32_t region) { return "region " + std::to_string(region); }

// unsubscribe...WithRegion: the class's subscription through the region goes, refused with `code` when it had none.
template <class Subscriptions, class Class>
void unsubscribe_through(Subscriptions& subscriptions, const Class& cls, const char* kind, std::uint32_t region,
                         ErrorCode code) {
    if (!erase_nested(subscriptions, cls.handle, region))
        raise(code, std::string(kind) + " '" + cls.qualified_name + "' is not subscribed with " + region_text(region));
}

// Region numbers are unique in the process, not only per federate: a RegionHandle of another ambassador
// then raises RegionNotKnown instead of naming this federate's region of the same number.
std::atomic<std::uint32_t> last_region_number{0};

std::uint32_t next_region_number() { return ++last_region_number; }

// A restored federate keeps its saved region numbers; new regions are numbered above them (and above
// any the federate had before the save) even in a process that never created them.
void reserve_region_numbers(std::uint32_t up_to) {
    std::uint32_t last = last_region_number.load();
    while (last < up_to && !last_region_number.compare_exchange_weak(last, up_to)) {
    }
}

}  // namespace

// ---- checks ----

const Client::LocalRegion& Client::known_region(std::uint32_t region) const {
    require_joined();
    auto it = ddm_.regions.find(region);
    if (it == ddm_.regions.end()) raise(ErrorCode::RegionNotKnown, region_text(region) + " is not known");
    return it->second;
}

wire::Handles Client::region_bounds(fom::Handle space, const Extent& extent) const {
    const auto* s = fom_->space(space);
    if (!s) raise(ErrorCode::SpaceNotDefined, "routing space handle " + std::to_string(space) + " is not defined");
    // Dimensions not given span the whole axis.
    wire::Handles bounds;
    for (std::size_t d = 0; d < s->dimensions.size(); ++d) {
        bounds.push_back(static_cast<std::uint32_t>(kMinExtent));
        bounds.push_back(static_cast<std::uint32_t>(kMaxExtent));
    }
    std::set<fom::Handle> given;
    for (const auto& range : extent) {
        const auto* dim = s->dimension(range.dimension);
        if (!dim)
            raise(ErrorCode::DimensionNotDefined, "dimension handle " + std::to_string(range.dimension) +
                                                      " is not defined in routing space '" + s->name + "'");
        if (!given.insert(range.dimension).second)
            raise(ErrorCode::InvalidExtents, "dimension '" + dim->name + "' is given twice");
        if (range.lower < kMinExtent || range.upper > kMaxExtent || range.lower > range.upper)
            raise(ErrorCode::InvalidExtents, "range [" + std::to_string(range.lower) + ", " +
                                                 std::to_string(range.upper) + "] of dimension '" + dim->name +
                                                 "' is not within [MIN_EXTENT, MAX_EXTENT] with lower <= upper");
        const auto i = 2 * static_cast<std::size_t>(dim - s->dimensions.data());
        bounds[i] = static_cast<std::uint32_t>(range.lower);
        bounds[i + 1] = static_cast<std::uint32_t>(range.upper);
    }
    return bounds;
}

void Client::check_region_space(const LocalRegion& region, const fom::ObjectClass& cls, fom::Handle attribute) const {
    const auto* a = cls.attribute(attribute);
    const auto* s = a && !a->space.empty() ? fom_->find_space(a->space) : nullptr;
    if (!s || s->handle != region.space)
        raise(ErrorCode::InvalidRegionContext,
              "attribute '" + (a ? a->name : std::to_string(attribute)) + "' of class '" + cls.qualified_name +
                  "' is not in the region's routing space '" + fom_->space(region.space)->name + "'");
}

// Used by a subscription, or by an update association of an object this federate still knows.
bool Client::region_in_use(std::uint32_t region) const {
    for (const auto& [cls, by_region] : ddm_.object_subscriptions)
        if (by_region.count(region)) return true;
    for (const auto& [cls, regions] : ddm_.interaction_subscriptions)
        if (regions.count(region)) return true;
    for (const auto& [object, associations] : ddm_.update_regions) {
        if (!objects_.count(object)) continue;
        for (const auto& [attr, regions] : associations)
            if (regions.count(region)) return true;
    }
    return false;
}

// ---- restore (HLA 1.3 §4.20; client/save_restore.cpp) ----

// During a restore the gateway ignores what a federate sends until it answers initiateFederateRestore,
// and the restore replaces this federate's regions: a region change made meanwhile would leave the two
// tables apart (and a later use of the region would get the federate dropped), so it is refused.
void Client::refuse_region_change_while_restoring(const char* service) const {
    if (save_restore_.restore != RestorePhase::None)
        raise(ErrorCode::RestoreInProgress, std::string(service) + " refused: a federation restore is in progress "
                                                                   "(until federationRestored or federationNotRestored)");
}

void Client::widen_regions() {
    for (auto& [handle, r] : ddm_.regions) {
        const auto* s = fom_->space(r.space);
        while (s && r.bounds.size() < 2 * s->dimensions.size()) {
            r.bounds.push_back(static_cast<std::uint32_t>(kMinExtent));
            r.bounds.push_back(static_cast<std::uint32_t>(kMaxExtent));
        }
    }
}

void Client::restore_regions(const wire::RestoredState& saved) {
    ddm_ = DdmState{};
    for (const auto& [region, space, bounds] : saved.regions) ddm_.regions[region] = LocalRegion{space, bounds};
    for (const auto& [cls, region, attrs] : saved.region_subscriptions)
        ddm_.object_subscriptions[cls][region] = std::set<fom::Handle>(attrs.begin(), attrs.end());
    for (const auto& [ic, region] : saved.region_interaction_subscriptions) ddm_.interaction_subscriptions[ic].insert(region);
    for (const auto& [object, attribute, region] : saved.update_regions) ddm_.update_regions[object][attribute].insert(region);
    reserve_region_numbers(saved.last_region);
}

// ---- regions (HLA 1.3 §9.2-9.4) ----

std::uint32_t Client::create_region(fom::Handle space, const Extent& extent) {
    std::uint32_t region;
    wire::Handles bounds;
    {
        std::lock_guard<std::mutex> lock(mu_);
        refuse_region_change_while_restoring("createRegion");
        require_joined();
        bounds = region_bounds(space, extent);
        region = next_region_number();
        ddm_.regions[region] = LocalRegion{space, bounds};
    }
    send(wire::CreateRegion{region, space, std::move(bounds)});
    return region;
}

void Client::modify_region(std::uint32_t region, const std::optional<Extent>& extent) {
    wire::Handles bounds;
    {
        std::lock_guard<std::mutex> lock(mu_);
        refuse_region_change_while_restoring("notifyAboutRegionModification");
        const LocalRegion& r = known_region(region);
        if (extent) {
            bounds = region_bounds(r.space, *extent);
            ddm_.regions[region].bounds = bounds;
        } else {
            bounds = r.bounds;
        }
    }
    send(wire::ModifyRegion{region, std::move(bounds)});
}

void Client::delete_region(std::uint32_t region) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        refuse_region_change_while_restoring("deleteRegion");
        known_region(region);
        if (region_in_use(region))
            raise(ErrorCode::RegionInUse, region_text(region) + " is used by a subscription or an update association");
        ddm_.regions.erase(region);
        forget_region(ddm_.update_regions, region);
    }
    send(wire::DeleteRegion{region});
}

std::pair<fom::Handle, Client::Extent> Client::region_extent(std::uint32_t region) const {
    std::lock_guard<std::mutex> lock(mu_);
    const LocalRegion& r = known_region(region);
    const auto* s = fom_->space(r.space);
    Extent extent;
    for (std::size_t d = 0; d < s->dimensions.size(); ++d)
        extent.push_back(Range{s->dimensions[d].handle, r.bounds[2 * d], r.bounds[2 * d + 1]});
    return {r.space, extent};
}

std::vector<std::uint32_t> Client::regions() const {
    std::lock_guard<std::mutex> lock(mu_);
    std::vector<std::uint32_t> handles;
    for (const auto& [handle, region] : ddm_.regions) handles.push_back(handle);
    return handles;
}

// ---- update regions (HLA 1.3 §9.5-9.7) ----

std::uint32_t Client::register_object_with_region(fom::Handle cls,
                                                  const std::vector<std::pair<fom::Handle, std::uint32_t>>& regions,
                                                  const std::string& name, bool adds) {
    std::set<fom::Handle> owned;
    wire::Handles attributes, region_handles;
    {
        std::lock_guard<std::mutex> lock(mu_);
        check_not_saving_or_restoring("registerObjectInstanceWithRegion");
        const auto& c = defined_object_class(cls);
        auto published = declarations_.published.find(cls);
        if (published == declarations_.published.end())
            raise(ErrorCode::ObjectClassNotPublished, "object class '" + c.qualified_name + "' is not published");
        for (const auto& [attr, region] : regions) {
            check_attributes(c, {attr});
            if (!published->second.count(attr))
                raise(ErrorCode::AttributeNotPublished,
                      "attribute '" + c.attribute(attr)->name + "' of class '" + c.qualified_name + "' is not published");
            check_region_space(known_region(region), c, attr);
            // HLA 1.3: an attribute named again takes this region instead.
            const auto again = std::find(attributes.begin(), attributes.end(), attr);
            if (!adds && again != attributes.end()) {
                region_handles[static_cast<std::size_t>(again - attributes.begin())] = region;
                continue;
            }
            attributes.push_back(attr);
            region_handles.push_back(region);
        }
        owned = published->second;
    }
    const auto id = next_request();
    auto registered =
        call<wire::ObjectRegistered>(wire::RegisterObjectWithRegion{id, cls, name, attributes, region_handles}, id);
    std::lock_guard<std::mutex> lock(mu_);
    add_registered(registered.object, cls, registered.name, std::move(owned));
    for (std::size_t i = 0; i < attributes.size(); ++i)
        associate_region(ddm_.update_regions, registered.object, attributes[i], region_handles[i], true);
    return registered.object;
}

void Client::check(const wire::AssociateRegion& m) {
    refuse_region_change_while_restoring("associateRegionForUpdates");
    const LocalObject& obj = known_object(m.object);
    const auto& cls = *fom_->object_class(obj.object_class);
    check_attributes(cls, m.attributes);
    const LocalRegion& r = known_region(m.region);
    for (auto attr : m.attributes) check_region_space(r, cls, attr);
    for (auto attr : m.attributes) associate_region(ddm_.update_regions, m.object, attr, m.region, m.adds);
}

// HLA 1.3 (no attributes named) refuses a region the object's attributes are not associated with; IEEE
// 1516-2010 (these attributes) has no such exception: a pair not associated is left as it is.
void Client::check(const wire::UnassociateRegion& m) {
    refuse_region_change_while_restoring("unassociateRegionForUpdates");
    const LocalObject& obj = known_object(m.object);
    check_attributes(*fom_->object_class(obj.object_class), m.attributes);
    known_region(m.region);
    if (!unassociate_region(ddm_.update_regions, m.object, m.region, m.attributes) && m.attributes.empty())
        raise(ErrorCode::InvalidRegionContext,
              region_text(m.region) + " is not associated with attributes of object '" + obj.name + "'");
}

// ---- subscriptions through regions (HLA 1.3 §9.8-9.11) ----

void Client::check(const wire::SubscribeObjectClassWithRegion& m) {
    refuse_region_change_while_restoring("subscribeObjectClassAttributesWithRegion");
    const auto& c = defined_object_class(m.object_class);
    check_attributes(c, m.attributes);
    const LocalRegion& r = known_region(m.region);
    for (auto attr : m.attributes) check_region_space(r, c, attr);
    if (m.attributes.empty()) {
        erase_nested(ddm_.object_subscriptions, m.object_class, m.region);
    } else {
        ddm_.object_subscriptions[m.object_class][m.region] = std::set<fom::Handle>(m.attributes.begin(), m.attributes.end());
    }
}

void Client::check(const wire::UnsubscribeObjectClassWithRegion& m) {
    refuse_region_change_while_restoring("unsubscribeObjectClassWithRegion");
    const auto& c = defined_object_class(m.object_class);
    known_region(m.region);
    unsubscribe_through(ddm_.object_subscriptions, c, "object class", m.region, ErrorCode::ObjectClassNotSubscribed);
}

void Client::check_interaction_region(const fom::InteractionClass& c, std::uint32_t region) const {
    const LocalRegion& r = known_region(region);
    const auto* s = c.space.empty() ? nullptr : fom_->find_space(c.space);
    if (!s || s->handle != r.space)
        raise(ErrorCode::InvalidRegionContext, "interaction class '" + c.qualified_name +
                                                   "' is not in the region's routing space '" +
                                                   fom_->space(r.space)->name + "'");
}

void Client::check(const wire::SubscribeInteractionClassWithRegion& m) {
    refuse_region_change_while_restoring("subscribeInteractionClassWithRegion");
    check_interaction_region(defined_interaction_class(m.interaction_class), m.region);
    ddm_.interaction_subscriptions[m.interaction_class].insert(m.region);
}

void Client::check(const wire::UnsubscribeInteractionClassWithRegion& m) {
    refuse_region_change_while_restoring("unsubscribeInteractionClassWithRegion");
    const auto& c = defined_interaction_class(m.interaction_class);
    known_region(m.region);
    unsubscribe_through(ddm_.interaction_subscriptions, c, "interaction class", m.region,
                        ErrorCode::InteractionClassNotSubscribed);
}

// ---- sending and requesting through regions (HLA 1.3 §9.12-9.13) ----

std::uint64_t Client::send_interaction_with_region(fom::Handle cls, wire::HandleValues values, wire::Handles regions,
                                                   const std::string& tag, wire::OptionalTime time) {
    wire::SendInteractionWithRegion interaction{cls, std::move(values), tag, time, 0, std::move(regions)};
    {
        std::lock_guard<std::mutex> lock(mu_);
        check_not_saving_or_restoring("sendInteractionWithRegion");
        const auto& c = check_sendable(cls, interaction.values);
        for (auto region : interaction.regions) check_interaction_region(c, region);
        check_forwardable(interaction, "sendInteractionWithRegion");
        interaction.serial = next_serial(time);
    }
    send(interaction);
    return interaction.serial;
}

void Client::check(const wire::RequestClassUpdateWithRegion& m) {
    check_attributes(defined_object_class(m.object_class), m.attributes);
    known_region(m.region);
}

}  // namespace hlacore
