// The gateway's reactor: the epoll loop, listening and accepting, the turn of the loop, writing what is
// queued for each connection (flush) and closing connections.
#include "rti/server/gateway.hpp"
#include "rti/busy_poll.hpp"
#include "rti/net/listen.hpp"
#include "rti/server/gateway_internal.hpp"
#include "rti/unix_socket.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <openssl/ssl.h>

namespace hlacore {

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
    spill_budget_.directory = options_.spill_dir;
    spill_budget_.limit = options_.disk_budget;
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
        net::Listening listening = net::listen_tcp(options_.host, options_.port, SOCK_NONBLOCK | SOCK_CLOEXEC);
        listen_fd_ = listening.fd;
        port_ = listening.port;
        const sockaddr_storage& bound = listening.bound;
        const socklen_t len = listening.length;

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
            // While senders wait, soon again: their consumer may have stopped reading, and spill (flow_control.cpp).
            loop_.wait(!paused_.empty() ? 20
                       : partial_pending || writes_pending || recording_pending || large_buffers_kept_ ? 250
                       : memory_freed_ ? 1000 : -1,
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
        if (!spill_failed_.empty()) drop_failed_spills();
        if (!paused_.empty()) service_paused();
        if (partial_pending) drop_stale_partials();
        if (writes_pending) drop_stalled_readers();
        if (large_buffers_kept_ && !keeping_large_buffers()) release_large_buffers();
        if (memory_freed_) give_memory_back();
        if (trace_) trace_->flush();
        if (recorder_) {
            recorder_->tick();
            recorder_failed();
        }
    }
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
            // A federate that does not read may be paused (spill.hpp) or gone: keepalive tells them apart while
            // the connection is idle, its host answering for a stopped process and not for a vanished one.
            net::serve_connection(fd);
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

// Moves released frames from the backlog into the output buffer while it holds less than kPacedBytes,
// then what was written behind them.
void Gateway::move_backlog(Connection& c) {
    if (c.backlog.empty() && !c.spill) return;
    if (c.out_offset == c.out.size()) {
        c.drop_sent();
        c.traced = 0;
    }
    while (!c.backlog.empty() && c.unsent() < kPacedBytes) {
        c.out.append(c.backlog.front());
        c.backlog_bytes -= c.backlog.front().size();
        c.backlog.pop_front();
    }
    if (!c.backlog.empty()) return;
    if (c.spill) {  // then what was spilled, read back as the client takes what is in memory
        if (!c.spill_failed.empty()) return;
        try {
            if (c.unsent() < spill_keep()) c.spill->read(c.out, spill_keep() - c.unsent());
        } catch (const SpillError& e) {
            spill_failed(c, e.what());
            return;
        }
        if (c.spill->size() > 0) return;
        c.spill.reset();
    }
    c.out.append(c.tail);
    std::string().swap(c.tail);
}

void Gateway::refill(Connection& c) {
    move_backlog(c);
    if (trace_ && c.federation && c.traced < c.out.size()) {
        c.traced += trace_->sending(c.federation->federation.name(), c.federate,
                                    std::string_view(c.out).substr(c.traced), MessageTrace::now_ns());
    }
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
