// The client's options, one row each: its keyword, its environment variable, its check and its help.
#include "rti/client/options.hpp"

#include <cstdlib>

#include "rti/auth.hpp"
#include "rti/exceptions.hpp"
#include "rti/unix_socket.hpp"

namespace hlacore {
namespace {

using S = ClientSettings;
using Text = const std::string&;

void set_address(S& s, Text t) {
    if (unix_socket::is_unix(t)) {
        if (t == "unix:") throw OptionError("names no socket: unix:PATH");
        s.host = t;
        s.port = 0;
        return;
    }
    const auto colon = t.rfind(':');
    if (colon == std::string::npos) throw OptionError("is not HOST:PORT (or unix:PATH)");
    std::string host = t.substr(0, colon);
    if (host.size() >= 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);
    try {
        s.port = static_cast<std::uint16_t>(whole_number(t.substr(colon + 1), 0, 65535, ""));
    } catch (const OptionError&) {
        throw OptionError("is not HOST:PORT (or unix:PATH)");
    }
    s.host = host.empty() ? "127.0.0.1" : host;
}

// A secret file's content, "" for none; AuthenticationFailed saying why when it cannot be used.
std::string secret(Text path) {
    if (path.empty()) return "";
    try {
        return auth::read_secret_file(path);
    } catch (const std::exception& e) {
        throw RtiError(ErrorCode::AuthenticationFailed, e.what());
    }
}

const char* env(const char* name) {
    const char* value = name ? std::getenv(name) : nullptr;
    return value && *value ? value : nullptr;
}

}  // namespace

const Options<ClientSettings>& client_options() {
    static const Options<ClientSettings> table = {
        {nullptr, "address", "HLACORE_RTIG", "HOST:PORT", false, set_address,
         [](const S& s) { return s.port ? s.host + ":" + std::to_string(s.port) : s.host; },
         "the gateway: HOST:PORT, or unix:PATH for a gateway on this host listening there (rtig --unix PATH); "
         "else CERTI's $CERTI_HOST and $CERTI_TCP_PORT, as PyHLA scripts and tutorials set them (a missing one "
         "takes its default)"},
        {nullptr, "timeout", "HLACORE_TIMEOUT", "S", false,
         [](S& s, Text t) { s.options.timeout_s = number_above(t, 0, false, "seconds"); },
         [](const S& s) { return std::to_string(static_cast<long long>(s.options.timeout_s)); },
         "bounds connecting, each reply and each send the gateway does not take: a gateway silent that long "
         "(stopped, frozen, unreachable; it is pinged after half of it while the federate waits) raises "
         "GatewayNotResponding and closes the connection (docs/robustness.md)"},
        {nullptr, "secret_file", "HLACORE_SECRET_FILE", "FILE", false,
         [](S& s, Text t) { s.options.secret = secret(t); }, nullptr,
         "the file with the secret a gateway may ask for (rtig --secret-file): it is proven by "
         "challenge-response, never sent; a gateway that asks when none is given, or refuses it, raises "
         "AuthenticationFailed (docs/networking.md)"},
        {nullptr, "federation_secret_file", "HLACORE_FEDERATION_SECRET_FILE", "FILE", false,
         [](S& s, Text t) { s.options.federation_secret = secret(t); }, nullptr,
         "the file with the secret of a federation that has one of its own (rtig --federation-secret NAME=FILE): "
         "creating, joining or destroying that federation proves it, and raises AuthenticationFailed without it"},
        {nullptr, "datagrams", "HLACORE_DATAGRAMS", "0|1", false,
         [](S& s, Text t) { s.options.datagrams = yes_or_no(t); },
         [](const S& s) { return std::string(s.options.datagrams ? "1" : "0"); },
         "updates and interactions whose values all travel best_effort and carry no timestamp go to the gateway "
         "as UDP datagrams, and the gateway sends such reflections back the same way, when it offers them and "
         "datagrams get through (tried at connect; otherwise one line on stderr and TCP); datagram_status() "
         "tells which, with the counts"},
        {nullptr, "tls", "HLACORE_TLS", "0|1|FILE", false,
         [](S& s, Text t) {
             s.options.tls = !(t.empty() || t == "0" || t == "false");
             s.options.tls_ca = s.options.tls && t != "1" && t != "true" ? t : "";
         },
         [](const S& s) { return s.options.tls ? (s.options.tls_ca.empty() ? "1" : s.options.tls_ca) : "0"; },
         "encrypts the connection for a gateway with TLS (rtig --tls-cert): 0, plain TCP; 1, TLS with the "
         "gateway's certificate verified against the system's default CA store; a file, TLS trusting the CA or "
         "self-signed certificate in that PEM file. The certificate must also name the host or IP address "
         "connected to; an untrusted certificate, a name that does not match, or a gateway without TLS raises "
         "AuthenticationFailed saying which. Under TLS the gateway offers no datagrams: best-effort messages go "
         "over the encrypted stream (docs/networking.md)"},
        {nullptr, "time_semantics", "HLACORE_TIME_SEMANTICS", "exact|certi", false,
         [](S& s, Text t) { s.options.time_semantics = time_semantics(t); },
         [](const S& s) { return std::string(s.options.time_semantics == TimeSemantics::Default ? "" : name_of(s.options.time_semantics)); },
         "the time rules of the federations this ambassador creates: exact (HLA 1.3's to the last double) or "
         "certi (CERTI's: a federate enabling regulation may start at a zero-lookahead TAR grant's time); by "
         "default the gateway's (rtig --time-semantics, docs/time-management.md)"},
        {nullptr, "busy_poll_us", "HLACORE_BUSY_POLL_US", "US", false,
         [](S& s, Text t) { s.options.busy_poll_us = busy_poll_micros(t); },
         [](const S& s) { return std::to_string(s.options.busy_poll_us); },
         "each wait for the gateway (a tick, a grant, a reply) polls the socket without sleeping for up to that "
         "many µs before it sleeps (0: off). A message that comes meanwhile is read without a wake-up, which on "
         "a machine with idle cores costs tens of µs; the price is a busy core while waiting. Worth it for "
         "federates that step in lockstep with fewer processes than cores, with rtig --busy-poll on the gateway "
         "(docs/performance.md, busy polling). Ctrl-C still interrupts a wait, within the spin and 0.1 s more"},
    };
    return table;
}

ClientSettings client_settings(const std::map<std::string, std::string>& given) {
    ClientSettings settings;
    const auto& table = client_options();
    for (const auto& [keyword, text] : given)
        if (!find_option(table, keyword, Given::Keyword))
            throw RtiError(ErrorCode::RTIinternalError, "no client option named '" + keyword + "'");
    try {
        for (const auto& option : table) {
            if (const auto g = given.find(option.keyword); g != given.end()) {
                apply(settings, option, Given::Keyword, g->second);
            } else if (const char* value = env(option.variable)) {
                apply(settings, option, Given::Variable, value);
            } else if (option.set == set_address && (env("CERTI_HOST") || env("CERTI_TCP_PORT"))) {
                const std::string port = env("CERTI_TCP_PORT") ? env("CERTI_TCP_PORT") : "60400";
                try {
                    whole_number(port, 0, 65535, "");
                } catch (const OptionError& e) {
                    throw OptionError(refused("CERTI_TCP_PORT", Given::Variable, port, e.what()));
                }
                set_address(settings, std::string(env("CERTI_HOST") ? env("CERTI_HOST") : "127.0.0.1") + ":" + port);
            }
        }
    } catch (const OptionError& e) {
        throw RtiError(ErrorCode::RTIinternalError, e.what());
    }
    return settings;
}

}  // namespace hlacore
