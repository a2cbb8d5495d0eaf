// The Federate Protocol's door (IEEE 1516.1-2025, HLA 4): federates that speak it over TCP join the federations of
// a gateway. Each session is an IEEE 1516-2010 federate of hlacore's own (cpp/rti1516e) connected to the gateway,
// which makes the calls the session's federate sends and turns its callbacks into the protocol's callback
// requests (fedpro/federate.cpp). The server listens on 127.0.0.1:15164 by default; a thread accepts, one thread per
// connection reads it, and a housekeeping thread ends the sessions not resumed in time as resigned federates.
// rtig --fedpro and hlacore.Gateway(fedpro=...) attach one to a gateway; docs/fedpro.md.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "fedpro/session.hpp"

namespace hlacore::fedpro {

constexpr std::uint16_t kDefaultPort = 15164;

struct ServerOptions {
    std::string host = "127.0.0.1";
    std::uint16_t port = kDefaultPort;  // 0: any free port (Server::port() says which)
    std::string gateway;                // the sessions' federates' local settings designator (federate.hpp)
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
    std::string address() const;  // HOST:PORT
    // Ends every session (their federates resign) and stops listening. Idempotent.
    void stop();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// A door on `listen` (HOST:PORT, as rtig --fedpro takes it), its federates connecting to the gateway at
// `gateway` (unix:PATH, the gateway's private socket for the door: PrivateSocket) with `secret_file` ("": none),
// its sessions resumable for `resume_timeout_s` after a drop.
std::unique_ptr<Server> open_door(std::string const& listen, std::string const& gateway, std::string const& secret_file,
                                  double resume_timeout_s);

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

// "HOST:PORT", ":PORT" or "HOST" (the default port) into `options`; std::invalid_argument saying why not.
void parse_listen_address(std::string const& text, ServerOptions& options);

}  // namespace hlacore::fedpro
