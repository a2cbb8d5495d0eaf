// The client's side of the hlacore session (session.hpp).
#include "rti/net/session.hpp"

#include "rti/auth.hpp"
#include "rti/exceptions.hpp"

namespace hlacore::net {

wire::Authenticate answer_challenge(const std::string& address, const std::string& secret, const std::string& challenge) {
    if (secret.empty())
        raise(ErrorCode::AuthenticationFailed,
              "the gateway at " + address + " asks for a secret and none was given (RTIAmbassador(secret_file=...), "
              "$HLACORE_SECRET_FILE; docs/networking.md)");
    return wire::Authenticate{auth::proof(secret, challenge)};
}

void check_authenticated(const std::string& address, const wire::Authenticated& answer) {
    if (!answer.accepted)
        raise(ErrorCode::AuthenticationFailed,
              "the gateway at " + address + " refused this client: " + answer.reason + " (docs/networking.md)");
}

}  // namespace hlacore::net
