// rtig --status without the federate side: dials the gateway, opens an hlacore session and asks for its
// status report (the JSON that python -m hlacore.status shows as a table), one blocking exchange at a time.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace hlacore::net {

struct StatusQueryOptions {
    std::string secret;  // proven when the gateway asks (its Welcome carries a challenge)
    bool tls = false;
    std::string tls_ca;
    std::chrono::steady_clock::duration timeout = std::chrono::seconds(5);  // the whole query
};

// The gateway's status as JSON; throws RtiError as dial() does, GatewayNotResponding when it does not answer
// within the timeout, AuthenticationFailed for a secret it refuses or asks for and was not given.
std::string query_status(const std::string& host, std::uint16_t port, const StatusQueryOptions& options);

}  // namespace hlacore::net
