// Best effort over UDP, the gateway's side (docs/networking.md): a datagram socket on the listening address
// and port. A client proves that datagrams get through both ways (DatagramHello, echoed; then DatagramPath in
// the stream); from then on the receive-order best-effort messages for it go as datagrams when they fit, and
// its own best-effort updates and interactions may come as datagrams. Nothing here waits or queues: a datagram
// the socket does not take is lost and counted, so best effort never holds back reliable traffic.
#include "rti/server/connection.hpp"
#include "rti/server/gateway.hpp"
#include "rti/auth.hpp"
#include "rti/wire/json.hpp"

#include <cerrno>
#include <cstring>

#include <netinet/in.h>
#include <unistd.h>

namespace hlacore {

namespace {

bool same_address(const sockaddr_storage& a, socklen_t a_length, const sockaddr_storage& b, socklen_t b_length) {
    return a_length == b_length && std::memcmp(&a, &b, a_length) == 0;
}

void json_counts(std::string& out, const wire::DatagramStats& s) {
    out += "{\"sent\":" + std::to_string(s.sent) + ",\"send_failed\":" + std::to_string(s.send_failed) +
           ",\"oversize\":" + std::to_string(s.oversize) + ",\"received\":" + std::to_string(s.received) +
           ",\"lost\":" + std::to_string(s.lost) + ",\"reordered\":" + std::to_string(s.reordered) +
           ",\"duplicates\":" + std::to_string(s.duplicates) + ",\"held_back\":" + std::to_string(s.held_back) +
           ",\"early\":" + std::to_string(s.early) + '}';
}

}  // namespace

void Gateway::open_datagrams(const sockaddr_storage& bound, socklen_t length) {
    datagram_fd_ = ::socket(bound.ss_family, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (datagram_fd_ >= 0 && ::bind(datagram_fd_, reinterpret_cast<const sockaddr*>(&bound), length) == 0) {
        loop_.add(datagram_fd_, EPOLLIN);
        return;
    }
    log("no datagrams on " + options_.host + ":" + std::to_string(port_) + " (" + std::strerror(errno) +
        "): best-effort messages go over TCP");
    if (datagram_fd_ >= 0) ::close(datagram_fd_);
    datagram_fd_ = -1;
}

void Gateway::give_datagram_token(Connection& c) {
    if (datagram_fd_ < 0 || c.local) return;
    do {
        const std::string random = auth::random_challenge();
        std::memcpy(&c.datagram_token, random.data(), sizeof c.datagram_token);
    } while (c.datagram_token == 0 || datagram_tokens_.count(c.datagram_token));
    datagram_tokens_[c.datagram_token] = c.fd;
}

void Gateway::on_datagrams() {
    // A bounded batch per turn of the loop: a flood of datagrams does not starve the connections (the socket
    // stays readable and the rest waits for the next turn, or is dropped by the kernel when its buffer fills).
    char datagram[65536];
    for (int i = 0; i < 256; ++i) {
        sockaddr_storage from{};
        socklen_t length = sizeof from;
        const ssize_t n = ::recvfrom(datagram_fd_, datagram, sizeof datagram, MSG_DONTWAIT,
                                     reinterpret_cast<sockaddr*>(&from), &length);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return;
        on_datagram(std::string_view(datagram, static_cast<std::size_t>(n)), from, length);
    }
}

// Whether a datagram's frame decodes into `m`; one that does not is what a stray (or forged) datagram looks
// like: counted and dropped, the connection unharmed.
template <class M>
bool Gateway::decodes(const wire::Frame& frame, M& m) {
    try {
        if constexpr (std::is_same_v<M, wire::Message>) wire::decode(frame, m);
        else wire::decode_fields(frame, m);
        return true;
    } catch (const wire::WireError&) {
        ++stray_datagrams_;
        return false;
    }
}

void Gateway::on_datagram(std::string_view datagram, const sockaddr_storage& from, socklen_t length) {
    const auto read = wire::read_datagram(datagram);
    auto owner = read ? datagram_tokens_.find(read->header.token) : datagram_tokens_.end();
    auto it = owner != datagram_tokens_.end() ? connections_.find(owner->second) : connections_.end();
    // Only an authenticated connection's token counts: the Welcome hands it out before the challenge is met.
    if (it == connections_.end() || !it->second->challenge.empty()) {
        ++stray_datagrams_;
        return;
    }
    Connection& c = *it->second;
    const wire::Frame& frame = read->frame;
    if (frame.type == wire::MessageType::DatagramHello) {
        wire::DatagramHello hello;
        if (!decodes(frame, hello)) return;
        // The client's datagrams come from here from now on; the echo tells it that datagrams get through.
        c.datagram_peer = from;
        c.datagram_peer_length = length;
        std::string echo;
        wire::put_datagram_header(echo, c.datagram_token, 0);
        wire::encode(echo, wire::DatagramHello{hello.attempt});
        ::sendto(datagram_fd_, echo.data(), echo.size(), MSG_DONTWAIT | MSG_NOSIGNAL,
                 reinterpret_cast<const sockaddr*>(&from), length);
        return;
    }
    if (!same_address(from, length, c.datagram_peer, c.datagram_peer_length)) {
        ++stray_datagrams_;
        return;
    }
    if (frame.type == wire::MessageType::UpdateAttributes)
        return serve_best_effort<wire::UpdateAttributesView>(c, read->header.sequence, frame);
    if (frame.type == wire::MessageType::SendInteraction)
        return serve_best_effort<wire::SendInteractionView>(c, read->header.sequence, frame);
    if (wire::Message m; decodes(frame, m))
        close(c.fd, std::string("protocol error: ") + wire::message_name(frame.type) + " in a datagram");
}

// An update or interaction that came as a datagram, decoded once (as a view into the datagram) and served
// unless it is stray, late or duplicated, or its sender is held back by flow control.
template <class View>
void Gateway::serve_best_effort(Connection& c, std::uint64_t sequence, const wire::Frame& frame) {
    View m;
    if (!decodes(frame, m)) return;
    if (!c.datagram_window.accept(sequence, c.datagrams)) return;
    if (c.paused) {  // held back by flow control: what it sends as best effort is dropped, not queued
        ++c.datagrams.held_back;
        return;
    }
    const int fd = c.fd;
    try {
        over_budget_ = -1;
        if (trace_) c.read_ns = MessageTrace::now_ns();
        serve_message(c, m);
    } catch (const wire::WireError& e) {
        close(fd, std::string("protocol error: ") + e.what());
        return;
    }
    if (connections_.count(fd)) pause_if_over_budget(c);
}

bool Gateway::send_datagram(Connection& c, std::string_view frame) {
    if (!c.datagram_path) return false;
    if (wire::kDatagramHeaderBytes + frame.size() > options_.max_datagram) {
        ++c.datagrams.oversize;
        return false;
    }
    datagram_out_.clear();
    wire::put_datagram_header(datagram_out_, c.datagram_token, ++c.datagram_sequence);
    datagram_out_.append(frame);
    const ssize_t n = ::sendto(datagram_fd_, datagram_out_.data(), datagram_out_.size(), MSG_DONTWAIT | MSG_NOSIGNAL,
                               reinterpret_cast<const sockaddr*>(&c.datagram_peer), c.datagram_peer_length);
    if (n < 0) {
        ++c.datagrams.send_failed;  // its sequence number stays unused: the client counts it lost
    } else {
        ++c.datagrams.sent;
        if (trace_ && c.federation) trace_->sending(federation_name(c), c.federate, frame, MessageTrace::now_ns());
    }
    return true;
}

void Gateway::serve(Connection& c, const wire::DatagramPath&) {
    if (!c.datagram_peer_length)
        throw wire::WireError("DatagramPath before any datagram came from the client");
    c.datagram_path = true;
}

void Gateway::write_datagram_status(std::string& json) const {
    json += "{\"port\":";
    json += datagram_fd_ >= 0 ? std::to_string(port_) : "null";
    json += ",\"max_datagram\":" + std::to_string(datagram_fd_ >= 0 ? options_.max_datagram : 0);
    json += ",\"stray\":" + std::to_string(stray_datagrams_) + ",\"federates\":";
    std::vector<const Connection*> joined;
    for (const auto& [fd, c] : connections_)
        if (c->federation) joined.push_back(c.get());
    json_array(json, joined, [&](const Connection* c) {
        json += "{\"federation\":";
        json_string(json, federation_name(*c));
        json += ",\"federate\":" + std::to_string(c->federate);
        json += std::string(",\"path\":") + (c->datagram_path ? "true" : "false") + ",\"counts\":";
        json_counts(json, c->datagrams);
        json += '}';
    });
    json += '}';
}

}  // namespace hlacore
