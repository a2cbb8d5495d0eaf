// Synchronization points (HLA 1.3 §4.6-4.10) of one federation: the registered labels, who must achieve
// each and who has. Owned by the Federation, which checks that the sender is joined.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "rti/server/outbox.hpp"

namespace hlacore {

class SyncPoints {
public:
    explicit SyncPoints(Outbox& outbox) : outbox_(outbox) {}

    // registerFederationSynchronizationPoint; `joined` are the federation's federates now. A label in use
    // or an unknown member is answered with synchronizationPointRegistrationFailed.
    void on(FederateHandle from, const wire::RegisterSyncPoint& m, const std::vector<FederateHandle>& joined);
    void on(FederateHandle from, const wire::SyncPointAchieved& m);
    // A pending point of the whole federation includes a late joiner, who is announced it (HLA 1.3 §4.6).
    void joined(FederateHandle federate);
    // A federate that left holds no point back.
    void departed(FederateHandle federate);
    // A restore renumbers the federates: pending points are dropped (docs/save-restore.md).
    void clear() { points_.clear(); }
    // A JSON array of the pending labels.
    void write_status(std::string& json) const;

private:
    struct Point {
        std::string tag;
        bool whole_federation = true;
        std::set<FederateHandle> members;
        std::set<FederateHandle> achieved;
    };
    // Sends federationSynchronized once every member achieved the point.
    void check(const std::string& label);

    Outbox& outbox_;
    std::map<std::string, Point> points_;
};

}  // namespace hlacore
