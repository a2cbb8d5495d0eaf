// Synchronization points (HLA 1.3 §4.6-4.10).
#include "bindings/convert.hpp"

namespace hlacore::bindings {

namespace {

// What help() says of each service of the group (convert.hpp: Documented).
const Doc kDocs[] = {
    {"registerFederationSynchronizationPoint", "Register a synchronization point (HLA 1.3 §4.6) for the whole federation or the given FederateHandles. Leads to synchronizationPointRegistrationSucceeded/Failed here and announceSynchronizationPoint at every member."},
    {"synchronizationPointAchieved", "Tell the RTI this federate reached an announced point (HLA 1.3 §4.9); federationSynchronized follows once every member has. Raises SynchronizationPointLabelWasNotAnnounced."},
};

}  // namespace

void bind_sync_points(Ambassador& rtia) {
    Documented(rtia, kDocs)
        .def("registerFederationSynchronizationPoint",
             [](Client& c, py::object label, py::object tag, std::optional<std::vector<FederateHandle>> federates) {
                 c.request(wire::RegisterSyncPoint{to_bytes(label, "label"), to_bytes(tag, "tag"), !federates,
                                                   federates ? to_handles(*federates) : wire::Handles{}});
             },
             py::arg("label"), py::arg("tag"), py::arg("federates") = py::none())
        .def("synchronizationPointAchieved",
             [](Client& c, py::object label) { c.request(wire::SyncPointAchieved{to_bytes(label, "label")}); },
             py::arg("label"));
}

}  // namespace hlacore::bindings
