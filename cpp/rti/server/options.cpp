// The gateway's options, one row each: how rtig and hlacore.Gateway spell it, its check and its help.
#include "rti/server/options.hpp"

#include "rti/auth.hpp"

namespace hlacore {
namespace {

using O = GatewayOptions;
using Text = const std::string&;

std::string text(double v) {
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s;
}

}  // namespace

const Options<GatewayOptions>& gateway_options() {
    static const Options<GatewayOptions> table = {
        {"--host", "host", nullptr, "HOST", false, [](O& o, Text t) { o.host = not_empty(t, "an address"); },
         [](const O& o) { return o.host; }, "address to listen on"},
        {"--port", "port", nullptr, "PORT", false,
         [](O& o, Text t) { o.port = static_cast<std::uint16_t>(whole_number(t, 0, 65535, "")); },
         [](const O& o) { return std::to_string(o.port); }, "TCP port, 0 picks a free one"},
        {"--unix", "unix", nullptr, "PATH", false, [](O& o, Text t) { o.unix_path = not_empty(t, "a path"); },
         [](const O& o) { return o.unix_path; },
         "also listen on a Unix socket at PATH, for federates on this host (address unix:PATH): less CPU per "
         "message than TCP, no datagrams, no TLS; the file is its owner's only and is removed when the gateway "
         "ends (docs/networking.md)"},
        {"--fom-path", "fom_path", nullptr, "DIR", true, [](O& o, Text t) { o.fom_path.push_back(not_empty(t, "a directory")); },
         nullptr, "where to look for FED files a federate could not read itself"},
        {"--frame-timeout", "frame_timeout", nullptr, "S", false,
         [](O& o, Text t) { o.partial_frame_timeout_s = number_above(t, 0, false, "seconds"); },
         [](const O& o) { return text(o.partial_frame_timeout_s); },
         "drop a client whose frame stays incomplete S seconds"},
        {"--client-budget", "client_budget", nullptr, "B", false,
         [](O& o, Text t) { o.client_budget = whole_number(t, kMinClientBudget, std::uint64_t{1} << 48, "bytes"); },
         [](const O& o) { return std::to_string(o.client_budget); },
         "bytes held for one client (its output queue, the messages time management keeps for it) above which "
         "the clients sending to it are no longer read until it takes half of them (docs/robustness.md)"},
        {"--stall-timeout", "stall_timeout", nullptr, "S", false,
         [](O& o, Text t) { o.stall_timeout_s = number_above(t, 0, true, "seconds"); },
         [](const O& o) { return text(o.stall_timeout_s); },
         "drop a client over its budget that takes nothing for S seconds (0: never)"},
        {"--max-frame", "max_frame", nullptr, "B", false,
         [](O& o, Text t) { o.max_frame_bytes = static_cast<std::uint32_t>(whole_number(t, kMinMaxFrame, kMaxMaxFrame, "bytes")); },
         [](const O& o) { return std::to_string(o.max_frame_bytes); },
         "the largest message in bytes, both directions: clients learn it when they connect and refuse larger "
         "values at the call (ValueLengthExceeded)"},
        {"--max-datagram", "max_datagram", nullptr, "B", false,
         [](O& o, Text t) {
             o.max_datagram = t == "0" ? 0 : static_cast<std::uint32_t>(whole_number(t, kMinMaxDatagram, wire::kMaxDatagramLimit, "bytes"));
         },
         [](const O& o) { return std::to_string(o.max_datagram); },
         "best effort over UDP on the same port: the largest datagram either side sends (0: none, everything "
         "over TCP); larger best-effort messages go over TCP (docs/networking.md)"},
        {"--secret-file", "secret_file", nullptr, "FILE", false,
         [](O& o, Text t) { o.secret = auth::read_secret_file(t); }, nullptr,
         "clients must prove they know the secret in FILE (readable by its owner only) before anything else; "
         "rtig requires one when HOST is not a loopback address (docs/networking.md)"},
        {"--federation-secret", "federation_secrets", nullptr, "NAME=FILE", true,
         [](O& o, Text t) {
             const auto equals = t.find('=');
             if (equals == 0 || equals == std::string::npos || equals + 1 == t.size()) throw OptionError("takes NAME=FILE");
             o.federation_secrets[t.substr(0, equals)] = auth::read_secret_file(t.substr(equals + 1));
         },
         nullptr,
         "creating, joining or destroying federation NAME needs a proof of the secret in FILE, whatever the "
         "client's connection secret (docs/networking.md)"},
        {"--tls-cert", "tls_cert", nullptr, "FILE", false, [](O& o, Text t) { o.tls_cert = not_empty(t, "a file"); },
         [](const O& o) { return o.tls_cert; },
         "every connection is TLS (1.2 at least, 1.3 preferred) with the certificate (chain) in this PEM file "
         "and the key of --tls-key; clients without TLS are refused. No datagrams are then offered: best-effort "
         "messages go over the encrypted TCP stream (docs/networking.md)"},
        {"--tls-key", "tls_key", nullptr, "FILE", false, [](O& o, Text t) { o.tls_key = not_empty(t, "a file"); },
         [](const O& o) { return o.tls_key; }, "the private key of --tls-cert, a PEM file readable by its owner only"},
        {"--save-dir", "save_dir", nullptr, "DIR", false, [](O& o, Text t) { o.save_dir = not_empty(t, "a directory"); },
         [](const O& o) { return o.save_dir; },
         "write federation saves to DIR (created if missing) and restore from there, also after a restart; "
         "without it saves live in memory only (docs/save-restore.md)"},
        {"--trace", "trace", nullptr, "FILE", false, [](O& o, Text t) { o.trace_path = not_empty(t, "a file"); },
         [](const O& o) { return o.trace_path; },
         "write when each update/interaction arrived and each reflection of it left, on the host's monotonic "
         "clock, as CSV (docs/robot.md, delay decomposition)"},
        {"--record", "record", nullptr, "FILE", false, [](O& o, Text t) { o.record_path = not_empty(t, "a file"); },
         [](const O& o) { return o.record_path; },
         "record every federation into FILE (MCAP): the FOM, joins, registrations, updates, interactions, "
         "requests and callbacks with their times, for python -m hlacore.replay and Foxglove; complete once the "
         "gateway stops (docs/record-replay.md)"},
        {"--busy-poll", "busy_poll_us", nullptr, "US", false,
         [](O& o, Text t) { o.busy_poll_us = busy_poll_micros(t); },
         [](const O& o) { return std::to_string(o.busy_poll_us); },
         "before each wait for clients sleeps, poll for up to US µs without sleeping (0: off): a message that "
         "comes meanwhile costs no wake-up, at the price of a busy core (docs/performance.md, busy polling)"},
        {"--verbose", "verbose", nullptr, nullptr, false, [](O& o, Text t) { o.verbose = yes_or_no(t); },
         [](const O& o) { return std::string(o.verbose ? "true" : "false"); }, "log connections, joins and federations to stderr"},
    };
    return table;
}

std::string gateway_options_conflict(const GatewayOptions& options, Given given) {
    if (options.tls_cert.empty() != options.tls_key.empty())
        return given == Given::Flag ? "--tls-cert and --tls-key go together" : "tls_cert and tls_key go together";
    return "";
}

}  // namespace hlacore
