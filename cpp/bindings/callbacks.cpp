// Callbacks: each message from the gateway becomes (name, arguments) with PyHLA's argument order, the
// names those of wire/callbacks.hpp; dispatch calls the ambassador's method of that name; tick drives it.
#include "bindings/convert.hpp"

#include <algorithm>
#include <array>
#include <bitset>
#include <chrono>
#include <ctime>

#include "rti/wire/callbacks.hpp"

namespace hlacore::bindings {

namespace {

using C = wire::Callback;

// A callback to deliver: which one, and its arguments in PyHLA's order, held for a vectorcall rather than in
// a tuple (a tuple's allocation and its garbage-collector tracking were 4 % of a subscriber's CPU).
struct Named {
    static constexpr std::size_t kMost = 7;  // a timed reflection's
    C callback;
    std::array<py::object, kMost> args;
    std::size_t count = 0;
};

template <class T>
py::object argument(T&& value) {
    if constexpr (std::is_base_of_v<py::object, std::decay_t<T>>) {
        return std::forward<T>(value);
    } else {
        return py::cast(std::forward<T>(value));
    }
}

template <class... Args>
Named named(C callback, Args&&... args) {
    static_assert(sizeof...(Args) <= Named::kMost, "a callback with more arguments than Named holds");
    return {callback, {argument(std::forward<Args>(args))...}, sizeof...(Args)};
}

// The ambassador's method name of each callback, an interned str made once: it is looked up per callback.
const py::object& method_name(C callback) {
    static const auto* names = [] {
        auto* interned = new std::array<py::object, static_cast<std::size_t>(C::Count)>();
        for (std::size_t i = 0; i < interned->size(); ++i)
            (*interned)[i] = py::reinterpret_steal<py::object>(PyUnicode_InternFromString(wire::kCallbackNames[i]));
        return interned;
    }();
    return (*names)[static_cast<std::size_t>(callback)];
}

// A callback that may carry a time: with one, the time and the EventRetractionHandle follow its arguments.
template <class M, class... Args>
Named timed(C callback, const M& m, Args&&... args) {
    if (!m.time) return named(callback, std::forward<Args>(args)...);
    return named(callback, std::forward<Args>(args)..., *m.time, make_retraction({m.sender, m.serial}));
}

// A callback about a set of an object's attributes (ownership, scope, updates on/off).
template <class M, class... Extra>
Named object_attributes(C callback, const M& m, Extra&&... extra) {
    return named(callback, ObjectHandle{m.object}, to_tuple<AttributeHandle>(m.attributes), std::forward<Extra>(extra)...);
}

// Each callback message as the callback it is, with PyHLA's argument order: one overload per message of
// HLACORE_CALLBACK_MESSAGES (wire/callbacks.hpp checks that none is missing).
struct ToCallback {
    Named operator()(const wire::SyncPointRegistrationSucceeded& m) const {
        return named(C::synchronizationPointRegistrationSucceeded, to_str(m.label));
    }
    Named operator()(const wire::SyncPointRegistrationFailed& m) const {
        return named(C::synchronizationPointRegistrationFailed, to_str(m.label));
    }
    Named operator()(const wire::AnnounceSyncPoint& m) const {
        return named(C::announceSynchronizationPoint, to_str(m.label), to_str(m.tag));
    }
    Named operator()(const wire::FederationSynchronized& m) const {
        return named(C::federationSynchronized, to_str(m.label));
    }
    Named operator()(const wire::StartRegistration& m) const {
        return named(C::startRegistrationForObjectClass, ObjectClassHandle{m.object_class});
    }
    Named operator()(const wire::StopRegistration& m) const {
        return named(C::stopRegistrationForObjectClass, ObjectClassHandle{m.object_class});
    }
    Named operator()(const wire::TurnInteractionsOn& m) const {
        return named(C::turnInteractionsOn, InteractionClassHandle{m.interaction_class});
    }
    Named operator()(const wire::TurnInteractionsOff& m) const {
        return named(C::turnInteractionsOff, InteractionClassHandle{m.interaction_class});
    }
    Named operator()(const wire::DiscoverObject& m) const {
        return named(C::discoverObjectInstance, handle_of<ObjectHandle>(m.object), ObjectClassHandle{m.object_class}, to_str(m.name));
    }
    Named operator()(const wire::ReflectAttributes& m) const {
        return timed(C::reflectAttributeValues, m, handle_of<ObjectHandle>(m.object), to_dict<AttributeHandle>(m.values), to_str(m.tag),
                     handle_of<OrderingHandle>(m.order), handle_of<TransportationHandle>(m.transport));
    }
    Named operator()(const wire::ReceiveInteraction& m) const {
        return timed(C::receiveInteraction, m, handle_of<InteractionClassHandle>(m.interaction_class), to_dict<ParameterHandle>(m.values),
                     to_str(m.tag), handle_of<OrderingHandle>(m.order), handle_of<TransportationHandle>(m.transport));
    }
    Named operator()(const wire::RemoveObject& m) const {
        return timed(C::removeObjectInstance, m, handle_of<ObjectHandle>(m.object), to_str(m.tag));
    }
    Named operator()(const wire::ObjectNamesReserved& m) const {
        if (m.multiple) {
            py::tuple names(m.names.size());
            for (std::size_t i = 0; i < m.names.size(); ++i) names[i] = to_str(m.names[i]);
            return named(m.success ? C::multipleObjectInstanceNameReservationSucceeded
                                   : C::multipleObjectInstanceNameReservationFailed, std::move(names));
        }
        return named(m.success ? C::objectInstanceNameReservationSucceeded : C::objectInstanceNameReservationFailed,
                     to_str(m.names.empty() ? std::string() : m.names.front()));
    }
    Named operator()(const wire::AttributeTransportationReported& m) const {
        return named(C::reportAttributeTransportationType, ObjectHandle{m.object}, AttributeHandle{m.attribute},
                     TransportationHandle{m.transport});
    }
    Named operator()(const wire::InteractionTransportationReported& m) const {
        return named(C::reportInteractionTransportationType, FederateHandle{m.federate},
                     InteractionClassHandle{m.interaction_class}, TransportationHandle{m.transport});
    }
    Named operator()(const wire::TimeRegulationEnabled& m) const { return named(C::timeRegulationEnabled, m.time); }
    Named operator()(const wire::TimeConstrainedEnabled& m) const { return named(C::timeConstrainedEnabled, m.time); }
    Named operator()(const wire::TimeAdvanceGrant& m) const { return named(C::timeAdvanceGrant, m.time); }
    Named operator()(const wire::RequestRetraction& m) const {
        return named(C::requestRetraction, EventRetractionHandle{m.sender, m.serial});
    }
#define HLACORE_X(message, callback) \
    Named operator()(const wire::message& m) const { return object_attributes(C::callback, m); }
    HLACORE_OBJECT_ATTRIBUTE_CALLBACKS(HLACORE_X)
#undef HLACORE_X
    Named operator()(const wire::RequestOwnershipAssumption& m) const {
        return object_attributes(C::requestAttributeOwnershipAssumption, m, to_str(m.tag));
    }
    Named operator()(const wire::RequestOwnershipRelease& m) const {
        return object_attributes(C::requestAttributeOwnershipRelease, m, to_str(m.tag));
    }
    Named operator()(const wire::OwnershipInformation& m) const {
        switch (static_cast<wire::OwnershipKind>(m.kind)) {
            case wire::OwnershipKind::OwnedByFederate:
                return named(C::informAttributeOwnership, ObjectHandle{m.object}, AttributeHandle{m.attribute},
                             FederateHandle{m.owner});
            case wire::OwnershipKind::OwnedByRti:
                return named(C::attributeOwnedByRTI, ObjectHandle{m.object}, AttributeHandle{m.attribute});
            default:
                return named(C::attributeIsNotOwned, ObjectHandle{m.object}, AttributeHandle{m.attribute});
        }
    }
    Named operator()(const wire::InitiateFederateSave& m) const {
        return named(C::initiateFederateSave, to_str(m.label));
    }
    Named operator()(const wire::FederationSaved& m) const {
        return named(m.success ? C::federationSaved : C::federationNotSaved);
    }
    Named operator()(const wire::RestoreRequestAnswer& m) const {
        if (m.succeeded)
            return named(C::requestFederationRestoreSucceeded, to_str(m.label));
        return named(C::requestFederationRestoreFailed, to_str(m.label), to_str(m.reason));
    }
    Named operator()(const wire::FederationRestoreBegun&) const { return named(C::federationRestoreBegun); }
    Named operator()(const wire::InitiateFederateRestore& m) const {
        return named(C::initiateFederateRestore, to_str(m.label), FederateHandle{m.federate});
    }
    Named operator()(const wire::FederationRestored& m) const {
        return named(m.success ? C::federationRestored : C::federationNotRestored);
    }
    Named unexpected() const { throw RtiError(ErrorCode::RTIinternalError, "unexpected message from the gateway"); }
};

Named to_callback(const wire::Message& message) {
    ToCallback to_callback;
    return wire::dispatch_callback<Named>(message, to_callback);
}

// The ambassador's method `name`, or null when it has none, without the AttributeError that getattr would
// build and clear for each callback an ambassador leaves out (timeAdvanceGrant, often once per step).
py::object optional_method(const py::handle& ambassador, const py::object& name) {
    PyObject* method = nullptr;
#if PY_VERSION_HEX >= 0x030D0000
    if (PyObject_GetOptionalAttr(ambassador.ptr(), name.ptr(), &method) < 0) throw py::error_already_set();
#else
    if (_PyObject_LookupAttr(ambassador.ptr(), name.ptr(), &method) < 0) throw py::error_already_set();
#endif
    return py::reinterpret_steal<py::object>(method);
}

// The ambassador's methods, each looked up at its first callback of a dispatch: a lookup and a bound method
// per callback were 9 % of a subscriber's CPU. A method the ambassador gains or replaces during a dispatch
// (inside a callback) is called from the next dispatch on.
class Methods {
public:
    explicit Methods(py::handle ambassador) : ambassador_(ambassador) {}

    // Borrowed; null when the ambassador has no such method.
    PyObject* of(C callback) {
        const auto i = static_cast<std::size_t>(callback);
        if (!looked_up_[i]) {
            methods_[i] = optional_method(ambassador_, method_name(callback));
            looked_up_[i] = true;
        }
        return methods_[i].ptr();
    }

private:
    static constexpr std::size_t kCount = static_cast<std::size_t>(C::Count);
    py::handle ambassador_;
    std::array<py::object, kCount> methods_;
    std::bitset<kCount> looked_up_;
};

// The callback's method with its arguments, as a vector with a free slot in front, where a bound method puts
// its self (PY_VECTORCALL_ARGUMENTS_OFFSET).
void call(PyObject* method, const Named& callback) {
    PyObject* vector[Named::kMost + 1];
    for (std::size_t i = 0; i < callback.count; ++i) vector[i + 1] = callback.args[i].ptr();
    PyObject* result = PyObject_Vectorcall(method, vector + 1, callback.count | PY_VECTORCALL_ARGUMENTS_OFFSET, nullptr);
    if (!result) throw py::error_already_set();
    Py_DECREF(result);
}

// Whether `deadline` has passed, for a loop that asks after every callback. The coarse clock (the time at the
// last timer tick, read from memory) answers while the deadline is more than a tick away, where the exact
// clock cost 5 % of a delivery; near it, the exact clock does. Both are CLOCK_MONOTONIC (steady_clock).
bool passed(Client::Clock::time_point deadline) {
    static const Client::Clock::duration timer_tick = [] {
        timespec resolution{};
        clock_getres(CLOCK_MONOTONIC_COARSE, &resolution);
        return std::chrono::duration_cast<Client::Clock::duration>(std::chrono::seconds(resolution.tv_sec) +
                                                                  std::chrono::nanoseconds(resolution.tv_nsec));
    }();
    timespec coarse{};
    clock_gettime(CLOCK_MONOTONIC_COARSE, &coarse);
    const Client::Clock::time_point at_last_tick(std::chrono::duration_cast<Client::Clock::duration>(
        std::chrono::seconds(coarse.tv_sec) + std::chrono::nanoseconds(coarse.tv_nsec)));
    return at_last_tick + timer_tick >= deadline && Client::Clock::now() >= deadline;
}

// Delivers queued callbacks to the ambassador's methods of the same name (absent ones are skipped), for
// at most max_seconds (< 0: no limit), stopping after a time advance grant if asked. Returns how many were
// delivered. The loop is here rather than in Python because it runs once per reflection.
int dispatch(Client& c, const py::object& ambassador, bool stop_after_grant, double max_seconds) {
    const auto deadline = Client::Clock::now() + std::chrono::duration_cast<Client::Clock::duration>(
                                                      std::chrono::duration<double>(max_seconds < 0 ? 0 : max_seconds));
    Methods methods(ambassador);
    int delivered = 0;
    for (;;) {
        auto m = c.pop_callback();
        if (!m) break;
        ++delivered;
        const Named callback = to_callback(*m);
        const bool granted = std::holds_alternative<wire::TimeAdvanceGrant>(*m);
        m.reset();  // its values are Python's copies now: the blocks they were read into go back to the reader
        if (!ambassador.is_none()) {
            if (PyObject* method = methods.of(callback.callback)) call(method, callback);
        }
        if (stop_after_grant && granted) break;
        if (max_seconds >= 0 && passed(deadline)) break;
    }
    return delivered;
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

// self._federate_ambassador (set by joinFederationExecution in rti.py), None before: read from the Python
// object the call was made on, rather than found again from the client (pybind11's instance map).
py::object federate_ambassador(py::handle self) {
    static const py::object& name =
        *new py::object(py::reinterpret_steal<py::object>(PyUnicode_InternFromString("_federate_ambassador")));
    py::object ambassador = optional_method(self, name);
    return ambassador ? ambassador : py::none();
}

// RTIAmbassador.await_grant: delivers what is ready up to the grant, waiting for the socket in between (the GIL
// released, Ctrl-C interrupts), until the pending time advance is granted; TimeoutError after timeout_s.
// Here rather than in Python: it runs once per step of every time-managed federate.
double await_grant(py::handle self, std::optional<double> timeout_s) {
    Client& c = client_of(self);
    if (!c.time_advance_pending()) throw RtiError(ErrorCode::TimeAdvanceWasNotInProgress, "no time advance is pending");
    const py::object ambassador = federate_ambassador(self);
    const auto start = Client::Clock::now();
    for (;;) {
        while (c.time_advance_pending() && dispatch(c, ambassador, true, -1.0) > 0) {
        }
        if (!c.time_advance_pending()) return c.query_federate_time();
        double remaining = -1.0;
        if (timeout_s) {
            remaining = *timeout_s - std::chrono::duration<double>(Client::Clock::now() - start).count();
            if (remaining <= 0) {
                const std::string seconds = py::str(py::float_(*timeout_s));
                PyErr_SetString(PyExc_TimeoutError, ("no time advance grant within " + seconds + " s").c_str());
                throw py::error_already_set();
            }
        }
        wait_for_callback(c, remaining);
    }
}

// A time advance request of `kind`, then await_grant.
template <AdvanceKind kind>
double advance_and_await(py::handle self, double time, std::optional<double> timeout_s) {
    client_of(self).time_advance(kind, time);
    return await_grant(self, timeout_s);
}

// HLA 1.3 tick: all that is ready (no window), or wait up to `minimum` for a first callback, then deliver
// for up to `maximum`, reading what arrives meanwhile. Callbacks go to self._federate_ambassador (set by
// joinFederationExecution in rti.py). Here rather than in Python: it runs once per reflection.
bool tick(py::handle self, std::optional<double> minimum, std::optional<double> maximum) {
    Client& c = client_of(self);
    const py::object ambassador = federate_ambassador(self);
    const auto poll = [&c] {
        py::gil_scoped_release release;
        c.poll_now();
    };
    if (!minimum && !maximum) {
        poll();
        dispatch(c, ambassador, false, -1.0);
        return c.has_callbacks();
    }
    const double lo = minimum.value_or(0.0);
    const double hi = std::max(maximum.value_or(lo), lo);
    const auto start = Client::Clock::now();
    if (!wait_for_callback(c, lo)) return c.has_callbacks();
    const auto deadline = start + std::chrono::duration_cast<Client::Clock::duration>(std::chrono::duration<double>(hi));
    for (;;) {
        const double left = std::chrono::duration<double>(deadline - Client::Clock::now()).count();
        dispatch(c, ambassador, false, std::max(0.0, left));
        if (Client::Clock::now() >= deadline) break;
        poll();  // more may have arrived meanwhile: deliver it within the same tick
        if (!c.has_callbacks()) break;
    }
    return c.has_callbacks();
}

const Doc kDocs[] = {
    {"advance_to", "timeAdvanceRequest(time), then deliver callbacks until the grant is delivered; returns the grant time. Beyond PyHLA (asyncio forms in hlacore.aio). Callbacks before the grant (the timestamped messages up to time) are delivered to the federate ambassador as usual, the grant included; callbacks queued behind it wait for the next tick. timeout (seconds, default none) raises TimeoutError with the request still pending."},
    {"next_event", "nextEventRequest(time), then deliver callbacks until granted; returns the grant time (the earliest of time and the next timestamped message). timeout as in advance_to."},
    {"await_grant", "Deliver callbacks until the pending time advance is granted; returns the federate's new time. For a request made with any of the five PyHLA calls. Raises TimeAdvanceWasNotInProgress when no request is pending and TimeoutError when timeout seconds pass first."},
    {"tick", "Evoke callbacks on this thread (HLA 1.3 §2.2 tick). tick() delivers the callbacks that are ready and returns at once; a read takes up to 128 KiB of small messages, so a burst larger than that takes several calls. tick(minimum, maximum) waits up to minimum seconds for the first callback (the GIL released; Ctrl-C interrupts it), then keeps delivering what is ready for at most maximum seconds. Returns True when callbacks are still pending, queued or still in the socket: `while tick(): pass` delivers all that had arrived. An exception raised by a callback propagates with its traceback; the callbacks not yet delivered stay queued for the next tick."},
};

}  // namespace

void bind_callbacks(Ambassador& rtia) {
    Documented(rtia, kDocs)
        .def("tick", &tick, py::arg("minimum") = py::none(), py::arg("maximum") = py::none())
        .def("_poll", &Client::poll_now, py::call_guard<py::gil_scoped_release>())
        .def("_wait", &wait_for_callback, py::arg("timeout"))
        .def("_has_callbacks", &Client::has_callbacks)
        .def("_lost", &Client::lost)
        .def("await_grant", &await_grant, py::arg("timeout") = py::none())
        .def("advance_to", &advance_and_await<AdvanceKind::TimeAdvanceRequest>, py::arg("time"),
             py::arg("timeout") = py::none())
        .def("next_event", &advance_and_await<AdvanceKind::NextEventRequest>, py::arg("time"),
             py::arg("timeout") = py::none())
        .def("_dispatch", &dispatch, py::arg("ambassador"), py::arg("stop_after_grant"), py::arg("max_seconds"));
}

}  // namespace hlacore::bindings
