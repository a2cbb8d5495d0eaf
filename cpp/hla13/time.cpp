// RTIambassador: time management (§8; the rules are hlacore's, docs/time-management.md).
#include "ambassador.hpp"
#include "fedtime.hh"

using namespace hlacore;
using hlacore::hla13::guarded;
using hlacore::hla13::time_of;

namespace {
// Sets `out` (an RTIfedTime) to `time`.
void set_time(RTI::FedTime& out, double time) {
    auto* t = dynamic_cast<RTIfedTime*>(&out);
    if (!t) throw RTI::InvalidFederationTime("not an RTIfedTime: hlacore's logical time is RTIfedTime (fedtime.hh)");
    *t = time;
}
}  // namespace

void RTI::RTIambassador::enableTimeRegulation(const FedTime& theFederateTime, const FedTime& theLookahead) {
    guarded([&] { privateRefs->client.enable_time_regulation(time_of(theFederateTime), time_of(theLookahead)); });
}

void RTI::RTIambassador::disableTimeRegulation() {
    guarded([&] { privateRefs->client.disable_time_regulation(); });
}

void RTI::RTIambassador::enableTimeConstrained() {
    guarded([&] { privateRefs->client.enable_time_constrained(); });
}

void RTI::RTIambassador::disableTimeConstrained() {
    guarded([&] { privateRefs->client.disable_time_constrained(); });
}

void RTI::RTIambassador::timeAdvanceRequest(const FedTime& theTime) {
    guarded([&] { privateRefs->client.time_advance(AdvanceKind::TimeAdvanceRequest, time_of(theTime)); });
}

void RTI::RTIambassador::timeAdvanceRequestAvailable(const FedTime& theTime) {
    guarded([&] { privateRefs->client.time_advance(AdvanceKind::TimeAdvanceRequestAvailable, time_of(theTime)); });
}

void RTI::RTIambassador::nextEventRequest(const FedTime& theTime) {
    guarded([&] { privateRefs->client.time_advance(AdvanceKind::NextEventRequest, time_of(theTime)); });
}

void RTI::RTIambassador::nextEventRequestAvailable(const FedTime& theTime) {
    guarded([&] { privateRefs->client.time_advance(AdvanceKind::NextEventRequestAvailable, time_of(theTime)); });
}

void RTI::RTIambassador::flushQueueRequest(const FedTime& theTime) {
    guarded([&] { privateRefs->client.time_advance(AdvanceKind::FlushQueueRequest, time_of(theTime)); });
}

void RTI::RTIambassador::enableAsynchronousDelivery() {
    guarded([&] { privateRefs->client.set_asynchronous_delivery(true); });
}

void RTI::RTIambassador::disableAsynchronousDelivery() {
    guarded([&] { privateRefs->client.set_asynchronous_delivery(false); });
}

void RTI::RTIambassador::queryLBTS(FedTime& theTime) {
    guarded([&] { set_time(theTime, privateRefs->client.query_lbts()); });
}

void RTI::RTIambassador::queryFederateTime(FedTime& theTime) {
    guarded([&] { set_time(theTime, privateRefs->client.query_federate_time()); });
}

void RTI::RTIambassador::queryMinNextEventTime(FedTime& theTime) {
    guarded([&] { set_time(theTime, privateRefs->client.query_min_next_event_time()); });
}

void RTI::RTIambassador::modifyLookahead(const FedTime& theLookahead) {
    guarded([&] { privateRefs->client.modify_lookahead(time_of(theLookahead)); });
}

void RTI::RTIambassador::queryLookahead(FedTime& theTime) {
    guarded([&] { set_time(theTime, privateRefs->client.query_lookahead()); });
}

void RTI::RTIambassador::retract(EventRetractionHandle theHandle) {
    guarded([&] { privateRefs->client.retract(hla13::h32(theHandle.sendingFederate), theHandle.theSerialNumber); });
}
