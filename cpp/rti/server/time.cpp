// Time management (HLA 1.3 §8) as the federation routes it; the rules are TimeManager's (time_manager.hpp,
// docs/time-management.md).
#include "rti/server/federation.hpp"

#include <algorithm>
#include <cmath>

namespace hlacore {

using wire::WireError;

// HLA 1.3 §8.1.1: receivers were granted on the regulating sender's bound, so a timestamp below it could
// land in their past. Clients check this first (InvalidFederationTime); here it is a protocol violation.
void Federation::check_timestamp(FederateHandle from, double time, const char* what) const {
    if (!std::isfinite(time)) throw WireError(std::string(what) + " at a timestamp that is not finite");
    if (time_.may_send(from, time)) return;
    throw WireError(std::string(what) + " at timestamp " + time_text(time) +
                    " is below the sender's output bound " + time_text(time_.promise(from)) +
                    " (lowest timestamp it may still send)");
}

void Federation::release_time() {
    if (time_frozen()) return;  // every federate is saving or restoring
    if (save_restore_.save.active && save_restore_.save.time) cap_requests_at_save_time();
    // A message at or below the sender's time can no longer be retracted (HLA 1.3 §8.21).
    auto forget_retractable = [&](FederateHandle sender, double time) {
        auto routed = routed_.find(sender);
        if (routed == routed_.end()) return;
        for (auto it = routed->second.begin(); it != routed->second.end();)
            it = it->second.time <= time ? routed->second.erase(it) : std::next(it);
    };
    // In the order of TimeManager::Release: messages below a new time precede the callback announcing it.
    for (auto& r : time_.release()) {
        auto f = federates_.find(r.federate);
        if (f == federates_.end()) continue;
        if (r.constrained_enabled) outbox_.send_unheld(r.federate, wire::TimeConstrainedEnabled{*r.constrained_enabled});
        outbox_.send_frames(r.federate, r.frames);
        if (r.regulation_enabled) {
            outbox_.send_unheld(r.federate, wire::TimeRegulationEnabled{*r.regulation_enabled});
            forget_retractable(r.federate, *r.regulation_enabled);
        }
        if (r.grant) {
            ++f->second.grants;
            outbox_.send_unheld(r.federate, wire::TimeAdvanceGrant{*r.grant});
            forget_retractable(r.federate, *r.grant);
        }
    }
    // A timed save starts at the grants reaching its time.
    if (save_restore_.save.active && save_restore_.save.time) tell_savers();
}

double Federation::query_time(FederateHandle f, wire::TimeQuery which) {
    federate(f);
    return which == wire::TimeQuery::Lbts ? time_.lbts(f) : time_.min_next_event_time(f);
}
// ---- time management (HLA 1.3 §8); the rules are in time_manager.hpp and docs/time-management.md ----

void Federation::on(FederateHandle from, const wire::EnableTimeRegulation& m) {
    federate(from);
    if (!(m.lookahead >= 0) || !std::isfinite(m.lookahead) || !std::isfinite(m.time))
        throw WireError("enable time regulation: the time and lookahead must be finite, the lookahead >= 0");
    // HLA 1.3 §8.2: the client refuses these (TimeRegulationAlreadyEnabled, EnableTimeRegulationPending,
    // TimeAdvanceAlreadyInProgress); re-enabling could also lower a bound others were granted on.
    if (time_.enabling_regulation(from)) throw WireError("enable time regulation while an enable is pending");
    if (time_.regulating(from)) throw WireError("enable time regulation while regulation is enabled");
    if (time_.advancing(from)) throw WireError("enable time regulation while a time advance is pending");
    time_.enable_regulation(from, m.time, m.lookahead);
    release_time();  // timeRegulationEnabled comes from there, at once unless constrained messages must go first
}

void Federation::on(FederateHandle from, const wire::DisableTimeRegulation&) {
    federate(from);
    time_.disable_regulation(from);
    release_time();
}

void Federation::on(FederateHandle from, const wire::EnableTimeConstrained&) {
    federate(from);
    time_.enable_constrained(from);
    release_time();
}

void Federation::on(FederateHandle from, const wire::DisableTimeConstrained&) {
    federate(from);
    for (const auto& frame : time_.disable_constrained(from)) outbox_.send_frame(from, frame);
    release_time();
}

void Federation::on(FederateHandle from, const wire::TimeAdvance& m) {
    FederateState& f = federate(from);
    if (m.kind < 1 || m.kind > 5 || !std::isfinite(m.time)) throw WireError("invalid time advance request (kind 1-5, a finite time)");
    if (m.time < time_.federate_time(from)) throw WireError("time advance request into the past");
    // HLA 1.3 §8.2: refused by the client too (EnableTimeRegulationPending).
    if (time_.enabling_regulation(from))
        throw WireError("time advance request while a regulation enable is pending");
    time_.request(from, static_cast<AdvanceKind>(m.kind), m.time);
    f.requested_at = std::chrono::steady_clock::now();
    release_time();
}

void Federation::on(FederateHandle from, const wire::ModifyLookahead& m) {
    federate(from);
    if (!(m.lookahead >= 0) || !std::isfinite(m.lookahead)) throw WireError("invalid lookahead (finite, >= 0)");
    time_.modify_lookahead(from, m.lookahead);
    release_time();
}

void Federation::on(FederateHandle from, const wire::SetAsynchronousDelivery& m) {
    federate(from);
    time_.set_asynchronous_delivery(from, m.on);
    release_time();
}

void Federation::on(FederateHandle from, const wire::Retract& m) {
    federate(from);
    auto sender = routed_.find(from);
    if (sender == routed_.end()) return;
    auto it = sender->second.find(m.serial);
    if (it == sender->second.end()) return;  // never routed TSO, or already in the past
    const auto removed = time_.retract(from, m.serial);
    for (FederateHandle to : it->second.receivers) {
        // Those who already got it are asked to retract it themselves (HLA 1.3 §8.22).
        if (federates_.count(to) && std::find(removed.begin(), removed.end(), to) == removed.end())
            outbox_.send(to, wire::RequestRetraction{from, m.serial});
    }
    sender->second.erase(it);
}

}  // namespace hlacore
