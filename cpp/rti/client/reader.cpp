// The client's receive path: one thread at a time reads the socket (pump, read_socket), files what came
// (answers by request id, callbacks in arrival order) and wakes the others; the handshake's answers, the
// liveness pings and the clock probes wait on the same path.
#include "rti/client/client.hpp"

#include "rti/busy_poll.hpp"
#include "rti/net/session.hpp"
#include "rti/net/wait.hpp"

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


}  // namespace

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

void Client::open_session(Clock::time_point deadline) {
    send(wire::Hello{});
    await_answer(deadline, [this] { return welcomed_; }, "no hlacore handshake");
    if (!challenge_.empty()) authenticate(deadline);
}

void Client::authenticate(Clock::time_point deadline) {
    send(net::answer_challenge(address_, options_.secret, challenge_));
    try {
        await_answer(deadline, [this] { return authenticated_.has_value(); }, "no answer to the authentication");
    } catch (const RtiError& e) {
        if (e.code() == ErrorCode::GatewayNotResponding) throw;
        raise(ErrorCode::AuthenticationFailed, std::string("authentication with ") + address_ + " failed: " + e.what());
    }
    net::check_authenticated(address_, *authenticated_);
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
    close_locked(code, reason);
}

void Client::close_locked(ErrorCode code, const std::string& reason) {
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
            if (refusal && refusal->error != 0) throw RtiError(error_code(refusal->error), refusal->message);
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
        if (tls::looks_like_record(in_.unread())) {
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
        if (!std::visit([this](auto& message) { return arrived(message); }, m)) continue;
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

// The answers: filed for the caller waiting on their id.
#define HLACORE_X(name)                         \
    bool Client::arrived(wire::name& m) {       \
        replies_[m.request] = std::move(m);     \
        return false;                           \
    }
HLACORE_ANSWERS(HLACORE_X)
#undef HLACORE_X

// The session's messages: what the handshake, the clock and the recorder federate wait for.
bool Client::arrived(wire::Welcome& w) {
    welcomed_ = true;
    max_frame_bytes_ = w.max_frame_bytes;
    challenge_ = std::move(w.challenge);
    nonce_ = std::move(w.nonce);
    datagram_token_ = w.datagram_token;
    max_datagram_ = w.max_datagram;
    return false;
}

bool Client::arrived(wire::Authenticated& a) {
    authenticated_ = std::move(a);
    return false;
}

bool Client::arrived(wire::ClockEcho& e) {
    clock_echo_ = e;
    return false;
}

bool Client::arrived(wire::Pong&) { return false; }  // what it says is that bytes came: last_heard_

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
    std::visit([this](const auto& callback) { delivered(callback); }, *m);
    return m;
}

bool Client::has_callbacks() const {
    std::lock_guard<std::mutex> lock(mu_);
    return !callbacks_.empty() || more_in_socket_;
}
}  // namespace hlacore
