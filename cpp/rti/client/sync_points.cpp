// Synchronization points (HLA 1.3 §4.6-4.10), the federate side: announcements are kept as they are popped.
#include "rti/client/client.hpp"

namespace hlacore {

void Client::register_sync_point(const std::string& label, const std::string& tag,
                                 const std::optional<std::vector<std::uint32_t>>& federates) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    send(wire::RegisterSyncPoint{label, tag, !federates.has_value(), federates.value_or(wire::Handles{})});
}

void Client::sync_point_achieved(const std::string& label) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
        if (!announced_.count(label))
            raise(ErrorCode::SynchronizationPointLabelWasNotAnnounced,
                  "synchronization point '" + label + "' was not announced to this federate");
    }
    send(wire::SyncPointAchieved{label});
}

}  // namespace hlacore
