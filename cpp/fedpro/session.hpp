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

#include "fedpro/session_protocol.hpp"

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

    // Runs connection `fd` (its handshake done) until it drops or the session ends; closes it.
    void serve(int fd);
    // A resume on connection `fd`: answers the federate, sends again what it lacks; false when refused (answered
    // too; `fd` is then the caller's to close).
    bool resume(int fd, std::uint32_t last_received_by_federate);
    // A callback for the federate (a CallbackRequest's bytes): numbered and kept, written when connected. Waits
    // while the kept messages are over budget, until the federate confirms some or the session ends.
    void send_callback(std::string_view request);

    // Dropped for longer than the resume timeout, or ended.
    bool expired(std::chrono::steady_clock::time_point now) const;
    bool ended() const { return ended_; }
    // Ends the session: the federate resigns, SessionTerminated is sent when `tell_federate`, the connection
    // closes. Idempotent.
    void end(bool tell_federate);

private:
    void send(MessageType type, std::string_view payload);
    bool write_locked(std::string_view bytes);
    void drop(int fd);
    void on_message(Header const& h, std::string_view payload);

    SessionState state_;
    SessionLimits limits_;
    std::unique_ptr<Federate> federate_;
    mutable std::mutex mutex_;  // state_, fd_, dropped_at_; the writes
    std::condition_variable confirmed_;
    int fd_ = -1;
    std::chrono::steady_clock::time_point dropped_at_{};
    std::atomic<bool> ended_{false};
    std::mutex ending_;
};

// Reads exactly `n` bytes into `out` from `fd`, polling so that `stop` is seen within 200 ms; false on end of
// stream, an error, `stop`, or no byte for `idle` (when nonzero).
bool read_exact(int fd, char* out, std::size_t n, std::atomic<bool> const& stop, std::chrono::milliseconds idle = {});
// Writes all of `bytes`; false on an error or a peer that takes nothing for `stall`.
bool write_all(int fd, std::string_view bytes, std::chrono::milliseconds stall);
// Reads one whole message (header and payload); false as read_exact. BadMessage for a bad header.
bool read_message(int fd, std::uint32_t max_size, std::atomic<bool> const& stop, Header& header, std::string& payload,
                  std::chrono::milliseconds idle = {});

}  // namespace hlacore::fedpro
