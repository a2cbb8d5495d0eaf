// The client's options (ClientOptions) and where it connects, as a table (rti/options.hpp): the keywords and
// docs of hlacore.rti.RTIAmbassador and the environment it and the HLA 1.3 C++ API read are made from it.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "rti/net/wait.hpp"
#include "rti/options.hpp"

namespace hlacore {

struct ClientOptions {
    // Bounds connecting, the handshake, each reply and each blocked send; a gateway silent for half of it
    // while the client waits is pinged.
    double timeout_s = 5.0;
    WaitHost* wait_host = nullptr;  // not owned; must outlive the client
    // Proven to a gateway that asks (its Welcome carries a challenge; rti/auth.hpp); never sent.
    std::string secret;
    // Proven when creating, joining or destroying a federation that has a secret of its own (over the
    // Welcome's nonce; auth::federation_proof); never sent.
    std::string federation_secret;
    // Best effort over UDP when the gateway offers it and datagrams get through (client/datagrams.cpp).
    bool datagrams = true;
    // TLS (rtig --tls-cert): the gateway's certificate is verified against the system's default CA store
    // (tls_ca empty) or the CA / self-signed certificate in the PEM file tls_ca, and must name the host
    // connected to. Failures raise AuthenticationFailed.
    bool tls = false;
    std::string tls_ca;
    // Busy polling (rti/busy_poll.hpp; 0, the default: off): a wait polls the socket without sleeping for up
    // to this many µs before it sleeps, so that a message arriving meanwhile costs no wake-up. At most
    // kMaxBusyPollUs. With a wait_host, a wait that spun sleeps in slices of 100 ms after it, each ended as if
    // interrupted, so that the host looks at signals the spin may have taken without a poll seeing them.
    std::uint32_t busy_poll_us = 0;
    // The time rules of the federations this client creates (rti/time.hpp); Default: the gateway's.
    TimeSemantics time_semantics = TimeSemantics::Default;
};

// Where a client connects and how.
struct ClientSettings {
    std::string host = "127.0.0.1";  // or unix:PATH, a gateway on this host (rtig --unix PATH), with port 0
    std::uint16_t port = 60400;
    ClientOptions options;
};

const Options<ClientSettings>& client_options();

// The settings from the values given (keyword → text), else the environment, else the defaults; CERTI's
// $CERTI_HOST and $CERTI_TCP_PORT stand in for an address neither gives, as PyHLA scripts set them. Throws
// RtiError: RTIinternalError naming the option as given for a value it refuses, AuthenticationFailed for a
// secret file that cannot be used.
ClientSettings client_settings(const std::map<std::string, std::string>& given);

}  // namespace hlacore
