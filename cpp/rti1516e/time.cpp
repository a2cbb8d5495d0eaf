// Time management (IEEE 1516.1-2010 §8) over the core's, whose times are doubles: an HLAinteger64Time
// federation's times are whole numbers of them (exact up to 2^53).
#include <RTI/time/HLAfloat64Interval.h>
#include <RTI/time/HLAfloat64Time.h>
#include <RTI/time/HLAinteger64Interval.h>
#include <RTI/time/HLAinteger64Time.h>
#include <RTI/time/HLAfloat64TimeFactory.h>
#include <RTI/time/HLAinteger64TimeFactory.h>

#include <cmath>
#include <limits>

#include "ambassador.hpp"

namespace hlacore::rti1516e {

namespace {
// A time or an interval of the federation's type as the core's double (`error` for another type).
template <class Float, class Integer, class Base>
double value_in(Base const& given, bool integer_federation, bool joined, const char* error) {
    if (auto f = dynamic_cast<Float const*>(&given)) {
        if (integer_federation) raise(error, "an HLAfloat64 time or interval in an HLAinteger64Time federation");
        return static_cast<double>(*f);
    }
    if (auto i = dynamic_cast<Integer const*>(&given)) {
        if (joined && !integer_federation) raise(error, "an HLAinteger64 time or interval in an HLAfloat64Time federation");
        return static_cast<double>(static_cast<Integer64>(*i));
    }
    raise(error, "hlacore serves the HLAfloat64Time and HLAinteger64Time types, not " + utf8(given.implementationName()));
}
}  // namespace

double Ambassador::time_in(LogicalTime const& time) const {
    return value_in<HLAfloat64Time, HLAinteger64Time>(time, integer_time_, joined_, "InvalidLogicalTime");
}

double Ambassador::interval_in(LogicalTimeInterval const& interval) const {
    return value_in<HLAfloat64Interval, HLAinteger64Interval>(interval, integer_time_, joined_, "InvalidLookahead");
}

LogicalTime const& TimeOut::operator()(double time) {
    if (!integer_) {
        float_.setTime(time);
        return float_;
    }
    const double whole = std::isinf(time) ? (time > 0 ? 9.2e18 : -9.2e18) : time;
    integer_time_.setTime(static_cast<Integer64>(whole));
    return integer_time_;
}
namespace {
// Into a time given by the caller, which must be of the federation's type.
void assign(LogicalTime& into, LogicalTime const& from) {
    if (into.implementationName() != from.implementationName())
        raise("InvalidLogicalTime", "the federation's times are " + utf8(from.implementationName()));
    into = from;
}
}  // namespace

void Ambassador::enableTimeRegulation(LogicalTimeInterval const& lookahead) {
    guarded([&] {
        Client& c = client();
        c.enable_time_regulation(c.query_federate_time(), interval_in(lookahead));
    });
}

void Ambassador::disableTimeRegulation() {
    guarded([&] { client().disable_time_regulation(); });
}

void Ambassador::enableTimeConstrained() {
    guarded([&] { client().enable_time_constrained(); });
}

void Ambassador::disableTimeConstrained() {
    guarded([&] { client().disable_time_constrained(); });
}

void Ambassador::timeAdvanceRequest(LogicalTime const& time) {
    guarded([&] { client().time_advance(AdvanceKind::TimeAdvanceRequest, time_in(time)); });
}

void Ambassador::timeAdvanceRequestAvailable(LogicalTime const& time) {
    guarded([&] { client().time_advance(AdvanceKind::TimeAdvanceRequestAvailable, time_in(time)); });
}

void Ambassador::nextMessageRequest(LogicalTime const& time) {
    guarded([&] { client().time_advance(AdvanceKind::NextEventRequest, time_in(time)); });
}

void Ambassador::nextMessageRequestAvailable(LogicalTime const& time) {
    guarded([&] { client().time_advance(AdvanceKind::NextEventRequestAvailable, time_in(time)); });
}

void Ambassador::flushQueueRequest(LogicalTime const& time) {
    guarded([&] { client().time_advance(AdvanceKind::FlushQueueRequest, time_in(time)); });
}

void Ambassador::enableAsynchronousDelivery() {
    guarded([&] { client().set_asynchronous_delivery(true); });
}

void Ambassador::disableAsynchronousDelivery() {
    guarded([&] { client().set_asynchronous_delivery(false); });
}

bool Ambassador::queryGALT(LogicalTime& time) {
    return guarded([&] {
        const double galt = client().query_lbts();
        if (std::isinf(galt)) return false;  // nothing holds this federate back
        assign(time, TimeOut(integer_time_)(galt));
        return true;
    });
}

void Ambassador::queryLogicalTime(LogicalTime& time) {
    guarded([&] { assign(time, TimeOut(integer_time_)(client().query_federate_time())); });
}

bool Ambassador::queryLITS(LogicalTime& time) {
    return guarded([&] {
        const double lits = client().query_min_next_event_time();
        if (std::isinf(lits)) return false;  // no message can come
        assign(time, TimeOut(integer_time_)(lits));
        return true;
    });
}

void Ambassador::modifyLookahead(LogicalTimeInterval const& lookahead) {
    guarded([&] { client().modify_lookahead(interval_in(lookahead)); });
}

void Ambassador::queryLookahead(LogicalTimeInterval& lookahead) {
    guarded([&] {
        const double l = client().query_lookahead();
        if (integer_time_) {
            if (!dynamic_cast<HLAinteger64Interval*>(&lookahead)) raise("InvalidLookahead", "an HLAinteger64Interval is wanted");
            lookahead = HLAinteger64Interval(static_cast<Integer64>(l));
        } else {
            if (!dynamic_cast<HLAfloat64Interval*>(&lookahead)) raise("InvalidLookahead", "an HLAfloat64Interval is wanted");
            lookahead = HLAfloat64Interval(l);
        }
    });
}

void Ambassador::retract(MessageRetractionHandle handle) {
    guarded([&] {
        if (!handle.isValid()) raise("InvalidMessageRetractionHandle", "an invalid handle");
        client().retract(static_cast<std::uint32_t>(MessageRetractionHandleFriend::sender(handle)),
                         MessageRetractionHandleFriend::value(handle));
    });
}

RTI_UNIQUE_PTR<LogicalTimeFactory> Ambassador::getTimeFactory() const {
    return guarded([&]() -> RTI_UNIQUE_PTR<LogicalTimeFactory> {
        client();
        if (integer_time_) return RTI_UNIQUE_PTR<LogicalTimeFactory>(new HLAinteger64TimeFactory());
        return RTI_UNIQUE_PTR<LogicalTimeFactory>(new HLAfloat64TimeFactory());
    });
}

}  // namespace hlacore::rti1516e
