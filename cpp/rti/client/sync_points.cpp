// Synchronization points (HLA 1.3 §4.6-4.10), the federate side: announcements are kept as they are popped.
#include "rti/client/client.hpp"

namespace hlacore {

void Client::check(const wire::RegisterSyncPoint&) { require_joined(); }

void Client::check(const wire::SyncPointAchieved& m) {
    require_joined();
    if (!announced_.count(m.label))
        raise(ErrorCode::SynchronizationPointLabelWasNotAnnounced,
              "synchronization point '" + m.label + "' was not announced to this federate");
}

// The labels announced and not yet synchronized, known at once (achieving one checks against them).
bool Client::arrived(wire::AnnounceSyncPoint& a) {
    announced_.insert(a.label);
    return true;
}

bool Client::arrived(wire::FederationSynchronized& s) {
    announced_.erase(s.label);
    return true;
}

}  // namespace hlacore
