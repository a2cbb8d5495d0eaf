#include "rti/server/update_rates.hpp"

#include <limits>

namespace hlacore {

void UpdateRateLimits::set(fom::Handle object_class, double rate) {
    if (rate > 0)
        interval_[object_class] = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate));
    else
        interval_.erase(object_class);
}

bool UpdateRateLimits::due(fom::Handle object_class, std::uint32_t object, fom::Handle attribute) {
    const auto interval = interval_.find(object_class);
    if (interval == interval_.end()) return true;
    const auto now = Clock::now();
    const auto [last, first] = sent_.try_emplace({object, attribute}, now);
    if (first) return true;
    if (now - last->second < interval->second) return false;
    last->second = now;
    return true;
}

void UpdateRateLimits::forget(std::uint32_t object) {
    sent_.erase(sent_.lower_bound({object, 0}), sent_.upper_bound({object, std::numeric_limits<fom::Handle>::max()}));
}

}  // namespace hlacore
