// Federation management (HLA 1.3 §4.2-4.5): create, destroy, join and resign, and the recorder federate's
// recording; rti.py wraps the underscored ones.
#include "bindings/convert.hpp"

namespace hlacore::bindings {

namespace {

// What help() says of each service of the group (convert.hpp: Documented).
const Doc kDocs[] = {
    {"destroyFederationExecution", "Destroy a federation execution (HLA 1.3 §4.3). Raises FederatesCurrentlyJoined, FederationExecutionDoesNotExist."},
};

}  // namespace

void bind_federation(Ambassador& rtia) {
    Documented(rtia, kDocs)
        .def("_create",
             [](Client& c, const std::string& name, const std::string& fed_name, const std::string& fed_text,
                int time_type) {
                 if (time_type < 0 || time_type > static_cast<int>(TimeType::Integer64))
                     throw RtiError(ErrorCode::RTIinternalError, "time type " + std::to_string(time_type));
                 py::gil_scoped_release release;
                 c.create_federation(name, fed_name, fed_text, static_cast<TimeType>(time_type));
             },
             py::arg("name"), py::arg("fed_name"), py::arg("fed_text"), py::arg("time_type") = 0)
        .def("_time_type", [](const Client& c) { return static_cast<int>(c.time_type()); })
        .def("destroyFederationExecution", &Client::destroy_federation,
             py::arg("executionName"), py::call_guard<py::gil_scoped_release>())
        .def("_join", [](Client& c, const std::string& federate, const std::string& federation,
                         const std::string& fom_modules, const std::string& federate_type) {
            H32 h;
            {
                py::gil_scoped_release release;
                h = c.join(federate, federation, fom_modules, federate_type);
            }
            return FederateHandle{h};
        }, py::arg("federate"), py::arg("federation"), py::arg("fom_modules") = "", py::arg("federate_type") = "")
        .def("_resign", [](Client& c, int action) {
            if (action < 0 || action > 255) throw RtiError(ErrorCode::InvalidResignAction, "invalid resign action");
            py::gil_scoped_release release;
            c.resign(static_cast<std::uint8_t>(action));
        })
        .def("_start_recording", &Client::start_recording, py::call_guard<py::gil_scoped_release>())
        .def("_stop_recording", &Client::stop_recording, py::call_guard<py::gil_scoped_release>());
}

}  // namespace hlacore::bindings
