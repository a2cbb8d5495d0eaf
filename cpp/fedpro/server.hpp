// The Federate Protocol's door (IEEE 1516.1-2025, HLA 4): federates that speak it over TCP, TLS or WebSocket (plain
// or secure) join the federations of a gateway. Each session is an IEEE 1516-2010 federate of hlacore's own (cpp/rti1516e) connected to the gateway,
// which makes the calls the session's federate sends and turns its callbacks into the protocol's callback
// requests (fedpro/federate.cpp). The server listens on 127.0.0.1:15164 by default; a thread accepts, one thread per
// connection makes its handshakes (TLS, WebSocket, the session's) and reads it, and a housekeeping thread ends the
// sessions not resumed in time as resigned federates. Beyond loopback a federate connects with the gateway's secret
// as HLAplainTextPassword credentials, over TLS. rtig --fedpro and hlacore.Gateway(fedpro=...) attach one to a
// gateway; docs/fedpro.md.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "fedpro/session.hpp"

namespace hlacore::fedpro {

// The protocol's transports, by the names its clients give them (Pitch's connect.protocol).
enum class Transport { Tcp, Tls, WebSocket, WebSocketSecure };
const char* name(Transport transport);
std::uint16_t default_port(Transport transport);  // 15164, 15165, 80, 443
constexpr std::uint16_t kDefaultPort = 15164;

struct ServerOptions {
    Transport transport = Transport::Tcp;
    std::string host = "127.0.0.1";
    std::uint16_t port = kDefaultPort;  // 0: any free port (Server::port() says which)
    std::string gateway;                // the sessions' federates' local settings designator (federate.hpp)
    std::string tls_cert, tls_key;      // PEM files, for Tls and WebSocketSecure (rti/tls.hpp)
    // Non-empty: connect must carry HLAplainTextPassword credentials with it (Unauthorized otherwise). Beyond
    // loopback the server needs one, and TLS to carry it, unless `anyone_beyond_loopback`.
    std::string password;
    bool anyone_beyond_loopback = false;
    SessionLimits limits;
};

class Server {
public:
    // Listens; std::runtime_error when it cannot, std::invalid_argument for options it refuses.
    explicit Server(ServerOptions options);
    ~Server();  // stop()
    Server(Server const&) = delete;
    Server& operator=(Server const&) = delete;

    std::uint16_t port() const;
    Transport transport() const;
    std::string address() const;  // HOST:PORT
    // "fedpro":{"address":..., "transport":..., "sessions":[...]}: the sessions open and the last ended ones
    // (Session::status_json), for the gateway's status report (Gateway::add_status_section) and the monitor.
    std::string status_json() const;
    // Ends every session (their federates resign) and stops listening. Idempotent.
    void stop();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// "[PROTOCOL://]HOST[:PORT]" into `options` (PROTOCOL: tcp, the default, tls, websocket or ws, websocketsecure or
// wss; without a port, the protocol's default); std::invalid_argument saying why not.
void parse_listen_address(std::string const& text, ServerOptions& options);

// The door of a gateway with `options` (a GatewayOptions, rti/server/gateway.hpp, which this side does not include:
// its `fedpro`, [PROTOCOL://]HOST[:PORT], and resume timeout), its federates connecting to the gateway at `gateway`
// (unix:PATH, the gateway's private socket for the door: PrivateSocket) with the gateway's secret file, TLS with the
// gateway's certificate, connect asking for the gateway's secret when it has one; `anyone_beyond_loopback`: rtig
// --no-secret.
template <class GatewayOptions>
std::unique_ptr<Server> open_door(GatewayOptions const& options, std::string const& gateway, bool anyone_beyond_loopback = false) {
    ServerOptions door;
    parse_listen_address(options.fedpro, door);
    door.limits.resume_timeout = std::chrono::milliseconds(static_cast<long long>(options.fedpro_resume_timeout_s * 1000));
    door.gateway = "address=" + gateway + (options.secret_file.empty() ? "" : "\nsecret_file=" + options.secret_file);
    door.tls_cert = options.tls_cert;
    door.tls_key = options.tls_key;
    door.password = options.secret;
    door.anyone_beyond_loopback = anyone_beyond_loopback;
    return std::make_unique<Server>(std::move(door));
}

// A Unix socket path in a directory of its own, readable by this user only, for the gateway to listen on for its
// door (no TLS there, so a gateway with --tls-cert needs nothing more for it); the directory goes when this does. Throws
// std::runtime_error when it cannot be made.
class PrivateSocket {
public:
    PrivateSocket();
    ~PrivateSocket();
    PrivateSocket(PrivateSocket const&) = delete;
    PrivateSocket& operator=(PrivateSocket const&) = delete;
    std::string const& path() const { return path_; }

private:
    std::string directory_, path_;
};


}  // namespace hlacore::fedpro
