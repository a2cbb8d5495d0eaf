// Best effort over UDP, the federate's side (docs/networking.md). At connect, when the gateway's Welcome
// offers a datagram token: a UDP socket connected to the gateway's address sends DatagramHello until the
// gateway echoes one (datagrams get through both ways), then DatagramPath tells the gateway over the stream.
// When no echo comes, the client says so once on stderr and everything goes over TCP. Updates and
// interactions whose values all travel best effort and that carry no timestamp then go as datagrams;
// reflections and interactions the gateway sends as datagrams are read beside the stream.
#include "rti/client/client.hpp"
#include "rti/net/wait.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace hlacore {

namespace {
// How long to wait for each echo of a DatagramHello, one attempt after the other (0.7 s in all).
constexpr int kHelloWaitsMs[] = {100, 200, 400};
}  // namespace

void Client::open_datagram_path(Clock::time_point deadline) {
    sockaddr_storage gateway{};
    socklen_t length = sizeof gateway;
    if (::getpeername(fd_, reinterpret_cast<sockaddr*>(&gateway), &length) < 0) return give_up_datagrams(std::strerror(errno));
    datagram_fd_ = ::socket(gateway.ss_family, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (datagram_fd_ < 0 || ::connect(datagram_fd_, reinterpret_cast<sockaddr*>(&gateway), length) < 0)
        return give_up_datagrams(std::strerror(errno));
    std::uint32_t attempt = 0;
    for (int wait_ms : kHelloWaitsMs) {
        std::string hello;
        wire::put_datagram_header(hello, datagram_token_, 0);
        wire::encode(hello, wire::DatagramHello{++attempt});
        ::send(datagram_fd_, hello.data(), hello.size(), MSG_DONTWAIT | MSG_NOSIGNAL);
        const auto until = std::min(deadline, Clock::now() + std::chrono::milliseconds(wait_ms));
        for (;;) {
            if (poll_until(options_.wait_host, datagram_fd_, POLLIN, until) <= 0) break;
            char echo[512];
            const ssize_t r = ::recv(datagram_fd_, echo, sizeof echo, MSG_DONTWAIT);
            if (r < 0 && errno == ECONNREFUSED)  // an ICMP "port unreachable" for an earlier hello
                return give_up_datagrams("the gateway's host refuses them (nothing listens for UDP on its port)");
            if (r < 0) continue;
            const auto read = wire::read_datagram(std::string_view(echo, static_cast<std::size_t>(r)));
            if (!read || read->header.token != datagram_token_ || read->frame.type != wire::MessageType::DatagramHello)
                continue;
            send(wire::DatagramPath{});
            datagram_path_ = true;
            return;
        }
        if (Clock::now() >= deadline) break;
    }
    give_up_datagrams("no answer to " + std::to_string(attempt) + " hellos within 0.7 s (a firewall or a NAT in the way?)");
}

void Client::give_up_datagrams(const std::string& reason) {
    if (datagram_fd_ >= 0) ::close(datagram_fd_);
    datagram_fd_ = -1;
    datagram_reason_ = reason;
    const std::string line = "hlacore: no datagrams with rtig at " + address_ + ": " + reason +
                             "; best-effort messages go over TCP (docs/networking.md)\n";
    std::fwrite(line.data(), 1, line.size(), stderr);
}

// By the thread that reads: every datagram waiting, each counted by its sequence number; only best-effort
// messages are taken from them.
void Client::read_datagrams(std::vector<wire::Message>& got) {
    char datagram[65536];
    for (;;) {
        const ssize_t r = ::recv(datagram_fd_, datagram, sizeof datagram, MSG_DONTWAIT);
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) return;  // drained (or an ICMP error for a datagram sent earlier: that one is lost)
        const auto read = wire::read_datagram(std::string_view(datagram, static_cast<std::size_t>(r)));
        if (!read || read->header.token != datagram_token_ || read->header.sequence == 0) continue;
        {
            std::lock_guard<std::mutex> lock(datagram_mu_);
            if (!datagram_window_.accept(read->header.sequence, datagram_stats_)) continue;
        }
        const wire::MessageType type = read->frame.type;
        try {
            if (type == wire::MessageType::ReflectAttributes || type == wire::MessageType::ReceiveInteraction)
                got.push_back(wire::decode(read->frame));
        } catch (const wire::WireError&) {
            // a datagram that is not what it claims: dropped (the stream is what must stay sound)
        }
    }
}

template <class M>
void Client::send_best_effort(const M& message) {
    if (datagram_path_) {
        auto lock = lock_send();
        require_member(M::kType);
        datagram_buffer_.clear();
        wire::put_datagram_header(datagram_buffer_, datagram_token_, datagram_sequence_ + 1);
        wire::encode(datagram_buffer_, message);
        if (datagram_buffer_.size() <= max_datagram_) {
            ++datagram_sequence_;
            const bool taken = ::send(datagram_fd_, datagram_buffer_.data(), datagram_buffer_.size(),
                                      MSG_DONTWAIT | MSG_NOSIGNAL) >= 0;
            std::lock_guard<std::mutex> counting(datagram_mu_);
            ++(taken ? datagram_stats_.sent : datagram_stats_.send_failed);
            return;
        }
        std::lock_guard<std::mutex> counting(datagram_mu_);
        ++datagram_stats_.oversize;
    }
    send(message);
}
template void Client::send_best_effort(const wire::UpdateAttributesView&);
template void Client::send_best_effort(const wire::SendInteractionView&);

bool Client::best_effort(const LocalObject& obj, const wire::HandleValueViews& values) const {
    if (!datagram_path_ || values.empty()) return false;
    const auto& cls = *fom_->object_class(obj.object_class);
    for (const auto& [attr, value] : values) {
        auto changed = obj.transport.find(attr);
        const auto transport = changed != obj.transport.end() ? changed->second : cls.attribute(attr)->transport;
        if (transport != fom::Transport::BestEffort) return false;
    }
    return true;
}

bool Client::best_effort(fom::Handle interaction_class) const {
    if (!datagram_path_) return false;
    auto changed = interaction_transport_.find(interaction_class);
    return (changed != interaction_transport_.end() ? changed->second
                                                    : fom_->interaction_class(interaction_class)->transport) ==
           fom::Transport::BestEffort;
}

DatagramStatus Client::datagram_status() const {
    std::lock_guard<std::mutex> lock(datagram_mu_);
    return DatagramStatus{datagram_path_, datagram_reason_, datagram_stats_};
}

}  // namespace hlacore
