// rtig: the hlacore gateway as a standalone server.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <thread>

#include "fedpro/server.hpp"
#include "rti/net/listen.hpp"
#include "rti/net/status_query.hpp"
#include "rti/server/options.hpp"

namespace {

hlacore::Gateway* g_gateway = nullptr;
// With the Federate Protocol's door the gateway serves on a thread, and the main thread ends the door's sessions
// (their federates resign) before it stops the gateway.
volatile std::sig_atomic_t g_stop = 0;
bool g_door = false;

void on_signal(int) {
    g_stop = 1;
    if (g_gateway && !g_door) g_gateway->stop();
}

// rtig's own options, beside the gateway's: the policy beyond loopback and how --status connects.
struct Command {
    bool no_secret = false;
    // --status over TLS: --tls, --tls-ca FILE, else $HLACORE_TLS as the clients read it (1: the system's CA
    // store, a path: that CA file, unset, empty or 0: no TLS).
    bool status_tls = false;
    std::string status_tls_ca;
};

const hlacore::Options<Command>& command_options() {
    using Text = const std::string&;
    static const hlacore::Options<Command> table = {
        {"--no-secret", nullptr, nullptr, nullptr, false, [](Command& c, Text) { c.no_secret = true; }, nullptr,
         "listen beyond loopback without a secret: anyone who reaches the port may read, join, and destroy "
         "federations"},
        {"--tls", nullptr, nullptr, nullptr, false,
         [](Command& c, Text) {
             c.status_tls = true;
             c.status_tls_ca.clear();
         },
         nullptr, "with --status: TLS, the gateway's certificate verified against the system's CA store (also $HLACORE_TLS=1)"},
        {"--tls-ca", nullptr, nullptr, "FILE", false,
         [](Command& c, Text t) {
             c.status_tls = true;
             c.status_tls_ca = hlacore::not_empty(t);
         },
         nullptr,
         "with --status: TLS, trusting the CA or self-signed certificate in FILE (also $HLACORE_TLS=FILE)"},
    };
    return table;
}

int usage(int status) {
    std::vector<std::string> synopsis = hlacore::synopsis(hlacore::gateway_options());
    synopsis.emplace_back("[--no-secret]");
    std::string text = "usage: rtig " + hlacore::wrap(synopsis, 98, 11, 110) +
                       "\n       rtig [--secret-file FILE] [--tls | --tls-ca FILE] --status [HOST:PORT]\n" +
                       hlacore::help_entries(hlacore::gateway_options()) + hlacore::help_entries(command_options()) +
                       hlacore::help_entry("--status [HOST:PORT]",
                                           "print the state of a running rtig (default 127.0.0.1:60400) as JSON: per "
                                           "federation each federate's time, lookahead, regulating/constrained, pending "
                                           "request, queued messages, LBTS (python -m hlacore.status is a table); "
                                           "--secret-file is then the secret to show",
                                           "");
    std::fputs(text.c_str(), status ? stderr : stdout);
    return status;
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
    Command command;
    if (const char* env = std::getenv("HLACORE_TLS"); env && *env && std::string(env) != "0") {
        command.status_tls = true;
        if (std::string(env) != "1") command.status_tls_ca = env;
    }
    for (int i = 1; i < argc; ++i) {
        const std::string arg = std::strcmp(argv[i], "-v") == 0 ? "--verbose" : argv[i];
        if (arg == "--help" || arg == "-h") return usage(0);
        if (arg == "--status") {
            if (i + 2 < argc) {
                std::fprintf(stderr, "rtig: --status takes at most one HOST:PORT\n");
                return usage(2);
            }
            return print_status(i + 1 < argc ? argv[i + 1] : "127.0.0.1:60400", options.secret, command.status_tls,
                                command.status_tls_ca);
        }
        // The option's value: the next argument, "1" for a switch.
        auto value = [&](const char* metavar) -> std::string {
            if (!metavar) return "1";
            if (i + 1 >= argc) {
                std::fprintf(stderr, "rtig: %s needs a value\n", arg.c_str());
                std::exit(usage(2));
            }
            return argv[++i];
        };
        try {
            using hlacore::Given;
            if (const auto* o = hlacore::find_option(hlacore::gateway_options(), arg, Given::Flag)) {
                hlacore::apply(options, *o, Given::Flag, value(o->metavar));
            } else if (const auto* c = hlacore::find_option(command_options(), arg, Given::Flag)) {
                hlacore::apply(command, *c, Given::Flag, value(c->metavar));
            } else {
                std::fprintf(stderr, "rtig: unknown argument '%s'\n", arg.c_str());
                return usage(2);
            }
        } catch (const hlacore::OptionError& e) {
            std::fprintf(stderr, "rtig: %s\n", e.what());
            return usage(2);
        } catch (const std::exception& e) {  // a secret file that cannot be used
            std::fprintf(stderr, "rtig: %s\n", e.what());
            return 2;
        }
    }
    if (const std::string conflict = hlacore::gateway_options_conflict(options, hlacore::Given::Flag); !conflict.empty()) {
        std::fprintf(stderr, "rtig: %s\n", conflict.c_str());
        return usage(2);
    }
    if (options.secret.empty() && !command.no_secret && !hlacore::net::is_loopback(options.host)) {
        std::fprintf(stderr,
                     "rtig: listening on %s, beyond this machine, needs --secret-file FILE (docs/networking.md), or\n"
                     "      --no-secret to let in anyone who reaches the port\n",
                     options.host.c_str());
        return 2;
    }
    try {
        // The door's federates reach the gateway through a Unix socket: the one asked for, else one of their own.
        const std::string asked_unix = options.unix_path;
        std::unique_ptr<hlacore::fedpro::PrivateSocket> door_socket;
        if (!options.fedpro.empty() && options.unix_path.empty()) {
            door_socket = std::make_unique<hlacore::fedpro::PrivateSocket>();
            options.unix_path = door_socket->path();
        }
        hlacore::Gateway gateway(options);
        g_gateway = &gateway;
        struct sigaction sa {};
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(SIGINT, &sa, nullptr);
        sigaction(SIGTERM, &sa, nullptr);
        std::signal(SIGPIPE, SIG_IGN);
        std::unique_ptr<hlacore::fedpro::Server> fedpro;
        if (!options.fedpro.empty())
            fedpro = hlacore::fedpro::open_door(options, "unix:" + options.unix_path, command.no_secret);
        std::string also = asked_unix.empty() ? "" : " and unix:" + asked_unix;
        if (fedpro) {
            gateway.add_status_section([door = fedpro.get()] { return door->status_json(); });
            also += ", the Federate Protocol on " + fedpro->address();
            if (fedpro->transport() != hlacore::fedpro::Transport::Tcp) also += std::string(" (") + name(fedpro->transport()) + ")";
        }
        std::printf("rtig listening on %s:%u%s\n", gateway.host().c_str(), static_cast<unsigned>(gateway.port()), also.c_str());
        std::fflush(stdout);
        if (fedpro) {
            g_door = true;
            std::atomic<bool> served{false};
            std::thread serving([&] {
                gateway.run();
                served = true;
            });
            while (!g_stop && !served) std::this_thread::sleep_for(std::chrono::milliseconds(100));
            fedpro->stop();
            gateway.stop();
            serving.join();
        } else {
            gateway.run();
        }
        g_gateway = nullptr;
        std::fprintf(stderr, "rtig: stopped\n");
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rtig: %s\n", e.what());
        return 1;
    }
}
