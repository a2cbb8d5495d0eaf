// One Federate Protocol session on the RTI's side: its numbering and kept messages (SessionState), the connection
// it is on now (none while dropped), and the federate behind it, which makes the calls and gets the callbacks.
// A connection's thread runs serve() until the connection drops; a resume on a new connection takes over where
// it stopped. Writes go out under one lock, in the order they were numbered.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>

#include "fedpro/session_protocol.hpp"
#include "fedpro/stream.hpp"

namespace hlacore::fedpro {

// The HLA side of a session: what a call returns, and what becomes of a callback's answer.
class Federate {
public:
    virtual ~Federate() = default;
    // A CallRequest's bytes to its CallResponse's bytes (an exception is a response too).
    virtual std::string call(std::string_view request) = 0;
    // A CallbackResponse's bytes.
    virtual void answered(std::string_view response) = 0;
    // The session ends: resign when joined, disconnect.
    virtual void end() = 0;
    // The federation and the name it joined as ({"", ""} when not joined), for the status report. Thread-safe.
    virtual std::pair<std::string, std::string> member() const = 0;
};

struct SessionLimits {
    std::uint32_t max_message = 64u << 20;        // a message's size, header included
    std::size_t kept_budget = 64u << 20;          // callbacks wait while the kept messages hold more
    std::chrono::milliseconds resume_timeout{60000};  // a dropped session not resumed within it ends
};

class Session {
public:
    Session(std::uint64_t id, SessionLimits limits) : state_(id), limits_(limits) {}
    ~Session();
    void set_federate(std::unique_ptr<Federate> federate) { federate_ = std::move(federate); }
    std::uint64_t id() const { return state_.id(); }

    // Runs the connection (its handshake done) until it drops or the session ends.
    void serve(std::shared_ptr<Stream> stream);
    // A resume on a new connection: answers the federate, sends again what it lacks; false when refused (answered
    // too).
    bool resume(std::shared_ptr<Stream> stream, std::uint32_t last_received_by_federate);
    // A callback for the federate (a CallbackRequest's bytes): numbered and kept, written when connected. Waits
    // while the kept messages are over budget, until the federate confirms some or the session ends.
    void send_callback(std::string_view request);

    // Dropped for longer than the resume timeout, or ended.
    bool expired(std::chrono::steady_clock::time_point now) const;
    bool ended() const { return ended_; }
    // Ends the session for `reason`: the federate resigns, SessionTerminated is sent when `tell_federate`, the
    // connection closes. Idempotent (the first reason stays).
    void end(bool tell_federate, std::string const& reason);
    // {"id":..., "federation":..., "federate":..., "state":"connected" | "dropped" | "ended", "dropped_seconds":...,
    // "kept_bytes":..., "resumes":..., "reason":...}: for the status report (the monitor).
    std::string status_json(std::chrono::steady_clock::time_point now) const;

private:
    void send(MessageType type, std::string_view payload);
    bool write_locked(std::string_view bytes);
    void drop(Stream const* stream);
    void on_message(Header const& h, std::string_view payload);

    SessionState state_;
    SessionLimits limits_;
    std::unique_ptr<Federate> federate_;
    // How long the connection has been dropped: zero while connected, once ended, or before any drop.
    std::chrono::steady_clock::duration dropped_for(std::chrono::steady_clock::time_point now) const;
    // Under mutex_ with state_ changed: what status_json and expired read without it (mutex_ is held while
    // writing to a slow federate, and the gateway's thread asks for the status).
    void noted();

    mutable std::mutex mutex_;  // state_, stream_; the writes
    std::condition_variable confirmed_;
    std::shared_ptr<Stream> stream_;  // none while dropped
    std::atomic<bool> ended_{false};
    std::mutex ending_;
    // For status_json and expired, never waiting on a write nor on the gateway.
    std::atomic<bool> connected_{false};
    std::atomic<std::chrono::steady_clock::rep> dropped_at_{0};  // since the clock's epoch; 0: not dropped
    std::atomic<std::size_t> kept_bytes_{0};
    std::atomic<std::uint32_t> resumes_{0};
    mutable std::mutex reason_mutex_;
    std::string end_reason_;
};

// Reads one whole message (header and payload); false as Stream::read_exact. BadMessage for a bad header.
bool read_message(Stream& stream, std::uint32_t max_size, std::atomic<bool> const& stop, Header& header, std::string& payload,
                  std::chrono::milliseconds idle = {});

}  // namespace hlacore::fedpro
