// A federate's update regions (HLA 1.3 §9.6-9.7, IEEE 1516.1-2010 §9.5-9.6), kept alike by the gateway
// (server/regions.hpp, which routes with them) and the client (client/regions.cpp, which checks with them):
// object -> attribute -> regions. An attribute absent has none: it is updated in the default region.
#pragma once

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <map>
#include <set>
#include <vector>

namespace hlacore {

using AttributeRegions = std::map<std::uint32_t, std::set<std::uint32_t>>;  // attribute -> regions
using UpdateRegions = std::map<std::uint32_t, AttributeRegions>;            // object -> ...

// HLA 1.3 gives an attribute one update region, so associating replaces it; IEEE 1516-2010 several, so
// associating adds (`adds`).
inline void associate_region(UpdateRegions& associations, std::uint32_t object, std::uint32_t attribute,
                             std::uint32_t region, bool adds) {
    auto& regions = associations[object][attribute];
    if (!adds) regions.clear();
    regions.insert(region);
}

// The region leaves the regions of the object's attributes named in `only` (all of them when it is empty);
// an attribute left with none is back in the default region. Returns whether some had it.
inline bool unassociate_region(UpdateRegions& associations, std::uint32_t object, std::uint32_t region,
                               const std::vector<std::uint32_t>& only) {
    auto obj = associations.find(object);
    if (obj == associations.end()) return false;
    bool found = false;
    for (auto it = obj->second.begin(); it != obj->second.end();) {
        if (only.empty() || std::find(only.begin(), only.end(), it->first) != only.end())
            found = it->second.erase(region) > 0 || found;
        it = it->second.empty() ? obj->second.erase(it) : std::next(it);
    }
    if (obj->second.empty()) associations.erase(obj);
    return found;
}

// A deleted region leaves every association.
inline void forget_region(UpdateRegions& associations, std::uint32_t region) {
    for (auto it = associations.begin(); it != associations.end();) {
        const auto object = it++->first;  // unassociate_region may erase the object's entry
        unassociate_region(associations, object, region, {});
    }
}

}  // namespace hlacore
