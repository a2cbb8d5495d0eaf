// Time management (HLA 1.3 §8).
#include "bindings/convert.hpp"

namespace hlacore::bindings {

namespace {
// timeAdvanceRequest and its four siblings differ only in the kind of advance asked for.
template <AdvanceKind kind>
void advance(Client& c, double time) {
    c.time_advance(kind, time);
}

// What `with rtia.batch():` enters (Client::hold_sends): in C++, because a busy-polled lockstep's step pays
// for every µs of it (16.9 µs with a contextlib context manager, 16.0 with a Python class, 14.7 with the two
// calls made directly: docs/performance.md, "Batched sends"); and a plain CPython type, because a pybind11
// instance (made, registered in pybind11's instance map, kept alive with its ambassador, freed) was half of
// the 0.47 µs a block cost. It holds its ambassador, whose client it holds the sends of.
struct BatchObject {
    PyObject_HEAD
    PyObject* ambassador;  // a strong reference: the client outlives the block
    Client* client;
};

PyTypeObject* batch_type = nullptr;  // made once by bind_time(), kept for the interpreter's life

// `call` on the block's client; its exceptions become Python's as pybind11's own bindings raise them.
template <void (Client::*call)()>
PyObject* on_client(PyObject* self) {
    try {
        (reinterpret_cast<BatchObject*>(self)->client->*call)();
    } catch (...) {
        py::detail::try_translate_exceptions();
        return nullptr;
    }
    Py_RETURN_NONE;
}

PyObject* batch_enter(PyObject* self, PyObject*) { return on_client<&Client::hold_sends>(self); }

PyObject* batch_exit(PyObject* self, PyObject* const*, Py_ssize_t) { return on_client<&Client::release_sends>(self); }

void batch_dealloc(PyObject* self) {
    PyTypeObject* type = Py_TYPE(self);
    Py_XDECREF(reinterpret_cast<BatchObject*>(self)->ambassador);
    type->tp_free(self);
    Py_DECREF(type);  // a heap type's instances hold it
}

PyMethodDef batch_methods[] = {
    {"__enter__", batch_enter, METH_NOARGS, "Hold the federate's messages (Client::hold_sends)."},
    {"__exit__", reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(batch_exit)), METH_FASTCALL,
     "Write what the block held, unless an outer block still holds."},
    {nullptr, nullptr, 0, nullptr},
};

PyType_Slot batch_slots[] = {
    {Py_tp_doc, const_cast<char*>("What `with rtia.batch():` enters (RTIAmbassadorBase.batch).")},
    {Py_tp_dealloc, reinterpret_cast<void*>(batch_dealloc)},
    {Py_tp_methods, batch_methods},
    {0, nullptr},
};

// Made by batch() only (Py_TPFLAGS_DISALLOW_INSTANTIATION).
PyType_Spec batch_spec = {"hlacore._core.Batch", sizeof(BatchObject), 0,
                          Py_TPFLAGS_DEFAULT | Py_TPFLAGS_DISALLOW_INSTANTIATION, batch_slots};

py::object batch(py::handle self) {
    Client& client = client_of(self);
    PyObject* made = batch_type->tp_alloc(batch_type, 0);
    if (!made) throw py::error_already_set();
    auto* b = reinterpret_cast<BatchObject*>(made);
    b->ambassador = py::handle(self).inc_ref().ptr();
    b->client = &client;
    return py::reinterpret_steal<py::object>(made);
}

// What help() says of each service of the group (convert.hpp: Documented).
const Doc kDocs[] = {
    {"enableTimeRegulation", "Become time-regulating (HLA 1.3 §8.2): timestamped messages from this federate are delivered in timestamp order to constrained federates. timeRegulationEnabled(t0) follows, with t0 >= federateTime chosen so no message can land in another federate's past. Raises TimeRegulationAlreadyEnabled, EnableTimeRegulationPending, TimeAdvanceAlreadyInProgress, InvalidFederationTime, InvalidLookahead."},
    {"disableTimeRegulation", "Stop being time-regulating (HLA 1.3 §8.4); takes effect at once. Raises TimeRegulationWasNotEnabled."},
    {"enableTimeConstrained", "Become time-constrained (HLA 1.3 §8.5): timestamped messages arrive in timestamp order, never in this federate's past. timeConstrainedEnabled(t) follows. Raises TimeConstrainedAlreadyEnabled, EnableTimeConstrainedPending, TimeAdvanceAlreadyInProgress."},
    {"disableTimeConstrained", "Stop being time-constrained (HLA 1.3 §8.7); queued timestamped messages are delivered at once. Raises TimeConstrainedWasNotEnabled."},
    {"timeAdvanceRequest", "Ask to advance to theTime (HLA 1.3 §8.8); every timestamped message <= theTime is delivered, then timeAdvanceGrant(theTime). Raises FederationTimeAlreadyPassed, TimeAdvanceAlreadyInProgress, EnableTimeRegulationPending, EnableTimeConstrainedPending, InvalidFederationTime."},
    {"timeAdvanceRequestAvailable", "Like timeAdvanceRequest, but messages at theTime itself may still arrive after the grant (HLA 1.3 §8.9); with zero lookahead, this federate may then send at theTime."},
    {"nextEventRequest", "Advance to the next timestamped message or theTime, whichever comes first (HLA 1.3 §8.10); the messages at the grant time are delivered, then timeAdvanceGrant(grant). Same exceptions as timeAdvanceRequest."},
    {"nextEventRequestAvailable", "Like nextEventRequest, but further messages at the grant time may arrive after the grant (HLA 1.3 §8.11)."},
    {"flushQueueRequest", "Deliver every queued timestamped message now and advance as far towards theTime as is safe (HLA 1.3 §8.12)."},
    {"enableAsynchronousDelivery", "Deliver receive-order messages to this constrained federate even when it is not advancing (HLA 1.3 §8.13). Raises AsynchronousDeliveryAlreadyEnabled."},
    {"disableAsynchronousDelivery", "Hold receive-order messages while this constrained federate is not advancing (HLA 1.3 §8.14; the default). Raises AsynchronousDeliveryAlreadyDisabled."},
    {"queryLBTS", "The lowest timestamp any other regulating federate may still send (HLA 1.3 §8.15); inf when there is none."},
    {"queryFederateTime", "This federate's logical time (HLA 1.3 §8.16), as of the last grant delivered."},
    {"queryMinNextEventTime", "min(LBTS, the earliest timestamped message queued for this federate) (HLA 1.3 §8.17)."},
    {"modifyLookahead", "Change the lookahead (HLA 1.3 §8.18); a lower value never allows a timestamp below one already allowed. Raises InvalidLookahead."},
    {"queryLookahead", "The current lookahead (HLA 1.3 §8.19); 0 before regulation."},
    {"clock_offset",
     "(offset, uncertainty) in seconds: the gateway's clock is this process's time.monotonic() + offset, to "
     "within ± uncertainty (half the best probe's round trip, whatever the path's asymmetry). Measured on the "
     "first call and again when older than max_age seconds (four round trips; docs/networking.md)."},
    {"batch", "Hold this federate's messages while a `with rtia.batch():` block runs and write them together, in one system call, when it ends, or before the first call inside it that waits for the gateway (tick, advance_to, a service that returns an answer), whichever comes first. Opt-in, for a step that sends several messages and then waits: around the updates and the time advance request after them, one write and one read of the gateway instead of one each. That pays where the gateway polls (rtig --busy-poll); where it sleeps, an update written at once wakes it while the request is still being made, and a batch measured slower (docs/performance.md has both). Best-effort updates that travel as datagrams (docs/networking.md) are not held. Outside a batch every message is written when it is sent. While a batch is open, other threads' messages are held too, in the order sent; batches nest, and the outermost one's end writes. A batch of more than 64 KiB is written at once."},
    {"retract", "Retract a timestamped message this federate sent above its current time (HLA 1.3 §8.21): it is removed where it is still queued; federates that already received it get requestRetraction. Raises InvalidRetractionHandle."},
};

}  // namespace

void bind_time(Ambassador& rtia) {
    batch_type = reinterpret_cast<PyTypeObject*>(PyType_FromSpec(&batch_spec));
    if (!batch_type) throw py::error_already_set();
    rtia.attr("Batch") = py::handle(reinterpret_cast<PyObject*>(batch_type));
    Documented(rtia, kDocs)
        .def("enableTimeRegulation", &Client::enable_time_regulation, py::arg("federateTime"), py::arg("lookahead"))
        .def("disableTimeRegulation", &Client::disable_time_regulation)
        .def("enableTimeConstrained", &Client::enable_time_constrained)
        .def("disableTimeConstrained", &Client::disable_time_constrained)
        .def("timeAdvanceRequest", &advance<AdvanceKind::TimeAdvanceRequest>, py::arg("theTime"))
        .def("timeAdvanceRequestAvailable", &advance<AdvanceKind::TimeAdvanceRequestAvailable>, py::arg("theTime"))
        .def("nextEventRequest", &advance<AdvanceKind::NextEventRequest>, py::arg("theTime"))
        .def("nextEventRequestAvailable", &advance<AdvanceKind::NextEventRequestAvailable>, py::arg("theTime"))
        .def("flushQueueRequest", &advance<AdvanceKind::FlushQueueRequest>, py::arg("theTime"))
        .def("enableAsynchronousDelivery", [](Client& c) { c.set_asynchronous_delivery(true); })
        .def("disableAsynchronousDelivery", [](Client& c) { c.set_asynchronous_delivery(false); })
        .def("queryLBTS", &Client::query_lbts, py::call_guard<py::gil_scoped_release>())
        .def("queryFederateTime", &Client::query_federate_time)
        .def("queryMinNextEventTime", &Client::query_min_next_event_time, py::call_guard<py::gil_scoped_release>())
        .def("modifyLookahead", &Client::modify_lookahead, py::arg("theLookahead"))
        .def("queryLookahead", &Client::query_lookahead)
        .def("retract",
             [](Client& c, const EventRetractionHandle& h) { c.retract(h.sender, h.serial); }, py::arg("theHandle"))
        .def("_time_advance_pending", &Client::time_advance_pending)
        .def("_lowest_sendable_time", &Client::lowest_sendable_time)
        .def("_status", &Client::query_status, py::arg("events_after") = 0, py::arg("instances") = true,
             py::call_guard<py::gil_scoped_release>())
        .def("batch", &batch)
        .def("_send_counts",
             [](const Client& c) {
                 const Client::SendCounts n = c.send_counts();
                 return std::make_pair(n.messages, n.writes);
             })
        .def("clock_offset",
             [](Client& c, double max_age) {
                 const ClockEstimate e = c.clock_offset(max_age);
                 return std::make_pair(e.offset_s, e.uncertainty_s);
             },
             py::arg("max_age") = 10.0, py::call_guard<py::gil_scoped_release>());
}

}  // namespace hlacore::bindings
