// The gateway's options (GatewayOptions) as a table (rti/options.hpp): rtig's command line and usage, and
// hlacore.Gateway's keywords and docs, are made from it.
#pragma once

#include "rti/options.hpp"
#include "rti/server/gateway.hpp"

namespace hlacore {

const Options<GatewayOptions>& gateway_options();

// What no single option can check (certificate and key go together): "" or why not, naming the options as
// `given` spells them.
std::string gateway_options_conflict(const GatewayOptions& options, Given given);

}  // namespace hlacore
