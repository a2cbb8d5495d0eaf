#include "fedpro/session.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

namespace hlacore::fedpro {

namespace {
constexpr std::chrono::milliseconds kPollSlice{200};
// A federate that takes nothing for this long while we write to it is gone: its connection is dropped, and what
// it had not received is sent again when it resumes.
constexpr std::chrono::milliseconds kWriteStall{10000};
}  // namespace

bool read_exact(int fd, char* out, std::size_t n, std::atomic<bool> const& stop, std::chrono::milliseconds idle) {
    auto quiet = std::chrono::milliseconds(0);
    while (n > 0) {
        if (stop) return false;
        pollfd p{fd, POLLIN, 0};
        const int ready = ::poll(&p, 1, int(kPollSlice.count()));
        if (ready < 0 && errno != EINTR) return false;
        if (ready <= 0) {
            quiet += kPollSlice;
            if (idle.count() && quiet >= idle) return false;
            continue;
        }
        const ssize_t got = ::recv(fd, out, n, 0);
        if (got == 0) return false;
        if (got < 0) {
            if (errno == EINTR || errno == EAGAIN) continue;
            return false;
        }
        out += got;
        n -= std::size_t(got);
        quiet = std::chrono::milliseconds(0);
    }
    return true;
}

bool write_all(int fd, std::string_view bytes, std::chrono::milliseconds stall) {
    auto waited = std::chrono::milliseconds(0);
    while (!bytes.empty()) {
        const ssize_t put = ::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
        if (put > 0) {
            bytes.remove_prefix(std::size_t(put));
            waited = std::chrono::milliseconds(0);
            continue;
        }
        if (put < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) return false;
        if (waited >= stall) return false;
        pollfd p{fd, POLLOUT, 0};
        ::poll(&p, 1, int(kPollSlice.count()));
        waited += kPollSlice;
    }
    return true;
}

bool read_message(int fd, std::uint32_t max_size, std::atomic<bool> const& stop, Header& header, std::string& payload,
                  std::chrono::milliseconds idle) {
    char head[kHeaderSize];
    if (!read_exact(fd, head, kHeaderSize, stop, idle)) return false;
    header = decode_header({head, kHeaderSize}, max_size);
    payload.resize(header.size - kHeaderSize);
    return read_exact(fd, payload.data(), payload.size(), stop, idle);
}

Session::~Session() { end(false); }

void Session::send(MessageType type, std::string_view payload) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string bytes = state_.frame(type, payload);
    write_locked(bytes);
}

bool Session::write_locked(std::string_view bytes) {
    if (fd_ < 0) return false;
    if (write_all(fd_, bytes, kWriteStall)) return true;
    ::shutdown(fd_, SHUT_RDWR);  // its reader sees the end and drops the connection
    return false;
}

void Session::send_callback(std::string_view request) {
    std::unique_lock<std::mutex> lock(mutex_);
    confirmed_.wait(lock, [&] { return ended_ || state_.kept_bytes() < limits_.kept_budget; });
    if (ended_) return;
    const std::string bytes = state_.frame(MessageType::HlaCallbackRequest, request);
    write_locked(bytes);
}

void Session::serve(int fd) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        fd_ = fd;
    }
    Header h;
    std::string payload;
    try {
        while (!ended_ && read_message(fd, limits_.max_message, ended_, h, payload)) on_message(h, payload);
    } catch (BadMessage const& e) {
        std::fprintf(stderr, "fedpro: session %llu: %s; the session ends\n", (unsigned long long)id(), e.what());
        end(false);
    }
    drop(fd);
}

void Session::on_message(Header const& h, std::string_view payload) {
    bool fresh;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        fresh = state_.receive(h);
    }
    confirmed_.notify_all();
    if (!fresh) return;  // sent again after a resume: done already
    switch (h.type) {
        case MessageType::Heartbeat:
            send(MessageType::HeartbeatResponse, u32s({h.sequence}));
            break;
        case MessageType::HlaCallRequest: {
            const std::string response = federate_->call(payload);
            send(MessageType::HlaCallResponse, u32s({h.sequence}) + response);
            break;
        }
        case MessageType::HlaCallbackResponse:
            payload_u32(payload, 0);  // the number of the callback answered: BadMessage when it is not there
            federate_->answered(payload.substr(4));
            break;
        case MessageType::TerminateSession:
            end(true);
            break;
        default:
            throw BadMessage(std::string("a ") + name(h.type) + " within a session");
    }
}

void Session::drop(int fd) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (fd_ == fd) {
            fd_ = -1;
            dropped_at_ = std::chrono::steady_clock::now();
        }
    }
    ::close(fd);
}

bool Session::resume(int fd, std::uint32_t last_received_by_federate) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (ended_) {
        write_all(fd, state_.first_frame(MessageType::ResumeStatus, u32s({kInvalidSession, kNoSequence})), kWriteStall);
        return false;
    }
    SessionState::Resume r = state_.resume(last_received_by_federate);
    if (fd_ >= 0) ::shutdown(fd_, SHUT_RDWR);  // the old connection, when the federate saw the drop first
    fd_ = fd;
    write_locked(state_.frame(MessageType::ResumeStatus, u32s({r.status, state_.last_hla_received()})));
    if (r.status != kResumeOk) {
        fd_ = -1;
        lock.unlock();
        end(false);
        return false;
    }
    for (auto const& bytes : r.resend)
        if (!write_locked(bytes)) break;  // dropped again: the next resume sends them
    dropped_at_ = {};
    return true;
}

bool Session::expired(std::chrono::steady_clock::time_point now) const {
    if (ended_) return true;
    std::lock_guard<std::mutex> lock(mutex_);
    return fd_ < 0 && dropped_at_ != std::chrono::steady_clock::time_point{} &&
           now - dropped_at_ > limits_.resume_timeout;
}

void Session::end(bool tell_federate) {
    std::lock_guard<std::mutex> once(ending_);
    if (ended_.exchange(true)) return;
    confirmed_.notify_all();  // a callback waiting for room gives up
    if (federate_) federate_->end();
    std::lock_guard<std::mutex> lock(mutex_);
    if (tell_federate) write_locked(state_.frame(MessageType::SessionTerminated, {}));
    if (fd_ >= 0) ::shutdown(fd_, SHUT_RDWR);  // its thread closes it
}

}  // namespace hlacore::fedpro
