// Synchronization points (HLA 1.3 §4.6-4.10).
#include "rti/server/sync_points.hpp"

#include "rti/wire/json.hpp"

namespace hlacore {

void SyncPoints::on(FederateHandle from, const wire::RegisterSyncPoint& m, const std::vector<FederateHandle>& joined) {
    if (points_.count(m.label)) {
        outbox_.send(from, wire::SyncPointRegistrationFailed{m.label});
        return;
    }
    Point point;
    point.tag = m.tag;
    point.whole_federation = m.whole_federation;
    const std::set<FederateHandle> all(joined.begin(), joined.end());
    for (auto h : m.whole_federation ? joined : m.federates) {
        if (!all.count(h)) {
            outbox_.send(from, wire::SyncPointRegistrationFailed{m.label});
            return;
        }
        point.members.insert(h);
    }
    outbox_.send(from, wire::SyncPointRegistrationSucceeded{m.label});
    for (auto h : point.members) outbox_.send(h, wire::AnnounceSyncPoint{m.label, m.tag});
    points_.emplace(m.label, std::move(point));
    check(m.label);  // an explicit empty set is synchronized at once
}

void SyncPoints::on(FederateHandle from, const wire::SyncPointAchieved& m) {
    auto it = points_.find(m.label);
    if (it == points_.end() || !it->second.members.count(from)) return;
    it->second.achieved.insert(from);
    check(m.label);
}

void SyncPoints::joined(FederateHandle federate) {
    for (auto& [label, point] : points_) {
        if (!point.whole_federation) continue;
        point.members.insert(federate);
        outbox_.send(federate, wire::AnnounceSyncPoint{label, point.tag});
    }
}

void SyncPoints::departed(FederateHandle federate) {
    std::vector<std::string> labels;
    for (auto& [label, point] : points_) {
        point.members.erase(federate);
        point.achieved.erase(federate);
        labels.push_back(label);
    }
    for (const auto& label : labels) check(label);
}

void SyncPoints::check(const std::string& label) {
    auto it = points_.find(label);
    if (it == points_.end() || it->second.achieved.size() < it->second.members.size()) return;
    const Point point = std::move(it->second);
    points_.erase(it);
    for (auto h : point.members) outbox_.send(h, wire::FederationSynchronized{label});
}

void SyncPoints::write_status(std::string& json) const {
    json_array(json, points_, [&](const auto& point) { json_string(json, point.first); });
}

}  // namespace hlacore
