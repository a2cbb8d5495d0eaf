// hlacore._core: the native layer under `import hlacore`. Declarations and conversions only: the handles,
// the in-process gateway, RTIAmbassadorBase (its services added per HLA service group by the files of the
// same name in this folder), the pure TimeManager for the property tests.
#include <map>
#include <memory>
#include <thread>

#include "bindings/convert.hpp"
#include "fedpro/server.hpp"
#include "rti/busy_poll.hpp"
#include "rti/client/options.hpp"
#include "rti/server/options.hpp"
#include "rti/server/time_manager.hpp"
#include "rti/wire/callbacks.hpp"

void bind_fed(py::module_& m);

namespace hlacore::bindings {
namespace {

// ---- the in-process gateway ----

class BackgroundGateway {
public:
    // The options given by keyword, as text (hlacore.Gateway makes it), checked by the gateway's table:
    // ValueError naming the one refused.
    explicit BackgroundGateway(const std::vector<std::pair<std::string, std::string>>& given) {
        GatewayOptions options;
        for (const auto& [keyword, text] : given) {
            const auto* option = find_option(gateway_options(), keyword, Given::Keyword);
            if (!option) throw std::invalid_argument("no gateway option named '" + keyword + "'");
            apply(options, *option, Given::Keyword, text);  // RuntimeError for a secret file that cannot be used
        }
        if (const std::string conflict = gateway_options_conflict(options, Given::Keyword); !conflict.empty())
            throw std::invalid_argument(conflict);
        // The door's federates reach the gateway through a Unix socket: the one asked for, else one of their own.
        if (!options.fedpro.empty() && options.unix_path.empty()) {
            door_socket_ = std::make_unique<fedpro::PrivateSocket>();
            options.unix_path = door_socket_->path();
        }
        gateway_ = std::make_unique<Gateway>(options);
        host_ = gateway_->host();
        port_ = gateway_->port();
        if (!options.fedpro.empty()) {
            fedpro_ = fedpro::open_door(options, "unix:" + options.unix_path);  // its federates connect once it runs
            gateway_->add_status_section([door = fedpro_.get()] { return door->status_json(); });
        }
        thread_ = std::thread([this] { gateway_->run(); });
    }
    ~BackgroundGateway() { stop(); }
    // Stops the loop and closes the gateway: its sockets (a Unix socket's file removed) and its recording.
    void stop() {
        if (fedpro_) fedpro_->stop();  // its federates resign while the gateway still serves
        if (thread_.joinable()) {
            gateway_->stop();
            thread_.join();
        }
        gateway_.reset();
        fedpro_.reset();  // after the gateway, whose status report reads it
        door_socket_.reset();  // after the gateway, which removes the socket itself
    }
    const std::string& host() const { return host_; }
    std::uint16_t port() const { return port_; }
    bool running() const { return thread_.joinable(); }
    std::uint16_t fedpro_port() const { return fedpro_ ? fedpro_->port() : 0; }

private:
    std::unique_ptr<fedpro::PrivateSocket> door_socket_;
    std::unique_ptr<Gateway> gateway_;
    std::unique_ptr<fedpro::Server> fedpro_;
    std::string host_;
    std::uint16_t port_ = 0;
    std::thread thread_;
};

// While a client call blocks: the GIL released (if this thread holds it), and a signal handled by Python
// (Ctrl-C raises KeyboardInterrupt out of the call).
class PythonWaitHost : public WaitHost {
public:
    void* begin_wait() override { return PyGILState_Check() ? PyEval_SaveThread() : nullptr; }
    void end_wait(void* state) override {
        if (state) PyEval_RestoreThread(static_cast<PyThreadState*>(state));
    }
    void interrupted() override {
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
};

std::unique_ptr<Client> connect_client(ClientSettings settings) {
    static PythonWaitHost wait_host;
    settings.options.wait_host = &wait_host;
    py::gil_scoped_release release;
    return std::make_unique<Client>(settings.host, settings.port, settings.options);
}

// A table's rows as Python sees them: (keyword, flag or variable, placeholder or None for a switch, repeated,
// the default as text, help).
template <class Settings>
py::list option_rows(const Options<Settings>& table) {
    py::list rows;
    const Settings defaults{};
    for (const auto& o : table) {
        if (!o.keyword) continue;
        const char* spelled = o.flag ? o.flag : o.variable;
        rows.append(py::make_tuple(o.keyword, spelled ? py::object(py::str(spelled)) : py::object(py::none()),
                                   o.metavar ? py::object(py::str(o.metavar)) : py::object(py::none()), o.repeated,
                                   o.shown ? o.shown(defaults) : std::string(), o.help));
    }
    return rows;
}

}  // namespace
}  // namespace hlacore::bindings

PYBIND11_MODULE(_core, m) {
    using namespace hlacore::bindings;
    using hlacore::Client;
    namespace wire = hlacore::wire;
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
    bind_retraction(m);

    bind_fed(m);

    // The bounds of the gateway's options, which hlacore.Gateway checks (server/gateway.hpp).
    m.attr("MIN_CLIENT_BUDGET") = hlacore::kMinClientBudget;
    m.attr("MAX_BUSY_POLL_US") = hlacore::kMaxBusyPollUs;
    m.attr("MAX_FRAME_RANGE") = py::make_tuple(hlacore::kMinMaxFrame, hlacore::kMaxMaxFrame);
    m.attr("MAX_DATAGRAM_RANGE") = py::make_tuple(hlacore::kMinMaxDatagram, hlacore::wire::kMaxDatagramLimit);
    m.def("gateway_options", [] { return option_rows(hlacore::gateway_options()); },
          "The gateway's options (server/options.cpp): (keyword, rtig flag, placeholder or None for a switch, repeated, "
          "default as text, help) each.");
    m.def("client_options", [] { return option_rows(hlacore::client_options()); },
          "The client's options (client/options.cpp): (keyword, environment variable, placeholder, repeated, default "
          "as text, help) each.");
    py::class_<hlacore::ClientSettings>(m, "ClientSettings", "Where and how a client connects (client_settings()).")
        .def_readonly("host", &hlacore::ClientSettings::host, "The gateway's host, or unix:PATH.")
        .def_readonly("port", &hlacore::ClientSettings::port, "The gateway's port, 0 for a Unix socket.");
    m.def("client_settings", &hlacore::client_settings, py::arg("given"),
          "The client's settings from the options given (keyword: text), else the environment, else the defaults; "
          "RTIinternalError naming a value refused.");
    py::class_<BackgroundGateway>(m, "BackgroundGateway",
                                  "The gateway serving on a thread of this process; hlacore.Gateway is its Python face.")
        .def(py::init<const std::vector<std::pair<std::string, std::string>>&>(), py::arg("given"),
             py::call_guard<py::gil_scoped_release>())
        .def("stop", &BackgroundGateway::stop, py::call_guard<py::gil_scoped_release>(),
             "Stops serving and waits for the gateway's thread to end.")
        .def_property_readonly("host", &BackgroundGateway::host, "The address it listens on.")
        .def_property_readonly("port", &BackgroundGateway::port, "The TCP port it listens on (the one picked, for port 0).")
        .def_property_readonly("running", &BackgroundGateway::running, "Whether its thread still serves.")
        .def_property_readonly("fedpro_port", &BackgroundGateway::fedpro_port,
                               "The Federate Protocol's TCP port (the one picked, for port 0); 0 without the door.");

    Ambassador rtia(m, "RTIAmbassadorBase",
                    "The federate's side of the connection to a gateway: the HLA 1.3 services under their PyHLA names; "
                    "hlacore.rti.RTIAmbassador builds on it.");
    rtia
        .def(py::init(&connect_client), py::arg("settings"))
        .def_property_readonly("address", &Client::address, "The gateway's \"host:port\" this ambassador is connected to.")
        .def("fileno", &Client::fileno,
             "The connection's socket, for select() or an event loop's add_reader (hlacore.aio): readable when the "
             "gateway has sent something, which tick() then delivers. Best-effort messages may arrive on a second, "
             "UDP socket (datagram_status()).")
        .def("_datagram_fileno", &Client::datagram_fileno)
        .def("datagram_status", [](const Client& c) {
                 const hlacore::DatagramStatus s = c.datagram_status();
                 py::dict d;
                 d["path"] = s.path;
                 d["reason"] = s.reason;
                 d["sent"] = s.counts.sent;
                 d["send_failed"] = s.counts.send_failed;
                 d["oversize"] = s.counts.oversize;
                 d["received"] = s.counts.received;
                 d["lost"] = s.counts.lost;
                 d["reordered"] = s.counts.reordered;
                 d["duplicates"] = s.counts.duplicates;
                 d["early"] = s.counts.early;
                 return d;
             },
             "Best effort over UDP (docs/networking.md): {'path': whether best-effort messages travel as datagrams, "
             "'reason': why not, when not, then counts: 'sent', 'send_failed', 'oversize' (sent over TCP for their "
             "size) of this federate's datagrams; 'received', 'lost', 'reordered', 'duplicates' of the gateway's, and "
             "'early' (reflections ahead of their object's discovery, dropped)}.");
    bind_federation(rtia);
    bind_sync_points(rtia);
    bind_save_restore(rtia);
    bind_declarations(rtia);
    bind_objects(rtia);
    bind_ownership(rtia);
    bind_time(rtia);
    bind_regions(rtia);
    bind_support(rtia);
    bind_callbacks(rtia);
    // The callbacks an HLA 1.3 ambassador may define, in their one declaration's order (wire/callbacks.hpp).
    m.attr("CALLBACKS") = py::tuple(py::cast(std::vector<std::string>(
        std::begin(hlacore::wire::kCallbackNames), std::begin(hlacore::wire::kCallbackNames) + hlacore::wire::kHla13Callbacks)));

    // The pure time manager, exposed for the property tests (tests/rti/test_time_manager_properties.py).
    using hlacore::AdvanceKind;
    using hlacore::TimeManager;
    py::class_<TimeManager>(m, "_TimeManager")
        .def(py::init([](const std::string& semantics) {
                 TimeManager tm;
                 tm.set_semantics(hlacore::time_semantics(semantics));
                 return tm;
             }),
             py::arg("semantics") = "exact")
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
                for (auto& frame : r.frames) frames.append(py::bytes(*frame));
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
            static const char* const kFields[] = {"federate", "time", "lookahead", "regulating", "constrained",
                                                  "asynchronous_delivery", "pending", "pending_time", "queued_tso",
                                                  "queued_ro", "enabling_regulation", "lbts", "output_bound"};
            py::list out;
            for (const auto& s : tm.status()) {
                const py::tuple values = py::make_tuple(
                    s.federate, s.time, s.lookahead, s.regulating, s.constrained, s.asynchronous_delivery,
                    static_cast<int>(s.pending), s.pending_time, s.queued_tso, s.queued_ro, s.enabling_regulation,
                    s.lbts, s.output_bound);
                py::dict d;
                for (std::size_t i = 0; i < values.size(); ++i) d[kFields[i]] = values[i];
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
