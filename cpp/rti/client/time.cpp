// The federate side of time management (HLA 1.3 §8): local checks with the spec's exceptions, the
// sending rule of docs/time-management.md, and the time state that the callbacks change when popped.
#include <cmath>
#include <sstream>

#include "rti/client/client.hpp"

namespace hlacore {

namespace {

// enableTimeRegulation / enableTimeConstrained (§8.2, §8.5): refused while on, or while asked for already.
void check_can_enable(bool on, bool pending, ErrorCode already_on, ErrorCode already_pending, const char* what,
                      const char* service) {
    if (on) raise(already_on, std::string(what) + " is already enabled");
    if (pending) raise(already_pending, std::string(service) + " is already pending");
}

// disableTimeRegulation / disableTimeConstrained (§8.4, §8.7): turns `on` off at once; refused while it is
// off, saying so when its enable callback is still undelivered.
void switch_off(bool& on, bool pending, ErrorCode not_on, const char* what, const char* callback) {
    if (!on)
        raise(not_on, pending ? std::string(what) + " is still being enabled (" + callback + " not yet delivered)"
                              : std::string(what) + " is not enabled");
    on = false;
}

std::string text(Time t) {
    std::ostringstream out;
    out.precision(17);
    out << t;
    return out.str();
}

const char* service_name(AdvanceKind kind) {
    switch (kind) {
        case AdvanceKind::TimeAdvanceRequest: return "timeAdvanceRequest";
        case AdvanceKind::TimeAdvanceRequestAvailable: return "timeAdvanceRequestAvailable";
        case AdvanceKind::NextEventRequest: return "nextEventRequest";
        case AdvanceKind::NextEventRequestAvailable: return "nextEventRequestAvailable";
        case AdvanceKind::FlushQueueRequest: return "flushQueueRequest";
        case AdvanceKind::None: break;
    }
    return "time advance";
}

}  // namespace

Time Client::lowest_sendable() const {
    const TimeState& s = time_;
    Time rule = after(s.time, s.lookahead, s.strict);
    if (s.pending != AdvanceKind::None)
        rule = std::max(rule, after(s.pending_time, s.lookahead, !is_available(s.pending)));
    return std::max(rule, s.floor);
}

void Client::check_send_time(const wire::OptionalTime& time) const {
    if (!time) return;
    if (!std::isfinite(*time)) raise(ErrorCode::InvalidFederationTime, "timestamp " + text(*time) + " is not finite");
    if (time_.regulation_pending)
        raise(ErrorCode::InvalidFederationTime,
              "timestamp " + text(*time) + " sent while enableTimeRegulation is pending; wait for timeRegulationEnabled");
    if (!time_.regulating) return;  // receive order everywhere: any timestamp will do
    const Time lowest = lowest_sendable();
    if (*time < lowest) {
        std::string why = time_.pending != AdvanceKind::None
                              ? "requested time " + text(time_.pending_time) + " + lookahead " + text(time_.lookahead)
                              : "federate time " + text(time_.time) + " + lookahead " + text(time_.lookahead);
        raise(ErrorCode::InvalidFederationTime, "timestamp " + text(*time) + " is below " + text(lowest) +
                                                    ", the lowest this federate may send (" + why + ")");
    }
}

std::uint64_t Client::next_serial(const wire::OptionalTime& time) {
    check_send_time(time);
    const std::uint64_t serial = ++serial_;
    if (time && time_.regulating) time_.retractable.emplace(serial, *time);  // until a grant passes it
    return serial;
}

// HLA 1.3 §8.3, §8.6, §8.13: the callbacks take effect when the federate receives them.
void Client::delivered(const wire::TimeRegulationEnabled& r) {
    TimeState& s = time_;
    s.regulation_pending = false;
    s.regulating = true;
    s.time = r.time;
    s.strict = false;
    // The gateway bounded this federate by after(t0, L) for every lookahead it had since asking.
    s.floor = after(r.time, s.enable_lookahead, false);
}

void Client::delivered(const wire::TimeConstrainedEnabled& c) {
    time_.constrained_pending = false;
    time_.constrained = true;
    time_.time = c.time;
}

void Client::delivered(const wire::TimeAdvanceGrant& g) {
    TimeState& s = time_;
    // A TARA/NERA grant to the very time a strict grant reached stays strict: others were granted it.
    const bool strict_kind = !is_available(s.pending) || (s.strict && g.time == s.time);
    s.time = g.time;
    s.strict = strict_kind;
    s.pending = AdvanceKind::None;
    // A message at or below the federate's time can no longer be retracted (§8.21).
    for (auto it = s.retractable.begin(); it != s.retractable.end();)
        it = it->second <= g.time ? s.retractable.erase(it) : std::next(it);
}

void Client::require_no_advance() const {
    if (time_.pending != AdvanceKind::None)
        raise(ErrorCode::TimeAdvanceAlreadyInProgress,
              std::string(service_name(time_.pending)) + "(" + text(time_.pending_time) + ") is in progress");
}

void Client::enable_time_regulation(Time time, Time lookahead) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_idle("enableTimeRegulation");
        check_can_enable(time_.regulating, time_.regulation_pending, ErrorCode::TimeRegulationAlreadyEnabled,
                         ErrorCode::EnableTimeRegulationPending, "time regulation", "enableTimeRegulation");
        require_no_advance();
        if (!std::isfinite(time)) raise(ErrorCode::InvalidFederationTime, "federate time " + text(time) + " is not finite");
        if (!(lookahead >= 0) || !std::isfinite(lookahead))
            raise(ErrorCode::InvalidLookahead, "lookahead " + text(lookahead) + " is not a finite value >= 0");
        time_.regulation_pending = true;
        time_.lookahead = lookahead;
        time_.enable_lookahead = lookahead;
        time_.floor = -kInfinity;
    }
    send(wire::EnableTimeRegulation{time, lookahead});
}

void Client::disable_time_regulation() {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_idle("disableTimeRegulation");
        switch_off(time_.regulating, time_.regulation_pending, ErrorCode::TimeRegulationWasNotEnabled,
                   "time regulation", "timeRegulationEnabled");
        time_.retractable.clear();
    }
    send(wire::DisableTimeRegulation{});
}

void Client::enable_time_constrained() {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_idle("enableTimeConstrained");
        check_can_enable(time_.constrained, time_.constrained_pending, ErrorCode::TimeConstrainedAlreadyEnabled,
                         ErrorCode::EnableTimeConstrainedPending, "time constrained", "enableTimeConstrained");
        require_no_advance();
        time_.constrained_pending = true;
    }
    send(wire::EnableTimeConstrained{});
}

void Client::disable_time_constrained() {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_idle("disableTimeConstrained");
        switch_off(time_.constrained, time_.constrained_pending, ErrorCode::TimeConstrainedWasNotEnabled,
                   "time constrained", "timeConstrainedEnabled");
    }
    send(wire::DisableTimeConstrained{});
}

// HLA 1.3 §8.8-8.12.
void Client::time_advance(AdvanceKind kind, Time time) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
        const char* name = service_name(kind);
        check_not_saving_or_restoring(name);
        if (!std::isfinite(time))
            raise(ErrorCode::InvalidFederationTime, std::string(name) + ": the time " + text(time) + " is not finite");
        require_no_advance();
        if (time_.regulation_pending)
            raise(ErrorCode::EnableTimeRegulationPending,
                  std::string(name) + " while enableTimeRegulation is pending; wait for timeRegulationEnabled");
        if (time_.constrained_pending)
            raise(ErrorCode::EnableTimeConstrainedPending,
                  std::string(name) + " while enableTimeConstrained is pending; wait for timeConstrainedEnabled");
        if (time < time_.time)
            raise(ErrorCode::FederationTimeAlreadyPassed,
                  std::string(name) + "(" + text(time) + ") is before the federate time " + text(time_.time));
        time_.pending = kind;
        time_.pending_time = time;
    }
    send(wire::TimeAdvance{static_cast<std::uint8_t>(kind), time});
}

void Client::modify_lookahead(Time lookahead) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_idle("modifyLookahead");
        if (!(lookahead >= 0) || !std::isfinite(lookahead))
            raise(ErrorCode::InvalidLookahead, "lookahead " + text(lookahead) + " is not a finite value >= 0");
        if (time_.regulating) time_.floor = lowest_sendable();
        if (time_.regulation_pending) time_.enable_lookahead = std::max(time_.enable_lookahead, lookahead);
        time_.lookahead = lookahead;
    }
    send(wire::ModifyLookahead{lookahead});
}

Time Client::query_lookahead() const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    return time_.lookahead;
}

Time Client::query_federate_time() const {
    std::lock_guard<std::mutex> lock(mu_);
    require_joined();
    return time_.time;
}

Time Client::query_lbts() { return query_time(wire::TimeQuery::Lbts); }

Time Client::query_min_next_event_time() { return query_time(wire::TimeQuery::MinNextEventTime); }

Time Client::query_time(wire::TimeQuery which) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
    }
    const auto id = next_request();
    return call<wire::TimeQueried>(wire::QueryTime{id, static_cast<std::uint8_t>(which)}, id).time;
}

void Client::set_asynchronous_delivery(bool on) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
        if (time_.asynchronous_delivery == on)
            raise(on ? ErrorCode::AsynchronousDeliveryAlreadyEnabled : ErrorCode::AsynchronousDeliveryAlreadyDisabled,
                  on ? "asynchronous delivery is already enabled" : "asynchronous delivery is already disabled");
        time_.asynchronous_delivery = on;
    }
    send(wire::SetAsynchronousDelivery{on});
}

// HLA 1.3 §8.21: only the sender may retract, and only messages above its current time.
void Client::retract(std::uint32_t sender, std::uint64_t serial) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_joined();
        if (sender != federate_ || !time_.retractable.erase(serial))
            raise(ErrorCode::InvalidRetractionHandle,
                  "event retraction handle " + std::to_string(sender) + ":" + std::to_string(serial) +
                      " does not name a timestamped message of this federate above its time " + text(time_.time));
    }
    send(wire::Retract{serial});
}

Time Client::lowest_sendable_time() const {
    std::lock_guard<std::mutex> lock(mu_);
    return time_.regulating ? lowest_sendable() : -kInfinity;
}

bool Client::time_advance_pending() const {
    std::lock_guard<std::mutex> lock(mu_);
    return time_.pending != AdvanceKind::None;
}

}  // namespace hlacore
