// Access control: a shared secret proven by challenge-response when a client connects (docs/networking.md).
// The gateway's Welcome carries a fresh random challenge; the client answers with HMAC-SHA256(secret,
// label + challenge), so the secret never crosses the network and a recorded answer is worth nothing for
// the next connection. OpenSSL's libcrypto does the cryptography.
#pragma once

#include <string>

namespace hlacore::auth {

constexpr std::size_t kChallengeBytes = 32;

// kChallengeBytes from the system's cryptographic random source.
std::string random_challenge();
// What a client that knows `secret` answers to `challenge`.
std::string proof(const std::string& secret, const std::string& challenge);
// Whether the proof answers the challenge, compared in constant time.
bool verify(const std::string& secret, const std::string& challenge, const std::string& proof);

// A federation's own secret (rtig --federation-secret NAME=FILE) guards its creation, joining and
// destruction: the client proves it for one `action` ("create", "join", "destroy") on one federation,
// over the connection's nonce (sent in the Welcome), so a proof seen on the network opens nothing else.
std::string federation_proof(const std::string& secret, const std::string& nonce, const std::string& action,
                             const std::string& federation);
bool verify_federation(const std::string& secret, const std::string& nonce, const std::string& action,
                       const std::string& federation, const std::string& proof);
// The secret kept in `path` (its content, without one trailing newline). Throws std::runtime_error, saying
// why, for a file that cannot be read, is empty, or that users other than its owner may read.
std::string read_secret_file(const std::string& path);
// Throws std::runtime_error unless `path` exists and only its owner may read or write it; `what` names the
// file in the message ("the secret file", "the TLS key file").
void require_owner_only(const std::string& path, const std::string& what);

}  // namespace hlacore::auth
