#include "rti/auth.hpp"

#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <openssl/rand.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hlacore::auth {
namespace {
// Binds a proof to this protocol, so that an answer cannot be replayed to another that signs challenges.
constexpr char kLabel[] = "hlacore gateway authentication 1\n";
constexpr char kFederationLabel[] = "hlacore federation authentication 1\n";

std::string hmac_sha256(const std::string& key, const std::string& message) {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    if (!HMAC(EVP_sha256(), key.data(), static_cast<int>(key.size()),
              reinterpret_cast<const unsigned char*>(message.data()), message.size(), digest, &length))
        throw std::runtime_error("HMAC-SHA256 failed");
    return std::string(reinterpret_cast<const char*>(digest), length);
}

bool same(const std::string& answer, const std::string& expected) {
    return answer.size() == expected.size() && CRYPTO_memcmp(answer.data(), expected.data(), expected.size()) == 0;
}
}  // namespace

std::string random_challenge() {
    std::string challenge(kChallengeBytes, '\0');
    if (RAND_bytes(reinterpret_cast<unsigned char*>(challenge.data()), static_cast<int>(challenge.size())) != 1)
        throw std::runtime_error("no random bytes for an authentication challenge");
    return challenge;
}

std::string proof(const std::string& secret, const std::string& challenge) {
    return hmac_sha256(secret, kLabel + challenge);
}

bool verify(const std::string& secret, const std::string& challenge, const std::string& answer) {
    return same(answer, proof(secret, challenge));
}

std::string federation_proof(const std::string& secret, const std::string& nonce, const std::string& action,
                             const std::string& federation) {
    // Lengths first: no two (action, federation, nonce) triples make the same message.
    return hmac_sha256(secret, kFederationLabel + std::to_string(action.size()) + ":" + action +
                                   std::to_string(federation.size()) + ":" + federation + nonce);
}

bool verify_federation(const std::string& secret, const std::string& nonce, const std::string& action,
                       const std::string& federation, const std::string& answer) {
    return same(answer, federation_proof(secret, nonce, action, federation));
}

void require_owner_only(const std::string& path, const std::string& what) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        throw std::runtime_error("cannot read " + what + " '" + path + "': " + std::strerror(errno));
    if (st.st_mode & (S_IRWXG | S_IRWXO))
        throw std::runtime_error(what + " '" + path + "' may be read by other users: chmod 600 '" + path + "'");
}

std::string read_secret_file(const std::string& path) {
    require_owner_only(path, "the secret file");
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw std::runtime_error("cannot read the secret file '" + path + "'");
    std::string secret = text.str();
    if (!secret.empty() && secret.back() == '\n') secret.pop_back();
    if (secret.empty()) throw std::runtime_error("the secret file '" + path + "' is empty");
    return secret;
}

}  // namespace hlacore::auth
