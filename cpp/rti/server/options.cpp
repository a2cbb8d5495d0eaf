// The gateway's options, one row each: how rtig and hlacore.Gateway spell it, its check and its help.
#include "rti/server/options.hpp"

#include "rti/auth.hpp"

namespace hlacore {
namespace {

using O = GatewayOptions;
using Text = const std::string&;

// A row whose value is a non-empty text kept as it is.
template <std::string GatewayOptions::*member>
Option<GatewayOptions> text_option(const char* flag, const char* keyword, const char* metavar, const char* help) {
    return {flag, keyword, nullptr, metavar, false, [](O& o, Text t) { o.*member = not_empty(t); },
            [](const O& o) { return o.*member; }, help};
}

std::string text(double v) {
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s;
}

}  // namespace

const Options<GatewayOptions>& gateway_options() {
    static const Options<GatewayOptions> table = {
        text_option<&O::host>("--host", "host", "HOST", "address to listen on"),
        {"--port", "port", nullptr, "PORT", false,
         [](O& o, Text t) { o.port = static_cast<std::uint16_t>(whole_number(t, 0, 65535, "")); },
         [](const O& o) { return std::to_string(o.port); }, "TCP port, 0 picks a free one"},
        text_option<&O::unix_path>("--unix", "unix", "PATH",
         "also listen on a Unix socket at PATH, for federates on this host (address unix:PATH): less CPU per "
         "message than TCP, no datagrams, no TLS; the file is its owner's only and is removed when the gateway "
         "ends (docs/networking.md)"),
        {"--fom-path", "fom_path", nullptr, "DIR", true, [](O& o, Text t) { o.fom_path.push_back(not_empty(t)); },
         nullptr, "where to look for FED files a federate could not read itself"},
        {"--frame-timeout", "frame_timeout", nullptr, "S", false,
         [](O& o, Text t) { o.partial_frame_timeout_s = number_above(t, 0, false, "seconds"); },
         [](const O& o) { return text(o.partial_frame_timeout_s); },
         "drop a client whose frame stays incomplete S seconds"},
        {"--client-budget", "client_budget", nullptr, "B", false,
         [](O& o, Text t) { o.client_budget = whole_number(t, kMinClientBudget, std::uint64_t{1} << 48, "bytes"); },
         [](const O& o) { return std::to_string(o.client_budget); },
         "bytes held in memory for one client (its output queue, the messages time management keeps for it): "
         "beyond it its output is spilled to disk (--spill-dir), or, for what time management keeps or without "
         "spilling, the clients sending to it are no longer read until it takes half of them (docs/robustness.md)"},
        {"--stall-timeout", "stall_timeout", nullptr, "S", false,
         [](O& o, Text t) { o.stall_timeout_s = number_above(t, 0, true, "seconds"); },
         [](const O& o) { return text(o.stall_timeout_s); },
         "drop a client over its budget in memory that takes nothing for S seconds (0: never); one that spills "
         "is dropped only when its peer is gone (TCP keepalive) or the disk budget is spent"},
        text_option<&O::spill_dir>("--spill-dir", "spill_dir", "DIR",
         "where what a client does not read beyond its budget (a federate paused in a debugger) is spilled, in "
         "unnamed files that never outlive the gateway ($TMPDIR, else /tmp, by default; docs/robustness.md)"),
        {"--disk-budget", "disk_budget", nullptr, "B", false,
         [](O& o, Text t) { o.disk_budget = whole_number(t, 0, std::uint64_t{1} << 50, "bytes"); },
         [](const O& o) { return std::to_string(o.disk_budget); },
         "bytes all spill files may take together: a client whose backlog would go beyond is dropped, saying so "
         "(0: no spilling; the clients sending to one over its budget are then no longer read until it takes "
         "half of it)"},
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
         [](O& o, Text t) {
             o.secret = auth::read_secret_file(t);
             o.secret_file = t;
         },
         nullptr,
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
        text_option<&O::tls_cert>("--tls-cert", "tls_cert", "FILE",
         "every connection is TLS (1.2 at least, 1.3 preferred) with the certificate (chain) in this PEM file "
         "and the key of --tls-key; clients without TLS are refused. No datagrams are then offered: best-effort "
         "messages go over the encrypted TCP stream (docs/networking.md)"),
        text_option<&O::tls_key>("--tls-key", "tls_key", "FILE", "the private key of --tls-cert, a PEM file readable by its owner only"),
        {"--time-semantics", "time_semantics", nullptr, "exact|certi", false,
         [](O& o, Text t) { o.time_semantics = time_semantics(t); },
         [](const O& o) { return std::string(name_of(o.time_semantics)); },
         "the time rules of a federation whose creator asks for none: exact, HLA 1.3's to the last double, or "
         "certi, CERTI's, where a federate enabling regulation may start at a zero-lookahead TAR grant's time "
         "(docs/time-management.md); federations created through hlacore-rtia ask for certi"},
        text_option<&O::save_dir>("--save-dir", "save_dir", "DIR",
         "write federation saves to DIR (created if missing) and restore from there, also after a restart; "
         "without it saves live in memory only (docs/save-restore.md)"),
        text_option<&O::trace_path>("--trace", "trace", "FILE",
         "write when each update/interaction arrived and each reflection of it left, on the host's monotonic "
         "clock, as CSV (docs/robot.md, delay decomposition)"),
        text_option<&O::record_path>("--record", "record", "FILE",
         "record every federation into FILE (MCAP): the FOM, joins, registrations, updates, interactions, "
         "requests and callbacks with their times, for python -m hlacore.replay and Foxglove; complete once the "
         "gateway stops (docs/record-replay.md)"),
        {"--busy-poll", "busy_poll_us", nullptr, "US", false,
         [](O& o, Text t) { o.busy_poll_us = busy_poll_micros(t); },
         [](const O& o) { return std::to_string(o.busy_poll_us); },
         "before each wait for clients sleeps, poll for up to US µs without sleeping (0: off): a message that "
         "comes meanwhile costs no wake-up, at the price of a busy core (docs/performance.md, busy polling)"},
        text_option<&O::fedpro>("--fedpro", "fedpro", "[PROTOCOL://]HOST[:PORT]",
         "also serve the HLA 4 Federate Protocol (IEEE 1516.1-2025) on HOST:PORT over PROTOCOL: tcp (the default; "
         "port 15164), tls (15165), websocket (80) or websocketsecure (443), the last two also ws and wss; TLS with "
         "--tls-cert and --tls-key. Federates in any language join through protobuf calls and callbacks, and resume "
         "after a dropped connection. With --secret-file, connect needs the secret as HLAplainTextPassword "
         "credentials; beyond loopback the door needs it, over tls or websocketsecure (or --no-secret). The door's "
         "federates reach this gateway through a Unix socket of their own (docs/fedpro.md)"),
        {"--fedpro-resume-timeout", "fedpro_resume_timeout", nullptr, "S", false,
         [](O& o, Text t) { o.fedpro_resume_timeout_s = number_above(t, 0, false, "seconds"); },
         [](const O& o) { return text(o.fedpro_resume_timeout_s); },
         "a Federate Protocol session whose connection dropped and is not resumed within S seconds ends: its "
         "federate resigns"},
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
