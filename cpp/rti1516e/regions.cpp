// Data distribution management (IEEE 1516.1-2010 §9) on the core's HLA 1.3 routing spaces, as
// hlacore.rti1516e serves it: the FOM modules' dimensions are one space (fom::kOmtSpace), a region's range
// [lower, upper) is the core's closed [lower, upper - 1], and a dimension a region does not name spans its
// whole axis. An attribute of an object is updated in several regions and an interaction sent in several:
// a subscriber receives it, once, when one of its regions overlaps one of them.
#include "ambassador.hpp"
#include "fed_parser/fom.hpp"

namespace hlacore::rti1516e {

std::uint32_t Ambassador::space() const {
    try {
        return client().routing_space_handle(fom::kOmtSpace);
    } catch (const RtiError&) {
        raise("InvalidDimensionHandle", "the FOM modules declare no dimension");
    }
}

std::map<std::uint32_t, RangeBounds>& Ambassador::region(RegionHandle const& r) {
    const auto it = regions_.find(core(r));
    if (it == regions_.end()) raise("RegionNotCreatedByThisFederate", utf8(r.toString()));
    return it->second;
}

Client::Extent Ambassador::extent(std::map<std::uint32_t, RangeBounds> const& ranges) const {
    Client::Extent out;
    for (const auto& [d, b] : ranges)
        out.push_back({d, static_cast<std::int64_t>(b.getLowerBound()), static_cast<std::int64_t>(b.getUpperBound()) - 1});
    return out;
}

std::vector<std::pair<wire::Handles, std::uint32_t>> Ambassador::region_pairs(
    AttributeHandleSetRegionHandleSetPairVector const& pairs) {
    std::vector<std::pair<wire::Handles, std::uint32_t>> out;
    for (const auto& [attributes, regions] : pairs)
        for (auto r : regions_of(regions)) out.emplace_back(cores(attributes), r);
    return out;
}

wire::Handles Ambassador::regions_of(RegionHandleSet const& regions) {
    wire::Handles out;
    for (const auto& r : regions) {
        region(r);
        out.push_back(core(r));
    }
    return out;
}

DimensionHandleSet Ambassador::dimensions_of(std::uint32_t space_handle) const {
    DimensionHandleSet found;
    if (space_handle == 0) return found;
    try {
        if (space_handle != space()) return found;
    } catch (const Exception&) {
        return found;
    }
    for (std::uint32_t d = 1;; ++d) {
        try {
            client().dimension_name(d, space_handle);
        } catch (const RtiError&) {
            return found;
        }
        found.insert(handle<DimensionHandle>(d));
    }
}

DimensionHandle Ambassador::getDimensionHandle(std::wstring const& name) {
    return guarded([&] { return handle<DimensionHandle>(client().dimension_handle(utf8(name), space())); });
}

std::wstring Ambassador::getDimensionName(DimensionHandle d) {
    return guarded([&] { return wide(client().dimension_name(core(d), space())); });
}

unsigned long Ambassador::getDimensionUpperBound(DimensionHandle d) {
    return guarded([&] { return static_cast<unsigned long>(client().dimension_upper_bound(core(d), space())); });
}

DimensionHandleSet Ambassador::getAvailableDimensionsForClassAttribute(ObjectClassHandle cls, AttributeHandle a) {
    return guarded([&] { return dimensions_of(client().attribute_routing_space(core(a), core(cls))); });
}

DimensionHandleSet Ambassador::availableDimensionsForObjectClass(ObjectClassHandle cls) {
    return guarded([&] {
        DimensionHandleSet out;
        for (auto space : client().attribute_routing_spaces(core(cls))) {
            const auto dimensions = dimensions_of(space);
            out.insert(dimensions.begin(), dimensions.end());
        }
        return out;
    });
}

DimensionHandleSet Ambassador::getAvailableDimensionsForInteractionClass(InteractionClassHandle cls) {
    return guarded([&] { return dimensions_of(client().interaction_routing_space(core(cls))); });
}

RegionHandle Ambassador::createRegion(DimensionHandleSet const& dimensions) {
    return guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        const std::uint32_t s = space();
        std::map<std::uint32_t, RangeBounds> ranges;
        for (const auto& d : dimensions)  // each range its whole axis until set
            ranges[core(d)] = RangeBounds(0, static_cast<unsigned long>(client().dimension_upper_bound(core(d), s)));
        const std::uint32_t r = client().create_region(s, extent(ranges));
        regions_[r] = std::move(ranges);
        return handle<RegionHandle>(r);
    });
}

void Ambassador::commitRegionModifications(RegionHandleSet const& regions) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        for (const auto& r : regions) client().modify_region(core(r), extent(region(r)));
    });
}

void Ambassador::deleteRegion(RegionHandle const& r) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        region(r);
        client().delete_region(core(r));
        regions_.erase(core(r));
    });
}

DimensionHandleSet Ambassador::getDimensionHandleSet(RegionHandle r) {
    return guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        DimensionHandleSet out;
        for (const auto& [d, b] : region(r)) out.insert(handle<DimensionHandle>(d));
        return out;
    });
}

RangeBounds Ambassador::getRangeBounds(RegionHandle r, DimensionHandle d) {
    return guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        const auto& ranges = region(r);
        const auto it = ranges.find(core(d));
        if (it == ranges.end()) raise("RegionDoesNotContainSpecifiedDimension", utf8(d.toString()));
        return it->second;
    });
}

void Ambassador::setRangeBounds(RegionHandle r, DimensionHandle d, RangeBounds const& bounds) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        getRangeBounds(r, d);
        const unsigned long upper = getDimensionUpperBound(d);
        if (!(bounds.getLowerBound() < bounds.getUpperBound() && bounds.getUpperBound() <= upper))
            raise("InvalidRangeBound", "[" + std::to_string(bounds.getLowerBound()) + ", " +
                                           std::to_string(bounds.getUpperBound()) + ") is not within [0, " +
                                           std::to_string(upper) + ") with lower < upper");
        region(r)[core(d)] = bounds;  // sent by commitRegionModifications
    });
}

ObjectInstanceHandle Ambassador::registerObjectInstanceWithRegions(ObjectClassHandle cls,
                                                                   AttributeHandleSetRegionHandleSetPairVector const& regions) {
    return guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        std::vector<std::pair<fom::Handle, std::uint32_t>> associated;
        for (const auto& [attributes, r] : region_pairs(regions))
            for (auto a : attributes) associated.emplace_back(a, r);
        return handle<ObjectInstanceHandle>(client().register_object_with_region(core(cls), associated, "", true));
    });
}

ObjectInstanceHandle Ambassador::registerObjectInstanceWithRegions(ObjectClassHandle cls,
                                                                   AttributeHandleSetRegionHandleSetPairVector const& regions,
                                                                   std::wstring const& name) {
    return guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        require_reserved(name);
        std::vector<std::pair<fom::Handle, std::uint32_t>> associated;
        for (const auto& [attributes, r] : region_pairs(regions))
            for (auto a : attributes) associated.emplace_back(a, r);
        const auto object = client().register_object_with_region(core(cls), associated, utf8(name), true);
        reserved_.erase(name);
        return handle<ObjectInstanceHandle>(object);
    });
}

void Ambassador::associateRegionsForUpdates(ObjectInstanceHandle object,
                                            AttributeHandleSetRegionHandleSetPairVector const& regions) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        for (const auto& [attributes, r] : region_pairs(regions))  // adds: the attributes keep their other regions
            client().request(wire::AssociateRegion{r, core(object), attributes, true});
    });
}

void Ambassador::unassociateRegionsForUpdates(ObjectInstanceHandle object,
                                              AttributeHandleSetRegionHandleSetPairVector const& regions) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        for (const auto& [attributes, r] : region_pairs(regions))
            if (!attributes.empty())  // no attributes on the wire would be all of them (HLA 1.3)
                client().request(wire::UnassociateRegion{r, core(object), attributes});
    });
}

void Ambassador::subscribeObjectClassAttributesWithRegions(ObjectClassHandle cls,
                                                           AttributeHandleSetRegionHandleSetPairVector const& regions,
                                                           bool active, std::wstring const& rate) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        client().request(wire::SubscriptionRate{core(cls), utf8(rate)});
        for (const auto& [attributes, set] : regions)
            for (const auto& r : set) {
                region(r);
                client().request(wire::SubscribeObjectClassWithRegion{core(cls), core(r), cores(attributes), active});
            }
    });
}

// The core drops a region's attributes of a class all together.
void Ambassador::unsubscribeObjectClassAttributesWithRegions(ObjectClassHandle cls,
                                                             AttributeHandleSetRegionHandleSetPairVector const& regions) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        for (const auto& [attributes, set] : regions)
            for (const auto& r : set) {
                region(r);
                client().request(wire::UnsubscribeObjectClassWithRegion{core(cls), core(r)});
            }
    });
}

void Ambassador::subscribeInteractionClassWithRegions(InteractionClassHandle cls, RegionHandleSet const& regions,
                                                      bool active) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        for (const auto& r : regions) {
            region(r);
            client().request(wire::SubscribeInteractionClassWithRegion{core(cls), core(r), active});
        }
    });
}

void Ambassador::unsubscribeInteractionClassWithRegions(InteractionClassHandle cls, RegionHandleSet const& regions) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        for (const auto& r : regions) {
            region(r);
            client().request(wire::UnsubscribeInteractionClassWithRegion{core(cls), core(r)});
        }
    });
}

void Ambassador::sendInteractionWithRegions(InteractionClassHandle cls, ParameterHandleValueMap const& values,
                                            RegionHandleSet const& regions, VariableLengthData const& tag) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        client().send_interaction_with_region(core(cls), copies(values), regions_of(regions), bytes(tag), std::nullopt);
    });
}

MessageRetractionHandle Ambassador::sendInteractionWithRegions(InteractionClassHandle cls,
                                                               ParameterHandleValueMap const& values,
                                                               RegionHandleSet const& regions,
                                                               VariableLengthData const& tag, LogicalTime const& time) {
    return guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        Client& c = client();
        return retraction(c.federate_handle(), c.send_interaction_with_region(core(cls), copies(values), regions_of(regions),
                                                                             bytes(tag), time_in(time)));
    });
}

void Ambassador::requestAttributeValueUpdateWithRegions(ObjectClassHandle cls,
                                                        AttributeHandleSetRegionHandleSetPairVector const& regions,
                                                        VariableLengthData const&) {
    guarded([&] {
        std::lock_guard<std::recursive_mutex> lock(mu_);
        for (const auto& [attributes, set] : regions)
            for (const auto& r : set) {
                region(r);
                client().request(wire::RequestClassUpdateWithRegion{core(cls), cores(attributes), core(r)});
            }
    });
}

}  // namespace hlacore::rti1516e
