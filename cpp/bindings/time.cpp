// Time management (HLA 1.3 §8).
#include "bindings/convert.hpp"

namespace hlacore::bindings {

void bind_time(Ambassador& rtia) {
    rtia
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
        .def("_status", &Client::query_status, py::call_guard<py::gil_scoped_release>());
}

}  // namespace hlacore::bindings
