// The client's send path: messages encoded under the send lock and written at once by the caller, or queued
// for the writer thread while it writes; held sends (batch()); large values written from where they are.
#include "rti/client/client.hpp"

#include "rti/busy_poll.hpp"
#include "rti/net/wait.hpp"
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

}  // namespace hlacore
