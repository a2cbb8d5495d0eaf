// The client's side of the hlacore session, for whatever carries its frames (the Client, rtig --status): the
// answer to the Welcome's challenge when the gateway has a secret (rti/auth.hpp), and
// the verdict on the gateway's Authenticated. The gateway's side is server/session.cpp.
#pragma once

#include <string>

#include "rti/wire/messages.hpp"

namespace hlacore::net {

// The proof of `secret` over the Welcome's challenge; AuthenticationFailed when no secret was given.
wire::Authenticate answer_challenge(const std::string& address, const std::string& secret, const std::string& challenge);

// AuthenticationFailed, saying why, unless the gateway accepted the proof.
void check_authenticated(const std::string& address, const wire::Authenticated& answer);

}  // namespace hlacore::net
