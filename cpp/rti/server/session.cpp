// The gateway's side of the hlacore session: the version handshake, the shared secret's challenge, the
// federations' own secrets and the requests any connection may make (Ping, ClockProbe).
#include "rti/server/gateway.hpp"
#include "rti/auth.hpp"
#include "rti/server/gateway_internal.hpp"

#include <string>

#include <openssl/ssl.h>

namespace hlacore {

// The session before any HLA service: the Hello answered with a Welcome (and a challenge when the gateway has a
// secret), then nothing but the answer to that challenge.
void Gateway::greet(Connection& c, wire::MessageType type, const wire::Message& message) {
    if (!c.greeted) {
        const auto* hello = std::get_if<wire::Hello>(&message);
        if (!hello || hello->magic != wire::kMagic)
            throw wire::WireError("expected a Hello handshake, got " + std::string(wire::message_name(type)));
        if (hello->version != wire::kProtocolVersion)
            throw wire::WireError("protocol version " + std::to_string(hello->version) + " is not supported (gateway speaks " +
                                  std::to_string(wire::kProtocolVersion) + ")");
        c.greeted = true;
        if (c.ssl && options_.verbose)
            log("TLS with " + c.peer + ": " + SSL_get_version(c.ssl.get()) + ", " + SSL_get_cipher_name(c.ssl.get()));
        if (!options_.secret.empty()) c.challenge = auth::random_challenge();
        if (!options_.federation_secrets.empty()) c.nonce = auth::random_challenge();
        give_datagram_token(c);
        wire::encode(c.out, wire::Welcome{wire::kProtocolVersion, "hlacore rtig", options_.max_frame_bytes, c.challenge,
                                          c.datagram_token, c.datagram_token ? options_.max_datagram : 0, c.nonce});
        mark_dirty(c);
        return;
    }
    if (!c.challenge.empty()) {  // nothing but the answer to the challenge, and nothing after a wrong one
        const auto* answer = std::get_if<wire::Authenticate>(&message);
        if (!answer)
            throw wire::WireError(std::string(wire::message_name(type)) + " sent before authenticating");
        if (!auth::verify(options_.secret, c.challenge, answer->proof)) {
            wire::encode(c.out, wire::Authenticated{false, "the gateway refused the secret"});
            flush(c);  // a small frame into an empty socket buffer: the client reads why
            close(c.fd, "authentication failed: wrong secret");
            return;
        }
        c.challenge.clear();
        wire::encode(c.out, wire::Authenticated{true, ""});
        mark_dirty(c);
    }
}

void Gateway::require_federation_secret(const Connection& c, const char* action, const std::string& federation,
                                        const std::string& proof) const {
    const auto secret = options_.federation_secrets.find(federation);
    if (secret == options_.federation_secrets.end()) return;
    if (auth::verify_federation(secret->second, c.nonce, action, federation, proof)) return;
    const std::string why = proof.empty() ? "no secret was given" : "the secret is wrong";
    log("refused to " + std::string(action) + " federation '" + federation + "' for " + c.peer + ": " + why);
    throw RtiError(ErrorCode::AuthenticationFailed,
                   "federation '" + federation + "' has a secret of its own and " + why +
                       " (RTIAmbassador(federation_secret_file=...), $HLACORE_FEDERATION_SECRET_FILE; docs/networking.md)");
}

void Gateway::serve(Connection& c, const wire::Authenticate&) {
    // Already authenticated, or no secret asked (on_frame answers the challenge itself): nothing to prove.
    wire::encode(output(c), wire::Authenticated{true, ""});
    mark_dirty(c);
}

void Gateway::serve(Connection& c, const wire::ClockProbe& m) {
    // The trace's clock (CLOCK_MONOTONIC), so that a client's offset applies to the trace's marks too.
    wire::encode(output(c), wire::ClockEcho{m.sequence, m.client_ns, static_cast<std::uint64_t>(MessageTrace::now_ns())});
    mark_dirty(c);
}

void Gateway::serve(Connection& c, const wire::Ping& m) {
    wire::encode(output(c), wire::Pong{m.sequence});
    mark_dirty(c);
}

}  // namespace hlacore
