// Federation save and restore (HLA 1.3 §4.11-4.22; docs/save-restore.md).
#include "bindings/convert.hpp"

namespace hlacore::bindings {

namespace {

// What help() says of each service of the group (convert.hpp: Documented).
const Doc kDocs[] = {
    {"requestFederationSave", "Ask every federate to save (HLA 1.3 §4.11): initiateFederateSave(label) goes to each, then federationSaved() or federationNotSaved(). With theTime, a regulating or constrained federate is told once granted theTime or beyond; the others at once. The gateway keeps its part (in --save-dir as a file). Raises FederationTimeAlreadyPassed, InvalidFederationTime, SaveInProgress, RestoreInProgress."},
    {"federateSaveBegun", "Tell the RTI this federate started saving (HLA 1.3 §4.13). Raises SaveNotInitiated."},
    {"federateSaveComplete", "Tell the RTI this federate saved its state (HLA 1.3 §4.14). Raises SaveNotInitiated."},
    {"federateSaveNotComplete", "Tell the RTI this federate could not save (HLA 1.3 §4.14): everyone gets federationNotSaved(). Raises SaveNotInitiated."},
    {"requestFederationRestore", "Ask to restore the save `label` (HLA 1.3 §4.17), from memory or the gateway's --save-dir; the joined federates must have the names of those saved. requestFederationRestoreSucceeded(label) or requestFederationRestoreFailed(label, reason) follows, then federationRestoreBegun(), initiateFederateRestore(label, federateHandle) and federationRestored() / federationNotRestored() at every federate. Raises SaveInProgress, RestoreInProgress."},
    {"federateRestoreComplete", "Tell the RTI this federate restored its state (HLA 1.3 §4.21). Raises RestoreNotRequested."},
    {"federateRestoreNotComplete", "Tell the RTI this federate could not restore (HLA 1.3 §4.21): everyone gets federationNotRestored(). Raises RestoreNotRequested."},
};

}  // namespace

void bind_save_restore(Ambassador& rtia) {
    Documented(rtia, kDocs)
        .def("requestFederationSave",
             [](Client& c, py::object label, std::optional<double> time) {
                 const std::string l = to_bytes(label, "label");
                 py::gil_scoped_release release;
                 c.request_federation_save(l, time);
             }, py::arg("label"), py::arg("theTime") = py::none())
        .def("federateSaveBegun", &Client::federate_save_begun)
        .def("federateSaveComplete", [](Client& c) { c.federate_save_complete(true); })
        .def("federateSaveNotComplete", [](Client& c) { c.federate_save_complete(false); })
        .def("requestFederationRestore",
             [](Client& c, py::object label) {
                 const std::string l = to_bytes(label, "label");
                 py::gil_scoped_release release;
                 c.request_federation_restore(l);
             }, py::arg("label"))
        .def("federateRestoreComplete", [](Client& c) { c.federate_restore_complete(true); })
        .def("federateRestoreNotComplete", [](Client& c) { c.federate_restore_complete(false); })
        // IEEE 1516-2010's, for hlacore.rti1516e.
        .def("_abort_save", &Client::abort_federation_save, py::call_guard<py::gil_scoped_release>())
        .def("_abort_restore", &Client::abort_federation_restore, py::call_guard<py::gil_scoped_release>())
        .def("_failure_reason", &Client::last_failure_reason);
}

}  // namespace hlacore::bindings
