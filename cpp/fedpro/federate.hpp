// The HLA side of a Federate Protocol session: an IEEE 1516-2010 federate of hlacore's own (the RTIambassador of
// cpp/rti1516e, connected to the gateway with HLA_IMMEDIATE callbacks) that makes each call the session's federate
// sends (a CallRequest into a CallResponse: calls.cpp) and turns each callback into a CallbackRequest for it
// (callbacks.cpp). Handles travel as their 1516-2010 encodings, times as the federation's time type encodes them.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "fedpro/session.hpp"

namespace hlacore::fedpro {

// `gateway`: the local settings designator its ambassador connects with (address=..., secret_file=...);
// `password`: "" or what connect's credentials must hold (HLAplainTextPassword; Unauthorized otherwise);
// `send_callback` gets each CallbackRequest's bytes, on the ambassador's callback thread.
std::unique_ptr<Federate> make_federate(std::string const& gateway, std::string const& password,
                                        std::function<void(std::string_view)> send_callback);

}  // namespace hlacore::fedpro
