#include "rti/server/time_manager.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace hlacore {

namespace {

bool is_next_event(AdvanceKind kind) {
    return kind == AdvanceKind::NextEventRequest || kind == AdvanceKind::NextEventRequestAvailable ||
           kind == AdvanceKind::FlushQueueRequest;
}

}  // namespace

Time TimeManager::bound_after(Time t, Time lookahead, AdvanceKind kind) {
    // HLA 1.3 §8.1.1 zero lookahead: after TAR/NER a federate sends only above its time, after TARA/NERA at it.
    return after(t, lookahead, !is_available(kind));
}

const TimeManager::State* TimeManager::find(std::uint32_t f) const {
    if (f < kIndexedHandles) return f < by_handle_.size() ? by_handle_[f] : nullptr;
    auto it = federates_.find(f);
    return it == federates_.end() ? nullptr : &it->second;
}

void TimeManager::index(std::uint32_t f, State* s) {
    if (f >= kIndexedHandles) return;
    if (f >= by_handle_.size()) by_handle_.resize(f + 1);
    by_handle_[f] = s;
}

TimeManager::State& TimeManager::state(std::uint32_t f) {
    return const_cast<State&>(std::as_const(*this).state(f));
}

const TimeManager::State& TimeManager::state(std::uint32_t f) const {
    const State* s = find(f);
    if (!s) throw std::logic_error("time manager: unknown federate " + std::to_string(f));
    return *s;
}

void TimeManager::add_federate(std::uint32_t f) { index(f, &federates_[f]); }

void TimeManager::remove_federate(std::uint32_t f) {
    changed_ = true;
    if (const State* s = find(f); s && s->parked) parking_->forget(f);
    federates_.erase(f);
    index(f, nullptr);
    regulating_.clear();  // it may point at the erased state until the next compute_bounds()
}

// HLA 1.3 §8.2 enableTimeRegulation: start where no message can fall into a constrained federate's past
// nor below a bound the others were already granted on; with CERTI's semantics, no earlier than the
// constrained federates' times (a strict grant to one does not lift it, nor do the others' bounds).
Time TimeManager::enable_regulation(std::uint32_t f, Time time, Time lookahead) {
    State& s = state(f);
    if (s.regulating || s.pending != AdvanceKind::None)
        throw std::logic_error("time manager: enable_regulation while regulating, enabling or advancing");
    changed_ = true;
    compute_bounds();
    Time highest = -kInfinity;
    for (const auto& [h, other] : federates_) {
        if (h == f) continue;
        const bool exact = semantics_ == TimeSemantics::Exact;
        if (other.constrained)
            highest = std::max(highest, exact && other.receives_above_time ? std::nextafter(other.time, kInfinity) : other.time);
        if (other.regulating && exact) highest = std::max(highest, other.promise);
    }
    Time start = std::max(time, s.time);
    if (highest > -kInfinity) {
        // The smallest start whose first allowed timestamp reaches `highest`.
        Time candidate = highest - lookahead;
        while (candidate + lookahead < highest) candidate = std::nextafter(candidate, kInfinity);
        start = std::max(start, candidate);
    }
    s.regulating = true;
    s.lookahead = lookahead;
    s.strict_after_grant = false;
    s.promise = bound_after(start, lookahead, AdvanceKind::TimeAdvanceRequestAvailable);
    s.enabling = start;
    // A constrained federate may still receive messages in [time, start): it moves there in release(),
    // after them. Otherwise nothing can land in between.
    if (!s.constrained) s.time = start;
    return start;
}

void TimeManager::disable_regulation(std::uint32_t f) {
    changed_ = true;
    State& s = state(f);
    s.regulating = false;
    s.promise = -kInfinity;
    s.enabling.reset();
}



void TimeManager::enable_constrained(std::uint32_t f) {
    changed_ = true;
    state(f).constrained_pending = true;
}

std::vector<std::string> TimeManager::disable_constrained(std::uint32_t f) {
    changed_ = true;
    State& s = state(f);
    s.constrained = false;
    s.constrained_pending = false;
    std::vector<std::string> frames;
    for (auto& m : s.tso_in_order()) frames.push_back(*frame_of(f, m, false));
    s.tso.clear();
    s.tso_bytes = 0;
    return frames;
}

void TimeManager::set_asynchronous_delivery(std::uint32_t f, bool on) {
    changed_ = true;
    state(f).asynchronous_delivery = on;
}

void TimeManager::modify_lookahead(std::uint32_t f, Time lookahead) {
    changed_ = true;
    state(f).lookahead = lookahead;
}

void TimeManager::request(std::uint32_t f, AdvanceKind kind, Time time) {
    changed_ = true;
    State& s = state(f);
    if (s.enabling) throw std::logic_error("time manager: request while enabling regulation");
    s.pending = kind;
    s.pending_time = time;
}

bool TimeManager::is_tso(std::uint32_t sender, std::uint32_t receiver) const {
    return state(sender).regulating && state(receiver).constrained;
}

bool TimeManager::holds_receive_order(std::uint32_t receiver) const {
    const State& s = state(receiver);
    return s.constrained && s.pending == AdvanceKind::None && !s.enabling && !s.asynchronous_delivery;
}

bool TimeManager::may_send(std::uint32_t sender, Time ts) const {
    const State& s = state(sender);
    return !s.regulating || ts >= s.promise;
}

Time TimeManager::promise(std::uint32_t f) const {
    const State& s = state(f);
    return s.regulating ? s.promise : -kInfinity;
}

void TimeManager::enqueue_tso(std::uint32_t receiver, TsoMessage message) {
    enqueue_tso(receiver, message.time, message.sender, message.serial,
                std::make_shared<std::string>(std::move(message.frame)));
}

void TimeManager::enqueue_tso(std::uint32_t receiver, Time time, std::uint32_t sender, std::uint64_t serial,
                              wire::SharedFrame frame) {
    State& s = state(receiver);
    // The queue only matters to bounds and grants of a federate in NER/NERA/FQR: a message cannot make a
    // TAR grantable, and the lockstep's updates would otherwise each cost a bound computation.
    if (is_next_event(s.pending)) changed_ = true;
    s.push_tso(Queued{time, sender, serial, hold(receiver, s, std::move(frame))});
}

void TimeManager::enqueue_receive_order(std::uint32_t receiver, std::string frame) {
    // Only called while the receiver holds receive-order messages: nothing becomes deliverable.
    State& s = state(receiver);
    Held held = hold(receiver, s, std::make_shared<std::string>(std::move(frame)));
    s.ro_bytes += held.weight();
    s.held_ro.push_back(std::move(held));
}

std::vector<std::uint32_t> TimeManager::retract(std::uint32_t sender, std::uint64_t serial) {
    changed_ = true;
    std::vector<std::uint32_t> removed_from;
    for (auto& [f, s] : federates_) {
        auto it = std::find_if(s.tso.begin(), s.tso.end(),
                               [&](const Queued& m) { return m.sender == sender && m.serial == serial; });
        if (it == s.tso.end()) continue;  // (sender, serial) names one message: at most once per queue
        s.tso_bytes -= it->weight();
        frame_of(f, std::move(*it), false);  // given up where it was parked
        s.tso.erase(it);
        std::make_heap(s.tso.begin(), s.tso.end(), later);
        removed_from.push_back(f);
    }
    return removed_from;
}

TimeManager::Held TimeManager::hold(std::uint32_t f, State& s, wire::SharedFrame frame) {
    if (parking_ && s.tso_bytes + s.ro_bytes > park_above_) {
        if (const auto ticket = parking_->park(f, *frame)) {
            s.parked = true;
            return Held{nullptr, *ticket, static_cast<std::uint32_t>(frame->size())};
        }
    }
    return Held{std::move(frame)};
}

wire::SharedFrame TimeManager::frame_of(std::uint32_t f, Held held, bool keep) const {
    if (!held.parked()) return std::move(held.frame);
    return std::make_shared<std::string>(parking_->unpark(f, held.ticket, held.size, keep));
}

std::size_t TimeManager::held_bytes(std::uint32_t f) const {
    const State* held = find(f);
    if (!held) return 0;
    const State& s = *held;
    return s.ro_bytes + (s.pending == AdvanceKind::None ? s.tso_bytes : 0);
}

// The greatest fixed point of the bound equations (see the header), by increasing bounds like Dijkstra:
// a federate's bound only depends on smaller ones through after(), which never lowers a value. Only a
// constrained federate in NER/NERA/FQR depends on others; without one, each bound is its own.
void TimeManager::compute_bounds() {
    regulating_.clear();
    bool relax = false;
    for (auto& [g, s] : federates_) {
        if (!s.regulating) continue;
        Time own;
        if (s.enabling) {
            own = bound_after(*s.enabling, s.lookahead, AdvanceKind::TimeAdvanceRequestAvailable);
        } else if (s.pending == AdvanceKind::None) {
            own = s.lookahead > 0 && s.time + s.lookahead > s.time ? s.time + s.lookahead
                  : s.strict_after_grant                            ? std::nextafter(s.time, kInfinity)
                                                                    : s.time;
        } else if (is_next_event(s.pending)) {
            own = bound_after(std::min(s.pending_time, s.constrained ? s.earliest_tso() : kInfinity), s.lookahead,
                              s.pending);
            relax = relax || s.constrained;
        } else {
            own = bound_after(s.pending_time, s.lookahead, s.pending);
        }
        s.bound = std::max(s.promise, own);
        s.settled = false;
        regulating_.push_back({g, &s});
    }
    for (std::size_t round = 0; relax && round < regulating_.size(); ++round) {
        // Settle the smallest unsettled bound, then relax the federates waiting on incoming messages.
        State* smallest = nullptr;
        for (auto& [g, s] : regulating_)
            if (!s->settled && (!smallest || s->bound < smallest->bound)) smallest = s;
        if (!smallest) break;
        smallest->settled = true;
        for (auto& [g, s] : regulating_) {
            if (s->settled || !s->constrained || !is_next_event(s->pending)) continue;
            s->bound = std::min(s->bound, std::max(s->promise, bound_after(smallest->bound, s->lookahead, s->pending)));
        }
    }
    // LBTS(f) is the lowest bound of the others: the lowest, or the second lowest for its owner.
    lowest_ = second_lowest_ = kInfinity;
    lowest_federate_ = 0;
    for (auto& [g, s] : regulating_) {
        s->promise = s->bound;
        if (s->bound < lowest_) {
            second_lowest_ = lowest_;
            lowest_ = s->bound;
            lowest_federate_ = g;
        } else if (s->bound < second_lowest_) {
            second_lowest_ = s->bound;
        }
    }
}

Time TimeManager::lbts_from_bounds(std::uint32_t f) const { return f == lowest_federate_ ? second_lowest_ : lowest_; }

Time TimeManager::output_bound(std::uint32_t f) {
    compute_bounds();
    const State& s = state(f);
    return s.regulating ? s.bound : kInfinity;
}

Time TimeManager::lbts(std::uint32_t f) {
    state(f);
    compute_bounds();
    return lbts_from_bounds(f);
}

Time TimeManager::min_next_event_time(std::uint32_t f) {
    const Time l = lbts(f);
    return std::min(l, state(f).earliest_tso());
}

Time TimeManager::federate_time(std::uint32_t f) const { return state(f).time; }

bool TimeManager::regulating(std::uint32_t f) const { return state(f).regulating; }

bool TimeManager::enabling_regulation(std::uint32_t f) const { return state(f).enabling.has_value(); }

bool TimeManager::advancing(std::uint32_t f) const { return state(f).pending != AdvanceKind::None; }

// HLA 1.3 §8.5-8.11: the grant conditions of each request, with the TSO messages that precede the grant.
bool TimeManager::try_grant(std::uint32_t f, State& s, Release& out) {
    if (s.pending == AdvanceKind::None) return false;
    const Time t = s.pending_time;
    Time grant = t;
    Time deliver_up_to = t;
    bool deliver_all = false;
    if (s.constrained) {
        const Time lbts = lbts_from_bounds(f);
        const Time next = std::min(t, s.earliest_tso());
        switch (s.pending) {
            case AdvanceKind::TimeAdvanceRequest:  // §8.5: nothing at or below t may still arrive
                if (!(t < lbts)) return false;
                break;
            case AdvanceKind::TimeAdvanceRequestAvailable:  // §8.6: nothing below t may still arrive
                if (!(t <= lbts)) return false;
                break;
            case AdvanceKind::NextEventRequest:  // §8.7
                if (!(next < lbts)) return false;
                grant = deliver_up_to = next;
                break;
            case AdvanceKind::NextEventRequestAvailable:  // §8.8
                if (!(next <= lbts)) return false;
                grant = deliver_up_to = next;
                break;
            case AdvanceKind::FlushQueueRequest:  // §8.9: everything queued, grant no further than is safe
                grant = std::max(s.time, std::min({t, lbts, s.earliest_tso()}));
                deliver_all = true;
                break;
            case AdvanceKind::None: return false;
        }
    }
    while (!s.tso.empty() && (deliver_all || s.tso.front().time <= deliver_up_to)) pop_tso(f, s, out.frames);
    s.time = grant;
    s.strict_after_grant = !is_available(s.pending) && !(s.lookahead > 0 && grant + s.lookahead > grant);
    // Conservative for newcomers: after FQR with zero lookahead too, start strictly above the grant.
    s.receives_above_time = s.constrained && (s.pending == AdvanceKind::TimeAdvanceRequest ||
                                              s.pending == AdvanceKind::NextEventRequest ||
                                              (s.pending == AdvanceKind::FlushQueueRequest && s.strict_after_grant));
    s.pending = AdvanceKind::None;
    out.grant = grant;
    return true;
}

// HLA 1.3 §8.2 for a constrained federate moving to t0 > T: like TARA(t0), what may still arrive below t0
// first. Its time is already t0 otherwise (see enable_regulation), or again so after disableTimeConstrained.
bool TimeManager::try_complete_regulation(std::uint32_t f, State& s, Release& out) {
    const Time t0 = *s.enabling;
    if (s.time < t0) {
        if (s.constrained) {
            if (!(t0 <= lbts_from_bounds(f))) return false;
            while (!s.tso.empty() && s.tso.front().time <= t0) pop_tso(f, s, out.frames);
        }
        s.time = t0;
        s.receives_above_time = false;  // messages at t0 itself may still come
    }
    s.enabling.reset();
    out.regulation_enabled = t0;
    return true;
}

std::vector<TimeManager::Release> TimeManager::release() {
    std::vector<Release> releases;
    if (!changed_) return releases;
    changed_ = false;
    std::map<std::uint32_t, std::size_t> index;
    auto slot = [&](std::uint32_t f) -> Release& {
        auto it = index.find(f);
        if (it != index.end()) return releases[it->second];
        index[f] = releases.size();
        releases.emplace_back();
        releases.back().federate = f;
        return releases.back();
    };
    for (bool progress = true; progress;) {
        progress = false;
        compute_bounds();
        for (auto& [f, s] : federates_) {
            if (!s.held_ro.empty() && !holds_receive_order(f)) {
                auto& frames = slot(f).frames;
                for (auto& held : s.held_ro) frames.push_back(frame_of(f, std::move(held), false));
                s.held_ro.clear();
                s.ro_bytes = 0;
            }
            if (s.constrained_pending && lbts_from_bounds(f) >= s.time) {
                s.constrained_pending = false;
                s.constrained = true;
                s.receives_above_time = false;
                slot(f).constrained_enabled = s.time;
                progress = true;
            }
            if (s.enabling) {
                Release attempt;
                if (try_complete_regulation(f, s, attempt)) {
                    Release& r = slot(f);
                    for (auto& frame : attempt.frames) r.frames.push_back(std::move(frame));
                    r.regulation_enabled = attempt.regulation_enabled;
                    progress = true;
                }
            }
            if (s.pending != AdvanceKind::None) {
                Release attempt;
                if (try_grant(f, s, attempt)) {
                    Release& r = slot(f);
                    for (auto& frame : attempt.frames) r.frames.push_back(std::move(frame));
                    r.grant = attempt.grant;
                    progress = true;  // a grant leaves every bound as it was (promises), but not who is advancing
                }
            }
        }
    }
    std::vector<Release> nonempty;
    for (auto& r : releases)
        if (!r.frames.empty() || r.grant || r.constrained_enabled || r.regulation_enabled)
            nonempty.push_back(std::move(r));
    return nonempty;
}

// The grant rules of docs/time-management.md read backwards: who keeps LBTS from allowing what f waits for.
std::vector<std::uint32_t> TimeManager::held_by(std::uint32_t f, const State& s) const {
    std::vector<std::uint32_t> out;
    if (!s.constrained && !s.constrained_pending) return out;
    Time wanted = kInfinity;
    bool strict = false;  // granted when LBTS > wanted (else >=)
    if (s.constrained_pending) {
        wanted = s.time;
    } else if (s.enabling && *s.enabling > s.time) {
        wanted = *s.enabling;
    } else if (s.pending != AdvanceKind::None && s.pending != AdvanceKind::FlushQueueRequest) {
        const bool next_event = s.pending == AdvanceKind::NextEventRequest || s.pending == AdvanceKind::NextEventRequestAvailable;
        wanted = next_event ? std::min(s.pending_time, s.earliest_tso()) : s.pending_time;
        strict = !is_available(s.pending);
    } else {
        return out;
    }
    for (const auto& [g, other] : federates_)
        if (g != f && other.regulating && (strict ? other.bound <= wanted : other.bound < wanted)) out.push_back(g);
    return out;
}

std::vector<TimeFederateStatus> TimeManager::status() {
    compute_bounds();
    std::vector<TimeFederateStatus> out;
    for (const auto& [f, s] : federates_) {
        TimeFederateStatus st;
        static_cast<wire::SavedTime&>(st) = s;
        st.federate = f;
        st.pending = s.pending;
        st.pending_time = s.pending_time;
        st.queued_tso = s.tso.size();
        st.queued_ro = s.held_ro.size();
        st.enabling_regulation = s.enabling.has_value();
        st.lbts = lbts_from_bounds(f);
        st.output_bound = s.regulating ? s.bound : kInfinity;
        st.held_by = held_by(f, s);
        out.push_back(st);
    }
    return out;
}

// ---- save/restore ----

bool TimeManager::constrained(std::uint32_t f) const { return state(f).constrained; }

void TimeManager::cap_request(std::uint32_t f, Time t) {
    State& s = state(f);
    if (s.pending == AdvanceKind::None || s.pending_time <= t) return;
    s.pending_time = t;
    changed_ = true;
}

TimeManager::SavedState TimeManager::save_state(std::uint32_t f) const {
    const State& s = state(f);
    SavedState out;
    out.time = s;  // the saved part of the state
    // A regulation enable whose callback is still held is not kept (nor is its bound: dropping a bound
    // never lets a message into anyone's past).
    out.time.regulating = s.regulating && !s.enabling;
    out.time.promise = out.time.regulating ? s.promise : -kInfinity;
    for (const auto& m : s.tso_in_order()) out.tso.push_back(TsoMessage{m.time, m.sender, m.serial, *frame_of(f, m, true)});
    for (const auto& held : s.held_ro) out.held_ro.push_back(*frame_of(f, held, true));
    return out;
}

void TimeManager::restore_state(std::uint32_t f, SavedState saved) {
    changed_ = true;
    regulating_.clear();  // recomputed by the next compute_bounds()
    State& s = federates_[f];
    if (s.parked) parking_->forget(f);
    index(f, &s);
    s = State{};
    static_cast<wire::SavedTime&>(s) = saved.time;
    if (!s.regulating) s.promise = -kInfinity;
    for (auto& m : saved.tso)
        s.push_tso(Queued{m.time, m.sender, m.serial, Held{std::make_shared<std::string>(std::move(m.frame))}});
    for (auto& frame : saved.held_ro) {
        s.held_ro.push_back(Held{std::make_shared<std::string>(std::move(frame))});
        s.ro_bytes += s.held_ro.back().weight();
    }
}

}  // namespace hlacore
