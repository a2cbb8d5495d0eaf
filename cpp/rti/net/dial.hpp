// Connecting to a gateway, for the federate side (Client) and rtig --status alike: TCP within the timeout
// (TCP_NODELAY), or its Unix socket (address unix:PATH), then the TLS handshake when asked, verifying the
// gateway's certificate and the host connected to. What comes after (the hlacore session) is the caller's.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "rti/net/wait.hpp"
#include "rti/tls.hpp"

namespace hlacore::net {

struct DialOptions {
    std::chrono::steady_clock::duration timeout{};  // for the messages; the wait is bounded by the deadline
    bool tls = false;
    std::string tls_ca;  // empty: the system's CA store
    WaitHost* wait_host = nullptr;
};

// A connected, non-blocking socket and, with TLS, its session; the caller owns both.
struct Dialed {
    int fd = -1;
    tls::Session ssl;
};

// How the messages name the gateway: HOST:PORT, or unix:PATH as given.
std::string address_of(const std::string& host, std::uint16_t port);

// Throws RtiError naming the address: RTIinternalError when the host cannot be resolved or nothing listens,
// GatewayNotResponding when the connect or the TLS handshake is not done by `deadline`, AuthenticationFailed
// for a certificate that is not trusted or not the host's, or a gateway without TLS.
Dialed dial(const std::string& host, std::uint16_t port, const DialOptions& options,
            std::chrono::steady_clock::time_point deadline);

}  // namespace hlacore::net
