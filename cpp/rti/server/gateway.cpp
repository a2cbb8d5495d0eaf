#include "rti/server/gateway.hpp"
#include "rti/auth.hpp"
#include "rti/busy_poll.hpp"
#include "rti/server/connection.hpp"
#include "rti/unix_socket.hpp"
#include "rti/wire/json.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <deque>
#include <fstream>
#include <new>
#include <stdexcept>
#include <unordered_map>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/eventfd.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <openssl/err.h>

namespace hlacore {

using Clock = std::chrono::steady_clock;

// Connection buffers above this capacity are released once empty (but see keeping_large_buffers()).
constexpr std::size_t kKeptBufferBytes = 1u << 20;
constexpr std::chrono::seconds kLargeFrameGrace{1};
// Released frames beyond this go through a connection's backlog rather than straight into its buffer.
constexpr std::size_t kPacedBytes = 256u << 10;

class Gateway::ConnectionOutbox : public Outbox {
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
    template <class M>
    bool spliced(FederateHandle federate, const M& m) {
        auto it = peers_.find(federate);
        if (!gateway_.splice_source_.block || it == peers_.end()) return false;
        Connection& c = *it->second;
        // TLS encrypts from one buffer, the trace reads the frames in `out`, and output() is `tail` while
        // there is a backlog.
        if (c.ssl || gateway_.trace_ || !c.backlog.empty()) return false;
        gateway_.mark_dirty(c);
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
        : outbox(gw), federation(std::move(name), std::move(fom), std::move(fed_name), std::move(fed_text), outbox) {}
    ConnectionOutbox outbox;
    Federation federation;
    std::unique_ptr<FederationRecording> recording;  // when the gateway records: what its outbox sends
};

namespace {

[[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error(what + ": " + std::strerror(errno));
}

std::string describe_peer(const sockaddr_storage& addr) {
    char host[INET6_ADDRSTRLEN] = "?";
    unsigned port = 0;
    if (addr.ss_family == AF_INET) {
        const auto* a = reinterpret_cast<const sockaddr_in*>(&addr);
        inet_ntop(AF_INET, &a->sin_addr, host, sizeof host);
        port = ntohs(a->sin_port);
    } else if (addr.ss_family == AF_INET6) {
        const auto* a = reinterpret_cast<const sockaddr_in6*>(&addr);
        inet_ntop(AF_INET6, &a->sin6_addr, host, sizeof host);
        port = ntohs(a->sin6_port);
    }
    return std::string(host) + ":" + std::to_string(port);
}

// A Unix socket's peer, by the process that connected (its credentials, SO_PEERCRED).
std::string describe_local_peer(int fd) {
    ucred peer{};
    socklen_t len = sizeof peer;
    if (getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &peer, &len) < 0) return "unix socket";
    return "unix socket, pid " + std::to_string(peer.pid);
}

// Reads at most `limit` bytes: parse_fed refuses a longer text anyway, and one byte more is enough for it
// to say so.
bool read_file(const std::string& path, std::string& text, std::size_t limit) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    text.clear();
    char buf[1 << 16];
    while (text.size() < limit) {
        in.read(buf, static_cast<std::streamsize>(std::min(sizeof buf, limit - text.size())));
        text.append(buf, static_cast<std::size_t>(in.gcount()));
        if (!in) break;
    }
    return !in.bad();
}

}  // namespace

// The gateway's epoll wrapper (gateway.hpp).

EventLoop::EventLoop() : epoll_fd_(epoll_create1(EPOLL_CLOEXEC)) {
    if (epoll_fd_ < 0) fail("epoll_create1");
}

EventLoop::~EventLoop() { ::close(epoll_fd_); }

void EventLoop::add(int fd, std::uint32_t events) {
    epoll_event ev{};
    ev.events = events;
    ev.data.fd = fd;
    if (epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, fd, &ev) < 0) fail("epoll_ctl add");
}

void EventLoop::modify(int fd, std::uint32_t events) {
    epoll_event ev{};
    ev.events = events;
    ev.data.fd = fd;
    if (epoll_ctl(epoll_fd_, EPOLL_CTL_MOD, fd, &ev) < 0) fail("epoll_ctl mod");
}

void EventLoop::remove(int fd) { epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, fd, nullptr); }

EventLoop::Ready EventLoop::wait(int timeout_ms, std::chrono::microseconds spin, bool yield_first) {
    int n = 0;
    if (spin.count() > 0 && timeout_ms != 0)
        n = busy_poll(spin, [&] { return epoll_wait(epoll_fd_, ready_, kMaxEvents, 0); }, yield_first);
    if (n == 0) n = epoll_wait(epoll_fd_, ready_, kMaxEvents, timeout_ms);
    if (n < 0) {
        if (errno != EINTR) fail("epoll_wait");
        n = 0;
    }
    return {ready_, ready_ + n};
}

Gateway::Gateway(GatewayOptions options) : options_(std::move(options)) {
    if (options_.max_datagram != 0 && (options_.max_datagram < kMinMaxDatagram || options_.max_datagram > wire::kMaxDatagramLimit))
        throw std::invalid_argument("max_datagram must be 0 or between " + std::to_string(kMinMaxDatagram) + " and " +
                                    std::to_string(wire::kMaxDatagramLimit) + " bytes, not " +
                                    std::to_string(options_.max_datagram));
    if (const std::string error = busy_poll_error(options_.busy_poll_us); !error.empty()) throw std::invalid_argument(error);
    if (options_.tls_cert.empty() != options_.tls_key.empty())
        throw std::invalid_argument("TLS needs both a certificate and its key (rtig --tls-cert FILE --tls-key FILE)");
    if (!options_.tls_cert.empty()) tls_ = tls::server_context(options_.tls_cert, options_.tls_key);
    // What the constructor opened is closed again when a later step fails (a Gateway made in Python that
    // cannot listen leaks nothing).
    try {
        addrinfo hints{};
        hints.ai_family = AF_UNSPEC;
        hints.ai_socktype = SOCK_STREAM;
        hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
        addrinfo* found = nullptr;
        const std::string port = std::to_string(options_.port);
        if (int rc = getaddrinfo(options_.host.c_str(), port.c_str(), &hints, &found); rc != 0)
            throw std::runtime_error("cannot resolve " + options_.host + ": " + gai_strerror(rc));
        std::unique_ptr<addrinfo, decltype(&freeaddrinfo)> guard(found, freeaddrinfo);

        listen_fd_ = socket(found->ai_family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
        if (listen_fd_ < 0) fail("socket");
        int one = 1;
        setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
        if (bind(listen_fd_, found->ai_addr, found->ai_addrlen) < 0) fail("cannot listen on " + options_.host + ":" + port);
        if (listen(listen_fd_, 128) < 0) fail("listen");
        sockaddr_storage bound{};
        socklen_t len = sizeof bound;
        getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&bound), &len);
        port_ = bound.ss_family == AF_INET6 ? ntohs(reinterpret_cast<sockaddr_in6*>(&bound)->sin6_port)
                                            : ntohs(reinterpret_cast<sockaddr_in*>(&bound)->sin_port);

        wake_fd_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
        if (wake_fd_ < 0) fail("eventfd");
        loop_.add(listen_fd_, EPOLLIN);
        loop_.add(wake_fd_, EPOLLIN);
        reserve_fd_ = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
        // Datagrams are neither encrypted nor signed: under TLS best effort goes over the encrypted stream.
        if (options_.max_datagram && !tls_) open_datagrams(bound, len);
        if (!options_.unix_path.empty()) {
            unix_listen_fd_ = unix_socket::listen_at(options_.unix_path);
            loop_.add(unix_listen_fd_, EPOLLIN);
        }
        if (!options_.trace_path.empty()) trace_ = std::make_unique<MessageTrace>(options_.trace_path);
        if (!options_.record_path.empty()) recorder_ = std::make_unique<Recorder>(options_.record_path);
    } catch (...) {
        close_descriptors();
        throw;
    }
}

Gateway::~Gateway() {
    if (recorder_) {
        try {
            recorder_->close();
        } catch (const std::exception& e) {
            log(std::string("the recording is incomplete: ") + e.what());
        }
        recorder_failed();
    }
    close_descriptors();
}

void Gateway::close_descriptors() {
    for (auto& [fd, c] : connections_) ::close(fd);
    for (int* fd : {&listen_fd_, &datagram_fd_, &wake_fd_, &reserve_fd_}) {
        if (*fd >= 0) ::close(*fd);
        *fd = -1;
    }
    if (unix_listen_fd_ >= 0) {
        ::close(unix_listen_fd_);
        ::unlink(options_.unix_path.c_str());  // only a file this gateway made: it listened there
        unix_listen_fd_ = -1;
    }
}

void Gateway::stop() {
    const std::uint64_t one = 1;
    [[maybe_unused]] auto n = ::write(wake_fd_, &one, sizeof one);
}

void Gateway::run() {
    for (;;) {
        bool partial_pending = false;  // or a connection that has not said Hello yet
        bool writes_pending = false;   // a client whose socket takes no more for now
        for (const auto& [fd, c] : connections_) {
            partial_pending |= !c->in.empty() || !c->greeted;
            writes_pending |= c->write_armed;
        }
        const bool recording_pending = recorder_ && recorder_->pending();  // written out within half a second
        const bool wrote = writes_ != writes_before_wait_;  // answers went out: their readers may want this core
        writes_before_wait_ = writes_;
        const EventLoop::Ready events =
            loop_.wait(partial_pending || writes_pending || !paused_.empty() || recording_pending || large_buffers_kept_
                           ? 250 : -1,
                       std::chrono::microseconds(options_.busy_poll_us), wrote);
        for (const epoll_event& ev : events) {
            const int fd = ev.data.fd;
            if (fd == wake_fd_) {
                std::uint64_t v;
                [[maybe_unused]] auto n = ::read(wake_fd_, &v, sizeof v);
                flush_dirty();
                if (trace_) trace_->flush();
                return;
            }
            if (fd == listen_fd_ || fd == unix_listen_fd_) {
                accept_all(fd);
                continue;
            }
            if (fd == datagram_fd_) {
                on_datagrams();
                continue;
            }
            auto it = connections_.find(fd);
            if (it == connections_.end()) continue;
            // A TLS read that had to write (the handshake into a full socket) goes on when it may.
            const bool read_on_write = (ev.events & EPOLLOUT) && it->second->read_wants_write;
            if ((ev.events & (EPOLLIN | EPOLLHUP | EPOLLERR)) || read_on_write) on_readable(*it->second);
            it = connections_.find(fd);
            if (it != connections_.end() && (ev.events & EPOLLOUT)) mark_dirty(*it->second);
        }
        flush_dirty();
        if (!paused_.empty()) service_paused();
        if (partial_pending) drop_stale_partials();
        if (writes_pending) drop_stalled_readers();
        if (large_buffers_kept_ && !keeping_large_buffers()) release_large_buffers();
        if (trace_) trace_->flush();
        if (recorder_) {
            recorder_->tick();
            recorder_failed();
        }
    }
}

void Gateway::recorder_failed() {
    const std::string failure = recorder_->take_failure();
    if (!failure.empty()) log("recording into " + options_.record_path + " stopped: " + failure);
}

void Gateway::record_federation(FederationEntry& entry) {
    if (!recorder_) recorder_ = std::make_unique<Recorder>();
    if (entry.recording) return;
    entry.recording = std::make_unique<FederationRecording>(*recorder_, entry.federation);
    entry.outbox.recorder = entry.recording.get();
}

void Gateway::accept_all(int listen_fd) {
    for (;;) {
        sockaddr_storage addr{};
        socklen_t len = sizeof addr;
        int fd = accept4(listen_fd, reinterpret_cast<sockaddr*>(&addr), &len, SOCK_NONBLOCK | SOCK_CLOEXEC);
        if (fd < 0) {
            if (errno == EINTR || errno == ECONNABORTED) continue;
            if ((errno == EMFILE || errno == ENFILE) && reserve_fd_ >= 0) {
                // Out of file descriptors: the pending connection would keep the (level-triggered) listening
                // socket readable and this loop spinning. Free the reserve, take the connection and close it,
                // take the reserve back. The peer sees EOF; the joined federates are unaffected.
                const int saved = errno;
                ::close(reserve_fd_);
                reserve_fd_ = -1;
                const int refused = accept4(listen_fd, nullptr, nullptr, SOCK_CLOEXEC);
                if (refused >= 0) ::close(refused);
                reserve_fd_ = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
                // accept4 reports EMFILE before looking at the queue: there may have been nothing to refuse.
                if (refused < 0) return;
                log(std::string("refused a connection: ") + std::strerror(saved) + " (" +
                    std::to_string(connections_.size()) + " connections open)");
                continue;
            }
            if (errno != EAGAIN && errno != EWOULDBLOCK) log(std::string("accept failed: ") + std::strerror(errno));
            return;
        }
        auto c = std::make_unique<Connection>();
        c->fd = fd;
        c->local = listen_fd == unix_listen_fd_;
        if (c->local) {
            unix_socket::size_send_buffer(fd);
            c->peer = describe_local_peer(fd);
        } else {
            int one = 1;
            setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
            c->peer = describe_peer(addr);
        }
        if (tls_ && !c->local) {
            try {
                c->ssl = tls::session(tls_.get(), fd);
            } catch (const std::exception& e) {
                log("refused a connection from " + c->peer + ": " + e.what());
                ::close(fd);
                continue;
            }
            SSL_set_accept_state(c->ssl.get());
        }
        loop_.add(fd, EPOLLIN);
        if (options_.verbose) log("connection from " + c->peer);
        connections_[fd] = std::move(c);
    }
}

namespace {
// Bounded per turn so that one busy peer cannot starve the others.
constexpr std::size_t kReadBudget = 16 * wire::ReadBuffer::kChunk;

// Whether `bytes` begin like a TLS record (a handshake or an alert, TLS 1.x): what a TLS client sends first.
// No hlacore Hello starts so: its length field is small.
bool looks_like_tls(std::string_view bytes) {
    return bytes.size() >= 2 && (bytes[0] == 0x16 || bytes[0] == 0x15) && bytes[1] == 0x03;
}
}  // namespace

std::string Gateway::read_plain(Connection& c, std::size_t budget, bool& peer_closed) {
    for (std::size_t got = 0; got < budget && !c.in.holds_large_frame();) {
        const std::size_t want = c.in.wanted(options_.max_frame_bytes);
        const ssize_t n = ::recv(c.fd, c.in.room(want), want, 0);
        if (n > 0) {
            if (c.in.empty()) c.partial_since = Clock::now();
            c.in.commit(static_cast<std::size_t>(n));
            got += static_cast<std::size_t>(n);
            if (static_cast<std::size_t>(n) < want) break;
            continue;
        }
        if (n == 0) {
            peer_closed = true;
            break;
        }
        if (errno == EINTR) continue;
        if (errno == EAGAIN || errno == EWOULDBLOCK) break;
        return std::string("read failed: ") + std::strerror(errno);
    }
    if (!c.greeted && looks_like_tls(c.in.unread()))
        return "it began a TLS handshake and this gateway has no TLS (rtig --tls-cert FILE --tls-key FILE)";
    return "";
}

// SSL_read until the session holds nothing more (SSL_has_pending) or wants more from the socket, so that no
// decrypted byte, nor a whole record, waits inside it while epoll reports nothing: what it may keep is the
// start of a record whose rest is still to come, which epoll will report.
std::string Gateway::read_tls(Connection& c, std::size_t budget, bool& peer_closed) {
    SSL* ssl = c.ssl.get();
    const bool waited_for_write = c.read_wants_write, write_waited = c.write_wants_read;
    c.read_wants_write = false;
    for (std::size_t got = 0; got < budget || SSL_has_pending(ssl);) {
        ERR_clear_error();
        errno = 0;
        const std::size_t want = std::min<std::size_t>(c.in.wanted(options_.max_frame_bytes), INT_MAX);
        const int n = SSL_read(ssl, c.in.room(want), static_cast<int>(want));
        if (n > 0) {
            if (c.in.empty()) c.partial_since = Clock::now();
            c.in.commit(static_cast<std::size_t>(n));
            got += static_cast<std::size_t>(n);
            if (!SSL_has_pending(ssl) && static_cast<std::size_t>(n) < want) break;
            continue;
        }
        const bool handshaking = !SSL_is_init_finished(ssl);
        switch (SSL_get_error(ssl, n)) {
            case SSL_ERROR_WANT_READ: break;
            case SSL_ERROR_WANT_WRITE:
                c.read_wants_write = true;
                break;
            case SSL_ERROR_ZERO_RETURN: peer_closed = true; break;
            case SSL_ERROR_SYSCALL:
                if (errno == 0 || errno == ECONNRESET) {
                    if (handshaking) return "connection closed during the TLS handshake";
                    peer_closed = true;
                    break;
                }
                return std::string("read failed: ") + std::strerror(errno);
            default: {
                if (!handshaking) return "TLS error: " + tls::errors("protocol error");
                // What the client sent besides is read and dropped, so that closing sends a FIN rather than a
                // reset that could overtake an alert: a client without TLS sees the connection closed (or
                // reads the alert, when OpenSSL sent one) and says what to do.
                char chunk[4096];
                for (int i = 0; i < 4 && ::recv(c.fd, chunk, sizeof chunk, MSG_DONTWAIT) > 0; ++i) {
                }
                // An alert from the client (OpenSSL's reasons from SSL_AD_REASON_OFFSET on): it refused the
                // certificate, most often; anything else at this stage is most often not TLS at all.
                const bool alert = ERR_GET_REASON(ERR_peek_error()) >= SSL_AD_REASON_OFFSET;
                return alert ? "TLS handshake failed: the client refused it (" + tls::errors() + ")"
                             : "TLS handshake failed (a client without TLS?): " + tls::errors("protocol error");
            }
        }
        break;
    }
    if (write_waited) {  // the write that waited for a read may go on
        c.write_wants_read = false;
        mark_dirty(c);
    }
    if (waited_for_write != c.read_wants_write || write_waited) update_events(c);
    return "";
}

void Gateway::on_readable(Connection& c) {
    const int fd = c.fd;
    bool peer_closed = false;
    std::string error;
    try {
        error = c.ssl ? read_tls(c, kReadBudget, peer_closed) : read_plain(c, kReadBudget, peer_closed);
    } catch (const std::bad_alloc&) {  // the block a large frame reserves once its header is in
        error = "no memory for a frame of " + std::to_string(c.in.unread().size() + c.in.wanted(options_.max_frame_bytes)) +
                " bytes";
    }
    if (trace_) c.read_ns = MessageTrace::now_ns();
    if (!error.empty()) {
        // What a greeted client sent before the error is served first: a federate killed with messages
        // unread resets its connection, and the frames read just before the reset were its last words.
        if (c.greeted) serve_frames(c);
        if (connections_.count(fd)) close(fd, error);
        return;
    }
    serve_frames(c);
    if (!connections_.count(fd)) return;
    if (peer_closed) {
        const std::size_t left = c.in.unread().size();
        close(fd, left ? "connection closed in the middle of a frame (" + std::to_string(left) + " bytes pending)"
                       : "connection closed by peer");
    }
}

void Gateway::serve_frames(Connection& c) {
    const int fd = c.fd;
    try {
        wire::Frame frame;
        while (!c.paused) {
            const std::size_t used = wire::next_frame(c.in.unread(), frame, options_.max_frame_bytes);
            if (!used) break;
            // The frame stays where it is until the next read: consumed now, served from there.
            c.in.consume(used);
            if (used > kKeptBufferBytes) {
                large_frame_at_ = Clock::now();
                large_buffers_kept_ = true;
            }
            over_budget_ = -1;
            on_frame(c, frame);
            if (!connections_.count(fd)) return;
            if (!c.in.empty()) c.partial_since = Clock::now();
            pause_if_over_budget(c);
            if (!connections_.count(fd)) return;
        }
    } catch (const wire::WireError& e) {
        close(fd, std::string("protocol error: ") + e.what());
        return;
    }
    if (!keeping_large_buffers()) c.in.release_above(kKeptBufferBytes);
}

bool Gateway::keeping_large_buffers() const {
    return large_buffers_kept_ && Clock::now() - large_frame_at_ < kLargeFrameGrace;
}

void Gateway::release_large_buffers() {
    bool in_use = false;  // a large buffer not empty yet: tried again on the next turn of the loop
    for (auto& [fd, c] : connections_) {
        c->in.release_above(kKeptBufferBytes);
        if (c->unsent() == 0 && c->out.capacity() > kKeptBufferBytes) {
            std::string().swap(c->out);
            c->out_offset = 0;
        }
        // A splice still to write pins a sender's read block, perhaps of a connection closed since.
        in_use |= c->in.capacity() > kKeptBufferBytes || c->out.capacity() > kKeptBufferBytes || !c->splices.empty();
    }
    large_buffers_kept_ = in_use;
#if defined(__GLIBC__)
    // Once per burst of large frames, when all is given back: the decoded values were freed below the top of
    // the heap, where glibc keeps up to twice the largest for reuse (tests/transport/test_large_values.py measures it).
    if (!in_use) malloc_trim(0);
#endif
}

void Gateway::pause_if_over_budget(Connection& producer) {
    if (over_budget_ < 0) return;
    // Give the consumer's kernel buffer its chance first: pausing a producer whose consumer takes everything
    // at once would cost it a loop turn (up to 250 ms) per message.
    auto consumer = connections_.find(over_budget_);
    if (consumer != connections_.end()) flush(*consumer->second);
    consumer = connections_.find(over_budget_);
    if (consumer != connections_.end() && held_for(*consumer->second) > options_.client_budget)
        pause(producer, *consumer->second);
}

namespace {
// Clients refuse these at the call (ValueLengthExceeded): forwarded, they would not fit.
void check_forwardable(const wire::Frame& frame, std::uint32_t max_frame_bytes) {
    switch (frame.type) {
        case wire::MessageType::UpdateAttributes:
        case wire::MessageType::SendInteraction:
        case wire::MessageType::SendInteractionWithRegion:
            if (2 + frame.payload.size() + wire::kForwardedGrowth > max_frame_bytes)
                throw wire::WireError(std::string(wire::message_name(frame.type)) + " of " +
                                      std::to_string(2 + frame.payload.size()) +
                                      " bytes would be forwarded over the frame limit of " +
                                      std::to_string(max_frame_bytes) + " bytes");
            break;
        default: break;
    }
}
}  // namespace

template <class View>
void Gateway::serve_view(Connection& c, const wire::Frame& frame) {
    check_forwardable(frame, options_.max_frame_bytes);
    const View view = wire::decode_as<View>(frame);
    if (recorder_ && c.federation) recorder_->request(c.federation->federation, c.federate, view);
    if (frame.payload.size() < wire::kSplicedValueBytes) return serve(c, view);
    struct Scope {  // the block is let go once served, whatever happens
        SpliceSource& source;
        ~Scope() { source = {}; }
    } scope{splice_source_};
    splice_source_ = {c.in.share(), frame.payload};
    serve(c, view);
}

void Gateway::on_frame(Connection& c, const wire::Frame& frame) {
    // Updates and interactions, when nothing needs them whole (the trace): served with their values viewed in
    // the frame rather than copied out of it, a camera frame's megabytes included.
    if (c.greeted && c.challenge.empty() && !trace_) {
        if (frame.type == wire::MessageType::UpdateAttributes) return serve_view<wire::UpdateAttributesView>(c, frame);
        if (frame.type == wire::MessageType::SendInteraction) return serve_view<wire::SendInteractionView>(c, frame);
    }
    wire::Message message = wire::decode(frame);
    if (!c.greeted) {
        const auto* hello = std::get_if<wire::Hello>(&message);
        if (!hello || hello->magic != wire::kMagic)
            throw wire::WireError("expected a Hello handshake, got " + std::string(wire::message_name(frame.type)));
        if (hello->version != wire::kProtocolVersion)
            throw wire::WireError("protocol version " + std::to_string(hello->version) + " is not supported (gateway speaks " +
                                  std::to_string(wire::kProtocolVersion) + ")");
        c.greeted = true;
        if (c.ssl && options_.verbose)
            log("TLS with " + c.peer + ": " + SSL_get_version(c.ssl.get()) + ", " + SSL_get_cipher_name(c.ssl.get()));
        if (!options_.secret.empty()) c.challenge = auth::random_challenge();
        if (!options_.federation_secrets.empty()) c.nonce = auth::random_challenge();
        give_datagram_token(c);
        wire::encode(c.out, wire::Welcome{wire::kProtocolVersion, "hlacore rtig", options_.max_frame_bytes, c.challenge,
                                          c.datagram_token, c.datagram_token ? options_.max_datagram : 0, c.nonce});
        mark_dirty(c);
        return;
    }
    if (!c.challenge.empty()) {  // nothing but the answer to the challenge, and nothing after a wrong one
        const auto* answer = std::get_if<wire::Authenticate>(&message);
        if (!answer)
            throw wire::WireError(std::string(wire::message_name(frame.type)) + " sent before authenticating");
        if (!auth::verify(options_.secret, c.challenge, answer->proof)) {
            wire::encode(c.out, wire::Authenticated{false, "the gateway refused the secret"});
            flush(c);  // a small frame into an empty socket buffer: the client reads why
            close(c.fd, "authentication failed: wrong secret");
            return;
        }
        c.challenge.clear();
        wire::encode(c.out, wire::Authenticated{true, ""});
        mark_dirty(c);
        return;
    }
    check_forwardable(frame, options_.max_frame_bytes);
    if (trace_ && c.federation) trace_->received(c.federation->federation.name(), c.federate, message, c.read_ns);
    on_request(c, message);
}

// The one dispatcher of the gateway process: each message goes to the overload of serve() for its type.
// Requests with a result are served here; everything else a joined federate sends goes to its federation.
void Gateway::on_request(Connection& c, const wire::Message& message) {
    if (recorder_ && c.federation) recorder_->request(c.federation->federation, c.federate, message);
    std::visit([&](const auto& m) { serve(c, m); }, message);
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

const std::string& Gateway::federation_name(const Connection& c) const { return c.federation->federation.name(); }

Federation& Gateway::joined(const Connection& c) const {
    if (!c.federation) throw RtiError(ErrorCode::FederateNotExecutionMember, "not joined to a federation");
    return c.federation->federation;
}

namespace {
template <class M>
const char* name_of() {
    if constexpr (std::is_same_v<M, std::monostate>) {
        return wire::message_name(wire::MessageType::Invalid);
    } else {
        return wire::message_name(M::kType);
    }
}
}  // namespace

template <class M>
void Gateway::serve(Connection& c, const M& m) {
    if (!c.federation) throw wire::WireError(std::string(name_of<M>()) + " sent before joining a federation");
    try {
        c.federation->federation.handle(c.federate, m);
    } catch (const RtiError& e) {
        throw wire::WireError(std::string("refused ") + name_of<M>() + ": " + e.what());
    }
}

void Gateway::require_federation_secret(const Connection& c, const char* action, const std::string& federation,
                                        const std::string& proof) const {
    const auto secret = options_.federation_secrets.find(federation);
    if (secret == options_.federation_secrets.end()) return;
    if (auth::verify_federation(secret->second, c.nonce, action, federation, proof)) return;
    const std::string why = proof.empty() ? "no secret was given" : "the secret is wrong";
    log("refused to " + std::string(action) + " federation '" + federation + "' for " + c.peer + ": " + why);
    throw RtiError(ErrorCode::AuthenticationFailed,
                   "federation '" + federation + "' has a secret of its own and " + why +
                       " (RTIAmbassador(federation_secret_file=...), $HLACORE_FEDERATION_SECRET_FILE; docs/networking.md)");
}

void Gateway::serve(Connection& c, const wire::CreateFederation& m) {
    answer(c, m.request, [&] {
        require_federation_secret(c, "create", m.federation, m.proof);
        if (federations_.count(m.federation))
            throw RtiError(ErrorCode::FederationExecutionAlreadyExists, "federation '" + m.federation + "' already exists");
        std::string text = m.fed_text;
        std::string source = m.fed_name;
        if (text.empty()) {
            source = find_fed_file(m.fed_name);
            if (source.empty() || !read_file(source, text, fom::kMaxFedBytes + 1))
                throw RtiError(ErrorCode::CouldNotOpenFED, "FED file '" + m.fed_name +
                                                               "' was not found by the client nor in the gateway's "
                                                               "--fom-path");
        }
        fom::Fom fom;
        try {
            fom = fom::parse_fed(text, m.fed_name);
        } catch (const fom::FedError& e) {
            throw RtiError(ErrorCode::ErrorReadingFED, e.what());
        }
        auto& entry = federations_[m.federation] =
            std::make_unique<FederationEntry>(*this, m.federation, std::move(fom), m.fed_name, std::move(text));
        entry->federation.set_save_dir(options_.save_dir);
        if (recorder_) {
            record_federation(*entry);
            recorder_->created(entry->federation);
        }
        events_.add("created", m.federation, 0, m.fed_name);
        if (options_.verbose) log("created federation '" + m.federation + "' from " + source);
    });
}

void Gateway::serve(Connection& c, const wire::DestroyFederation& m) {
    answer(c, m.request, [&] {
        require_federation_secret(c, "destroy", m.federation, m.proof);
        auto it = federations_.find(m.federation);
        if (it == federations_.end())
            throw RtiError(ErrorCode::FederationExecutionDoesNotExist, "federation '" + m.federation + "' does not exist");
        if (it->second->federation.has_federates())
            throw RtiError(ErrorCode::FederatesCurrentlyJoined, std::to_string(it->second->federation.federate_count()) +
                                                                    " federate(s) still joined to '" + m.federation + "'");
        if (recorder_) recorder_->forget(it->second->federation);
        federations_.erase(it);
        events_.add("destroyed", m.federation, 0, "");
        if (options_.verbose) log("destroyed federation '" + m.federation + "'");
    });
}

void Gateway::serve(Connection& c, const wire::JoinFederation& m) {
    FederationEntry* entered = nullptr;
    answer(c, m.request, [&] {
        if (c.federation)
            throw RtiError(ErrorCode::FederateAlreadyExecutionMember,
                           "this ambassador is already joined to '" + c.federation->federation.name() + "'");
        require_federation_secret(c, "join", m.federation, m.proof);
        auto it = federations_.find(m.federation);
        if (it == federations_.end())
            throw RtiError(ErrorCode::FederationExecutionDoesNotExist, "federation '" + m.federation + "' does not exist");
        FederationEntry& entry = *it->second;
        entry.federation.check_membership_change("joinFederationExecution");
        const FederateHandle h = entry.federation.join(m.federate);
        c.federation = entered = &entry;
        c.federate = h;
        entry.outbox.peers_[h] = &c;
        return wire::FederationJoined{m.request, h, entry.federation.fed_text(), entry.federation.fed_name()};
    });
    if (!entered) return;
    if (recorder_) recorder_->joined(entered->federation, c.federate);
    events_.add("joined", m.federation, c.federate, m.federate);
    entered->federation.announce_pending(c.federate);  // after the reply: the client is joined by then
    if (trace_) trace_->joined(m.federation, c.federate, m.federate, c.read_ns);
    if (options_.verbose)
        log("'" + m.federate + "' joined '" + m.federation + "' as federate " + std::to_string(c.federate));
}

void Gateway::serve(Connection& c, const wire::ResignFederation& m) {
    answer(c, m.request, [&] {
        Federation& federation = joined(c);
        federation.check_membership_change("resignFederationExecution");
        const std::string name = federation.federate_name(c.federate);
        federation.resign(c.federate, static_cast<wire::ResignAction>(m.action));
        events_.add("resigned", federation.name(), c.federate, name);
        if (c.tap) recorder_->detach(*c.tap);
        c.tap.reset();
        c.federation->outbox.peers_.erase(c.federate);
        c.federation = nullptr;
        c.federate = 0;
    });
}

void Gateway::serve(Connection& c, const wire::RegisterObject& m) {
    answer(c, m.request, [&] {
        auto [handle, name] = joined(c).register_object(c.federate, m.object_class, m.name);
        return wire::ObjectRegistered{m.request, handle, std::move(name)};
    });
}

void Gateway::serve(Connection& c, const wire::RegisterObjectWithRegion& m) {
    answer(c, m.request, [&] {
        auto [handle, name] = joined(c).register_object_with_region(c.federate, m);
        return wire::ObjectRegistered{m.request, handle, std::move(name)};
    });
}

// Save/restore requests (HLA 1.3 §4.11, §4.17): the outcome comes as callbacks, refusals in the Reply.
void Gateway::serve(Connection& c, const wire::RequestFederationSave& m) {
    answer(c, m.request, [&] { joined(c).request_save(c.federate, m.label, m.time); });
}

void Gateway::serve(Connection& c, const wire::RequestFederationRestore& m) {
    answer(c, m.request, [&] {
        Federation& federation = joined(c);
        federation.request_restore(c.federate, m.label);
        if (options_.verbose) log("federation '" + federation.name() + "' restore '" + m.label + "' requested");
    });
}

void Gateway::serve(Connection& c, const wire::ReleaseResponse& m) {
    answer(c, m.request, [&] {
        return wire::AttributesReleased{m.request, joined(c).release_response(c.federate, m)};
    });
}

namespace {

// ,"process":{...}: the gateway's process (for an in-process gateway, the federate's program that runs it).
void write_process_status(std::string& json) {
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    const double cpu = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                       static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
    long long resident_pages = 0;  // now, not the peak that ru_maxrss gives
    if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(statm, "%*s %lld", &resident_pages) != 1) resident_pages = 0;
        std::fclose(statm);
    }
    json += ",\"process\":{\"pid\":" + std::to_string(::getpid()) + ",\"rss_bytes\":" +
            std::to_string(resident_pages * ::sysconf(_SC_PAGESIZE)) + ",\"cpu_seconds\":";
    json_number(json, cpu);
    json += '}';
}

}  // namespace

void Gateway::serve(Connection& c, const wire::QueryStatus& m) {
    answer(c, m.request, [&] {
        std::string json = "{\"server\":\"hlacore rtig\",\"address\":";
        json_string(json, options_.host + ":" + std::to_string(port_));
        json += tls_ ? ",\"tls\":true" : ",\"tls\":false";
        json += ",\"connections\":" + std::to_string(connections_.size()) + ",\"federations\":[";
        bool first = true;
        for (auto& [name, entry] : federations_) {
            if (!first) json += ',';
            first = false;
            entry->federation.write_status(json, m.instances);
        }
        json += "],\"datagrams\":";
        write_datagram_status(json);
        write_process_status(json);
        events_.write_after(m.events_after, json);
        json += '}';
        return wire::StatusReport{m.request, std::move(json)};
    });
}

void Gateway::serve(Connection& c, const wire::StartRecording& m) {
    answer(c, m.request, [&] {
        Federation& federation = joined(c);
        if (c.tap) throw RtiError(ErrorCode::RTIinternalError, "this federate records already");
        record_federation(*c.federation);
        c.tap = std::make_unique<ConnectionTap>(*this, c);
        recorder_->attach(federation, *c.tap);
        if (options_.verbose) log("'" + federation.federate_name(c.federate) + "' records '" + federation.name() + "'");
    });
}

void Gateway::serve(Connection& c, const wire::Authenticate&) {
    // Already authenticated, or no secret asked (on_frame answers the challenge itself): nothing to prove.
    wire::encode(output(c), wire::Authenticated{true, ""});
    mark_dirty(c);
}

void Gateway::serve(Connection& c, const wire::ClockProbe& m) {
    // The trace's clock (CLOCK_MONOTONIC), so that a client's offset applies to the trace's marks too.
    wire::encode(output(c), wire::ClockEcho{m.sequence, m.client_ns, static_cast<std::uint64_t>(MessageTrace::now_ns())});
    mark_dirty(c);
}

void Gateway::serve(Connection& c, const wire::Ping& m) {
    wire::encode(output(c), wire::Pong{m.sequence});
    mark_dirty(c);
}

void Gateway::serve(Connection& c, const wire::QueryTime& m) {
    answer(c, m.request, [&] {
        return wire::TimeQueried{m.request, joined(c).query_time(c.federate, static_cast<wire::TimeQuery>(m.which))};
    });
}

std::string Gateway::find_fed_file(const std::string& name) const {
    // Only regular files inside --fom-path: a client must not make the gateway open arbitrary paths, and
    // opening a FIFO or a device would block the whole gateway.
    auto readable = [](const std::string& p) {
        struct stat st {};
        return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(p.c_str(), R_OK) == 0;
    };
    const auto slash = name.find_last_of('/');
    const std::string base = slash == std::string::npos ? name : name.substr(slash + 1);
    if (base.empty() || base == "." || base == "..") return "";
    for (const auto& dir : options_.fom_path) {
        if (name[0] != '/' && name.find("..") == std::string::npos && readable(dir + "/" + name)) return dir + "/" + name;
        if (readable(dir + "/" + base)) return dir + "/" + base;
    }
    return "";
}

void Gateway::mark_dirty(Connection& c) {
    if (!c.dirty) {
        c.dirty = true;
        dirty_.push_back(c.fd);
    }
    if (held_for(c) > options_.client_budget) over_budget_ = c.fd;
}

// ---- flow control ----

std::string& Gateway::output(Connection& c) { return c.backlog.empty() ? c.out : c.tail; }

std::size_t Gateway::held_for(const Connection& c) const {
    const std::size_t queued = c.unsent() + c.backlog_bytes + c.tail.size();
    return c.federation ? queued + c.federation->federation.held_bytes(c.federate) : queued;
}

void Gateway::pause(Connection& producer, const Connection& consumer) {
    // A client over its budget with messages only its own requests release (a time advance) is not held
    // back from sending them; one whose output queue alone is over it is (it asks more than it reads).
    if (&producer == &consumer && producer.unsent() <= options_.client_budget) return;
    // Two clients holding each other back (each over its budget with the other's messages) would wait for
    // ever: the one that closes the circle is not paused and its consumer goes over budget instead.
    for (int fd = consumer.fd, steps = 0; steps <= static_cast<int>(paused_.size()); ++steps) {
        if (fd == producer.fd && &producer != &consumer) return;
        auto it = connections_.find(fd);
        if (it == connections_.end() || !it->second->paused) break;
        fd = it->second->blocked_by;
    }
    producer.paused = true;
    producer.blocked_by = consumer.fd;
    producer.paused_since = producer.keepalive_at = Clock::now();
    producer.pause_logged = false;
    paused_.push_back(producer.fd);
    update_events(producer);
}

void Gateway::update_events(Connection& c) {
    // A TLS write waiting for a read waits on EPOLLIN (which a paused connection still needs then), not on
    // EPOLLOUT, which would fire at once.
    const bool in = !c.paused || c.write_wants_read;
    const bool out = (c.write_armed && !c.write_wants_read) || c.read_wants_write;
    loop_.modify(c.fd, (in ? static_cast<std::uint32_t>(EPOLLIN) : 0u) | (out ? static_cast<std::uint32_t>(EPOLLOUT) : 0u));
}

// Each turn of the loop while connections are paused: resumes those whose consumer is below half its
// budget (or gone), sends the others a Pong now and then (their clients see the gateway alive while their
// sends wait) and logs a pause that lasts (drop_stalled_readers drops a consumer that stopped reading).
void Gateway::service_paused() {
    const auto now = Clock::now();
    std::vector<int> paused;
    paused.swap(paused_);
    for (int fd : paused) {
        auto it = connections_.find(fd);
        if (it == connections_.end()) continue;
        Connection& p = *it->second;
        auto blocker = connections_.find(p.blocked_by);
        if (blocker != connections_.end() && held_for(*blocker->second) > options_.client_budget / 2) {
            Connection& c = *blocker->second;
            if (!p.pause_logged && now - p.paused_since > std::chrono::seconds(10)) {
                p.pause_logged = true;
                log("holding back " + p.peer + " for 10 s: " + c.peer + " holds " + std::to_string(held_for(c)) +
                    " bytes for it (budget " + std::to_string(options_.client_budget) + "; docs/robustness.md)");
            }
            if (now - p.keepalive_at > std::chrono::seconds(1)) {
                p.keepalive_at = now;
                wire::encode(output(p), wire::Pong{0});
                mark_dirty(p);
            }
            paused_.push_back(fd);
            continue;
        }
        p.paused = false;
        p.blocked_by = -1;
        p.partial_since = now;
        update_events(p);
        serve_frames(p);  // what it had already sent; may pause it again
    }
    flush_dirty();
}

// Drops the clients that hold more than half their budget and have taken nothing for stall_timeout_s, whether
// or not a producer waits for them (it may have sent everything already); their producers resume next turn.
void Gateway::drop_stalled_readers() {
    if (options_.stall_timeout_s <= 0) return;
    const auto now = Clock::now();
    std::vector<std::pair<int, std::string>> stalled;
    for (const auto& [fd, c] : connections_) {
        const double idle = std::chrono::duration<double>(now - c->progress_at).count();
        if (c->write_armed && idle > options_.stall_timeout_s && held_for(*c) > options_.client_budget / 2)
            stalled.emplace_back(fd, "not reading: " + std::to_string(c->unsent()) +
                                         " bytes queued, none taken for " + std::to_string(static_cast<int>(idle)) +
                                         " s (budget " + std::to_string(options_.client_budget) + ")");
    }
    for (const auto& [fd, why] : stalled) close(fd, why);
}

void Gateway::flush_dirty() {
    // Closing a connection can dirty others (resign notices), so loop until quiet.
    while (!dirty_.empty()) {
        std::vector<int> batch;
        batch.swap(dirty_);
        for (int fd : batch) {
            auto it = connections_.find(fd);
            if (it == connections_.end()) continue;
            it->second->dirty = false;
            flush(*it->second);
        }
    }
}

void Gateway::flush(Connection& c) {
    refill(c);
    if (c.idle) {
        c.idle = false;
        c.progress_at = Clock::now();
    }
    while (c.unsent() > 0) {
        std::string error;
        const long n = write_some(c, error);
        if (n > 0) {
            ++writes_;
            c.sent(static_cast<std::size_t>(n));
            c.progress_at = Clock::now();
            if (c.unsent() < kPacedBytes) refill(c);
            continue;
        }
        if (n == 0) break;
        close(c.fd, error);
        return;
    }
    if (c.unsent() == 0) {
        // A queue that once grew large gives its buffer back rather than keeping it for the connection's life.
        if (c.out.capacity() > kKeptBufferBytes && !keeping_large_buffers()) std::string().swap(c.out);
        c.out.clear();
        c.out_offset = 0;
        c.traced = 0;
        c.idle = true;
        if (c.write_armed) {
            c.write_armed = false;
            update_events(c);
        }
        return;
    }
    if (c.out_offset > (1u << 20) && c.out_offset > c.out.size() / 2) {
        c.traced = c.traced > c.out_offset ? c.traced - c.out_offset : 0;
        c.drop_sent();
    }
    if (!c.write_armed) {
        c.write_armed = true;
        update_events(c);
    }
}

long Gateway::write_some(Connection& c, std::string& error) {
    const std::size_t left = c.out.size() - c.out_offset;
    if (!c.ssl) {
        for (;;) {
            const ssize_t n = c.splices.empty() ? ::send(c.fd, c.out.data() + c.out_offset, left, MSG_NOSIGNAL)
                                                : c.write_queued();
            if (n > 0) return static_cast<long>(n);
            if (n < 0 && errno == EINTR) continue;
            if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return 0;
            error = std::string("write failed: ") + std::strerror(n < 0 ? errno : EPIPE);
            return -1;
        }
    }
    // Partial writes are on and the buffer may move: a retry after WANT_WRITE passes the same bytes from
    // c.out_offset on, with more behind them perhaps, as OpenSSL requires.
    ERR_clear_error();
    errno = 0;
    const int n = SSL_write(c.ssl.get(), c.out.data() + c.out_offset, static_cast<int>(std::min<std::size_t>(left, INT_MAX)));
    if (n > 0) return n;
    switch (SSL_get_error(c.ssl.get(), n)) {
        case SSL_ERROR_WANT_WRITE: return 0;
        case SSL_ERROR_WANT_READ:  // not after the handshake (no renegotiation); EPOLLIN brings it back
            c.write_wants_read = true;
            update_events(c);
            return 0;
        case SSL_ERROR_SYSCALL:
            error = std::string("write failed: ") + std::strerror(errno ? errno : EPIPE);
            return -1;
        default:
            error = "TLS error while writing: " + tls::errors("protocol error");
            return -1;
    }
}

// Moves released frames from the backlog into the output buffer while it holds less than kPacedBytes,
// then what was written behind them.
void Gateway::move_backlog(Connection& c) {
    if (c.backlog.empty()) return;
    if (c.out_offset == c.out.size()) {
        c.drop_sent();
        c.traced = 0;
    }
    while (!c.backlog.empty() && c.unsent() < kPacedBytes) {
        c.out.append(c.backlog.front());
        c.backlog_bytes -= c.backlog.front().size();
        c.backlog.pop_front();
    }
    if (c.backlog.empty()) {
        c.out.append(c.tail);
        std::string().swap(c.tail);
    }
}

void Gateway::refill(Connection& c) {
    move_backlog(c);
    if (trace_ && c.federation && c.traced < c.out.size()) {
        trace_->sending(c.federation->federation.name(), c.federate,
                        std::string_view(c.out).substr(c.traced), MessageTrace::now_ns());
        c.traced = c.out.size();
    }
}

void Gateway::drop_stale_partials() {
    const auto now = Clock::now();
    const auto limit = std::chrono::duration<double>(options_.partial_frame_timeout_s);
    std::vector<std::pair<int, const char*>> stale;
    for (const auto& [fd, c] : connections_) {
        // A paused connection's unread frames wait for the gateway, not for the client.
        if (!c->paused && !c->in.empty() && now - c->partial_since > limit)
            stale.emplace_back(fd, "incomplete frame for too long");
        else if (!c->greeted && now - c->accepted_at > limit)  // connected, and silent since
            stale.emplace_back(fd, c->ssl && !SSL_is_init_finished(c->ssl.get())
                                       ? "no TLS handshake within the frame timeout"
                                       : "no handshake within the frame timeout");
    }
    for (const auto& [fd, why] : stale) close(fd, why);
}

void Gateway::close(int fd, const std::string& why) {
    auto it = connections_.find(fd);
    if (it == connections_.end()) return;
    std::unique_ptr<Connection> c = std::move(it->second);
    connections_.erase(it);
    if (c->datagram_token) datagram_tokens_.erase(c->datagram_token);
    loop_.remove(fd);
    ::close(fd);
    std::string who = c->peer;
    if (c->federation) {
        FederationEntry& entry = *c->federation;
        who += " (federate " + std::to_string(c->federate) + " of '" + entry.federation.name() + "')";
        entry.outbox.peers_.erase(c->federate);
        if (c->tap) recorder_->detach(*c->tap);
        if (recorder_) recorder_->dropped(entry.federation, c->federate, why);
        events_.add("dropped", entry.federation.name(), c->federate, entry.federation.federate_name(c->federate), why);
        try {
            // A federate that vanishes resigns with the default action: its objects go, the rest is released.
            entry.federation.resign(c->federate, wire::ResignAction::DeleteObjectsAndReleaseAttributes);
        } catch (const std::exception& e) {
            log("resigning " + who + " failed: " + e.what());
        }
    }
    const bool expected = why == "connection closed by peer" && !c->federation;
    const bool held_memory = c->federation || c->out.capacity() > kKeptBufferBytes || c->in.capacity() > kKeptBufferBytes;
    c.reset();
    if (!expected || options_.verbose) log("dropped " + who + ": " + why);
#if defined(__GLIBC__)
    // What a departed federate held (its queues, its messages queued in the federation) is freed by now, but
    // glibc keeps freed memory below the top of the heap; without this a burst of dying federates left rtig
    // tens of MiB larger for good (tests/transport/test_death.py measures it).
    if (held_memory) malloc_trim(0);
#else
    (void)held_memory;
#endif
}

void Gateway::log(const std::string& line) const {
    const std::string text = "rtig: " + line + "\n";
    std::fwrite(text.data(), 1, text.size(), stderr);
    std::fflush(stderr);
}

}  // namespace hlacore
