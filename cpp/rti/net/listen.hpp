// The listening side of a TCP connection, for the gateway and the Federate Protocol's door alike: the socket,
// what a server sets on each connection it accepts, and what counts as this host.
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

namespace hlacore::net {

struct Listening {
    int fd = -1;
    std::uint16_t port = 0;  // the one bound (port 0 asked: the one picked)
    sockaddr_storage bound{};
    socklen_t length = sizeof(sockaddr_storage);
};

// A socket listening on host:port with SO_REUSEADDR (`type_flags`: SOCK_NONBLOCK, SOCK_CLOEXEC); throws
// std::runtime_error saying why not, with nothing left open.
inline Listening listen_tcp(const std::string& host, std::uint16_t port, int type_flags) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
    addrinfo* found = nullptr;
    const std::string service = std::to_string(port);
    if (int rc = getaddrinfo(host.c_str(), service.c_str(), &hints, &found); rc != 0)
        throw std::runtime_error("cannot resolve " + host + ": " + gai_strerror(rc));
    std::unique_ptr<addrinfo, decltype(&freeaddrinfo)> guard(found, freeaddrinfo);
    Listening l;
    l.fd = ::socket(found->ai_family, SOCK_STREAM | type_flags, 0);
    if (l.fd < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
    int one = 1;
    ::setsockopt(l.fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(l.fd, found->ai_addr, found->ai_addrlen) < 0 || ::listen(l.fd, 128) < 0) {
        const std::string why = std::strerror(errno);
        ::close(l.fd);
        throw std::runtime_error("cannot listen on " + host + ":" + service + ": " + why);
    }
    ::getsockname(l.fd, reinterpret_cast<sockaddr*>(&l.bound), &l.length);
    l.port = l.bound.ss_family == AF_INET6 ? ntohs(reinterpret_cast<sockaddr_in6*>(&l.bound)->sin6_port)
                                           : ntohs(reinterpret_cast<sockaddr_in*>(&l.bound)->sin_port);
    return l;
}

// What a server sets on an accepted TCP connection: each message at once (no Nagle), and keepalive, so that a
// peer that stopped reading (paused) is told from one that vanished (its host silent: dropped within ~25 s)
// while the connection is idle.
inline void serve_connection(int fd) {
    int one = 1, idle = 10, interval = 5, count = 3;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    ::setsockopt(fd, SOL_SOCKET, SO_KEEPALIVE, &one, sizeof one);
    ::setsockopt(fd, IPPROTO_TCP, TCP_KEEPIDLE, &idle, sizeof idle);
    ::setsockopt(fd, IPPROTO_TCP, TCP_KEEPINTVL, &interval, sizeof interval);
    ::setsockopt(fd, IPPROTO_TCP, TCP_KEEPCNT, &count, sizeof count);
}

inline bool is_loopback(const std::string& host) {
    return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

}  // namespace hlacore::net
