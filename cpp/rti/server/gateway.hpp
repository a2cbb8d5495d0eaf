// The gateway: a single-threaded epoll reactor that runs federations for federates connected over TCP (with
// UDP datagrams beside it for best-effort messages, server/datagrams.cpp).
// `rtig` is a thin main around it; Python runs the same class in a background thread.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <sys/epoll.h>
#include <sys/socket.h>

#include "rti/server/event_log.hpp"
#include "rti/server/federation.hpp"
#include "rti/tls.hpp"
#include "rti/server/recorder.hpp"
#include "rti/server/spill.hpp"
#include "rti/trace.hpp"
#include "rti/wire/datagram.hpp"

namespace hlacore {

// A thin epoll wrapper for the gateway's loop: register file descriptors, wait for readiness (reactor.cpp).
class EventLoop {
public:
    EventLoop();
    ~EventLoop();
    EventLoop(const EventLoop&) = delete;
    EventLoop& operator=(const EventLoop&) = delete;

    void add(int fd, std::uint32_t events);
    void modify(int fd, std::uint32_t events);
    void remove(int fd);

    // The events of one wait, in the loop's own array (until the next wait).
    struct Ready {
        const epoll_event* first;
        const epoll_event* last;
        const epoll_event* begin() const { return first; }
        const epoll_event* end() const { return last; }
    };
    // Waits up to timeout_ms (-1: forever) and returns the ready events; EINTR yields none. With `spin`, polls
    // without sleeping for up to that long first (rti/busy_poll.hpp).
    Ready wait(int timeout_ms, std::chrono::microseconds spin = {}, bool yield_first = false);

private:
    static constexpr int kMaxEvents = 256;
    int epoll_fd_;
    epoll_event ready_[kMaxEvents];  // not a vector sized per wait: a busy-polling turn zeroed all of it
};

struct GatewayOptions {
    std::string host = "127.0.0.1";
    std::uint16_t port = 60400;  // 0: pick a free port
    std::vector<std::string> fom_path;  // searched for FED files a client could not read itself
    bool verbose = false;
    double partial_frame_timeout_s = 10.0;     // a half-sent frame older than this drops the connection
    // Flow control (docs/robustness.md): the bytes the gateway holds in memory for one client (its output
    // queue and the messages time management keeps for it). Beyond it, what is written for the client is
    // spilled to a file in spill_dir (server/spill.hpp), all such files within disk_budget; without spilling
    // (disk_budget 0), or for what time management holds, the clients sending to it are paused (not read)
    // until it is below half of it again, and a client over its budget that takes nothing from its queue for
    // stall_timeout_s is dropped (0: never).
    std::size_t client_budget = 64u << 20;
    double stall_timeout_s = 30.0;
    std::string spill_dir;  // "": $TMPDIR, else /tmp
    std::uint64_t disk_budget = std::uint64_t{1} << 30;
    std::uint32_t max_frame_bytes = wire::kMaxFrameBytes;  // announced in the Welcome; larger frames are refused
    std::string save_dir;  // federation saves are written here as files ("": kept in memory only)
    // The time semantics of a federation whose creator does not ask for one (rti/time.hpp).
    TimeSemantics time_semantics = TimeSemantics::Exact;
    // Non-empty: every client proves it knows this secret (challenge-response, rti/auth.hpp) before anything
    // else; docs/networking.md.
    std::string secret;
    std::string secret_file;  // where `secret` was read (the Federate Protocol's door gives it to its federates)
    // Federations with a secret of their own: creating, joining or destroying one needs a proof of it
    // (auth::federation_proof), whatever the connection's secret.
    std::map<std::string, std::string> federation_secrets;
    std::string trace_path;  // non-empty: write the message trace there (trace.hpp)
    std::string record_path;  // non-empty: record every federation there (server/recorder.hpp)
    // Best effort over UDP, on the same port (server/datagrams.cpp, docs/networking.md): the largest datagram
    // either side sends; larger best-effort messages go over TCP. 0: no datagrams, everything over TCP.
    std::uint32_t max_datagram = wire::kDefaultMaxDatagram;
    // Both non-empty: every TCP connection is TLS with this certificate (chain) and private key, PEM files
    // (the key readable by its owner only; rti/tls.hpp); then no datagrams are offered (best effort goes
    // over the encrypted stream). Both empty: plain TCP.
    std::string tls_cert;
    std::string tls_key;
    // Busy polling (rti/busy_poll.hpp; 0, the default: off): each wait for the clients polls without sleeping
    // for up to this many µs before it sleeps. At most kMaxBusyPollUs.
    std::uint32_t busy_poll_us = 0;
    // Non-empty: also listen on a Unix socket at this path, for federates on this host (rti/unix_socket.hpp);
    // its connections get neither TLS nor datagrams. The file is removed when the gateway ends.
    std::string unix_path;
    // Non-empty, HOST:PORT: the HLA 4 Federate Protocol's door on this gateway (cpp/fedpro/server.hpp), opened by
    // rtig and hlacore.Gateway, not by the Gateway class (the door is a federate side of its own).
    std::string fedpro;
    double fedpro_resume_timeout_s = 60.0;  // a dropped Federate Protocol session not resumed within it ends
};
// The bounds of the options (rtig's arguments and hlacore.Gateway check them; both included). The smallest
// max_datagram (or 0) leaves room for a header and a small message.
constexpr std::size_t kMinClientBudget = 65536;
constexpr std::uint32_t kMinMaxFrame = 65536;
constexpr std::uint32_t kMaxMaxFrame = 1u << 30;
constexpr std::uint32_t kMinMaxDatagram = 256;

class Gateway {
public:
    // Binds and listens; throws std::runtime_error when the address is unusable.
    explicit Gateway(GatewayOptions options);
    ~Gateway();
    Gateway(const Gateway&) = delete;
    Gateway& operator=(const Gateway&) = delete;

    const std::string& host() const { return options_.host; }
    std::uint16_t port() const { return port_; }

    // Serves until stop() is called.
    void run();
    // Another part of the process's share of the status report (the Federate Protocol's door: its sessions):
    // `section` returns `"name":{...}`, called on the gateway's thread while it answers a status query, so it must
    // be quick and thread-safe. Set before run().
    void add_status_section(std::function<std::string()> section) { status_sections_.push_back(std::move(section)); }
    // Thread-safe and async-signal-safe.
    void stop();

private:
    struct Connection;
    struct FederationEntry;
    class ConnectionOutbox;
    class ConnectionTap;

    void accept_all(int listen_fd);
    void close_descriptors();  // the sockets and descriptors it opened (the destructor, a failed constructor)
    void on_readable(Connection& c);
    // Reads into c.in what the socket (or, with TLS, the TLS session) has, at most about `budget` bytes but
    // never leaving decrypted bytes inside the session; "" or why the connection must be closed, with
    // `peer_closed` set at the end of the stream.
    std::string read_plain(Connection& c, std::size_t budget, bool& peer_closed);
    std::string read_tls(Connection& c, std::size_t budget, bool& peer_closed);
    // Writes from c.out at c.out_offset: bytes taken, 0 when the socket takes no more now, -1 with `error`.
    long write_some(Connection& c, std::string& error);
    // Serves the whole frames read from c, until one of them delivers to a client over its budget.
    void serve_frames(Connection& c);
    void on_frame(Connection& c, const wire::Frame& frame);
    // The session before any service: the Hello, then the answer to the challenge (session.cpp).
    void greet(Connection& c, wire::MessageType type, const wire::Message& message);
    // The one dispatcher: a switch over the frame's type onto serve() (gateway.cpp), past the taps.
    void on_request(Connection& c, const wire::Frame& frame);
    template <class M>
    void serve_frame(Connection& c, const wire::Frame& frame);
    template <class M>
    void serve_message(Connection& c, const M& m);  // through the taps onto serve()
    template <class M>
    void tap(Connection& c, const M& m);
#define HLACORE_X(name) void serve(Connection& c, const wire::name& m);
    HLACORE_GATEWAY_SERVICES(HLACORE_X)
#undef HLACORE_X
    template <class M>
    void serve(Connection& c, const M& m);  // any other message: the joined federate's federation handles it
    // Answers `request` with the result serve_request() returns (a Reply when it returns nothing), or with
    // the RtiError it throws as an error Reply.
    template <class F>
    void answer(Connection& c, std::uint32_t request, F&& serve_request);
    Federation& joined(const Connection& c) const;  // throws FederateNotExecutionMember
    // For a federation with a secret of its own: throws AuthenticationFailed (and logs) unless `proof` proves
    // it for `action` over c's nonce.
    void require_federation_secret(const Connection& c, const char* action, const std::string& federation,
                                   const std::string& proof) const;
    const std::string& federation_name(const Connection& c) const;  // c is joined
    void close(int fd, const std::string& why);
    void flush(Connection& c);
    // What flush() writes next: released frames from the backlog (move_backlog), through the message trace.
    void refill(Connection& c);
    void move_backlog(Connection& c);
    void flush_dirty();
    void drop_stale_partials();
    // Connection buffers that grew past kKeptBufferBytes are given back once empty, unless frames that large
    // went through within kLargeFrameGrace: the next camera frame then reuses them (fresh pages cost more
    // than the copy). Once the large frames stop, the next turn of the loop gives them all back.
    bool keeping_large_buffers() const;
    void release_large_buffers();
    // After federates resign and objects are deleted: the heap glibc keeps below its top goes back to the
    // system, at most once a second, so that a long-running gateway returns to near its idle size.
    void give_memory_back();
    void mark_dirty(Connection& c);
    // Flow control: what the gateway holds for c, c stops being read while `consumer` is over its budget,
    // and each turn of the loop resumes, keeps alive or drops what waits.
    std::size_t held_for(const Connection& c) const;
    // Where the next frame for c goes: behind its backlog of released frames, if any.
    std::string& output(Connection& c);
    void pause(Connection& producer, const Connection& consumer);
    void update_events(Connection& c);
    void service_paused();
    void drop_stalled_readers();
    // Moves what c holds in memory beyond what it takes next to its spill file (made now if need be): true
    // when c is within its budget then (or is being dropped, its spill having failed), false when what keeps
    // it over is held by time management, which does not spill.
    bool spill(Connection& c);
    void spill_failed(Connection& c, const std::string& why);  // c is dropped at the end of the turn
    // FrameParking for c's federate (ConnectionOutbox): nullopt, or "", with c dropped, when its file fails.
    std::optional<std::uint64_t> park(Connection& c, std::string_view frame);
    std::string unpark(Connection& c, std::uint64_t ticket, std::uint32_t size, bool keep);
    void log_spilling(const Connection& c, const char* what, const std::string& directory);
    // Whether c has taken nothing of what waits for it for kStoppedReading: a client that is reading, only
    // slower than its senders, holds them back; one that stopped (at a breakpoint) spills.
    bool stopped_reading(const Connection& c) const;
    static constexpr std::chrono::milliseconds kStoppedReading{50};
    // While c spills: what it may hold in `out` and in `tail` each (a quarter of its budget, at most 256 KiB).
    std::size_t spill_keep() const { return std::min<std::size_t>(256u << 10, options_.client_budget / 4); }
    void drop_failed_spills();
    // After serving a frame of `producer`: pauses it when a client it sent to is still over its budget once
    // flushed.
    void pause_if_over_budget(Connection& producer);
    std::string find_fed_file(const std::string& name) const;
    void log(const std::string& line) const;

    // ---- best effort over UDP (server/datagrams.cpp) ----
    // The datagram socket on the listening address (nothing, with a log line, when it cannot be had).
    void open_datagrams(const sockaddr_storage& bound, socklen_t length);
    void on_datagrams();
    void on_datagram(std::string_view datagram, const sockaddr_storage& from, socklen_t length);
    template <class M>
    bool decodes(const wire::Frame& frame, M& m);  // counts a datagram that does not as stray
    template <class View>
    void serve_best_effort(Connection& c, std::uint64_t sequence, const wire::Frame& frame);
    // Sends `frame` to c as a datagram when c takes them and it fits; false: it goes in the stream.
    bool send_datagram(Connection& c, std::string_view frame);
    void give_datagram_token(Connection& c);
    void write_datagram_status(std::string& json) const;

    GatewayOptions options_;
    int listen_fd_ = -1;
    int unix_listen_fd_ = -1;  // options_.unix_path's
    int wake_fd_ = -1;
    int reserve_fd_ = -1;  // kept open to accept-and-close a connection when out of file descriptors
    std::uint16_t port_ = 0;
    EventLoop loop_;
    std::uint64_t writes_ = 0;             // successful socket writes, for the busy-polling wait after them
    std::uint64_t writes_before_wait_ = 0;
    tls::Context tls_;  // set: every connection is TLS
    std::map<int, std::unique_ptr<Connection>> connections_;
    std::map<std::string, std::unique_ptr<FederationEntry>> federations_;
    std::vector<int> dirty_;
    std::vector<int> paused_;
    SpillBudget spill_budget_;
    std::vector<int> spill_failed_;  // connections whose spill failed, dropped at the end of the turn
    int over_budget_ = -1;  // a client found over its budget while the current frame was served
    int serving_ = -1;      // the client whose frame is being served
    std::chrono::steady_clock::time_point large_frame_at_{};  // when the last frame above kKeptBufferBytes came
    bool large_buffers_kept_ = false;  // since then, buffers above it may be kept for the next one
    bool memory_freed_ = false;        // a resign, a deletion or a spill since the last give_memory_back()
    std::chrono::steady_clock::time_point memory_given_back_at_{};
    std::unique_ptr<MessageTrace> trace_;
    std::unique_ptr<Recorder> recorder_;
    // While a frame of at least wire::kSplicedValueBytes is served (on_frame): the frame and the read block it
    // lies in, which a forwarded update's or interaction's large values are written to the receivers from
    // (ConnectionOutbox::spliced).
    struct SpliceSource {
        std::shared_ptr<const char[]> block;
        std::string_view frame;
    };
    SpliceSource splice_source_;
    EventLog events_;  // joins, resigns and drops, for the status report
    std::vector<std::function<std::string()>> status_sections_;  // add_status_section
    void recorder_failed();  // logs why recording into the file stopped, once
    // Has the federation's outbox hand its callbacks to the recorder (made now if there is none).
    void record_federation(FederationEntry& entry);
    int datagram_fd_ = -1;
    std::unordered_map<std::uint64_t, int> datagram_tokens_;  // token -> connection descriptor
    std::uint64_t stray_datagrams_ = 0;  // not hlacore datagrams, unknown tokens, from the wrong address
    std::string datagram_out_;  // the datagram being sent
};

}  // namespace hlacore
