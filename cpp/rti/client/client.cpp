#include "rti/client/client.hpp"

#include <cerrno>
#include <cstring>

#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace hlacore {

Client::Client(const std::string& host, std::uint16_t port) : address_(host + ":" + std::to_string(port)) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_NUMERICSERV;
    addrinfo* found = nullptr;
    const std::string service = std::to_string(port);
    if (int rc = getaddrinfo(host.c_str(), service.c_str(), &hints, &found); rc != 0)
        raise(ErrorCode::RTIinternalError, "cannot resolve rtig host '" + host + "': " + gai_strerror(rc));
    std::string error = "no address";
    for (addrinfo* a = found; a; a = a->ai_next) {
        int fd = ::socket(a->ai_family, SOCK_STREAM | SOCK_CLOEXEC, 0);
        if (fd < 0) continue;
        if (::connect(fd, a->ai_addr, a->ai_addrlen) == 0) {
            fd_ = fd;
            break;
        }
        error = std::strerror(errno);
        ::close(fd);
    }
    freeaddrinfo(found);
    if (fd_ < 0) raise(ErrorCode::RTIinternalError, "cannot connect to rtig at " + address_ + ": " + error);
    int one = 1;
    setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);

    send(wire::Hello{});
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    bool welcomed = false;
    for (;;) {
        std::vector<wire::Message> got;
        if (read_socket(deadline, got) == WaitStatus::Timeout || closed_) break;
        for (auto& m : got) {
            if (std::holds_alternative<wire::Welcome>(m)) welcomed = true;
        }
        if (welcomed) break;
    }
    if (!welcomed) {
        ::close(fd_);
        fd_ = -1;
        raise(ErrorCode::RTIinternalError, "no hlacore handshake from " + address_ +
                                               (closed_reason_.empty() ? std::string() : ": " + closed_reason_));
    }
}

Client::~Client() {
    if (fd_ >= 0) ::close(fd_);
}

// ---- plumbing ----

template <class M>
void Client::send(const M& message) {
    std::lock_guard<std::mutex> lock(send_mu_);
    send_buffer_.clear();
    wire::encode(send_buffer_, message);
    write_send_buffer();
}
#define HLACORE_X(name) template void Client::send(const wire::name&);
HLACORE_MESSAGES(HLACORE_X)
#undef HLACORE_X

void Client::write_send_buffer() {
    std::size_t done = 0;
    while (done < send_buffer_.size()) {
        ssize_t n = ::send(fd_, send_buffer_.data() + done, send_buffer_.size() - done, MSG_NOSIGNAL);
        if (n > 0) {
            done += static_cast<std::size_t>(n);
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else {
            raise(ErrorCode::RTIinternalError, "connection to rtig at " + address_ + " lost: " + std::strerror(errno));
        }
    }
}

std::uint32_t Client::next_request() {
    std::lock_guard<std::mutex> lock(mu_);
    return ++last_request_;
}

wire::Reply Client::call(wire::Message request, std::uint32_t id) {
    std::visit(
        [this](const auto& m) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(m)>, std::monostate>) send(m);
        },
        request);
    for (;;) {
        auto status = pump(Clock::time_point::max(), [&] { return replies_.count(id) > 0; });
        std::unique_lock<std::mutex> lock(mu_);
        auto it = replies_.find(id);
        if (it != replies_.end()) {
            wire::Reply reply = std::move(it->second);
            replies_.erase(it);
            lock.unlock();
            if (reply.error != 0) {
                const auto code = reply.error < static_cast<std::uint16_t>(ErrorCode::Count)
                                      ? static_cast<ErrorCode>(reply.error)
                                      : ErrorCode::RTIinternalError;
                throw RtiError(code, reply.message);
            }
            return reply;
        }
        if (closed_) connection_lost();
        (void)status;  // interrupted: the reply is still owed, keep waiting
    }
}

template <class Pred>
Client::WaitStatus Client::pump(Clock::time_point deadline, Pred pred) {
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
        std::vector<wire::Message> got;
        WaitStatus status = WaitStatus::Ready;
        try {
            status = read_socket(deadline, got);
        } catch (...) {
            lock.lock();
            reading_ = false;
            cv_.notify_all();
            throw;
        }
        lock.lock();
        reading_ = false;
        file(got);
        cv_.notify_all();
        if (status == WaitStatus::Interrupted) return status;
    }
}

// Waits for readable data (up to the deadline), then reads everything available and decodes whole frames.
Client::WaitStatus Client::read_socket(Clock::time_point deadline, std::vector<wire::Message>& got) {
    pollfd p{fd_, POLLIN, 0};
    timespec ts{};
    const timespec* timeout = nullptr;
    if (deadline != Clock::time_point::max()) {
        auto left = std::chrono::duration_cast<std::chrono::nanoseconds>(deadline - Clock::now()).count();
        if (left < 0) left = 0;
        ts.tv_sec = static_cast<time_t>(left / 1000000000);
        ts.tv_nsec = static_cast<long>(left % 1000000000);
        timeout = &ts;
    }
    int n = ::ppoll(&p, 1, timeout, nullptr);
    if (n < 0) return errno == EINTR ? WaitStatus::Interrupted : WaitStatus::Ready;
    if (n == 0) return WaitStatus::Timeout;
    char chunk[65536];
    std::string reason;
    for (;;) {
        ssize_t r = ::recv(fd_, chunk, sizeof chunk, MSG_DONTWAIT);
        if (r > 0) {
            in_.append(chunk, static_cast<std::size_t>(r));
            if (static_cast<std::size_t>(r) < sizeof chunk) break;
            continue;
        }
        if (r < 0 && errno == EINTR) continue;
        if (r < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
        reason = r == 0 ? "the gateway closed the connection" : std::strerror(errno);
        break;
    }
    std::size_t offset = 0;
    try {
        wire::Frame frame;
        while (std::size_t used = wire::next_frame(std::string_view(in_).substr(offset), frame)) {
            got.push_back(wire::decode(frame));
            offset += used;
        }
    } catch (const wire::WireError& e) {
        reason = std::string("protocol error from the gateway: ") + e.what();
    }
    in_.erase(0, offset);
    if (!reason.empty()) {
        std::lock_guard<std::mutex> lock(mu_);
        closed_ = true;
        closed_reason_ = reason;
        cv_.notify_all();
    }
    return WaitStatus::Ready;
}

// Keeps the federate's view current as messages arrive, then queues the callbacks.
void Client::file(std::vector<wire::Message>& got) {
    for (auto& m : got) {
        if (auto* r = std::get_if<wire::Reply>(&m)) {
            replies_[r->request] = std::move(*r);
            continue;
        }
        if (std::holds_alternative<wire::Welcome>(m)) continue;
        if (auto* d = std::get_if<wire::DiscoverObject>(&m)) {
            objects_[d->object] = make_local_object(d->object_class, d->name);
        } else if (auto* rm = std::get_if<wire::RemoveObject>(&m)) {
            objects_.erase(rm->object);
        } else if (auto* a = std::get_if<wire::AnnounceSyncPoint>(&m)) {
            announced_.insert(a->label);
        } else if (auto* s = std::get_if<wire::FederationSynchronized>(&m)) {
            announced_.erase(s->label);
        }
        callbacks_.push(std::move(m));
    }
}

std::string Client::query_status() {
    const auto id = next_request();
    return call(wire::QueryStatus{id}, id).text;
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
    wire::Message m = callbacks_.pop();
    apply_time_callback(m);
    apply_ownership_callback(m);
    apply_save_callback(m);
    return m;
}

bool Client::has_callbacks() const {
    std::lock_guard<std::mutex> lock(mu_);
    return !callbacks_.empty();
}

void Client::connection_lost() const {
    raise(ErrorCode::RTIinternalError, "connection to rtig at " + address_ + " lost: " + closed_reason_);
}

// ---- checks ----

void Client::require_joined() const {
    if (!fom_) raise(ErrorCode::FederateNotExecutionMember, "the federate is not joined to a federation execution");
    if (closed_) connection_lost();
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

void Client::create_federation(const std::string& name, const std::string& fed_name, const std::string& fed_text) {
    const auto id = next_request();
    call(wire::CreateFederation{id, name, fed_name, fed_text}, id);
}

void Client::destroy_federation(const std::string& name) {
    const auto id = next_request();
    call(wire::DestroyFederation{id, name}, id);
}

std::uint32_t Client::join(const std::string& federate, const std::string& federation) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (fom_) raise(ErrorCode::FederateAlreadyExecutionMember, "this ambassador is already joined");
    }
    const auto id = next_request();
    wire::Reply reply = call(wire::JoinFederation{id, federate, federation}, id);
    auto parsed = std::make_unique<fom::Fom>(fom::parse_fed(reply.text, reply.text2));
    std::lock_guard<std::mutex> lock(mu_);
    fom_ = std::move(parsed);
    federate_ = reply.handle;
    return reply.handle;
}

void Client::resign(std::uint8_t action) {
    {
        std::lock_guard<std::mutex> lock(mu_);
        require_idle("resignFederationExecution");
        if (action < 1 || action > 4)
            raise(ErrorCode::InvalidResignAction, "resign action " + std::to_string(action) + " is not one of 1-4");
    }
    const auto id = next_request();
    call(wire::ResignFederation{id, action}, id);
    std::lock_guard<std::mutex> lock(mu_);
    fom_.reset();
    federate_ = 0;
    published_.clear();
    subscribed_.clear();
    published_interactions_.clear();
    subscribed_interactions_.clear();
    objects_.clear();
    announced_.clear();
    time_ = TimeState{};
    save_phase_ = SavePhase::None;
    restore_phase_ = RestorePhase::None;
    ddm_ = DdmState{};
}

}  // namespace hlacore
