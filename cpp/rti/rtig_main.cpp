// rtig: the hlacore gateway as a standalone server.
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include "rti/auth.hpp"
#include "rti/busy_poll.hpp"
#include "rti/net/status_query.hpp"
#include "rti/server/gateway.hpp"

namespace {

hlacore::Gateway* g_gateway = nullptr;

void on_signal(int) {
    if (g_gateway) g_gateway->stop();
}

int usage(int status) {
    std::fprintf(status ? stderr : stdout,
                 "usage: rtig [--host HOST] [--port PORT] [--unix PATH] [--fom-path DIR]... [--frame-timeout S]\n"
                 "            [--client-budget B] [--stall-timeout S] [--max-frame B] [--max-datagram B]\n"
                 "            [--secret-file FILE | --no-secret] [--federation-secret NAME=FILE]...\n"
                 "            [--tls-cert FILE --tls-key FILE] [--save-dir DIR] [--trace FILE] [--record FILE]\n"
                 "            [--busy-poll US] [--verbose]\n"
                 "       rtig [--secret-file FILE] [--tls | --tls-ca FILE] --status [HOST:PORT]\n"
                 "  --host HOST        address to listen on (default 127.0.0.1)\n"
                 "  --port PORT        TCP port, 0 picks a free one (default 60400)\n"
                 "  --unix PATH        also listen on a Unix socket at PATH, for federates on this host (address\n"
                 "                     unix:PATH): less CPU per message than TCP, no datagrams, no TLS; the file\n"
                 "                     is its owner's only and is removed when rtig ends (docs/networking.md)\n"
                 "  --fom-path DIR     where to look for FED files a federate could not read itself\n"
                 "  --frame-timeout S  drop a client whose frame stays incomplete S seconds (default 10)\n"
                 "  --client-budget B  bytes held for one client (its output queue, the messages time management\n"
                 "                     keeps for it) above which the clients sending to it are no longer read\n"
                 "                     until it takes half of them (default 67108864, at least 65536)\n"
                 "  --stall-timeout S  drop a client over its budget that takes nothing for S seconds (default 30,\n"
                 "                     0: never)\n"
                 "  --max-frame B      the largest message in bytes, both directions (default 67108864, 65536 to\n"
                 "                     1073741824): clients learn it when they connect and refuse larger values\n"
                 "                     at the call (ValueLengthExceeded)\n"
                 "  --max-datagram B   best effort over UDP on the same port: the largest datagram (default 1400,\n"
                 "                     256 to 65507; 0: none, everything over TCP); larger best-effort messages go\n"
                 "                     over TCP (docs/networking.md)\n"
                 "  --secret-file FILE clients must prove they know the secret in FILE (readable by its owner only)\n"
                 "                     before anything else; required when HOST is not a loopback address\n"
                 "                     (docs/networking.md); with --status: the secret to show\n"
                 "  --no-secret        listen beyond loopback without a secret: anyone who reaches the port may\n"
                 "                     read, join, and destroy federations\n"
                 "  --federation-secret NAME=FILE  creating, joining or destroying federation NAME needs a proof of\n"
                 "                     the secret in FILE, whatever the client's connection secret (docs/networking.md)\n"
                 "  --tls-cert FILE    every connection is TLS (1.2 at least, 1.3 preferred) with the certificate\n"
                 "  --tls-key FILE     (chain) and the private key in these PEM files (the key readable by its owner\n"
                 "                     only); clients without TLS are refused. No datagrams are then offered:\n"
                 "                     best-effort messages go over the encrypted TCP stream (docs/networking.md)\n"
                 "  --tls              with --status: TLS, the gateway's certificate verified against the system's\n"
                 "                     CA store (also $HLACORE_TLS=1)\n"
                 "  --tls-ca FILE      with --status: TLS, trusting the CA or self-signed certificate in FILE (also\n"
                 "                     $HLACORE_TLS=FILE)\n"
                 "  --save-dir DIR     write federation saves to DIR (created if missing) and restore from\n"
                 "                     there, also after a restart; without it saves live in memory only\n"
                 "  --trace FILE       write when each update/interaction arrived and each reflection of it left,\n"
                 "                     on the host's monotonic clock, as CSV (docs/robot.md, delay decomposition)\n"
                 "  --record FILE      record every federation into FILE (MCAP): the FOM, joins, registrations,\n"
                 "                     updates, interactions, requests and callbacks with their times, for\n"
                 "                     python -m hlacore.replay and Foxglove (docs/record-replay.md)\n"
                 "  --busy-poll US     before each wait for clients sleeps, poll for up to US µs without sleeping\n"
                 "                     (0 to 100000; default 0: off): a message that comes meanwhile costs no\n"
                 "                     wake-up, at the price of a busy core (docs/performance.md, busy polling)\n"
                 "  --verbose          log connections, joins and federations to stderr\n"
                 "  --status           print the state of a running rtig (default 127.0.0.1:60400) as JSON:\n"
                 "                     per federation each federate's time, lookahead, regulating/constrained,\n"
                 "                     pending request, queued messages, LBTS (`python -m hlacore.status` is a table)\n");
    return status;
}

bool is_loopback(const std::string& host) {
    return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

// Connects to a running gateway and prints its status report.
int print_status(const std::string& address, const std::string& secret, bool tls, const std::string& tls_ca) {
    const auto colon = address.rfind(':');
    const std::string host = colon == std::string::npos ? address : address.substr(0, colon);
    const std::string port_text = colon == std::string::npos ? "60400" : address.substr(colon + 1);
    char* end = nullptr;
    const long port = std::strtol(port_text.c_str(), &end, 10);
    if (port_text.empty() || *end != '\0' || port <= 0 || port > 65535) {
        std::fprintf(stderr, "rtig: invalid address '%s' (HOST:PORT expected)\n", address.c_str());
        return 2;
    }
    try {
        hlacore::net::StatusQueryOptions query;
        query.secret = secret;
        query.tls = tls;
        query.tls_ca = tls_ca;
        std::printf("%s\n", hlacore::net::query_status(host.empty() ? "127.0.0.1" : host, static_cast<std::uint16_t>(port),
                                                       query).c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rtig: %s\n", e.what());
        return 1;
    }
}

}  // namespace

int main(int argc, char** argv) {
    hlacore::GatewayOptions options;
    bool no_secret = false;
    // --status over TLS: --tls, --tls-ca FILE, else $HLACORE_TLS as the Python client reads it (1: the
    // system's CA store, a path: that CA file, unset, empty or 0: no TLS).
    bool status_tls = false;
    std::string status_tls_ca;
    if (const char* env = std::getenv("HLACORE_TLS"); env && *env && std::string(env) != "0") {
        status_tls = true;
        if (std::string(env) != "1") status_tls_ca = env;
    }
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&](const char* name) -> const char* {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "rtig: %s needs a value\n", name);
                std::exit(usage(2));
            }
            return argv[++i];
        };
        // The option's value as a number above `low` (or equal to it when `low_ok`); exits on anything else.
        auto number = [&](const char* name, double low, bool low_ok) {
            const char* text = value(name);
            char* end = nullptr;
            const double v = std::strtod(text, &end);
            if (*text == '\0' || *end != '\0' || !(v > low || (low_ok && v == low)) || !(v < 1e15)) {
                std::fprintf(stderr, "rtig: invalid %s '%s'\n", name, text);
                std::exit(usage(2));
            }
            return v;
        };
        if (arg == "--host") {
            options.host = value("--host");
        } else if (arg == "--port") {
            const char* text = value("--port");
            char* end = nullptr;
            const long port = std::strtol(text, &end, 10);
            if (*text == '\0' || *end != '\0' || port < 0 || port > 65535) {
                std::fprintf(stderr, "rtig: invalid port '%s'\n", text);
                return usage(2);
            }
            options.port = static_cast<std::uint16_t>(port);
        } else if (arg == "--unix") {
            options.unix_path = value("--unix");
        } else if (arg == "--fom-path") {
            options.fom_path.emplace_back(value("--fom-path"));
        } else if (arg == "--frame-timeout") {
            options.partial_frame_timeout_s = number("--frame-timeout", 0, false);
        } else if (arg == "--client-budget") {
            options.client_budget = static_cast<std::size_t>(number("--client-budget", hlacore::kMinClientBudget, true));
        } else if (arg == "--stall-timeout") {
            options.stall_timeout_s = number("--stall-timeout", 0, true);
        } else if (arg == "--max-frame") {
            const double v = number("--max-frame", hlacore::kMinMaxFrame, true);
            if (v > hlacore::kMaxMaxFrame) {
                std::fprintf(stderr, "rtig: invalid --max-frame '%s'\n", argv[i]);
                return usage(2);
            }
            options.max_frame_bytes = static_cast<std::uint32_t>(v);
        } else if (arg == "--busy-poll") {
            const double v = number("--busy-poll", 0, true);
            if (v > hlacore::kMaxBusyPollUs || v != static_cast<std::uint32_t>(v)) {
                std::fprintf(stderr, "rtig: invalid --busy-poll '%s' (whole µs, 0 to %u)\n", argv[i],
                             static_cast<unsigned>(hlacore::kMaxBusyPollUs));
                return usage(2);
            }
            options.busy_poll_us = static_cast<std::uint32_t>(v);
        } else if (arg == "--max-datagram") {
            const double v = number("--max-datagram", 0, true);
            if ((v != 0 && v < hlacore::kMinMaxDatagram) || v > hlacore::wire::kMaxDatagramLimit || v != static_cast<std::uint32_t>(v)) {
                std::fprintf(stderr, "rtig: invalid --max-datagram '%s'\n", argv[i]);
                return usage(2);
            }
            options.max_datagram = static_cast<std::uint32_t>(v);
        } else if (arg == "--secret-file") {
            const char* path = value("--secret-file");
            try {
                options.secret = hlacore::auth::read_secret_file(path);
            } catch (const std::exception& e) {
                std::fprintf(stderr, "rtig: %s\n", e.what());
                return 2;
            }
        } else if (arg == "--federation-secret") {
            const std::string text = value("--federation-secret");
            const auto equals = text.find('=');
            if (equals == 0 || equals == std::string::npos || equals + 1 == text.size()) {
                std::fprintf(stderr, "rtig: --federation-secret takes NAME=FILE, not '%s'\n", text.c_str());
                return usage(2);
            }
            try {
                options.federation_secrets[text.substr(0, equals)] = hlacore::auth::read_secret_file(text.substr(equals + 1));
            } catch (const std::exception& e) {
                std::fprintf(stderr, "rtig: %s\n", e.what());
                return 2;
            }
        } else if (arg == "--tls-cert") {
            options.tls_cert = value("--tls-cert");
        } else if (arg == "--tls-key") {
            options.tls_key = value("--tls-key");
        } else if (arg == "--tls") {
            status_tls = true;
            status_tls_ca.clear();
        } else if (arg == "--tls-ca") {
            status_tls = true;
            status_tls_ca = value("--tls-ca");
        } else if (arg == "--no-secret") {
            no_secret = true;
        } else if (arg == "--save-dir") {
            options.save_dir = value("--save-dir");
            if (options.save_dir.empty()) {
                std::fprintf(stderr, "rtig: --save-dir needs a directory\n");
                return usage(2);
            }
        } else if (arg == "--trace") {
            options.trace_path = value("--trace");
        } else if (arg == "--record") {
            options.record_path = value("--record");
            if (options.record_path.empty()) {
                std::fprintf(stderr, "rtig: --record needs a file\n");
                return usage(2);
            }
        } else if (arg == "--verbose" || arg == "-v") {
            options.verbose = true;
        } else if (arg == "--status") {
            if (i + 2 < argc) {
                std::fprintf(stderr, "rtig: --status takes at most one HOST:PORT\n");
                return usage(2);
            }
            return print_status(i + 1 < argc ? argv[i + 1] : "127.0.0.1:60400", options.secret, status_tls, status_tls_ca);
        } else if (arg == "--help" || arg == "-h") {
            return usage(0);
        } else {
            std::fprintf(stderr, "rtig: unknown argument '%s'\n", arg.c_str());
            return usage(2);
        }
    }
    if (options.tls_cert.empty() != options.tls_key.empty()) {
        std::fprintf(stderr, "rtig: --tls-cert and --tls-key go together\n");
        return usage(2);
    }
    if (options.secret.empty() && !no_secret && !is_loopback(options.host)) {
        std::fprintf(stderr,
                     "rtig: listening on %s, beyond this machine, needs --secret-file FILE (docs/networking.md), or\n"
                     "      --no-secret to let in anyone who reaches the port\n",
                     options.host.c_str());
        return 2;
    }
    try {
        hlacore::Gateway gateway(options);
        g_gateway = &gateway;
        struct sigaction sa {};
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(SIGINT, &sa, nullptr);
        sigaction(SIGTERM, &sa, nullptr);
        std::signal(SIGPIPE, SIG_IGN);
        std::printf("rtig listening on %s:%u%s\n", gateway.host().c_str(), static_cast<unsigned>(gateway.port()),
                    options.unix_path.empty() ? "" : (" and unix:" + options.unix_path).c_str());
        std::fflush(stdout);
        gateway.run();
        g_gateway = nullptr;
        std::fprintf(stderr, "rtig: stopped\n");
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rtig: %s\n", e.what());
        return 1;
    }
}
