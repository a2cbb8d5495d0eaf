#include "rti/client/client.hpp"

#include "rti/auth.hpp"
#include "rti/busy_poll.hpp"
#include "rti/client/waiting.hpp"
#include "rti/unix_socket.hpp"
#include "rti/wire/splices.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>

#include <openssl/err.h>
#include <openssl/x509_vfy.h>

#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

namespace hlacore {

namespace {

std::string seconds(std::chrono::steady_clock::duration d) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", std::chrono::duration<double>(d).count());
    return text;
}

// Whether the first bytes from a gateway are a TLS record (a handshake or an alert): what a gateway with TLS
// answers a client without it. No hlacore frame starts so before the Welcome.
bool looks_like_tls(std::string_view bytes) {
    return bytes.size() >= 2 && (bytes[0] == 0x16 || bytes[0] == 0x15) && bytes[1] == 0x03;
}

// The request id an answer of the gateway echoes (HLACORE_ANSWERS); null for any other message.
const std::uint32_t* answered_request(const wire::Message& m) {
#define HLACORE_X(name) \
    if (const auto* answer = std::get_if<wire::name>(&m)) return &answer->request;
    HLACORE_ANSWERS(HLACORE_X)
#undef HLACORE_X
    return nullptr;
}

}  // namespace

Client::Client(const std::string& host, std::uint16_t port, ClientOptions options)
    : address_(unix_socket::is_unix(host) ? host : host + ":" + std::to_string(port)),
      options_(options),
      timeout_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.timeout_s))) {
    if (!(options.timeout_s > 0) || options.timeout_s > 1e6)
        raise(ErrorCode::RTIinternalError, "the client's timeout must be between 0 and 1e6 seconds, not " +
                                               std::to_string(options.timeout_s));
    if (const std::string error = busy_poll_error(options.busy_poll_us); !error.empty())
        raise(ErrorCode::RTIinternalError, error);
    const bool local = unix_socket::is_unix(host);
    if (local && options_.tls)
        raise(ErrorCode::RTIinternalError, "TLS is for TCP: a Unix socket (" + host + ") does not leave this host");
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_NUMERICSERV;
    addrinfo* found = nullptr;
    const std::string service = std::to_string(port);
    if (int rc = local ? 0 : getaddrinfo(host.c_str(), service.c_str(), &hints, &found); rc != 0)
        raise(ErrorCode::RTIinternalError, "cannot resolve rtig host '" + host + "': " + gai_strerror(rc));
    std::unique_ptr<addrinfo, decltype(&freeaddrinfo)> guard(found, freeaddrinfo);
    tls::Context tls_context;  // before connecting: a CA file that cannot be used fails without the network
    if (options_.tls) {
        try {
            tls_context = tls::client_context(options_.tls_ca);
        } catch (const std::exception& e) {
            raise(ErrorCode::AuthenticationFailed, e.what());
        }
    }
    const auto deadline = Clock::now() + timeout_;
    std::string error = "no address";
    ErrorCode code = ErrorCode::RTIinternalError;
    try {
        if (local) connect_local(unix_socket::path_of(host));
        for (addrinfo* a = found; a && fd_ < 0; a = a->ai_next) {
            fd_ = ::socket(a->ai_family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
            if (fd_ < 0) continue;
            int rc = ::connect(fd_, a->ai_addr, a->ai_addrlen);
            // A gateway host that drops packets leaves the connect pending: bounded by the timeout.
            if (rc < 0 && (errno == EINPROGRESS || errno == EINTR)) {
                if (poll_until(options_.wait_host, fd_, POLLOUT, deadline) == 0) {
                    errno = ETIMEDOUT;
                    code = ErrorCode::GatewayNotResponding;
                } else {
                    int so_error = 0;
                    socklen_t len = sizeof so_error;
                    getsockopt(fd_, SOL_SOCKET, SO_ERROR, &so_error, &len);
                    errno = so_error;
                    rc = so_error == 0 ? 0 : -1;
                }
            }
            if (rc == 0) break;
            error = std::strerror(errno);
            ::close(fd_);
            fd_ = -1;
        }
        if (fd_ < 0) raise(code, "cannot connect to rtig at " + address_ + ": " + error);
        if (!local) {
            int one = 1;
            setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
        }
        if (tls_context) start_tls(tls_context.get(), host, deadline);
        last_heard_ = Clock::now();
        send(wire::Hello{});
        await_answer(deadline, [this] { return welcomed_; }, "no hlacore handshake");
        if (!challenge_.empty()) authenticate(deadline);
        if (datagram_token_) {
            if (options_.datagrams) open_datagram_path(deadline);
            else datagram_reason_ = "datagrams turned off on this side";
        } else if (local) {
            datagram_reason_ = "no datagrams over a Unix socket: best-effort messages go over it as a stream";
        } else {
            datagram_reason_ = ssl_ ? "the gateway offers no datagrams under TLS: best-effort messages go over the "
                                      "encrypted TCP stream"
                                    : "the gateway offers no datagrams";
        }
    } catch (...) {
        ssl_.reset();
        if (fd_ >= 0) ::close(fd_);
        if (datagram_fd_ >= 0) ::close(datagram_fd_);
        fd_ = datagram_fd_ = -1;
        throw;
    }
}

// fd_ connected to the gateway's Unix socket at `path`, or RTIinternalError saying why not. A connect to
// a Unix socket does not wait: it succeeds or fails at once (EAGAIN: the gateway's backlog is full).
void Client::connect_local(const std::string& path) {
    sockaddr_un a{};
    try {
        a = unix_socket::address_of(path);
    } catch (const std::invalid_argument& e) {
        raise(ErrorCode::RTIinternalError, e.what());
    }
    fd_ = ::socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (fd_ < 0 || ::connect(fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) < 0) {
        const int error = errno;
        raise(error == EAGAIN ? ErrorCode::GatewayNotResponding : ErrorCode::RTIinternalError,
              "cannot connect to rtig at " + address_ + ": " +
                  (error == EAGAIN ? std::string("it takes no more connections now") : std::strerror(error)));
    }
    unix_socket::size_send_buffer(fd_);
}

void Client::start_tls(SSL_CTX* context, const std::string& host, Clock::time_point deadline) {
    try {
        ssl_ = tls::session(context, fd_);  // the session holds its own reference to the context
    } catch (const std::exception& e) {
        raise(ErrorCode::AuthenticationFailed, e.what());
    }
    tls::expect_host(ssl_.get(), host);
    SSL_set_connect_state(ssl_.get());
    const std::string trusted = options_.tls_ca.empty() ? "the system's CA store" : "the CA file '" + options_.tls_ca + "'";
    for (;;) {
        ERR_clear_error();
        errno = 0;
        const int rc = SSL_do_handshake(ssl_.get());
        if (rc == 1) return;
        const int error = SSL_get_error(ssl_.get(), rc);
        const short events = error == SSL_ERROR_WANT_READ ? POLLIN : error == SSL_ERROR_WANT_WRITE ? POLLOUT : 0;
        if (!events) {
            const int saved_errno = errno;
            const long verify = SSL_get_verify_result(ssl_.get());
            const unsigned long first = ERR_peek_error();
            const std::string errors = tls::errors();
            if (verify == X509_V_ERR_HOSTNAME_MISMATCH || verify == X509_V_ERR_IP_ADDRESS_MISMATCH)
                raise(ErrorCode::AuthenticationFailed,
                      "the gateway's certificate at " + address_ + " is not for '" + host + "' (" +
                          X509_verify_cert_error_string(verify) + "): connect by a name or address it names "
                          "(docs/networking.md)");
            if (verify != X509_V_OK)
                raise(ErrorCode::AuthenticationFailed, "the gateway's certificate is not trusted: " +
                                                           std::string(X509_verify_cert_error_string(verify)) + " (" +
                                                           address_ + ", checked against " + trusted + ")");
            const int reason = ERR_GET_REASON(first);
            if ((error == SSL_ERROR_SYSCALL || error == SSL_ERROR_ZERO_RETURN) && errors.empty())
                raise(ErrorCode::AuthenticationFailed,
                      "the gateway at " + address_ + " does not speak TLS: it closed the connection during the TLS "
                      "handshake (" + (saved_errno ? std::strerror(saved_errno) : "end of stream") +
                          "; an rtig without --tls-cert does so)");
            if (reason == SSL_R_WRONG_VERSION_NUMBER || reason == SSL_R_PACKET_LENGTH_TOO_LONG ||
                reason == SSL_R_RECORD_LENGTH_MISMATCH || reason == SSL_R_UNEXPECTED_EOF_WHILE_READING)
                raise(ErrorCode::AuthenticationFailed,
                      "the gateway at " + address_ + " does not speak TLS: " + errors);
            raise(ErrorCode::AuthenticationFailed, "the TLS handshake with the gateway at " + address_ +
                                                       " failed: " + (errors.empty() ? std::strerror(saved_errno) : errors));
        }
        if (poll_until(options_.wait_host, fd_, events, deadline) == 0)
            raise(ErrorCode::GatewayNotResponding, "no TLS handshake from " + address_ + " within " + seconds(timeout_) +
                                                       ": the gateway is not responding (or does not speak TLS)");
    }
}

namespace {

// One SSL_read or SSL_write (`io`) under the session's lock: bytes moved, 0 when the socket would block,
// -1 with `error`.
template <class Io>
long tls_io(std::mutex& mu, SSL* ssl, Io io, std::string& error) {
    std::lock_guard<std::mutex> lock(mu);
    ERR_clear_error();
    errno = 0;
    const int n = io(ssl);
    if (n > 0) return n;
    switch (SSL_get_error(ssl, n)) {
        case SSL_ERROR_WANT_READ:
        case SSL_ERROR_WANT_WRITE: return 0;  // not after the handshake: no renegotiation
        case SSL_ERROR_ZERO_RETURN: error = "the gateway closed the connection"; return -1;
        case SSL_ERROR_SYSCALL: error = errno ? std::strerror(errno) : "the gateway closed the connection"; return -1;
        default: error = "TLS error: " + tls::errors("protocol error"); return -1;
    }
}

int clamped(std::size_t length) { return static_cast<int>(std::min<std::size_t>(length, INT_MAX)); }

}  // namespace

long Client::tls_write(const char* data, std::size_t length, std::string& error) {
    return tls_io(ssl_mu_, ssl_.get(), [&](SSL* ssl) { return SSL_write(ssl, data, clamped(length)); }, error);
}

long Client::tls_read(char* data, std::size_t length, std::string& error) {
    return tls_io(ssl_mu_, ssl_.get(), [&](SSL* ssl) { return SSL_read(ssl, data, clamped(length)); }, error);
}

bool Client::tls_pending() {
    std::lock_guard<std::mutex> lock(ssl_mu_);
    return SSL_has_pending(ssl_.get()) != 0;
}

bool Client::tls_readable() {
    std::lock_guard<std::mutex> lock(ssl_mu_);
    return SSL_pending(ssl_.get()) > 0;
}

template <class Pred>
void Client::await_answer(Clock::time_point deadline, Pred done, const char* what) {
    for (;;) {
        const auto status = pump(deadline, done);
        std::unique_lock<std::mutex> lock(mu_);
        if (done()) return;
        if (closed_) raise(closed_code_, std::string(what) + " from " + address_ + ": " + closed_reason_);
        lock.unlock();
        if (status == WaitStatus::Interrupted) {
            if (options_.wait_host) options_.wait_host->interrupted();
            continue;
        }
        if (status == WaitStatus::Timeout)
            raise(ErrorCode::GatewayNotResponding, std::string(what) + " from " + address_ + " within " +
                                                       seconds(timeout_) + ": the gateway is not responding");
    }
}

void Client::authenticate(Clock::time_point deadline) {
    if (options_.secret.empty())
        raise(ErrorCode::AuthenticationFailed,
              "the gateway at " + address_ + " asks for a secret and none was given (RTIAmbassador(secret_file=...), "
              "$HLACORE_SECRET_FILE; docs/networking.md)");
    send(wire::Authenticate{auth::proof(options_.secret, challenge_)});
    try {
        await_answer(deadline, [this] { return authenticated_.has_value(); }, "no answer to the authentication");
    } catch (const RtiError& e) {
        if (e.code() == ErrorCode::GatewayNotResponding) throw;
        raise(ErrorCode::AuthenticationFailed, std::string("authentication with ") + address_ + " failed: " + e.what());
    }
    if (!authenticated_->accepted)
        raise(ErrorCode::AuthenticationFailed, "the gateway at " + address_ + " refused this client: " +
                                                   authenticated_->reason + " (docs/networking.md)");
}

namespace {
std::uint64_t steady_ns(Client::Clock::time_point t) {
    return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count());
}
}  // namespace

// Sequential probes; the one with the shortest round trip bounds the offset best.
ClockEstimate Client::measure_clock(int probes) {
    ClockEstimate best;
    double best_rtt = -1;
    for (int i = 0; i < probes; ++i) {
        const std::uint32_t sequence = ++clock_probes_;
        const auto sent = Clock::now();
        send(wire::ClockProbe{sequence, steady_ns(sent)});
        await_answer(sent + timeout_, [&] { return clock_echo_ && clock_echo_->sequence == sequence; },
                        "no answer to a clock probe");
        const auto back = Clock::now();
        std::uint64_t gateway_ns;
        {
            std::lock_guard<std::mutex> lock(mu_);
            gateway_ns = clock_echo_->gateway_ns;
        }
        const double rtt = std::chrono::duration<double>(back - sent).count();
        if (best_rtt < 0 || rtt < best_rtt) {
            best_rtt = rtt;
            const double midpoint_ns = (static_cast<double>(steady_ns(sent)) + static_cast<double>(steady_ns(back))) / 2;
            best = ClockEstimate{(static_cast<double>(gateway_ns) - midpoint_ns) * 1e-9, rtt / 2, back};
        }
    }
    return best;
}

ClockEstimate Client::clock_offset(double max_age_s) {
    std::lock_guard<std::mutex> lock(clock_mu_);
    // Measured on first use rather than at connect: most connections (status queries, most federates) never ask.
    if (!clock_measured_ || std::chrono::duration<double>(Clock::now() - clock_.measured_at).count() > max_age_s) {
        clock_ = measure_clock(4);
        clock_measured_ = true;
    }
    return clock_;
}

Client::~Client() {
    if (writer_.joinable()) {  // it writes what is pending first (bounded by the timeout)
        {
            std::lock_guard<std::mutex> lock(send_mu_);
            writer_stop_ = true;
        }
        writer_work_.notify_all();
        writer_.join();
    }
    if (ssl_) {  // close_notify, if the socket takes it: the gateway sees a clean end
        std::lock_guard<std::mutex> lock(ssl_mu_);
        SSL_shutdown(ssl_.get());
        ERR_clear_error();
        ssl_.reset();
    }
    if (fd_ >= 0) ::close(fd_);
    if (datagram_fd_ >= 0) ::close(datagram_fd_);
}

// ---- plumbing ----

namespace {
// The messages the gateway serves only for a joined federate: from a connection that is not (one that has
// sent its resign) they are a protocol error that drops it. By type code, so that the view types
// (UpdateAttributesView, SendInteractionView) count as the messages they encode.
constexpr bool federation_service(wire::MessageType type) {
    switch (type) {
#define HLACORE_X(name) case wire::MessageType::name:
        HLACORE_FEDERATION_SERVICES(HLACORE_X)
#undef HLACORE_X
        return true;
        default: return false;
    }
}
}  // namespace

std::unique_lock<std::mutex> Client::lock_send() {
    // Another thread's send may be blocked: wait for it without holding the host's lock (the GIL).
    std::unique_lock<std::mutex> lock(send_mu_, std::try_to_lock);
    if (!lock) {
        Waiting waiting(options_.wait_host);
        lock.lock();
    }
    return lock;
}

template <class M>
void Client::send(const M& message) {
    auto lock = lock_send();
    if constexpr (federation_service(M::kType)) require_member(M::kType);
    if constexpr (std::is_same_v<M, wire::UpdateAttributesView> || std::is_same_v<M, wire::SendInteractionView>) {
        if (!ssl_ && !writer_busy_ && pending_.empty() && holds_ == 0 && wire::has_spliced_value(message.values))
            return send_spliced(message);
    }
    send_buffer_.clear();
    wire::encode(send_buffer_, message);
    check_frame_length(M::kType, send_buffer_.size() - 4);
    if (holds_ > 0) return hold_encoded(lock);
    send_encoded(lock);
}

void Client::hold_sends() {
    auto lock = lock_send();
    ++holds_;
}

void Client::release_sends() {
    auto lock = lock_send();
    if (holds_ > 0 && --holds_ == 0) write_held(lock);
}

void Client::hold_encoded(std::unique_lock<std::mutex>& lock) {
    held_ += send_buffer_;
    ++held_messages_;
    has_held_.store(true, std::memory_order_relaxed);
    if (held_.size() >= kMaxHeldBytes) write_held(lock);
}

// What is held, as one message of send_encoded's (written now, or queued behind the writer thread's).
void Client::write_held(std::unique_lock<std::mutex>& lock) {
    if (held_.empty()) return;
    send_buffer_.swap(held_);
    held_.clear();
    messages_sent_ += held_messages_ - 1;  // send_encoded counts one
    held_messages_ = 0;
    has_held_.store(false, std::memory_order_relaxed);
    send_encoded(lock);
}

void Client::check_frame_length(wire::MessageType type, std::size_t length) {
    if (length <= max_frame_bytes_) return;
    send_buffer_.clear();  // a name, tag or FED beyond reason: refused, not sent
    raise(ErrorCode::ValueLengthExceeded, std::string(wire::message_name(type)) + " of " + std::to_string(length) +
                                              " bytes is over the gateway's frame limit of " +
                                              std::to_string(max_frame_bytes_) + " bytes");
}

template <class M>
void Client::send_spliced(const M& message) {
    check_frame_length(M::kType, wire::frame_length(message));
    send_buffer_.clear();
    std::vector<wire::Splice> splices;
    wire::SplicingOutput out{send_buffer_, [&splices](std::size_t at, std::string_view bytes) {
                                 splices.push_back({at, bytes});
                                 return true;
                             }};
    wire::encode_to(out, message);
    std::vector<iovec> pieces(2 * splices.size() + 1);
    const std::size_t count = wire::gather(send_buffer_, 0, splices, pieces.data(), pieces.size());
    ++messages_sent_;
    write_pieces(pieces.data(), count, options_.wait_host);
}

// Writes the pieces in order (without TLS), waiting for the socket with the host released.
void Client::write_pieces(iovec* pieces, std::size_t count, WaitHost* host) {
    std::size_t first = 0, done = 0;
    for (;;) {
        while (first < count && pieces[first].iov_len == 0) ++first;
        if (first == count) return;
        msghdr m{};
        m.msg_iov = pieces + first;
        m.msg_iovlen = std::min<std::size_t>(count - first, IOV_MAX);
        constexpr int kFlags = MSG_NOSIGNAL | MSG_DONTWAIT;
        const ssize_t n = m.msg_iovlen == 1 ? ::send(fd_, m.msg_iov->iov_base, m.msg_iov->iov_len, kFlags)
                                            : ::sendmsg(fd_, &m, kFlags);
        if (n > 0) {
            ++write_calls_;
            done += static_cast<std::size_t>(n);
            for (std::size_t left = static_cast<std::size_t>(n); left > 0;) {
                iovec& piece = pieces[first];
                const std::size_t k = std::min(left, piece.iov_len);
                piece.iov_base = static_cast<char*>(piece.iov_base) + k;
                piece.iov_len -= k;
                left -= k;
                if (piece.iov_len == 0) ++first;
            }
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            wait_writable(done, host);
        } else {
            close_connection(ErrorCode::RTIinternalError, std::strerror(errno));  // keeps an earlier reason
            connection_lost();
        }
    }
}
#define HLACORE_X(name) template void Client::send(const wire::name&);
HLACORE_MESSAGES(HLACORE_X)
#undef HLACORE_X
template void Client::send(const wire::UpdateAttributesView&);
template void Client::send(const wire::SendInteractionView&);

void Client::require_member(wire::MessageType type) const {
    // Checked when sending, in the order of the socket: another thread's resign may have gone out just before.
    if (!member_)
        raise(ErrorCode::FederateNotExecutionMember,
              std::string(wire::message_name(type)) + ": the federate is not joined (it has resigned)");
}

// The one message in send_buffer_: written now by the caller, or queued behind what the writer thread has
// (the stream's order) or as part of a long run of sends.
void Client::send_encoded(std::unique_lock<std::mutex>& lock) {
    ++messages_sent_;
    if (writer_busy_ || !pending_.empty() || ++sends_since_wait_ > kDirectSends) {
        queue_send(lock);
        return;
    }
    write_send_buffer();
}

void Client::write_send_buffer() { write_bytes(send_buffer_.data(), send_buffer_.size(), options_.wait_host); }

void Client::write_bytes(const char* data, std::size_t size, WaitHost* host) {
    if (!ssl_) {
        iovec piece{const_cast<char*>(data), size};
        return write_pieces(&piece, 1, host);
    }
    std::size_t done = 0;
    while (done < size) {
        std::string error;
        const long n = tls_write(data + done, size - done, error);
        if (n > 0) {
            ++write_calls_;
            done += static_cast<std::size_t>(n);
        } else if (n == 0) {
            // The session may hold part of the message in a record it could not finish: the message is
            // owed from the first WANT_WRITE on (an abandoned wait closes the connection).
            wait_writable(std::max<std::size_t>(done, 1), host);
        } else {
            close_connection(ErrorCode::RTIinternalError, error);
            connection_lost();
        }
    }
}

// A message of a longer run of sends: to the writer thread (started on the first), behind what it has. The
// caller waits while kMaxPending bytes are pending, as a blocked send waits (the writer declares the gateway
// not responding after the timeout); a signal meanwhile goes to the host (Ctrl-C), the message staying queued.
void Client::queue_send(std::unique_lock<std::mutex>& lock) {
    if (closed_) {
        std::lock_guard<std::mutex> state(mu_);
        connection_lost();
    }
    if (!writer_.joinable()) writer_ = std::thread([this] { writer_loop(); });
    if (pending_.empty())
        pending_.swap(send_buffer_);  // not copied: a large update would cost a copy of its values
    else
        pending_ += send_buffer_;
    queued_.fetch_add(1, std::memory_order_release);
    if (writer_asleep_) writer_work_.notify_one();
    while (pending_.size() > kMaxPending) {
        {
            Waiting waiting(options_.wait_host);
            writer_room_.wait_for(lock, std::chrono::milliseconds(50));
        }
        {
            std::lock_guard<std::mutex> state(mu_);
            if (closed_) connection_lost();
        }
        if (options_.wait_host) {
            lock.unlock();
            options_.wait_host->interrupted();  // a pending Ctrl-C is raised here
            lock.lock();
        }
    }
}

// The writer thread: takes all that is pending and writes it in one go, again while more came meanwhile.
// Signals go to the other threads. A failed write closes the connection (the callers' next send raises).
void Client::writer_loop() {
    sigset_t all;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, nullptr);
    std::string writing;
    std::size_t written = 0;  // by the last write
    std::unique_lock<std::mutex> lock(send_mu_);
    for (;;) {
        // Linger after a batch of small messages: more may come before a sleep would be over. (A large
        // message takes longer to make than a wake-up costs.)
        if (pending_.empty() && !writer_stop_ && written > 0 && written < kWriterLingerBelow) {
            const std::uint64_t seen = queued_.load(std::memory_order_acquire);
            lock.unlock();
            busy_poll(kWriterLinger, [&] { return queued_.load(std::memory_order_acquire) != seen ? 1 : 0; });
            lock.lock();
        }
        writer_asleep_ = true;
        writer_work_.wait(lock, [this] { return writer_stop_ || !pending_.empty(); });
        writer_asleep_ = false;
        if (pending_.empty()) return;  // stopped, and everything written
        writing.swap(pending_);
        pending_.clear();
        writer_busy_ = true;
        lock.unlock();
        try {
            write_bytes(writing.data(), writing.size(), nullptr);
        } catch (const RtiError&) {  // the connection is closed, saying why
        } catch (const std::exception& e) {
            close_connection(ErrorCode::RTIinternalError, std::string("writing to the gateway: ") + e.what());
        }
        lock.lock();
        writer_busy_ = false;
        written = writing.size();
        writing.clear();
        writer_room_.notify_all();
        {
            std::lock_guard<std::mutex> state(mu_);
            if (closed_) pending_.clear();  // nobody will read it
        }
    }
}

// The socket's buffer is full: the gateway is behind, holding this federate back (flow control) or gone.
// Waits with the GIL released (WaitHost), reading what the gateway sends meanwhile (it may be waiting for
// this federate to take its own messages, and sends a Pong now and then while it holds it back): it is
// declared not responding after the timeout without a byte either way.
void Client::wait_writable(std::size_t sent, WaitHost* host) {
    auto deadline = Clock::now() + timeout_;
    std::uint64_t heard = heard_bytes_;
    for (;;) {
        pollfd p{fd_, POLLOUT | POLLIN, 0};
        int n;
        {
            Waiting waiting(host);
            n = ::poll(&p, 1, ms_until(deadline));
            if (n > 0 && !(p.revents & POLLOUT)) read_beside_send();
        }
        if (n > 0 && (p.revents & POLLOUT)) return;
        if (n < 0 && errno == EINTR) {
            if (host) on_interrupt(sent > 0 ? "the rest of a message already partly sent" : nullptr);
            continue;
        }
        {
            std::lock_guard<std::mutex> lock(mu_);
            if (closed_) connection_lost();
        }
        if (heard_bytes_ != heard) {
            heard = heard_bytes_;
            deadline = Clock::now() + timeout_;
            continue;
        }
        if (n > 0) continue;
        close_connection(ErrorCode::GatewayNotResponding,
                         "the gateway has read nothing from this federate for " + seconds(timeout_) +
                             ": it is not responding");
        connection_lost();
    }
}

// Takes what arrived while a send waits, unless another thread is reading it (then waits a little for it).
void Client::read_beside_send() {
    std::unique_lock<std::mutex> lock(mu_);
    if (reading_) {
        cv_.wait_for(lock, std::chrono::milliseconds(50));
        return;
    }
    reading_ = true;
    lock.unlock();
    read_socket(Clock::now(), arrivals_);
    lock.lock();
    reading_ = false;
    file(arrivals_);
    cv_.notify_all();
}

void Client::on_interrupt(const char* owed) {
    if (!options_.wait_host) return;
    try {
        options_.wait_host->interrupted();
    } catch (...) {
        if (owed) close_connection(ErrorCode::RTIinternalError, std::string("a call was interrupted while waiting for ") + owed);
        throw;
    }
}

void Client::close_connection(ErrorCode code, const std::string& reason) {
    std::lock_guard<std::mutex> lock(mu_);
    if (closed_) return;
    closed_ = true;
    closed_code_ = code;
    closed_reason_ = reason;
    ::shutdown(fd_, SHUT_RDWR);  // the gateway sees the end at once and resigns the federate
    cv_.notify_all();
}

std::uint32_t Client::next_request() {
    std::lock_guard<std::mutex> lock(mu_);
    return ++last_request_;
}

template <class Result>
Result Client::call(wire::Message request, std::uint32_t id) {
    std::visit(
        [this](const auto& m) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(m)>, std::monostate>) send(m);
        },
        request);
    return await_reply<Result>(id);
}
#define HLACORE_X(name) template wire::name Client::call(wire::Message, std::uint32_t);
HLACORE_ANSWERS(HLACORE_X)
#undef HLACORE_X

template <class Result>
Result Client::await_reply(std::uint32_t id) {
    wire::Message answer = take_answer(id);
    if (auto* result = std::get_if<Result>(&answer)) return std::move(*result);
    const auto got = static_cast<wire::MessageType>(answer.index());  // the variant's index is the wire code
    close_connection(ErrorCode::RTIinternalError, std::string("protocol error from the gateway: ") +
                                                      wire::message_name(got) + " answered request " +
                                                      std::to_string(id) + " (" + wire::message_name(Result::kType) +
                                                      " expected)");
    connection_lost();
}

wire::Message Client::take_answer(std::uint32_t id) {
    for (;;) {
        auto status = pump(Clock::time_point::max(), [&] { return replies_.count(id) > 0; });
        if (status == WaitStatus::Interrupted) on_interrupt("the gateway's reply");
        std::unique_lock<std::mutex> lock(mu_);
        auto it = replies_.find(id);
        if (it != replies_.end()) {
            wire::Message answer = std::move(it->second);
            replies_.erase(it);
            lock.unlock();
            const auto* refusal = std::get_if<wire::Reply>(&answer);
            if (refusal && refusal->error != 0) {
                const auto code = refusal->error < static_cast<std::uint16_t>(ErrorCode::Count)
                                      ? static_cast<ErrorCode>(refusal->error)
                                      : ErrorCode::RTIinternalError;
                throw RtiError(code, refusal->message);
            }
            return answer;
        }
        if (closed_) connection_lost();
    }
}

template <class Pred>
Client::WaitStatus Client::pump(Clock::time_point deadline, Pred pred) {
    if (has_held_.load(std::memory_order_relaxed)) {  // a wait inside a batch: what it holds goes first
        auto sending = lock_send();
        write_held(sending);
    }
    sends_since_wait_.store(0, std::memory_order_relaxed);  // the next message is a lone one: written at once
    std::unique_lock<std::mutex> lock(mu_);
    bool read_once = false;  // even with a deadline already past, look at the socket once (poll_now)
    for (;;) {
        if (pred()) return WaitStatus::Ready;
        if (closed_) return WaitStatus::Ready;
        if ((read_once || reading_) && Clock::now() >= deadline) return WaitStatus::Timeout;
        if (reading_) {
            if (deadline == Clock::time_point::max()) {
                cv_.wait(lock);
            } else {
                cv_.wait_until(lock, deadline);
            }
            continue;
        }
        reading_ = true;
        read_once = true;
        lock.unlock();
        WaitStatus status = WaitStatus::Ready;
        try {
            status = read_socket(std::min(deadline, liveness_deadline()), arrivals_);
            check_liveness();
        } catch (...) {
            lock.lock();
            reading_ = false;
            arrivals_.clear();
            cv_.notify_all();
            throw;
        }
        lock.lock();
        reading_ = false;
        file(arrivals_);
        cv_.notify_all();
        if (status == WaitStatus::Interrupted) return status;
    }
}

// ppoll() on the connection's sockets; when busy polling (ClientOptions::busy_poll_us) and the wait may sleep,
// a spin first. With `spin_read`, the spin's turns after the first poll the stream by reading it (recv without
// waiting, into the room made then), so that the call that finds a message also reads it: one system call
// fewer per message waited for. Those turns look at the datagram socket every kDatagramTurns; the first looks
// at both, so a busy stream does not keep datagrams waiting. A signal that comes while spinning is handled
// without interrupting a poll, so with a wait host the sleep after a spin is cut to a slice that ends as if
// interrupted (`sliced`), for the host to look for one. A spin and a sleep that found nothing make an idle
// connection, which sleeps at once until something arrives.
int Client::wait_readable(pollfd* p, nfds_t count, const timespec* timeout, bool& sliced, SpinRead* spin_read) {
    static constexpr timespec kNow{}, kSlice{0, 100'000'000};
    static constexpr unsigned kDatagramTurns = 8;
    const bool may_sleep = !timeout || timeout->tv_sec || timeout->tv_nsec;
    if (!options_.busy_poll_us || !may_sleep || idle_after_spin_) {
        const int n = ::ppoll(p, count, timeout, nullptr);
        if (n > 0) idle_after_spin_ = false;
        return n;
    }
    const std::uint64_t writes = write_calls_.load(std::memory_order_relaxed);
    const bool wrote = writes != writes_before_spin_;  // a request just went out: its answer cannot be here yet
    writes_before_spin_ = writes;
    unsigned turn = 0;
    int n = busy_poll(std::chrono::microseconds(options_.busy_poll_us), [&] {
        if (!spin_read || turn++ == 0) return ::ppoll(p, count, &kNow, nullptr);
        if (turn == 2) {
            spin_read->want = in_.wanted(max_frame_bytes_);
            spin_read->into = in_.room(spin_read->want);
        }
        const ssize_t r = ::recv(fd_, spin_read->into, spin_read->want, MSG_DONTWAIT);
        if (r >= 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
            spin_read->done = true;
            spin_read->result = r;
            spin_read->error = r < 0 ? errno : 0;
            p[0].revents = POLLIN;
            if (count > 1) p[1].revents = 0;
            return 1;
        }
        if (count < 2 || turn % kDatagramTurns != 0) return 0;
        p[0].revents = 0;
        return ::ppoll(p + 1, 1, &kNow, nullptr);
    }, wrote);
    if (n != 0) return n;
    sliced = options_.wait_host && (!timeout || timeout->tv_sec || timeout->tv_nsec > kSlice.tv_nsec);
    n = ::ppoll(p, count, sliced ? &kSlice : timeout, nullptr);
    idle_after_spin_ = n == 0;
    return n;
}

// Waits for readable data (up to the deadline), then reads everything available and decodes whole frames.
Client::WaitStatus Client::read_socket(Clock::time_point deadline, Arrivals& got) {
    pollfd p[2] = {{fd_, POLLIN, 0}, {datagram_fd_, POLLIN, 0}};
    timespec ts{};
    const timespec* timeout = nullptr;
    if (deadline != Clock::time_point::max()) {
        auto left = std::chrono::duration_cast<std::chrono::nanoseconds>(deadline - Clock::now()).count();
        if (left < 0) left = 0;
        ts.tv_sec = static_cast<time_t>(left / 1000000000);
        ts.tv_nsec = static_cast<long>(left % 1000000000);
        timeout = &ts;
    }
    // Decrypted bytes already in the TLS session: the socket may have nothing more to say. (The reads below
    // leave none, nor a whole record; this is the belt to their braces.)
    const bool buffered = ssl_ && tls_readable();
    const timespec now{};
    if (buffered) timeout = &now;
    bool sliced = false;
    SpinRead spin_read;
    const bool read_in_spin = options_.busy_poll_us && !ssl_ && !in_.holds_large_frame();
    int n = wait_readable(p, datagram_path_ ? 2 : 1, timeout, sliced, read_in_spin ? &spin_read : nullptr);
    if (n == 0 && sliced) return WaitStatus::Interrupted;
    if (buffered && n >= 0) {
        p[0].revents |= POLLIN;
        n = std::max(n, 1);
    }
    if (n < 0) return errno == EINTR ? WaitStatus::Interrupted : WaitStatus::Ready;
    if (n == 0) return WaitStatus::Timeout;
    if (datagram_path_ && p[1].revents) read_datagrams(got.datagrams);
    if (!p[0].revents) return WaitStatus::Ready;
    std::string reason;
    ErrorCode code = ErrorCode::RTIinternalError;
    const bool first_bytes = heard_bytes_ == 0;
    std::size_t read_now = 0;
    got.more_in_socket = false;
    for (;;) {
        if (ssl_) {
            // SSL_read while the session holds bytes (SSL_has_pending), until it wants more from the socket:
            // what it may keep then is the start of a record whose rest is still to come, which poll() (and
            // hlacore.aio's add_reader on fileno()) will see.
            const std::size_t want = in_.wanted(max_frame_bytes_);
            const long r = tls_read(in_.room(want), want, reason);
            if (r <= 0) break;
            last_heard_ = Clock::now();
            heard_bytes_ += static_cast<std::uint64_t>(r);
            in_.commit(static_cast<std::size_t>(r));
            if (static_cast<std::size_t>(r) < want && !tls_pending()) break;
            continue;
        }
        if (in_.holds_large_frame()) break;
        std::size_t want = in_.wanted(max_frame_bytes_);
        ssize_t r = 0;
        if (spin_read.done) {  // the spin's read, into the room made for it then
            spin_read.done = false;
            want = spin_read.want;
            r = spin_read.result;
            errno = spin_read.error;
        } else {
            r = ::recv(fd_, in_.room(want), want, MSG_DONTWAIT);
        }
        if (r > 0) {
            last_heard_ = Clock::now();
            heard_bytes_ += static_cast<std::uint64_t>(r);
            in_.commit(static_cast<std::size_t>(r));
            read_now += static_cast<std::size_t>(r);
            if (static_cast<std::size_t>(r) < want) break;
            // Small frames are read a batch at a time: the rest waits in the socket (poll() sees it), and the
            // batch is delivered before more is decoded, in the room the arrival vector keeps (Arrivals::kKept).
            if (want == wire::ReadBuffer::kChunk && read_now >= kReadBatchBytes) {
                got.more_in_socket = true;
                break;
            }
            continue;
        }
        if (r < 0 && errno == EINTR) continue;
        if (r < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
        reason = r == 0 ? "the gateway closed the connection" : std::strerror(errno);
        break;
    }
    if (!ssl_ && first_bytes) {  // a client without TLS at a gateway with it
        if (looks_like_tls(in_.unread())) {
            reason = "it answered with TLS: give RTIAmbassador(tls=...) or $HLACORE_TLS for a gateway with TLS "
                     "(rtig --tls-cert; docs/networking.md)";
            code = ErrorCode::AuthenticationFailed;
            in_.clear();
        } else if (in_.empty() && !reason.empty()) {
            reason += " before its Welcome, as a gateway with TLS does to a client without it: give "
                      "RTIAmbassador(tls=...) or $HLACORE_TLS for a gateway with TLS (rtig --tls-cert; docs/networking.md)";
        }
    }
    try {
        // Large values are decoded as views into the block (wire::Value): the callback's caller copies them once.
        // Fewer bytes than one such value hold none, and small reads do not touch the block's count.
        std::shared_ptr<const char[]> block;
        if (in_.unread().size() >= wire::kSplicedValueBytes) block = in_.share();
        wire::Frame frame;
        while (std::size_t used = wire::next_frame(in_.unread(), frame, max_frame_bytes_)) {
            frame.block = block ? &block : nullptr;
            wire::Message& m = got.stream.emplace_back();
            try {
                wire::decode(frame, m);
            } catch (const wire::WireError&) {
                got.stream.pop_back();
                throw;
            }
            in_.consume(used);
        }
    } catch (const wire::WireError& e) {
        reason = std::string("protocol error from the gateway: ") + e.what();
    }
    if (!reason.empty()) close_connection(code, reason);
    return WaitStatus::Ready;
}

Client::Clock::time_point Client::liveness_deadline() const {
    if (ping_sent_ > last_heard_) return std::max(last_heard_ + timeout_, ping_sent_ + timeout_ / 2);
    return last_heard_ + timeout_ / 2;
}

void Client::check_liveness() {
    const auto now = Clock::now();
    if (now < liveness_deadline()) return;
    if (ping_sent_ <= last_heard_) {
        // Skipped while another thread sends: a send the gateway does not take has its own bound.
        std::unique_lock<std::mutex> sending(send_mu_, std::try_to_lock);
        if (!sending) return;
        send_buffer_.clear();
        wire::encode(send_buffer_, wire::Ping{++pings_});
        send_encoded(sending);
        ping_sent_ = now;
        return;
    }
    close_connection(ErrorCode::GatewayNotResponding,
                     "the gateway has sent nothing for " + seconds(now - last_heard_) + " and has not answered a ping for " +
                         seconds(now - ping_sent_) + ": it is not responding (stopped, frozen or unreachable)");
}

// Keeps the federate's view current as messages arrive, then queues the callbacks: those of the stream
// gathered at the front of got.stream in their order, and queued together.
void Client::file(Arrivals& got) {
    std::size_t callbacks = 0;
    for (auto& m : got.stream) {
        if (const std::uint32_t* request = answered_request(m)) {
            replies_[*request] = std::move(m);
            continue;
        }
        if (auto* w = std::get_if<wire::Welcome>(&m)) {
            welcomed_ = true;
            max_frame_bytes_ = w->max_frame_bytes;
            challenge_ = std::move(w->challenge);
            nonce_ = std::move(w->nonce);
            datagram_token_ = w->datagram_token;
            max_datagram_ = w->max_datagram;
            continue;
        }
        if (auto* a = std::get_if<wire::Authenticated>(&m)) {
            authenticated_ = std::move(*a);
            continue;
        }
        if (auto* e = std::get_if<wire::ClockEcho>(&m)) {
            clock_echo_ = *e;
            continue;
        }
        if (std::holds_alternative<wire::Pong>(m)) continue;  // what it says is that bytes came: last_heard_
        if (std::holds_alternative<wire::RecordedTopic>(m) || std::holds_alternative<wire::Recorded>(m)) {
            write_recorded(m);
            continue;
        }
        if (auto* d = std::get_if<wire::DiscoverObject>(&m)) {
            objects_[d->object] = make_local_object(d->object_class, d->name);
        } else if (auto* rm = std::get_if<wire::RemoveObject>(&m)) {
            objects_.erase(rm->object);
        } else if (auto* a = std::get_if<wire::AnnounceSyncPoint>(&m)) {
            announced_.insert(a->label);
        } else if (auto* s = std::get_if<wire::FederationSynchronized>(&m)) {
            announced_.erase(s->label);
        }
        if (&m != &got.stream[callbacks]) got.stream[callbacks] = std::move(m);
        ++callbacks;
    }
    got.stream.erase(got.stream.begin() + static_cast<std::ptrdiff_t>(callbacks), got.stream.end());
    callbacks_.push_all(got.stream);
    if (got.more_in_socket) more_in_socket_ = *got.more_in_socket;
    for (auto& m : got.datagrams) {
        // A datagram may overtake the discovery of its object in the stream: HLA has no callback for that.
        const auto* r = std::get_if<wire::ReflectAttributes>(&m);
        if (r && !objects_.count(r->object)) {
            std::lock_guard<std::mutex> lock(datagram_mu_);
            ++datagram_stats_.early;
            continue;
        }
        callbacks_.push(std::move(m));
    }
    got.clear();
}

void Client::Arrivals::clear() {
    more_in_socket.reset();
    for (auto* messages : {&stream, &datagrams}) {
        if (messages->capacity() > kKept) {
            *messages = {};
        } else {
            messages->clear();
        }
    }
}

std::string Client::query_status(std::uint64_t events_after, bool instances) {
    const auto id = next_request();
    return call<wire::StatusReport>(wire::QueryStatus{id, events_after, instances}, id).json;
}

void Client::start_recording(const std::string& path) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (recording_) throw RtiError(ErrorCode::RTIinternalError, "this federate records already");
        recording_ = std::make_unique<mcap::Writer>(path, "hlacore", "hlacore recorder federate");
        recording_failure_.clear();
    }
    const auto id = next_request();
    try {
        call<wire::Reply>(wire::StartRecording{id}, id);
    } catch (...) {
        std::lock_guard<std::mutex> lock(mu_);
        recording_.reset();
        throw;
    }
}

std::uint64_t Client::stop_recording() {
    std::unique_ptr<mcap::Writer> writer;
    std::string failure;
    {
        std::lock_guard<std::mutex> lock(mu_);
        writer = std::move(recording_);
        failure = std::move(recording_failure_);
    }
    if (!failure.empty()) throw std::runtime_error(failure);
    if (!writer) return 0;
    writer->close();
    return writer->messages();
}

// Under mu_: a topic or a record of the recording this federate asked for (start_recording).
void Client::write_recorded(const wire::Message& m) {
    if (!recording_) return;  // stopped: the gateway's last records before it heard of it
    try {
        if (const auto* topic = std::get_if<wire::RecordedTopic>(&m)) {
            recording_->channel(topic->topic, topic->schema_name, topic->schema);
        } else if (const auto* r = std::get_if<wire::Recorded>(&m)) {
            if (!recording_->has_channel(r->topic))
                throw std::runtime_error("the gateway sent a record on '" + r->topic + "' before announcing the topic");
            recording_->message(recording_->channel_id(r->topic), r->sequence, r->log_ns, r->data);
        }
    } catch (const std::exception& e) {
        recording_failure_ = e.what();
        recording_.reset();
    }
}

void Client::poll_now() { pump(Clock::now(), [] { return false; }); }

Client::WaitStatus Client::wait_for_callback(Clock::time_point deadline) {
    return pump(deadline, [this] { return !callbacks_.empty(); });
}

std::optional<wire::Message> Client::pop_callback() {
    std::lock_guard<std::mutex> lock(mu_);
    if (callbacks_.empty()) {
        if (closed_) connection_lost();
        return std::nullopt;
    }
    std::optional<wire::Message> m = callbacks_.pop();
    apply_time_callback(*m);
    apply_ownership_callback(*m);
    apply_save_callback(*m);
    return m;
}

bool Client::has_callbacks() const {
    std::lock_guard<std::mutex> lock(mu_);
    return !callbacks_.empty() || more_in_socket_;
}

void Client::connection_lost() const {
    raise(closed_code_, "connection to rtig at " + address_ + " lost: " + closed_reason_);
}

// ---- checks ----

void Client::require_joined() const {
    if (!fom_) raise(ErrorCode::FederateNotExecutionMember, "the federate is not joined to a federation execution");
    if (closed_) connection_lost();
}

void Client::too_long(const char* service, std::size_t length) const {
    raise(ErrorCode::ValueLengthExceeded,
          std::string(service) + ": the values and tag make a message of " + std::to_string(length) +
              " bytes as the gateway forwards it, over its frame limit of " + std::to_string(max_frame_bytes_) +
              " bytes (rtig --max-frame)");
}

const fom::ObjectClass& Client::defined_object_class(fom::Handle cls) const {
    require_joined();
    const auto* c = fom_->object_class(cls);
    if (!c) raise(ErrorCode::ObjectClassNotDefined, "object class handle " + std::to_string(cls) + " is not defined");
    return *c;
}

const fom::InteractionClass& Client::defined_interaction_class(fom::Handle cls) const {
    require_joined();
    const auto* c = fom_->interaction_class(cls);
    if (!c)
        raise(ErrorCode::InteractionClassNotDefined, "interaction class handle " + std::to_string(cls) + " is not defined");
    return *c;
}

const Client::LocalObject& Client::known_object(std::uint32_t object) const {
    require_joined();
    auto it = objects_.find(object);
    if (it == objects_.end()) raise(ErrorCode::ObjectNotKnown, "object " + std::to_string(object) + " is not known");
    return it->second;
}

void Client::check_attributes(const fom::ObjectClass& cls, const std::vector<fom::Handle>& attributes) {
    for (auto a : attributes) {
        if (!cls.attribute(a))
            raise(ErrorCode::AttributeNotDefined,
                  "attribute handle " + std::to_string(a) + " is not defined for class '" + cls.qualified_name + "'");
    }
}

// ---- federation management ----

std::string Client::federation_proof(const char* action, const std::string& federation) const {
    if (options_.federation_secret.empty() || nonce_.empty()) return "";
    return auth::federation_proof(options_.federation_secret, nonce_, action, federation);
}

void Client::create_federation(const std::string& name, const std::string& fed_name, const std::string& fed_text) {
    const auto id = next_request();
    call(wire::CreateFederation{id, name, fed_name, fed_text, federation_proof("create", name)}, id);
}

void Client::destroy_federation(const std::string& name) {
    const auto id = next_request();
    call(wire::DestroyFederation{id, name, federation_proof("destroy", name)}, id);
}

std::uint32_t Client::join(const std::string& federate, const std::string& federation) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (fom_) raise(ErrorCode::FederateAlreadyExecutionMember, "this ambassador is already joined");
    }
    const auto id = next_request();
    auto joined = call<wire::FederationJoined>(
        wire::JoinFederation{id, federate, federation, federation_proof("join", federation)}, id);
    auto parsed = std::make_unique<fom::Fom>(fom::parse_fed(joined.fed_text, joined.fed_name));
    {
        auto sending = lock_send();
        member_ = true;
    }
    std::lock_guard<std::mutex> lock(mu_);
    fom_ = std::move(parsed);
    federate_ = joined.federate;
    return joined.federate;
}

void Client::resign(std::uint8_t action) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_idle("resignFederationExecution");
        if (action < 1 || action > 4)
            raise(ErrorCode::InvalidResignAction, "resign action " + std::to_string(action) + " is not one of 1-4");
    }
    // Other threads may still be sending (a bridge shutting down): from the resign on, in the socket's order,
    // their federation messages raise FederateNotExecutionMember here instead of reaching the gateway after
    // it, where they would be a protocol error. Until the reply, also when the resign is then refused.
    const auto id = next_request();
    {
        auto sending = lock_send();
        if (!member_) raise(ErrorCode::FederateNotExecutionMember, "the federate is already resigning");
        member_ = false;
        send_buffer_.clear();
        wire::encode(send_buffer_, wire::ResignFederation{id, action});
        send_encoded(sending);
    }
    try {
        await_reply(id);
    } catch (const RtiError&) {
        bool closed;
        {
            std::lock_guard<std::mutex> lock(mu_);
            closed = closed_;
        }
        if (!closed) {
            auto sending = lock_send();
            member_ = true;  // refused (FederateOwnsAttributes ...): still joined
        }
        throw;
    }
    std::lock_guard<std::mutex> lock(mu_);
    callbacks_ = CallbackQueue{};  // what the federation sent before the resign: no callback after it
    fom_.reset();
    federate_ = 0;
    declarations_.published.clear();
    declarations_.subscribed.clear();
    declarations_.published_interactions.clear();
    declarations_.subscribed_interactions.clear();
    objects_.clear();
    announced_.clear();
    time_ = TimeState{};
    save_restore_.save = SavePhase::None;
    save_restore_.restore = RestorePhase::None;
    ddm_ = DdmState{};
}

}  // namespace hlacore
