// The gateway's private types, shared by its files (gateway.cpp, reactor.cpp, transport.cpp, session.cpp,
// flow_control.cpp, federations.cpp, datagrams.cpp, status.cpp): a federation's entry with the outbox that
// writes its callbacks into connections, and the helpers on the path of every delivery, inline.
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "rti/server/connection.hpp"
#include "rti/server/gateway.hpp"
#include "rti/wire/splices.hpp"

namespace hlacore {

using Clock = std::chrono::steady_clock;

// Connection buffers above this capacity are released once empty (but see keeping_large_buffers()).
constexpr std::size_t kKeptBufferBytes = 1u << 20;
constexpr std::chrono::seconds kLargeFrameGrace{1};
// Released frames beyond this go through a connection's backlog rather than straight into its buffer.
constexpr std::size_t kPacedBytes = 256u << 10;

class Gateway::ConnectionOutbox : public Outbox, public FrameParking {
public:
    explicit ConnectionOutbox(Gateway& gateway) : gateway_(gateway) {}
    std::string& buffer(FederateHandle federate) override {
        auto it = peers_.find(federate);
        if (it == peers_.end()) return discard_;  // not reachable: federates are bound before use
        gateway_.mark_dirty(*it->second);
        return gateway_.output(*it->second);
    }
    void send_frames(FederateHandle federate, std::vector<wire::SharedFrame>& frames) override {
        auto it = peers_.find(federate);
        if (it == peers_.end()) return;
        Connection& c = *it->second;
        std::size_t total = 0;
        for (const auto& frame : frames) total += frame->size();
        if (c.spill) {  // behind what is spilled: through `tail`, which mark_dirty() spills
            for (const auto& frame : frames) c.tail.append(*frame);
            return gateway_.mark_dirty(c);
        }
        if (c.backlog.empty() && total < kPacedBytes) return Outbox::send_frames(federate, frames);
        if (!c.tail.empty()) {
            c.backlog_bytes += c.tail.size();
            c.backlog.push_back(std::move(c.tail));
            c.tail.clear();
        }
        // A frame no other queue holds any more is moved (a large one is megabytes), a shared one copied.
        for (auto& frame : frames) c.backlog.push_back(frame.use_count() == 1 ? std::move(*frame) : *frame);
        c.backlog_bytes += total;
        gateway_.mark_dirty(c);
    }
    bool takes_datagrams(FederateHandle federate) const override {
        auto it = peers_.find(federate);
        return it != peers_.end() && it->second->datagram_path;
    }
    bool send_datagram(FederateHandle federate, std::string_view frame) override {
        auto it = peers_.find(federate);
        return it != peers_.end() && gateway_.send_datagram(*it->second, frame);
    }
    bool send_spliced(FederateHandle federate, const wire::ForwardedReflection& m) override { return spliced(federate, m); }
    bool send_spliced(FederateHandle federate, const wire::ForwardedInteraction& m) override { return spliced(federate, m); }
    void held(FederateHandle federate) override {
        auto it = peers_.find(federate);
        if (it != peers_.end()) gateway_.mark_dirty(*it->second);
    }
    // The messages time management holds for a federate beyond its share go to its connection's file.
    std::optional<std::uint64_t> park(std::uint32_t federate, std::string_view frame) override {
        Connection* c = peer(federate);
        return c ? gateway_.park(*c, frame) : std::nullopt;
    }
    std::string unpark(std::uint32_t federate, std::uint64_t ticket, std::uint32_t size, bool keep) override {
        Connection* c = peer(federate);
        return c ? gateway_.unpark(*c, ticket, size, keep) : std::string();
    }
    void forget(std::uint32_t federate) override {
        if (Connection* c = peer(federate)) c->parked.reset();
    }
    void rehandle(const std::map<FederateHandle, FederateHandle>& new_handles) override {
        std::unordered_map<FederateHandle, Connection*> peers;
        for (auto& [old_handle, c] : peers_) {
            auto it = new_handles.find(old_handle);
            c->federate = it == new_handles.end() ? old_handle : it->second;
            peers[c->federate] = c;
        }
        peers_.swap(peers);
    }
    std::unordered_map<FederateHandle, Connection*> peers_;

private:
    Connection* peer(FederateHandle federate) {
        auto it = peers_.find(federate);
        return it == peers_.end() ? nullptr : it->second;
    }
    template <class M>
    bool spliced(FederateHandle federate, const M& m) {
        auto it = peers_.find(federate);
        if (!gateway_.splice_source_.block || it == peers_.end()) return false;
        Connection& c = *it->second;
        // TLS encrypts from one buffer, the trace reads the frames in `out`, and output() is `tail` while
        // there is a backlog or a spill. Asked after mark_dirty(), which may start spilling c: its stream then
        // goes on in the spill file, and a frame put in `out` would come before the rest of the one cut there.
        if (c.ssl || gateway_.trace_) return false;
        gateway_.mark_dirty(c);
        if (&gateway_.output(c) != &c.out) return false;
        // The large values that lie in the frame being served are spliced in, referenced rather than copied.
        const SpliceSource& source = gateway_.splice_source_;
        wire::SplicingOutput output{c.out, [&c, &source](std::size_t at, std::string_view bytes) {
                                        const std::less_equal<const char*> le;
                                        if (!le(source.frame.data(), bytes.data()) ||
                                            !le(bytes.data() + bytes.size(), source.frame.data() + source.frame.size()))
                                            return false;
                                        c.splices.push_back({{at, bytes}, source.block});
                                        c.splice_bytes += bytes.size();
                                        return true;
                                    }};
        wire::encode_to(output, m);
        return true;
    }
    Gateway& gateway_;
    std::string discard_;
};

// A recorder federate's connection as a tap of the recording: each record becomes a Recorded message.
class Gateway::ConnectionTap : public RecordTap {
public:
    ConnectionTap(Gateway& gateway, Connection& c) : gateway_(gateway), c_(c) {}
    void recorded(const std::string& topic, const std::string& schema_name, const std::string& schema,
                  std::uint32_t sequence, std::uint64_t log_ns, const std::string& json) override {
        std::string& out = gateway_.output(c_);
        if (!schema.empty()) wire::encode(out, wire::RecordedTopic{topic, schema_name, schema});
        wire::encode(out, wire::Recorded{topic, sequence, log_ns, json});
        gateway_.mark_dirty(c_);
    }

private:
    Gateway& gateway_;
    Connection& c_;
};

struct Gateway::FederationEntry {
    FederationEntry(Gateway& gw, std::string name, fom::Fom fom, std::string fed_name, std::string fed_text)
        : outbox(gw), federation(std::move(name), std::move(fom), std::move(fed_name), std::move(fed_text), outbox) {
        if (gw.spill_budget_.on()) federation.attach_parking(&outbox, gw.options_.client_budget / 4);
    }
    ConnectionOutbox outbox;
    Federation federation;
    std::unique_ptr<FederationRecording> recording;  // when the gateway records: what its outbox sends
};

inline std::string& Gateway::output(Connection& c) { return c.backlog.empty() && !c.spill ? c.out : c.tail; }

inline std::size_t Gateway::held_for(const Connection& c) const {
    const std::size_t queued = c.unsent() + c.backlog_bytes + c.tail.size();
    return c.federation ? queued + c.federation->federation.held_bytes(c.federate) : queued;
}
inline bool Gateway::stopped_reading(const Connection& c) const {
    return !c.idle && Clock::now() - c.progress_at >= kStoppedReading;
}
inline void Gateway::mark_dirty(Connection& c) {
    if (!c.dirty) {
        c.dirty = true;
        dirty_.push_back(c.fd);
    }
    // Over its budget, or spilling with a tail worth writing: to disk, else its senders are paused.
    if ((c.spill && c.tail.size() >= spill_keep()) || held_for(c) > options_.client_budget) {
        if (!spill(c)) over_budget_ = c.fd;
    }
}
template <class F>
void Gateway::answer(Connection& c, std::uint32_t request, F&& serve_request) {
    try {
        if constexpr (std::is_void_v<decltype(serve_request())>) {
            serve_request();
            wire::encode(output(c), wire::Reply{request, 0, ""});
        } else {
            const auto result = serve_request();
            if constexpr (std::is_same_v<std::decay_t<decltype(result)>, wire::ObjectRegistered>) {
                if (recorder_ && c.federation) recorder_->answered(c.federation->federation, c.federate, result);
            }
            wire::encode(output(c), result);
        }
    } catch (const RtiError& e) {
        const wire::Reply refusal{request, static_cast<std::uint16_t>(e.code()), e.what()};
        if (recorder_ && c.federation) recorder_->answered(c.federation->federation, c.federate, refusal);
        wire::encode(output(c), refusal);
    }
    mark_dirty(c);
}

}  // namespace hlacore
