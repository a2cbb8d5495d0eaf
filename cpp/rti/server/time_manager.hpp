// Conservative time management of one federation (HLA 1.3 §8): regulating and constrained federates,
// lookahead, TAR/TARA/NER/NERA/flushQueueRequest, and the timestamp-ordered (TSO) queue of each
// constrained federate. Pure state, no I/O: the federation feeds it requests and messages and sends
// what release() hands back.
//
// The gateway sees every federate's state, so instead of exchanging null messages it computes each
// regulating federate's output bound exactly: the lowest timestamp it may still send. For a federate in
// NER/NERA that bound depends on the messages it may still receive, so the bounds are the greatest
// fixed point of   bound(g) = max(promise(g), min(own(g), after(g, min over h != g of bound(h)))),
// computed like shortest paths (Dijkstra), which is why NER grants land exactly on message times.
//
// Zero lookahead needs no epsilon: after a TAR/NER grant to T a zero-lookahead federate may only send
// timestamps > T, which for doubles is >= nextafter(T, +inf); after TARA/NERA it may send at T itself.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "rti/time.hpp"
#include "rti/wire/codec.hpp"

namespace hlacore {

// A message waiting in a constrained federate's TSO queue. Ties in time are broken by the sending
// federate's handle, then by the sender's serial number: deterministic, independent of arrival order.
struct TsoMessage {
    Time time = 0;
    std::uint32_t sender = 0;
    std::uint64_t serial = 0;
    std::string frame;  // opaque to the time manager: the encoded callback to deliver
    HLACORE_FIELDS(time, sender, serial, frame)  // kept in save files
};

// A federate's time state for introspection: its current state (regulating counts while enabling) and
// what is in progress.
struct TimeFederateStatus : wire::SavedTime {
    std::uint32_t federate = 0;
    AdvanceKind pending = AdvanceKind::None;
    Time pending_time = 0;
    std::size_t queued_tso = 0;
    std::size_t queued_ro = 0;
    bool enabling_regulation = false;  // timeRegulationEnabled not released yet
    Time lbts = kInfinity;
    Time output_bound = kInfinity;  // infinity when not regulating
    // While a constrained federate waits (a request, an enable): the regulating federates whose output bound
    // keeps it waiting, those that may still send at or below what it waits for (docs/time-management.md).
    std::vector<std::uint32_t> held_by;
};

// Where a federate's held messages go while it holds more than a threshold of them in memory (the gateway's
// spill files, server/spill.hpp): the time manager keeps each message's place in its queue and a ticket, and
// takes the bytes back when it releases the message. Attached at one point (TimeManager::attach_parking);
// without it every held message stays in memory.
class FrameParking {
public:
    virtual ~FrameParking() = default;
    // Keeps `frame` for federate f and returns its ticket; nullopt when it cannot (it then stays in memory).
    virtual std::optional<std::uint64_t> park(std::uint32_t f, std::string_view frame) = 0;
    // The frame of `ticket`, `size` bytes, given up unless `keep` (a save reads it and keeps it).
    virtual std::string unpark(std::uint32_t f, std::uint64_t ticket, std::uint32_t size, bool keep) = 0;
    // Every frame kept for f is given up (it left, or a restore replaced its queues).
    virtual void forget(std::uint32_t f) = 0;
};

class TimeManager {
public:
    // What release() hands back for one federate. Delivery order: constrained_enabled, frames,
    // regulation_enabled, grant (messages below a new time come before the callback announcing it).
    struct Release {
        std::uint32_t federate = 0;
        std::vector<wire::SharedFrame> frames;  // held receive-order messages, then TSO messages in order
        std::optional<Time> grant;                  // timeAdvanceGrant
        std::optional<Time> constrained_enabled;    // timeConstrainedEnabled
        std::optional<Time> regulation_enabled;     // timeRegulationEnabled
    };

    void add_federate(std::uint32_t f);
    // The federation's reading of the rules (rti/time.hpp); Exact until set.
    void set_semantics(TimeSemantics semantics) { semantics_ = semantics; }
    TimeSemantics semantics() const { return semantics_; }
    // From now on a federate's held messages beyond `park_above` bytes in memory go to `parking`.
    void attach_parking(FrameParking* parking, std::size_t park_above) {
        parking_ = parking;
        park_above_ = park_above;
    }
    // Forgets the federate: it leaves the regulating set and its queues are dropped.
    void remove_federate(std::uint32_t f);

    // HLA 1.3 §8.2. Returns the time t0 at which regulation starts: no earlier than `time`, the federate's
    // time, and what every constrained federate's current time allows (so it cannot send into their past).
    // The bound counts at once; timeRegulationEnabled(t0) comes out of release(), for a constrained
    // federate only once nothing below t0 can still reach it (like TARA(t0)). Not while regulating, enabling
    // or advancing (std::logic_error: the caller checks).
    Time enable_regulation(std::uint32_t f, Time time, Time lookahead);
    // Also cancels a pending enable.
    void disable_regulation(std::uint32_t f);
    // HLA 1.3 §8.4. Enabling completes in release() once no regulating federate can still send below the
    // federate's time. Disabling hands back the queued TSO messages, now receive order.
    void enable_constrained(std::uint32_t f);
    std::vector<std::string> disable_constrained(std::uint32_t f);
    void set_asynchronous_delivery(std::uint32_t f, bool on);
    // HLA 1.3 §8.19: a lower lookahead never withdraws a bound already promised.
    void modify_lookahead(std::uint32_t f, Time lookahead);
    // Not while enabling regulation (std::logic_error: the caller checks).
    void request(std::uint32_t f, AdvanceKind kind, Time time);

    // Whether a message with a timestamp goes timestamp-ordered from `sender` to `receiver`
    // (the FOM's order is checked by the caller): sender regulating, receiver constrained.
    bool is_tso(std::uint32_t sender, std::uint32_t receiver) const;
    // Whether a receive-order message to `receiver` must wait: constrained, not advancing (no request
    // and no regulation enable pending), and asynchronous delivery off (HLA 1.3 §8.1.2).
    bool holds_receive_order(std::uint32_t receiver) const;
    // Whether `sender` may send a message with timestamp `ts`: not regulating, or `ts` at or above its
    // promise, the highest bound others were ever given for it (a lower one could land in their past).
    bool may_send(std::uint32_t sender, Time ts) const;
    // That promise (-kInfinity when not regulating).
    Time promise(std::uint32_t f) const;
    void enqueue_tso(std::uint32_t receiver, TsoMessage message);
    // The same with a frame that other receivers' queues may hold too.
    void enqueue_tso(std::uint32_t receiver, Time time, std::uint32_t sender, std::uint64_t serial, wire::SharedFrame frame);
    void enqueue_receive_order(std::uint32_t receiver, std::string frame);
    // Removes an undelivered TSO message from every queue; returns the federates it was removed for.
    std::vector<std::uint32_t> retract(std::uint32_t sender, std::uint64_t serial);

    // Everything deliverable now: held receive-order messages, TSO messages that are safe, grants.
    std::vector<Release> release();
    // The bytes of the messages waiting for `f` that only its own progress releases: held receive-order
    // messages, and TSO messages while it is not advancing (while it is, they wait for the senders' own
    // progress, which holding those senders back would stop). Flow control counts them (docs/robustness.md).
    std::size_t held_bytes(std::uint32_t f) const;

    // The lowest timestamp a regulating federate may still send (kInfinity if not regulating).
    Time output_bound(std::uint32_t f);
    // LBTS of f: the lowest timestamp any other regulating federate may still send (HLA 1.3 §8.16).
    Time lbts(std::uint32_t f);
    // min(LBTS, earliest queued TSO message) (HLA 1.3 §8.18).
    Time min_next_event_time(std::uint32_t f);
    Time federate_time(std::uint32_t f) const;
    bool regulating(std::uint32_t f) const;           // enabled or being enabled
    bool enabling_regulation(std::uint32_t f) const;  // timeRegulationEnabled not released yet
    bool advancing(std::uint32_t f) const;            // a time advance request is pending
    std::vector<TimeFederateStatus> status();

    // ---- save/restore (docs/save-restore.md) ----
    // What a federation save keeps of one federate (in the save file as its fields in order): its time
    // state, with only the switches already enabled, and the messages waiting for it.
    struct SavedState {
        wire::SavedTime time;
        std::vector<TsoMessage> tso;  // in delivery order
        std::vector<std::string> held_ro;
        HLACORE_FIELDS(time, tso, held_ro)
    };
    bool constrained(std::uint32_t f) const;
    // A timed save at `t`: a pending request beyond it is granted at most `t`.
    void cap_request(std::uint32_t f, Time t);
    SavedState save_state(std::uint32_t f) const;
    // Adds the federate, or replaces its state.
    void restore_state(std::uint32_t f, SavedState saved);

private:
    // A held frame: in memory, or parked (FrameParking) as `size` bytes under `ticket`.
    struct Held {
        wire::SharedFrame frame;
        std::uint64_t ticket = 0;
        std::uint32_t size = 0;
        bool parked() const { return !frame; }
        std::size_t weight() const { return parked() ? kParkedWeight : TimeManager::weight(*frame); }
    };
    // A message in a constrained federate's TSO queue, in delivery order by (time, sender, serial).
    struct Queued : Held {
        Queued(Time t, std::uint32_t from, std::uint64_t n, Held held) : Held(std::move(held)), time(t), sender(from), serial(n) {}
        Time time = 0;
        std::uint32_t sender = 0;
        std::uint64_t serial = 0;
    };
    static bool later(const Queued& a, const Queued& b) {
        return std::tie(a.time, a.sender, a.serial) > std::tie(b.time, b.sender, b.serial);
    }
    // A federate's state: what a save keeps of it, and what is in progress.
    struct State : wire::SavedTime {
        bool constrained_pending = false;
        AdvanceKind pending = AdvanceKind::None;
        Time pending_time = 0;
        std::optional<Time> enabling;  // t0 of a regulation enable whose callback is not released yet
        Time bound = kInfinity;        // output bound, valid after compute_bounds() while regulating
        bool settled = false;          // scratch for compute_bounds()
        // The TSO queue: a heap with the earliest message at the front (a tree node per queued message was
        // 10 % of the gateway's CPU in a 32-federate lockstep).
        std::vector<Queued> tso;
        std::vector<Held> held_ro;
        std::size_t tso_bytes = 0;  // the weight() of the frames in tso
        std::size_t ro_bytes = 0;   // and in held_ro
        bool parked = false;        // some of them are parked
        Time earliest_tso() const { return tso.empty() ? kInfinity : tso.front().time; }
        // Removes the earliest TSO message.
        Held pop_tso() {
            std::pop_heap(tso.begin(), tso.end(), later);
            tso_bytes -= tso.back().weight();
            Held held = std::move(tso.back());
            tso.pop_back();
            return held;
        }
        void push_tso(Queued message) {
            tso_bytes += message.weight();
            tso.push_back(std::move(message));
            std::push_heap(tso.begin(), tso.end(), later);
        }
        // The queue in delivery order (for saves and disableTimeConstrained).
        std::vector<Queued> tso_in_order() const {
            std::vector<Queued> ordered = tso;
            std::sort(ordered.begin(), ordered.end(), [](const Queued& a, const Queued& b) { return later(b, a); });
            return ordered;
        }
    };

    // What a held frame costs the gateway: its bytes and its queue entry (with the routing record of a
    // timestamped message), so that small messages are not held far beyond the budget.
    static std::size_t weight(const std::string& frame) { return frame.size() + 160; }
    static constexpr std::size_t kParkedWeight = 64;
    // A frame about to be held for f: parked when f holds more than park_above_ in memory and it can be.
    Held hold(std::uint32_t f, State& s, wire::SharedFrame frame);
    // The frame of a held message, taken back from the parking if it was parked (given up there unless `keep`).
    wire::SharedFrame frame_of(std::uint32_t f, Held held, bool keep) const;
    void pop_tso(std::uint32_t f, State& s, std::vector<wire::SharedFrame>& frames) {
        frames.push_back(frame_of(f, s.pop_tso(), false));
    }

    State& state(std::uint32_t f);
    const State& state(std::uint32_t f) const;
    // The bound implied by a grant to `t` of `kind`, for a federate with lookahead `lookahead`.
    static Time bound_after(Time t, Time lookahead, AdvanceKind kind);
    void compute_bounds();
    Time lbts_from_bounds(std::uint32_t f) const;
    std::vector<std::uint32_t> held_by(std::uint32_t f, const State& s) const;  // after compute_bounds()
    bool try_grant(std::uint32_t f, State& s, Release& out);
    bool try_complete_regulation(std::uint32_t f, State& s, Release& out);

    std::map<std::uint32_t, State> federates_;
    TimeSemantics semantics_ = TimeSemantics::Exact;
    // federates_ by handle, for the lookups of every routed message (walking the map was 7 % of the rtig's
    // CPU in a 32-federate lockstep); handles from kIndexedHandles on are looked up in the map.
    static constexpr std::uint32_t kIndexedHandles = 1u << 16;
    std::vector<State*> by_handle_;
    const State* find(std::uint32_t f) const;
    void index(std::uint32_t f, State* s);
    // Valid after compute_bounds(): the regulating federates, the lowest bound and whose it is, the next.
    std::vector<std::pair<std::uint32_t, State*>> regulating_;
    Time lowest_ = kInfinity;
    Time second_lowest_ = kInfinity;
    std::uint32_t lowest_federate_ = 0;
    // Set by every change that can make something deliverable; release() does nothing otherwise, which
    // keeps the bound computation off the path of plain receive-order updates.
    bool changed_ = false;
    FrameParking* parking_ = nullptr;
    std::size_t park_above_ = 0;
};

}  // namespace hlacore
