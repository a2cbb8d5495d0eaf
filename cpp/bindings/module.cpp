// hlacore._core: the native layer under `import hlacore`. Declarations and conversions only; the
// PyHLA-shaped API and its docstrings live in python/hlacore/rti.py, which subclasses RTIAmbassadorBase.
#include <array>
#include <chrono>
#include <memory>
#include <thread>
#include <unordered_map>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "fed_parser/fom.hpp"
#include "rti/client/client.hpp"
#include "rti/server/gateway.hpp"
#include "rti/server/time_manager.hpp"

namespace py = pybind11;
namespace fom = hlacore::fom;
namespace wire = hlacore::wire;
using hlacore::Client;
using hlacore::ErrorCode;
using hlacore::Gateway;
using hlacore::GatewayOptions;
using hlacore::RtiError;

void bind_fed(py::module_& m);

namespace {

// ---- exceptions: one Python class per HLA 1.3 exception, all under RTIexception ----

PyObject* g_base_exception = nullptr;
std::array<PyObject*, static_cast<std::size_t>(ErrorCode::Count)> g_exceptions{};

PyObject* exception_class(ErrorCode code) {
    auto i = static_cast<std::size_t>(code);
    return i < g_exceptions.size() && g_exceptions[i] ? g_exceptions[i] : g_base_exception;
}

void register_exceptions(py::module_& m) {
    g_base_exception = PyErr_NewExceptionWithDoc("hlacore._core.RTIexception",
                                                 "Base of every HLA 1.3 exception raised by hlacore.", nullptr, nullptr);
    m.add_object("RTIexception", py::handle(g_base_exception));
#define HLACORE_X(name)                                                                                   \
    g_exceptions[static_cast<std::size_t>(ErrorCode::name)] =                                             \
        PyErr_NewExceptionWithDoc("hlacore._core." #name, "The HLA 1.3 exception " #name ".", g_base_exception, \
                                  nullptr);                                                               \
    m.add_object(#name, py::handle(g_exceptions[static_cast<std::size_t>(ErrorCode::name)]));
    HLACORE_EXCEPTIONS(HLACORE_X)
#undef HLACORE_X

    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const RtiError& e) {
            PyErr_SetString(exception_class(e.code()), e.what());
        } catch (const fom::FedError& e) {
            py::object cls = py::reinterpret_borrow<py::object>(exception_class(ErrorCode::ErrorReadingFED));
            py::object exc = cls(e.what());
            exc.attr("file") = e.file();
            exc.attr("line") = e.line();
            exc.attr("column") = e.column();
            PyErr_SetObject(cls.ptr(), exc.ptr());
        } catch (const wire::WireError& e) {
            PyErr_SetString(exception_class(ErrorCode::RTIinternalError), e.what());
        }
    });
}

// ---- typed handles: hashable, ordered, never interchangeable ----

template <int Kind>
struct Handle {
    std::uint32_t value;
};
using ObjectClassHandle = Handle<1>;
using AttributeHandle = Handle<2>;
using InteractionClassHandle = Handle<3>;
using ParameterHandle = Handle<4>;
using ObjectHandle = Handle<5>;
using FederateHandle = Handle<6>;
using OrderingHandle = Handle<7>;
using TransportationHandle = Handle<8>;
using SpaceHandle = Handle<9>;
using DimensionHandle = Handle<10>;
using RegionHandle = Handle<11>;  // data distribution management: a region of the federate that created it

// createRegion's extent, PyHLA's form: [(DimensionHandle, (lower, upper)), ...].
using PyExtent = std::vector<std::pair<DimensionHandle, std::pair<std::int64_t, std::int64_t>>>;
Client::Extent to_extent(const PyExtent& ranges) {
    Client::Extent extent;
    for (const auto& [dimension, bounds] : ranges) extent.push_back(Client::Range{dimension.value, bounds.first, bounds.second});
    return extent;
}

struct EventRetractionHandle {
    std::uint32_t sender;
    std::uint64_t serial;
};

template <class H>
void bind_handle(py::module_& m, const char* name) {
    const std::string repr_prefix = std::string("<rti.") + name + "=";
    py::class_<H>(m, name, (std::string("An HLA ") + name + "; obtained from the RTI, never constructed.").c_str())
        .def("__eq__", [](const H& a, const H& b) { return a.value == b.value; }, py::is_operator())
        .def("__ne__", [](const H& a, const H& b) { return a.value != b.value; }, py::is_operator())
        .def("__lt__", [](const H& a, const H& b) { return a.value < b.value; }, py::is_operator())
        .def("__le__", [](const H& a, const H& b) { return a.value <= b.value; }, py::is_operator())
        .def("__gt__", [](const H& a, const H& b) { return a.value > b.value; }, py::is_operator())
        .def("__ge__", [](const H& a, const H& b) { return a.value >= b.value; }, py::is_operator())
        .def("__hash__", [name](const H& h) { return py::hash(py::make_tuple(name, h.value)); })
        .def("__int__", [](const H& h) { return h.value; })
        .def("__index__", [](const H& h) { return h.value; })
        .def("__repr__", [repr_prefix](const H& h) { return repr_prefix + std::to_string(h.value) + ">"; });
}

// ---- value conversions ----

// Tags and labels are bytes on the wire; str goes through UTF-8 with surrogateescape so nothing is lost.
std::string to_bytes(const py::handle& value, const char* what) {
    if (PyBytes_Check(value.ptr())) return std::string(PyBytes_AS_STRING(value.ptr()), PyBytes_GET_SIZE(value.ptr()));
    if (PyUnicode_Check(value.ptr())) {
        py::object encoded = py::reinterpret_steal<py::object>(
            PyUnicode_AsEncodedString(value.ptr(), "utf-8", "surrogateescape"));
        if (!encoded) throw py::error_already_set();
        return std::string(PyBytes_AS_STRING(encoded.ptr()), PyBytes_GET_SIZE(encoded.ptr()));
    }
    if (PyObject_CheckBuffer(value.ptr())) {
        py::buffer_info info = py::reinterpret_borrow<py::buffer>(value).request();
        if (info.itemsize * info.size < 0) throw py::value_error("bad buffer");
        return std::string(static_cast<const char*>(info.ptr), static_cast<std::size_t>(info.itemsize * info.size));
    }
    throw py::type_error(std::string(what) + " must be bytes or str, not " + std::string(py::str(py::type::handle_of(value).attr("__name__"))));
}

py::str to_str(const std::string& s) {
    return py::reinterpret_steal<py::str>(PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "surrogateescape"));
}

template <class H>
wire::HandleValues to_handle_values(const py::handle& mapping, const char* key_name) {
    if (!PyDict_Check(mapping.ptr()) && !PyMapping_Check(mapping.ptr()))
        throw py::type_error(std::string("a mapping {") + key_name + ": bytes} is required");
    py::dict d = py::reinterpret_borrow<py::object>(mapping).cast<py::dict>();
    wire::HandleValues values;
    values.reserve(d.size());
    for (auto item : d) {
        if (!py::isinstance<H>(item.first)) throw py::type_error(std::string(key_name) + " object required as key");
        values.emplace_back(item.first.cast<const H&>().value, to_bytes(item.second, "a value"));
    }
    return values;
}

template <class H>
std::vector<std::uint32_t> to_handles(const std::vector<H>& handles) {
    std::vector<std::uint32_t> out;
    out.reserve(handles.size());
    for (const auto& h : handles) out.push_back(h.value);
    return out;
}

// Handle objects are immutable values, so callbacks share them: creating a pybind11 instance costs about
// as much as the rest of a reflection's conversion. The caches live as long as the interpreter.
template <class H>
py::object handle_of(std::uint32_t value) {
    static auto* cache = new std::unordered_map<std::uint32_t, py::object>();
    auto it = cache->find(value);
    if (it != cache->end()) return it->second;
    py::object h = py::cast(H{value});
    if (cache->size() < (1u << 16)) cache->emplace(value, h);
    return h;
}

template <class H>
py::dict to_dict(const wire::HandleValues& values) {
    py::dict d;
    for (const auto& [h, v] : values) d[handle_of<H>(h)] = py::bytes(v);
    return d;
}

template <class H>
py::tuple to_tuple(const wire::Handles& handles) {
    py::tuple t(handles.size());
    for (std::size_t i = 0; i < handles.size(); ++i) t[i] = py::cast(H{handles[i]});
    return t;
}

py::object retraction_or_none(std::uint64_t serial, std::uint32_t sender) {
    return py::cast(EventRetractionHandle{sender, serial});
}

// A queued message as (callback name, arguments), with PyHLA's argument order.
py::object to_callback(const wire::Message& message) {
    return std::visit(
        [](const auto& m) -> py::object {
            using M = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<M, wire::SyncPointRegistrationSucceeded>) {
                return py::make_tuple("synchronizationPointRegistrationSucceeded", py::make_tuple(to_str(m.label)));
            } else if constexpr (std::is_same_v<M, wire::SyncPointRegistrationFailed>) {
                return py::make_tuple("synchronizationPointRegistrationFailed", py::make_tuple(to_str(m.label)));
            } else if constexpr (std::is_same_v<M, wire::AnnounceSyncPoint>) {
                return py::make_tuple("announceSynchronizationPoint", py::make_tuple(to_str(m.label), to_str(m.tag)));
            } else if constexpr (std::is_same_v<M, wire::FederationSynchronized>) {
                return py::make_tuple("federationSynchronized", py::make_tuple(to_str(m.label)));
            } else if constexpr (std::is_same_v<M, wire::StartRegistration>) {
                return py::make_tuple("startRegistrationForObjectClass", py::make_tuple(ObjectClassHandle{m.object_class}));
            } else if constexpr (std::is_same_v<M, wire::StopRegistration>) {
                return py::make_tuple("stopRegistrationForObjectClass", py::make_tuple(ObjectClassHandle{m.object_class}));
            } else if constexpr (std::is_same_v<M, wire::TurnInteractionsOn>) {
                return py::make_tuple("turnInteractionsOn", py::make_tuple(InteractionClassHandle{m.interaction_class}));
            } else if constexpr (std::is_same_v<M, wire::TurnInteractionsOff>) {
                return py::make_tuple("turnInteractionsOff", py::make_tuple(InteractionClassHandle{m.interaction_class}));
            } else if constexpr (std::is_same_v<M, wire::DiscoverObject>) {
                return py::make_tuple("discoverObjectInstance",
                                      py::make_tuple(handle_of<ObjectHandle>(m.object), ObjectClassHandle{m.object_class}, to_str(m.name)));
            } else if constexpr (std::is_same_v<M, wire::ReflectAttributes>) {
                py::tuple args = m.time ? (py::tuple)py::make_tuple(handle_of<ObjectHandle>(m.object), to_dict<AttributeHandle>(m.values),
                                                         to_str(m.tag), handle_of<OrderingHandle>(m.order),
                                                         handle_of<TransportationHandle>(m.transport), *m.time,
                                                         retraction_or_none(m.serial, m.sender))
                                        : (py::tuple)py::make_tuple(handle_of<ObjectHandle>(m.object), to_dict<AttributeHandle>(m.values),
                                                         to_str(m.tag), handle_of<OrderingHandle>(m.order),
                                                         handle_of<TransportationHandle>(m.transport));
                return py::make_tuple("reflectAttributeValues", args);
            } else if constexpr (std::is_same_v<M, wire::ReceiveInteraction>) {
                py::tuple args = m.time ? (py::tuple)py::make_tuple(handle_of<InteractionClassHandle>(m.interaction_class),
                                                         to_dict<ParameterHandle>(m.values), to_str(m.tag),
                                                         handle_of<OrderingHandle>(m.order), handle_of<TransportationHandle>(m.transport),
                                                         *m.time, retraction_or_none(m.serial, m.sender))
                                        : (py::tuple)py::make_tuple(handle_of<InteractionClassHandle>(m.interaction_class),
                                                         to_dict<ParameterHandle>(m.values), to_str(m.tag),
                                                         handle_of<OrderingHandle>(m.order), handle_of<TransportationHandle>(m.transport));
                return py::make_tuple("receiveInteraction", args);
            } else if constexpr (std::is_same_v<M, wire::RemoveObject>) {
                py::tuple args = m.time ? (py::tuple)py::make_tuple(handle_of<ObjectHandle>(m.object), to_str(m.tag), *m.time,
                                                         retraction_or_none(m.serial, m.sender))
                                        : (py::tuple)py::make_tuple(handle_of<ObjectHandle>(m.object), to_str(m.tag));
                return py::make_tuple("removeObjectInstance", args);
            } else if constexpr (std::is_same_v<M, wire::TimeRegulationEnabled>) {
                return py::make_tuple("timeRegulationEnabled", py::make_tuple(m.time));
            } else if constexpr (std::is_same_v<M, wire::TimeConstrainedEnabled>) {
                return py::make_tuple("timeConstrainedEnabled", py::make_tuple(m.time));
            } else if constexpr (std::is_same_v<M, wire::TimeAdvanceGrant>) {
                return py::make_tuple("timeAdvanceGrant", py::make_tuple(m.time));
            } else if constexpr (std::is_same_v<M, wire::RequestRetraction>) {
                return py::make_tuple("requestRetraction", py::make_tuple(EventRetractionHandle{m.sender, m.serial}));
            } else if constexpr (std::is_same_v<M, wire::ProvideAttributeValueUpdate>) {
                return py::make_tuple("provideAttributeValueUpdate",
                                      py::make_tuple(ObjectHandle{m.object}, to_tuple<AttributeHandle>(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::RequestOwnershipAssumption>) {
                return py::make_tuple("requestAttributeOwnershipAssumption",
                                      py::make_tuple(ObjectHandle{m.object}, to_tuple<AttributeHandle>(m.attributes),
                                                     to_str(m.tag)));
            } else if constexpr (std::is_same_v<M, wire::DivestitureNotification>) {
                return py::make_tuple("attributeOwnershipDivestitureNotification",
                                      py::make_tuple(ObjectHandle{m.object}, to_tuple<AttributeHandle>(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::AcquisitionNotification>) {
                return py::make_tuple("attributeOwnershipAcquisitionNotification",
                                      py::make_tuple(ObjectHandle{m.object}, to_tuple<AttributeHandle>(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::OwnershipUnavailable>) {
                return py::make_tuple("attributeOwnershipUnavailable",
                                      py::make_tuple(ObjectHandle{m.object}, to_tuple<AttributeHandle>(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::RequestOwnershipRelease>) {
                return py::make_tuple("requestAttributeOwnershipRelease",
                                      py::make_tuple(ObjectHandle{m.object}, to_tuple<AttributeHandle>(m.attributes),
                                                     to_str(m.tag)));
            } else if constexpr (std::is_same_v<M, wire::ConfirmAcquisitionCancellation>) {
                return py::make_tuple("confirmAttributeOwnershipAcquisitionCancellation",
                                      py::make_tuple(ObjectHandle{m.object}, to_tuple<AttributeHandle>(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::AttributesInScope>) {
                return py::make_tuple("attributesInScope",
                                      py::make_tuple(ObjectHandle{m.object}, to_tuple<AttributeHandle>(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::AttributesOutOfScope>) {
                return py::make_tuple("attributesOutOfScope",
                                      py::make_tuple(ObjectHandle{m.object}, to_tuple<AttributeHandle>(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::TurnUpdatesOn>) {
                return py::make_tuple("turnUpdatesOnForObjectInstance",
                                      py::make_tuple(ObjectHandle{m.object}, to_tuple<AttributeHandle>(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::TurnUpdatesOff>) {
                return py::make_tuple("turnUpdatesOffForObjectInstance",
                                      py::make_tuple(ObjectHandle{m.object}, to_tuple<AttributeHandle>(m.attributes)));
            } else if constexpr (std::is_same_v<M, wire::OwnershipInformation>) {
                switch (static_cast<wire::OwnershipKind>(m.kind)) {
                    case wire::OwnershipKind::OwnedByFederate:
                        return py::make_tuple("informAttributeOwnership",
                                              py::make_tuple(ObjectHandle{m.object}, AttributeHandle{m.attribute},
                                                             FederateHandle{m.owner}));
                    case wire::OwnershipKind::OwnedByRti:
                        return py::make_tuple("attributeOwnedByRTI",
                                              py::make_tuple(ObjectHandle{m.object}, AttributeHandle{m.attribute}));
                    default:
                        return py::make_tuple("attributeIsNotOwned",
                                              py::make_tuple(ObjectHandle{m.object}, AttributeHandle{m.attribute}));
                }
            // save/restore (HLA 1.3 §4.11-4.22)
            } else if constexpr (std::is_same_v<M, wire::InitiateFederateSave>) {
                return py::make_tuple("initiateFederateSave", py::make_tuple(to_str(m.label)));
            } else if constexpr (std::is_same_v<M, wire::FederationSaved>) {
                return py::make_tuple(m.success ? "federationSaved" : "federationNotSaved", py::tuple());
            } else if constexpr (std::is_same_v<M, wire::RestoreRequestAnswer>) {
                if (m.succeeded)
                    return py::make_tuple("requestFederationRestoreSucceeded", py::make_tuple(to_str(m.label)));
                return py::make_tuple("requestFederationRestoreFailed", py::make_tuple(to_str(m.label), to_str(m.reason)));
            } else if constexpr (std::is_same_v<M, wire::FederationRestoreBegun>) {
                return py::make_tuple("federationRestoreBegun", py::tuple());
            } else if constexpr (std::is_same_v<M, wire::InitiateFederateRestore>) {
                return py::make_tuple("initiateFederateRestore", py::make_tuple(to_str(m.label), FederateHandle{m.federate}));
            } else if constexpr (std::is_same_v<M, wire::FederationRestored>) {
                return py::make_tuple(m.success ? "federationRestored" : "federationNotRestored", py::tuple());
            } else {
                throw RtiError(ErrorCode::RTIinternalError, "unexpected message from the gateway");
            }
        },
        message);
}

// Delivers queued callbacks to the ambassador's methods of the same name (absent ones are skipped), for
// at most max_seconds (< 0: no limit), stopping after a time advance grant if asked. Returns how many were
// delivered. The loop is here rather than in Python because it runs once per reflection.
int dispatch(Client& c, const py::object& ambassador, bool stop_after_grant, double max_seconds) {
    const auto deadline = Client::Clock::now() + std::chrono::duration_cast<Client::Clock::duration>(
                                                      std::chrono::duration<double>(max_seconds < 0 ? 0 : max_seconds));
    int delivered = 0;
    for (;;) {
        auto m = c.pop_callback();
        if (!m) break;
        ++delivered;
        py::tuple callback = to_callback(*m);
        if (!ambassador.is_none()) {
            py::object method = py::getattr(ambassador, callback[0], py::none());
            if (!method.is_none()) method(*callback[1]);
        }
        if (stop_after_grant && std::holds_alternative<wire::TimeAdvanceGrant>(*m)) break;
        if (max_seconds >= 0 && Client::Clock::now() >= deadline) break;
    }
    return delivered;
}

py::object serial_result(std::uint64_t serial, const std::optional<double>& time, const Client& c) {
    if (!time) return py::none();
    return py::cast(EventRetractionHandle{c.federate_handle(), serial});
}

// Waits for a callback with the GIL released; a signal (Ctrl-C) gets to Python between waits.
bool wait_for_callback(Client& c, double timeout_s) {
    const auto deadline = timeout_s < 0 ? Client::Clock::time_point::max()
                                        : Client::Clock::now() + std::chrono::duration_cast<Client::Clock::duration>(
                                                                     std::chrono::duration<double>(timeout_s));
    for (;;) {
        Client::WaitStatus status;
        {
            py::gil_scoped_release release;
            status = c.wait_for_callback(deadline);
        }
        if (status != Client::WaitStatus::Interrupted) return status == Client::WaitStatus::Ready;
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
}

// ---- the in-process gateway ----

class BackgroundGateway {
public:
    BackgroundGateway(const std::string& host, std::uint16_t port, std::vector<std::string> fom_path, bool verbose,
                      const std::string& save_dir, std::string trace_path) {
        GatewayOptions options;
        options.save_dir = save_dir;
        options.host = host;
        options.port = port;
        options.fom_path = std::move(fom_path);
        options.verbose = verbose;
        options.trace_path = std::move(trace_path);
        gateway_ = std::make_unique<Gateway>(options);
        thread_ = std::thread([this] { gateway_->run(); });
    }
    ~BackgroundGateway() { stop(); }
    void stop() {
        if (thread_.joinable()) {
            gateway_->stop();
            thread_.join();
        }
    }
    std::string host() const { return gateway_->host(); }
    std::uint16_t port() const { return gateway_->port(); }
    bool running() const { return thread_.joinable(); }

private:
    std::unique_ptr<Gateway> gateway_;
    std::thread thread_;
};

}  // namespace

PYBIND11_MODULE(_core, m) {
    m.doc() = "hlacore native core: gateway, client connection, FED parser";
    register_exceptions(m);

    bind_handle<ObjectClassHandle>(m, "ObjectClassHandle");
    bind_handle<AttributeHandle>(m, "AttributeHandle");
    bind_handle<InteractionClassHandle>(m, "InteractionClassHandle");
    bind_handle<ParameterHandle>(m, "ParameterHandle");
    bind_handle<ObjectHandle>(m, "ObjectHandle");
    bind_handle<FederateHandle>(m, "FederateHandle");
    bind_handle<OrderingHandle>(m, "OrderingHandle");
    bind_handle<TransportationHandle>(m, "TransportationHandle");
    bind_handle<SpaceHandle>(m, "SpaceHandle");
    bind_handle<DimensionHandle>(m, "DimensionHandle");
    bind_handle<RegionHandle>(m, "RegionHandle");
    m.attr("MIN_EXTENT") = Client::kMinExtent;
    m.attr("MAX_EXTENT") = Client::kMaxExtent;
    py::class_<EventRetractionHandle>(m, "EventRetractionHandle",
                                      "Names a timestamped message so that its sender can retract it.")
        .def_readonly("sendingFederate", &EventRetractionHandle::sender)
        .def_readonly("serial", &EventRetractionHandle::serial)
        .def("__eq__", [](const EventRetractionHandle& a, const EventRetractionHandle& b) {
            return a.sender == b.sender && a.serial == b.serial; }, py::is_operator())
        .def("__hash__", [](const EventRetractionHandle& h) { return py::hash(py::make_tuple("ERH", h.sender, h.serial)); })
        .def("__repr__", [](const EventRetractionHandle& h) {
            return "<rti.EventRetractionHandle=" + std::to_string(h.sender) + ":" + std::to_string(h.serial) + ">";
        });

    bind_fed(m);

    py::class_<BackgroundGateway>(m, "BackgroundGateway")
        .def(py::init<const std::string&, std::uint16_t, std::vector<std::string>, bool, const std::string&,
                      std::string>(),
             py::arg("host"), py::arg("port"), py::arg("fom_path"), py::arg("verbose"), py::arg("save_dir") = "",
             py::arg("trace_path") = "",
             py::call_guard<py::gil_scoped_release>())
        .def("stop", &BackgroundGateway::stop, py::call_guard<py::gil_scoped_release>())
        .def_property_readonly("host", &BackgroundGateway::host)
        .def_property_readonly("port", &BackgroundGateway::port)
        .def_property_readonly("running", &BackgroundGateway::running);

    using H32 = std::uint32_t;
    py::class_<Client>(m, "RTIAmbassadorBase")
        .def(py::init<const std::string&, std::uint16_t>(), py::arg("host"), py::arg("port"),
             py::call_guard<py::gil_scoped_release>())
        .def_property_readonly("address", &Client::address)
        .def("fileno", &Client::fileno)
        // federation management
        .def("_create", &Client::create_federation, py::call_guard<py::gil_scoped_release>())
        .def("destroyFederationExecution", &Client::destroy_federation, py::arg("executionName"),
             py::call_guard<py::gil_scoped_release>(),
             "Destroy a federation execution (HLA 1.3 §4.3). Raises FederatesCurrentlyJoined, FederationExecutionDoesNotExist.")
        .def("_join", [](Client& c, const std::string& federate, const std::string& federation) {
            H32 h;
            {
                py::gil_scoped_release release;
                h = c.join(federate, federation);
            }
            return FederateHandle{h};
        })
        .def("_resign", [](Client& c, int action) {
            if (action < 0 || action > 255) throw RtiError(ErrorCode::InvalidResignAction, "invalid resign action");
            py::gil_scoped_release release;
            c.resign(static_cast<std::uint8_t>(action));
        })
        .def("registerFederationSynchronizationPoint",
             [](Client& c, py::object label, py::object tag, std::optional<std::vector<FederateHandle>> federates) {
                 std::optional<std::vector<H32>> set;
                 if (federates) set = to_handles(*federates);
                 c.register_sync_point(to_bytes(label, "label"), to_bytes(tag, "tag"), set);
             },
             py::arg("label"), py::arg("tag"), py::arg("federates") = py::none(),
             "Register a synchronization point (HLA 1.3 §4.6) for the whole federation or the given FederateHandles. Leads to synchronizationPointRegistrationSucceeded/Failed here and announceSynchronizationPoint at every member.")
        .def("synchronizationPointAchieved",
             [](Client& c, py::object label) { c.sync_point_achieved(to_bytes(label, "label")); }, py::arg("label"),
             "Tell the RTI this federate reached an announced point (HLA 1.3 §4.9); federationSynchronized follows once every member has. Raises SynchronizationPointLabelWasNotAnnounced.")
        // declaration management
        .def("publishObjectClass",
             [](Client& c, ObjectClassHandle cls, std::vector<AttributeHandle> attrs) {
                 c.publish_object_class(cls.value, to_handles(attrs));
             }, py::arg("objectClass"), py::arg("attributes"),
             "Publish attributes of an object class (HLA 1.3 §5.2); owned attributes of its instances no longer published are divested unconditionally (privilegeToDelete counts as published with the class). Raises ObjectClassNotDefined, AttributeNotDefined.")
        .def("unpublishObjectClass", [](Client& c, ObjectClassHandle cls) { c.unpublish_object_class(cls.value); },
             py::arg("objectClass"),
             "Stop publishing an object class (HLA 1.3 §5.3); the owned attributes of its instances are divested unconditionally. Raises ObjectClassNotPublished, OwnershipAcquisitionPending.")
        .def("subscribeObjectClassAttributes",
             [](Client& c, ObjectClassHandle cls, std::vector<AttributeHandle> attrs, bool active) {
                 c.subscribe_object_class(cls.value, to_handles(attrs), active);
             }, py::arg("objectClass"), py::arg("attributes"), py::arg("active") = true,
             "Subscribe to attributes of an object class (HLA 1.3 §5.6); instances of it and its subclasses are discovered (discoverObjectInstance). Raises ObjectClassNotDefined, AttributeNotDefined.")
        .def("unsubscribeObjectClass", [](Client& c, ObjectClassHandle cls) { c.unsubscribe_object_class(cls.value); },
             py::arg("objectClass"),
             "Stop subscribing to an object class (HLA 1.3 §5.7). Raises ObjectClassNotSubscribed.")
        .def("publishInteractionClass",
             [](Client& c, InteractionClassHandle ic) { c.publish_interaction_class(ic.value); }, py::arg("interactionClass"),
             "Publish an interaction class (HLA 1.3 §5.4). Raises InteractionClassNotDefined.")
        .def("unpublishInteractionClass",
             [](Client& c, InteractionClassHandle ic) { c.unpublish_interaction_class(ic.value); }, py::arg("interactionClass"),
             "Stop publishing an interaction class (HLA 1.3 §5.5). Raises InteractionClassNotPublished.")
        .def("subscribeInteractionClass",
             [](Client& c, InteractionClassHandle ic, bool active) { c.subscribe_interaction_class(ic.value, active); },
             py::arg("interactionClass"), py::arg("active") = true,
             "Subscribe to an interaction class and its subclasses (HLA 1.3 §5.8); leads to receiveInteraction. Raises InteractionClassNotDefined.")
        .def("unsubscribeInteractionClass",
             [](Client& c, InteractionClassHandle ic) { c.unsubscribe_interaction_class(ic.value); },
             py::arg("interactionClass"),
             "Stop subscribing to an interaction class (HLA 1.3 §5.9). Raises InteractionClassNotSubscribed.")
        .def("_set_advisory_switch",
             [](Client& c, int which, bool on) { c.set_advisory_switch(static_cast<wire::AdvisorySwitch>(which), on); })
        // object management
        .def("registerObjectInstance",
             [](Client& c, ObjectClassHandle cls, std::optional<std::string> name) {
                 H32 h;
                 {
                     py::gil_scoped_release release;
                     h = c.register_object(cls.value, name.value_or(""));
                 }
                 return ObjectHandle{h};
             }, py::arg("objectClass"), py::arg("objectName") = py::none(),
             "Register an instance of a published class (HLA 1.3 §6.2), optionally named (names are unique in the federation); returns its ObjectHandle and makes this federate the owner of the published attributes. Subscribers get discoverObjectInstance. Raises ObjectClassNotDefined, ObjectClassNotPublished, ObjectAlreadyRegistered.")
        .def("updateAttributeValues",
             [](Client& c, ObjectHandle obj, py::handle values, py::handle tag, std::optional<double> time) {
                 auto serial = c.update_attributes(obj.value, to_handle_values<AttributeHandle>(values, "AttributeHandle"),
                                                   to_bytes(tag, "tag"), time);
                 return serial_result(serial, time, c);
             }, py::arg("object"), py::arg("attributes"), py::arg("tag"), py::arg("time") = py::none(),
             "Update owned attributes {AttributeHandle: bytes} of an object (HLA 1.3 §6.4); subscribers get reflectAttributeValues with the attributes they subscribed. With a time, returns an EventRetractionHandle. Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned.")
        .def("sendInteraction",
             [](Client& c, InteractionClassHandle ic, py::handle values, py::handle tag, std::optional<double> time) {
                 auto serial = c.send_interaction(ic.value, to_handle_values<ParameterHandle>(values, "ParameterHandle"),
                                                  to_bytes(tag, "tag"), time);
                 return serial_result(serial, time, c);
             }, py::arg("interactionClass"), py::arg("parameters"), py::arg("tag"), py::arg("time") = py::none(),
             "Send an interaction {ParameterHandle: bytes} (HLA 1.3 §6.6); subscribers get receiveInteraction. With a time, returns an EventRetractionHandle. Raises InteractionClassNotDefined, InteractionClassNotPublished, InteractionParameterNotDefined.")
        .def("deleteObjectInstance",
             [](Client& c, ObjectHandle obj, py::handle tag, std::optional<double> time) {
                 auto serial = c.delete_object(obj.value, to_bytes(tag, "tag"), time);
                 return serial_result(serial, time, c);
             }, py::arg("object"), py::arg("tag"), py::arg("time") = py::none(),
             "Delete an object this federate may delete (HLA 1.3 §6.8); the others get removeObjectInstance. Raises ObjectNotKnown, DeletePrivilegeNotHeld.")
        .def("localDeleteObjectInstance", [](Client& c, ObjectHandle obj) { c.local_delete_object(obj.value); },
             py::arg("object"),
             "Forget an object locally (HLA 1.3 §6.10); it may be discovered again. Raises ObjectNotKnown, FederateOwnsAttributes.")
        .def("requestObjectAttributeValueUpdate",
             [](Client& c, ObjectHandle obj, std::vector<AttributeHandle> attrs) {
                 c.request_object_update(obj.value, to_handles(attrs));
             }, py::arg("object"), py::arg("attributes"),
             "Ask the owners of an object's attributes to update them (HLA 1.3 §6.15); they get provideAttributeValueUpdate. Raises ObjectNotKnown, AttributeNotDefined.")
        .def("requestClassAttributeValueUpdate",
             [](Client& c, ObjectClassHandle cls, std::vector<AttributeHandle> attrs) {
                 c.request_class_update(cls.value, to_handles(attrs));
             }, py::arg("objectClass"), py::arg("attributes"),
             "Ask the owners of attributes of every instance of a class to update them (HLA 1.3 §6.15). Raises ObjectClassNotDefined, AttributeNotDefined.")
        // transport and order changes (HLA 1.3 §6.19-6.22)
        .def("changeAttributeTransportationType",
             [](Client& c, ObjectHandle obj, std::vector<AttributeHandle> attrs, TransportationHandle t) {
                 c.change_attribute_transportation(obj.value, to_handles(attrs), t.value);
             }, py::arg("object"), py::arg("attributes"), py::arg("transportationHandle"),
             "Change the transportation of owned attributes (HLA 1.3 §6.19) for this federate's later updates of that object; reflectAttributeValues reports it. Forgotten when the attribute changes owner. Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned, InvalidTransportationHandle.")
        .def("changeInteractionTransportationType",
             [](Client& c, InteractionClassHandle ic, TransportationHandle t) {
                 c.change_interaction_transportation(ic.value, t.value);
             }, py::arg("interactionClass"), py::arg("transportationHandle"),
             "Change the transportation of this federate's later interactions of a published class (HLA 1.3 §6.20), until it unpublishes the class; receiveInteraction reports it. Raises InteractionClassNotDefined, InteractionClassNotPublished, InvalidTransportationHandle.")
        .def("changeAttributeOrderType",
             [](Client& c, ObjectHandle obj, std::vector<AttributeHandle> attrs, OrderingHandle o) {
                 c.change_attribute_order(obj.value, to_handles(attrs), o.value);
             }, py::arg("object"), py::arg("attributes"), py::arg("orderingHandle"),
             "Change the order (Receive or Timestamp) of owned attributes (HLA 1.3 §6.21) for this federate's later updates of that object: timestamp order still needs a time, a regulating sender and a constrained receiver; reflectAttributeValues reports the order used. Forgotten when the attribute changes owner. Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned, InvalidOrderingHandle.")
        .def("changeInteractionOrderType",
             [](Client& c, InteractionClassHandle ic, OrderingHandle o) { c.change_interaction_order(ic.value, o.value); },
             py::arg("interactionClass"), py::arg("orderingHandle"),
             "Change the order (Receive or Timestamp) of this federate's later interactions of a published class (HLA 1.3 §6.22), until it unpublishes the class; receiveInteraction reports the order used. Raises InteractionClassNotDefined, InteractionClassNotPublished, InvalidOrderingHandle.")
        // ownership management (HLA 1.3 §7)
        .def("unconditionalAttributeOwnershipDivestiture",
             [](Client& c, ObjectHandle obj, std::vector<AttributeHandle> attrs) {
                 c.unconditional_divestiture(obj.value, to_handles(attrs));
             }, py::arg("object"), py::arg("attributes"),
             "Give up owned attributes at once (HLA 1.3 §7.2): they become unowned, or go to a federate waiting to acquire them. Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned.")
        .def("negotiatedAttributeOwnershipDivestiture",
             [](Client& c, ObjectHandle obj, std::vector<AttributeHandle> attrs, py::handle tag) {
                 c.negotiated_divestiture(obj.value, to_handles(attrs), to_bytes(tag, "tag"));
             }, py::arg("object"), py::arg("attributes"), py::arg("tag"),
             "Offer owned attributes (HLA 1.3 §7.3): the federates publishing them get requestAttributeOwnershipAssumption; this federate owns them until attributeOwnershipDivestitureNotification. Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned, AttributeAlreadyBeingDivested.")
        .def("attributeOwnershipAcquisition",
             [](Client& c, ObjectHandle obj, std::vector<AttributeHandle> attrs, py::handle tag) {
                 c.ownership_acquisition(obj.value, to_handles(attrs), to_bytes(tag, "tag"));
             }, py::arg("object"), py::arg("attributes"), py::arg("tag"),
             "Ask for published attributes (HLA 1.3 §7.7): unowned or divested ones come at once, owned ones after their owner gets requestAttributeOwnershipRelease and releases them; attributeOwnershipAcquisitionNotification tells. Raises ObjectNotKnown, ObjectClassNotPublished, AttributeNotDefined, AttributeNotPublished, FederateOwnsAttributes.")
        .def("attributeOwnershipAcquisitionIfAvailable",
             [](Client& c, ObjectHandle obj, std::vector<AttributeHandle> attrs) {
                 c.ownership_acquisition_if_available(obj.value, to_handles(attrs));
             }, py::arg("object"), py::arg("attributes"),
             "Take published attributes that are unowned or being divested (HLA 1.3 §7.8): attributeOwnershipAcquisitionNotification, else attributeOwnershipUnavailable. Raises ObjectNotKnown, ObjectClassNotPublished, AttributeNotDefined, AttributeNotPublished, FederateOwnsAttributes, AttributeAlreadyBeingAcquired.")
        .def("attributeOwnershipReleaseResponse",
             [](Client& c, ObjectHandle obj, std::vector<AttributeHandle> attrs) {
                 std::vector<H32> released;
                 {
                     py::gil_scoped_release release;
                     released = c.release_response(obj.value, to_handles(attrs));
                 }
                 return to_tuple<AttributeHandle>(released);
             }, py::arg("object"), py::arg("attributes"),
             "Release attributes this federate was asked for by requestAttributeOwnershipRelease (HLA 1.3 §7.11); returns the tuple of AttributeHandles actually released (those a federate still waits for), the others stay owned. Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned, FederateWasNotAskedToReleaseAttribute.")
        .def("cancelNegotiatedAttributeOwnershipDivestiture",
             [](Client& c, ObjectHandle obj, std::vector<AttributeHandle> attrs) {
                 c.cancel_negotiated_divestiture(obj.value, to_handles(attrs));
             }, py::arg("object"), py::arg("attributes"),
             "Withdraw a negotiated divestiture (HLA 1.3 §7.12). Raises ObjectNotKnown, AttributeNotDefined, AttributeNotOwned, AttributeDivestitureWasNotRequested.")
        .def("cancelAttributeOwnershipAcquisition",
             [](Client& c, ObjectHandle obj, std::vector<AttributeHandle> attrs) {
                 c.cancel_ownership_acquisition(obj.value, to_handles(attrs));
             }, py::arg("object"), py::arg("attributes"),
             "Withdraw an attributeOwnershipAcquisition (HLA 1.3 §7.13): confirmAttributeOwnershipAcquisitionCancellation follows for what was still awaited. Raises ObjectNotKnown, AttributeNotDefined, AttributeAlreadyOwned, AttributeAcquisitionWasNotRequested.")
        .def("queryAttributeOwnership",
             [](Client& c, ObjectHandle obj, AttributeHandle attr) { c.query_ownership(obj.value, attr.value); },
             py::arg("object"), py::arg("attribute"),
             "Ask who owns an attribute (HLA 1.3 §7.15): informAttributeOwnership(object, attribute, owner) or attributeIsNotOwned(object, attribute) follows. Raises ObjectNotKnown, AttributeNotDefined.")
        .def("isAttributeOwnedByFederate",
             [](Client& c, ObjectHandle obj, AttributeHandle attr) { return c.is_owned(obj.value, attr.value); },
             py::arg("object"), py::arg("attribute"),
             "Whether this federate owns the attribute (HLA 1.3 §7.17), as of the ownership notifications delivered so far; answered locally. Raises ObjectNotKnown, AttributeNotDefined.")
        // save/restore (HLA 1.3 §4.11-4.22; docs/save-restore.md)
        .def("requestFederationSave",
             [](Client& c, py::object label, std::optional<double> time) {
                 const std::string l = to_bytes(label, "label");
                 py::gil_scoped_release release;
                 c.request_federation_save(l, time);
             }, py::arg("label"), py::arg("theTime") = py::none(),
             "Ask every federate to save (HLA 1.3 §4.11): initiateFederateSave(label) goes to each, then federationSaved() or federationNotSaved(). With theTime, a regulating or constrained federate is told once granted theTime or beyond; the others at once. The gateway keeps its part (in --save-dir as a file). Raises FederationTimeAlreadyPassed, InvalidFederationTime, SaveInProgress, RestoreInProgress.")
        .def("federateSaveBegun", &Client::federate_save_begun,
             "Tell the RTI this federate started saving (HLA 1.3 §4.13). Raises SaveNotInitiated.")
        .def("federateSaveComplete", [](Client& c) { c.federate_save_complete(true); },
             "Tell the RTI this federate saved its state (HLA 1.3 §4.14). Raises SaveNotInitiated.")
        .def("federateSaveNotComplete", [](Client& c) { c.federate_save_complete(false); },
             "Tell the RTI this federate could not save (HLA 1.3 §4.14): everyone gets federationNotSaved(). Raises SaveNotInitiated.")
        .def("requestFederationRestore",
             [](Client& c, py::object label) {
                 const std::string l = to_bytes(label, "label");
                 py::gil_scoped_release release;
                 c.request_federation_restore(l);
             }, py::arg("label"),
             "Ask to restore the save `label` (HLA 1.3 §4.17), from memory or the gateway's --save-dir; the joined federates must have the names of those saved. requestFederationRestoreSucceeded(label) or requestFederationRestoreFailed(label, reason) follows, then federationRestoreBegun(), initiateFederateRestore(label, federateHandle) and federationRestored() / federationNotRestored() at every federate. Raises SaveInProgress, RestoreInProgress.")
        .def("federateRestoreComplete", [](Client& c) { c.federate_restore_complete(true); },
             "Tell the RTI this federate restored its state (HLA 1.3 §4.21). Raises RestoreNotRequested.")
        .def("federateRestoreNotComplete", [](Client& c) { c.federate_restore_complete(false); },
             "Tell the RTI this federate could not restore (HLA 1.3 §4.21): everyone gets federationNotRestored(). Raises RestoreNotRequested.")
        // support services
        .def("getObjectClassHandle", [](Client& c, const std::string& n) { return ObjectClassHandle{c.object_class_handle(n)}; },
             py::arg("name"),
             "Handle of an object class by qualified or bare name ('ObjectRoot.robot', 'robot'). Raises NameNotFound.")
        .def("getObjectClassName", [](Client& c, ObjectClassHandle h) { return c.object_class_name(h.value); },
             py::arg("objectClass"),
             "Name of an object class, qualified as CERTI does ('robot', 'robot.turtlebot': root classes are not prepended). Raises ObjectClassNotDefined.")
        .def("getAttributeHandle",
             [](Client& c, const std::string& n, ObjectClassHandle cls) { return AttributeHandle{c.attribute_handle(n, cls.value)}; },
             py::arg("name"), py::arg("objectClass"),
             "Handle of an attribute of an object class. Raises ObjectClassNotDefined, NameNotFound.")
        .def("getAttributeName",
             [](Client& c, AttributeHandle a, ObjectClassHandle cls) { return c.attribute_name(a.value, cls.value); },
             py::arg("attribute"), py::arg("objectClass"),
             "Name of an attribute of an object class. Raises ObjectClassNotDefined, AttributeNotDefined.")
        .def("getInteractionClassHandle",
             [](Client& c, const std::string& n) { return InteractionClassHandle{c.interaction_class_handle(n)}; },
             py::arg("name"),
             "Handle of an interaction class by name. Raises NameNotFound.")
        .def("getInteractionClassName", [](Client& c, InteractionClassHandle h) { return c.interaction_class_name(h.value); },
             py::arg("interactionClass"),
             "Qualified name of an interaction class. Raises InteractionClassNotDefined.")
        .def("getParameterHandle",
             [](Client& c, const std::string& n, InteractionClassHandle ic) {
                 return ParameterHandle{c.parameter_handle(n, ic.value)};
             }, py::arg("name"), py::arg("interactionClass"),
             "Handle of a parameter of an interaction class. Raises InteractionClassNotDefined, NameNotFound.")
        .def("getParameterName",
             [](Client& c, ParameterHandle p, InteractionClassHandle ic) { return c.parameter_name(p.value, ic.value); },
             py::arg("parameter"), py::arg("interactionClass"),
             "Name of a parameter. Raises InteractionClassNotDefined, InteractionParameterNotDefined.")
        .def("getObjectInstanceHandle",
             [](Client& c, const std::string& n) { return ObjectHandle{c.object_instance_handle(n)}; }, py::arg("name"),
             "Handle of an object known to this federate, by name. Raises ObjectNotKnown.")
        .def("getObjectInstanceName", [](Client& c, ObjectHandle o) { return c.object_instance_name(o.value); },
             py::arg("object"),
             "Name of an object known to this federate. Raises ObjectNotKnown.")
        .def("getObjectClass", [](Client& c, ObjectHandle o) { return ObjectClassHandle{c.object_class_of(o.value)}; },
             py::arg("object"),
             "Class of a known object (for a discovered one, the class it was discovered as). Raises ObjectNotKnown.")
        .def("getRoutingSpaceHandle",
             [](Client& c, const std::string& n) { return SpaceHandle{c.routing_space_handle(n)}; }, py::arg("name"),
             "Handle of a routing space of the FOM. Raises NameNotFound.")
        .def("getRoutingSpaceName", [](Client& c, SpaceHandle s) { return c.routing_space_name(s.value); },
             py::arg("space"),
             "Name of a routing space. Raises SpaceNotDefined.")
        .def("getDimensionHandle",
             [](Client& c, const std::string& n, SpaceHandle s) { return DimensionHandle{c.dimension_handle(n, s.value)}; },
             py::arg("name"), py::arg("space"),
             "Handle of a dimension of a routing space. Raises SpaceNotDefined, NameNotFound.")
        .def("getDimensionName",
             [](Client& c, DimensionHandle d, SpaceHandle s) { return c.dimension_name(d.value, s.value); },
             py::arg("dimension"), py::arg("space"),
             "Name of a dimension. Raises SpaceNotDefined, DimensionNotDefined.")
        .def("getAttributeRoutingSpaceHandle",
             [](Client& c, AttributeHandle a, ObjectClassHandle cls) {
                 return SpaceHandle{c.attribute_routing_space(a.value, cls.value)};
             }, py::arg("attribute"), py::arg("objectClass"),
             "Routing space of an attribute (handle 0 when it has none).")
        .def("getInteractionRoutingSpaceHandle",
             [](Client& c, InteractionClassHandle ic) { return SpaceHandle{c.interaction_routing_space(ic.value)}; },
             py::arg("interactionClass"),
             "Routing space of an interaction class (handle 0 when it has none).")
        .def("_federate_handle", [](Client& c) { return FederateHandle{c.federate_handle()}; })
        // data distribution management (HLA 1.3 §9; routing by extent overlap in the gateway, docs/ddm.md)
        .def("createRegion",
             [](Client& c, SpaceHandle space, const PyExtent& extent) {
                 return RegionHandle{c.create_region(space.value, to_extent(extent))};
             }, py::arg("space"), py::arg("extent"),
             "Create a region of a routing space (HLA 1.3 §9.2) with one extent [(DimensionHandle, (lower, upper)), ...]: closed ranges within [MIN_EXTENT, MAX_EXTENT]; dimensions not given span the whole axis. The region belongs to this federate. Raises SpaceNotDefined, DimensionNotDefined, InvalidExtents.")
        .def("notifyAboutRegionModification",
             [](Client& c, RegionHandle r, std::optional<PyExtent> extent) {
                 std::optional<Client::Extent> e;
                 if (extent) e = to_extent(*extent);
                 c.modify_region(r.value, e);
             }, py::arg("region"), py::arg("extent") = py::none(),
             "Apply a region's new extent (HLA 1.3 §9.3): given here in createRegion's form (the dimensions not given span the whole axis), it is used for every message routed from now on. Raises RegionNotKnown, DimensionNotDefined, InvalidExtents.")
        .def("deleteRegion", [](Client& c, RegionHandle r) { c.delete_region(r.value); }, py::arg("region"),
             "Delete a region (HLA 1.3 §9.4). Raises RegionNotKnown, RegionInUse (a subscription or an update association uses it).")
        .def("getRegionExtent",
             [](Client& c, RegionHandle r) {
                 auto [space, extent] = c.region_extent(r.value);
                 py::list ranges;
                 for (const auto& range : extent)
                     ranges.append(py::make_tuple(DimensionHandle{range.dimension}, py::make_tuple(range.lower, range.upper)));
                 return py::make_tuple(SpaceHandle{space}, ranges);
             }, py::arg("region"),
             "(SpaceHandle, [(DimensionHandle, (lower, upper)), ...]) of a region of this federate, every dimension listed. Raises RegionNotKnown.")
        .def("getRegions",
             [](Client& c) {
                 py::list out;
                 for (auto handle : c.regions()) out.append(RegionHandle{handle});
                 return out;
             },
             "hlacore extension: the RegionHandles of the regions this federate holds, in creation order. After a restore they are the saved regions, so a federate restored in a new process (rtig restarted on its --save-dir) gets handles for them here.")
        .def("registerObjectInstanceWithRegion",
             [](Client& c, ObjectClassHandle cls, std::vector<std::pair<AttributeHandle, RegionHandle>> pairs,
                std::optional<std::string> name) {
                 std::vector<std::pair<H32, H32>> regions;
                 for (const auto& [a, r] : pairs) regions.emplace_back(a.value, r.value);
                 H32 h;
                 {
                     py::gil_scoped_release release;
                     h = c.register_object_with_region(cls.value, regions, name.value_or(""));
                 }
                 return ObjectHandle{h};
             }, py::arg("objectClass"), py::arg("attributes"), py::arg("objectName") = py::none(),
             "registerObjectInstance with update regions [(AttributeHandle, RegionHandle), ...] in place before any subscriber can discover the instance (HLA 1.3 §9.5). Raises ObjectClassNotDefined, ObjectClassNotPublished, AttributeNotDefined, AttributeNotPublished, RegionNotKnown, InvalidRegionContext, ObjectAlreadyRegistered.")
        .def("associateRegionForUpdates",
             [](Client& c, RegionHandle r, ObjectHandle obj, std::vector<AttributeHandle> attrs) {
                 c.associate_region(r.value, obj.value, to_handles(attrs));
             }, py::arg("region"), py::arg("object"), py::arg("attributes"),
             "This federate's updates of these attributes of the object reach only the subscribers whose regions overlap `region` (HLA 1.3 §9.6); replaces the attribute's previous update region. Raises ObjectNotKnown, AttributeNotDefined, RegionNotKnown, InvalidRegionContext (an attribute of another routing space).")
        .def("unassociateRegionForUpdates",
             [](Client& c, RegionHandle r, ObjectHandle obj) { c.unassociate_region(r.value, obj.value); },
             py::arg("region"), py::arg("object"),
             "The object's attributes associated with `region` go back to the default region, the whole space (HLA 1.3 §9.7). Raises ObjectNotKnown, RegionNotKnown, InvalidRegionContext (not associated).")
        .def("subscribeObjectClassAttributesWithRegion",
             [](Client& c, ObjectClassHandle cls, RegionHandle r, std::vector<AttributeHandle> attrs, bool active) {
                 c.subscribe_object_class_with_region(cls.value, r.value, to_handles(attrs), active);
             }, py::arg("objectClass"), py::arg("region"), py::arg("attributes"), py::arg("active") = true,
             "Subscribe to attributes of a class through a region (HLA 1.3 §9.8): reflected only when the updater's region overlaps it; replaces the attributes subscribed with this class and region. Raises ObjectClassNotDefined, AttributeNotDefined, RegionNotKnown, InvalidRegionContext.")
        .def("unsubscribeObjectClassWithRegion",
             [](Client& c, ObjectClassHandle cls, RegionHandle r) { c.unsubscribe_object_class_with_region(cls.value, r.value); },
             py::arg("objectClass"), py::arg("region"),
             "End the subscription to a class through a region (HLA 1.3 §9.9). Raises ObjectClassNotDefined, RegionNotKnown, ObjectClassNotSubscribed.")
        .def("subscribeInteractionClassWithRegion",
             [](Client& c, InteractionClassHandle ic, RegionHandle r, bool active) {
                 c.subscribe_interaction_class_with_region(ic.value, r.value, active);
             }, py::arg("interactionClass"), py::arg("region"), py::arg("active") = true,
             "Subscribe to an interaction class through a region (HLA 1.3 §9.10): received when sent without region or with an overlapping one. Raises InteractionClassNotDefined, RegionNotKnown, InvalidRegionContext.")
        .def("unsubscribeInteractionClassWithRegion",
             [](Client& c, InteractionClassHandle ic, RegionHandle r) {
                 c.unsubscribe_interaction_class_with_region(ic.value, r.value);
             }, py::arg("interactionClass"), py::arg("region"),
             "End the subscription to an interaction class through a region (HLA 1.3 §9.11). Raises InteractionClassNotDefined, RegionNotKnown, InteractionClassNotSubscribed.")
        .def("sendInteractionWithRegion",
             [](Client& c, InteractionClassHandle ic, py::handle values, RegionHandle r, py::handle tag,
                std::optional<double> time) {
                 auto serial = c.send_interaction_with_region(
                     ic.value, to_handle_values<ParameterHandle>(values, "ParameterHandle"), r.value, to_bytes(tag, "tag"), time);
                 return serial_result(serial, time, c);
             }, py::arg("interactionClass"), py::arg("parameters"), py::arg("region"), py::arg("tag"),
             py::arg("time") = py::none(),
             "Send an interaction that reaches the plain subscribers and those subscribed through a region overlapping `region` (HLA 1.3 §9.12). With a time, returns an EventRetractionHandle. Raises InteractionClassNotDefined, InteractionClassNotPublished, InteractionParameterNotDefined, RegionNotKnown, InvalidRegionContext, InvalidFederationTime.")
        .def("requestClassAttributeValueUpdateWithRegion",
             [](Client& c, ObjectClassHandle cls, std::vector<AttributeHandle> attrs, RegionHandle r) {
                 c.request_class_update_with_region(cls.value, to_handles(attrs), r.value);
             }, py::arg("objectClass"), py::arg("attributes"), py::arg("region"),
             "Ask the owners to provide the attributes of instances of the class whose update region overlaps `region` (HLA 1.3 §9.13); unassociated attributes are in the whole space. Raises ObjectClassNotDefined, AttributeNotDefined, RegionNotKnown.")
        // time management
        .def("enableTimeRegulation", &Client::enable_time_regulation, py::arg("federateTime"), py::arg("lookahead"),
             "Become time-regulating (HLA 1.3 §8.2): timestamped messages from this federate are delivered in timestamp order to constrained federates. timeRegulationEnabled(t0) follows, with t0 >= federateTime chosen so no message can land in another federate's past. Raises TimeRegulationAlreadyEnabled, EnableTimeRegulationPending, TimeAdvanceAlreadyInProgress, InvalidFederationTime, InvalidLookahead.")
        .def("disableTimeRegulation", &Client::disable_time_regulation,
             "Stop being time-regulating (HLA 1.3 §8.4); takes effect at once. Raises TimeRegulationWasNotEnabled.")
        .def("enableTimeConstrained", &Client::enable_time_constrained,
             "Become time-constrained (HLA 1.3 §8.5): timestamped messages arrive in timestamp order, never in this federate's past. timeConstrainedEnabled(t) follows. Raises TimeConstrainedAlreadyEnabled, EnableTimeConstrainedPending, TimeAdvanceAlreadyInProgress.")
        .def("disableTimeConstrained", &Client::disable_time_constrained,
             "Stop being time-constrained (HLA 1.3 §8.7); queued timestamped messages are delivered at once. Raises TimeConstrainedWasNotEnabled.")
        .def("timeAdvanceRequest",
             [](Client& c, double t) { c.time_advance(hlacore::AdvanceKind::TimeAdvanceRequest, t); }, py::arg("theTime"),
             "Ask to advance to theTime (HLA 1.3 §8.8); every timestamped message <= theTime is delivered, then timeAdvanceGrant(theTime). Raises FederationTimeAlreadyPassed, TimeAdvanceAlreadyInProgress, EnableTimeRegulationPending, EnableTimeConstrainedPending, InvalidFederationTime.")
        .def("timeAdvanceRequestAvailable",
             [](Client& c, double t) { c.time_advance(hlacore::AdvanceKind::TimeAdvanceRequestAvailable, t); },
             py::arg("theTime"),
             "Like timeAdvanceRequest, but messages at theTime itself may still arrive after the grant (HLA 1.3 §8.9); with zero lookahead, this federate may then send at theTime.")
        .def("nextEventRequest",
             [](Client& c, double t) { c.time_advance(hlacore::AdvanceKind::NextEventRequest, t); }, py::arg("theTime"),
             "Advance to the next timestamped message or theTime, whichever comes first (HLA 1.3 §8.10); the messages at the grant time are delivered, then timeAdvanceGrant(grant). Same exceptions as timeAdvanceRequest.")
        .def("nextEventRequestAvailable",
             [](Client& c, double t) { c.time_advance(hlacore::AdvanceKind::NextEventRequestAvailable, t); },
             py::arg("theTime"),
             "Like nextEventRequest, but further messages at the grant time may arrive after the grant (HLA 1.3 §8.11).")
        .def("flushQueueRequest",
             [](Client& c, double t) { c.time_advance(hlacore::AdvanceKind::FlushQueueRequest, t); }, py::arg("theTime"),
             "Deliver every queued timestamped message now and advance as far towards theTime as is safe (HLA 1.3 §8.12).")
        .def("enableAsynchronousDelivery", [](Client& c) { c.set_asynchronous_delivery(true); },
             "Deliver receive-order messages to this constrained federate even when it is not advancing (HLA 1.3 §8.13). Raises AsynchronousDeliveryAlreadyEnabled.")
        .def("disableAsynchronousDelivery", [](Client& c) { c.set_asynchronous_delivery(false); },
             "Hold receive-order messages while this constrained federate is not advancing (HLA 1.3 §8.14; the default). Raises AsynchronousDeliveryAlreadyDisabled.")
        .def("queryLBTS", &Client::query_lbts, py::call_guard<py::gil_scoped_release>(),
             "The lowest timestamp any other regulating federate may still send (HLA 1.3 §8.15); inf when there is none.")
        .def("queryFederateTime", &Client::query_federate_time,
             "This federate's logical time (HLA 1.3 §8.16), as of the last grant delivered.")
        .def("queryMinNextEventTime", &Client::query_min_next_event_time, py::call_guard<py::gil_scoped_release>(),
             "min(LBTS, the earliest timestamped message queued for this federate) (HLA 1.3 §8.17).")
        .def("modifyLookahead", &Client::modify_lookahead, py::arg("theLookahead"),
             "Change the lookahead (HLA 1.3 §8.18); a lower value never allows a timestamp below one already allowed. Raises InvalidLookahead.")
        .def("queryLookahead", &Client::query_lookahead, "The current lookahead (HLA 1.3 §8.19); 0 before regulation.")
        .def("retract",
             [](Client& c, const EventRetractionHandle& h) { c.retract(h.sender, h.serial); }, py::arg("theHandle"),
             "Retract a timestamped message this federate sent above its current time (HLA 1.3 §8.21): it is removed where it is still queued; federates that already received it get requestRetraction. Raises InvalidRetractionHandle.")
        .def("_time_advance_pending", &Client::time_advance_pending)
        .def("_lowest_sendable_time", &Client::lowest_sendable_time)
        .def("_status", &Client::query_status, py::call_guard<py::gil_scoped_release>())
        // evoking callbacks
        .def("_poll", &Client::poll_now, py::call_guard<py::gil_scoped_release>())
        .def("_wait", &wait_for_callback, py::arg("timeout"))
        .def("_has_callbacks", &Client::has_callbacks)
        .def("_next_callback", [](Client& c) -> py::object {
            auto m = c.pop_callback();
            if (!m) return py::none();
            return to_callback(*m);
        })
        .def("_dispatch", &dispatch, py::arg("ambassador"), py::arg("stop_after_grant"), py::arg("max_seconds"));

    // The pure time manager, exposed for the property tests (tests/test_time_manager_properties.py).
    using hlacore::AdvanceKind;
    using hlacore::TimeManager;
    py::class_<TimeManager>(m, "_TimeManager")
        .def(py::init<>())
        .def("add_federate", &TimeManager::add_federate)
        .def("remove_federate", &TimeManager::remove_federate)
        .def("enable_regulation", &TimeManager::enable_regulation)
        .def("disable_regulation", &TimeManager::disable_regulation)
        .def("enable_constrained", &TimeManager::enable_constrained)
        .def("disable_constrained", [](TimeManager& tm, std::uint32_t f) {
            py::list out;
            for (auto& frame : tm.disable_constrained(f)) out.append(py::bytes(frame));
            return out;
        })
        .def("set_asynchronous_delivery", &TimeManager::set_asynchronous_delivery)
        .def("modify_lookahead", &TimeManager::modify_lookahead)
        .def("request", [](TimeManager& tm, std::uint32_t f, int kind, double t) {
            if (kind < 1 || kind > 5) throw py::value_error("kind must be 1-5");
            tm.request(f, static_cast<AdvanceKind>(kind), t);
        })
        .def("is_tso", &TimeManager::is_tso)
        .def("holds_receive_order", &TimeManager::holds_receive_order)
        .def("may_send", &TimeManager::may_send)
        .def("promise", &TimeManager::promise)
        .def("regulating", &TimeManager::regulating)
        .def("enabling_regulation", &TimeManager::enabling_regulation)
        .def("advancing", &TimeManager::advancing)
        .def("enqueue_tso", [](TimeManager& tm, std::uint32_t receiver, double t, std::uint32_t sender,
                               std::uint64_t serial, py::bytes payload) {
            tm.enqueue_tso(receiver, hlacore::TsoMessage{t, sender, serial, std::string(payload)});
        })
        .def("enqueue_receive_order",
             [](TimeManager& tm, std::uint32_t receiver, py::bytes payload) { tm.enqueue_receive_order(receiver, payload); })
        .def("retract", [](TimeManager& tm, std::uint32_t sender, std::uint64_t serial) {
            return tm.retract(sender, serial).size();
        })
        .def("release", [](TimeManager& tm) {
            py::list out;
            auto time_or_none = [](const std::optional<double>& t) -> py::object {
                return t ? py::object(py::cast(*t)) : py::object(py::none());
            };
            // (federate, frames, grant, constrained_enabled, regulation_enabled)
            for (auto& r : tm.release()) {
                py::list frames;
                for (auto& frame : r.frames) frames.append(py::bytes(frame));
                out.append(py::make_tuple(r.federate, frames, time_or_none(r.grant),
                                          time_or_none(r.constrained_enabled), time_or_none(r.regulation_enabled)));
            }
            return out;
        })
        .def("output_bound", &TimeManager::output_bound)
        .def("lbts", &TimeManager::lbts)
        .def("min_next_event_time", &TimeManager::min_next_event_time)
        .def("federate_time", &TimeManager::federate_time)
        .def("status", [](TimeManager& tm) {
            py::list out;
            for (const auto& s : tm.status()) {
                py::dict d;
                d["federate"] = s.federate;
                d["time"] = s.time;
                d["lookahead"] = s.lookahead;
                d["regulating"] = s.regulating;
                d["constrained"] = s.constrained;
                d["asynchronous_delivery"] = s.asynchronous_delivery;
                d["pending"] = static_cast<int>(s.pending);
                d["pending_time"] = s.pending_time;
                d["queued_tso"] = s.queued_tso;
                d["queued_ro"] = s.queued_ro;
                d["enabling_regulation"] = s.enabling_regulation;
                d["lbts"] = s.lbts;
                d["output_bound"] = s.output_bound;
                out.append(d);
            }
            return out;
        });

    // The wire message names in code order (code = index + 1), for the hostile-client tests.
    m.def("_message_names", [] {
        std::vector<std::string> names;
        for (int i = 1; i < static_cast<int>(wire::MessageType::Count); ++i)
            names.emplace_back(wire::message_name(static_cast<wire::MessageType>(i)));
        return names;
    });
    m.def("_transportation_handle", [](std::uint32_t v) { return TransportationHandle{v}; });
    m.def("_ordering_handle", [](std::uint32_t v) { return OrderingHandle{v}; });
    m.def("_federate_handle_of", [](std::uint32_t v) { return FederateHandle{v}; });
}
