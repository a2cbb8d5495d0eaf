#include "fedpro/server.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <cstdio>
#include <deque>
#include <list>
#include <map>
#include <mutex>
#include <random>
#include <stdexcept>
#include <thread>

#include "fedpro/federate.hpp"
#include "rti/net/listen.hpp"
#include "rti/wire/json.hpp"

namespace hlacore::fedpro {

namespace {

constexpr std::chrono::milliseconds kHandshakeIdle{10000};  // a connection that says nothing for this long is closed
constexpr std::size_t kEndedKept = 32;

}  // namespace

const char* name(Transport transport) {
    switch (transport) {
        case Transport::Tcp: return "tcp";
        case Transport::Tls: return "tls";
        case Transport::WebSocket: return "websocket";
        case Transport::WebSocketSecure: return "websocketsecure";
    }
    return "?";
}

std::uint16_t default_port(Transport transport) {
    switch (transport) {
        case Transport::Tcp: return kDefaultPort;
        case Transport::Tls: return 15165;
        case Transport::WebSocket: return 80;
        case Transport::WebSocketSecure: return 443;
    }
    return kDefaultPort;
}

void parse_listen_address(std::string const& given, ServerOptions& options) {
    std::string text = given;
    options.transport = Transport::Tcp;
    if (const auto scheme = text.find("://"); scheme != std::string::npos) {
        const std::string protocol = text.substr(0, scheme);
        if (protocol == "tcp") options.transport = Transport::Tcp;
        else if (protocol == "tls") options.transport = Transport::Tls;
        else if (protocol == "websocket" || protocol == "ws") options.transport = Transport::WebSocket;
        else if (protocol == "websocketsecure" || protocol == "wss") options.transport = Transport::WebSocketSecure;
        else
            throw std::invalid_argument("'" + protocol + "' is not a transport of the Federate Protocol (tcp, tls, websocket, websocketsecure)");
        text = text.substr(scheme + 3);
    }
    options.port = default_port(options.transport);
    const auto colon = text.rfind(':');
    std::string host = colon == std::string::npos ? text : text.substr(0, colon);
    if (!host.empty()) options.host = host;
    if (colon == std::string::npos) return;
    const std::string port = text.substr(colon + 1);
    char* end = nullptr;
    const long n = std::strtol(port.c_str(), &end, 10);
    if (port.empty() || *end != '\0' || n < 0 || n > 65535)
        throw std::invalid_argument("'" + given + "' is not [PROTOCOL://]HOST:PORT (the Federate Protocol's address)");
    options.port = std::uint16_t(n);
}

PrivateSocket::PrivateSocket() {
    const char* tmp = std::getenv("TMPDIR");
    std::string dir = std::string(tmp && *tmp ? tmp : "/tmp") + "/hlacore-door-XXXXXX";
    if (!::mkdtemp(dir.data())) throw std::runtime_error("no private directory for the door's socket in " + dir);
    directory_ = dir;
    path_ = dir + "/gateway.sock";
}

PrivateSocket::~PrivateSocket() {
    ::unlink(path_.c_str());  // the gateway removes it; a gateway that failed to start may not have
    ::rmdir(directory_.c_str());
}

struct Server::Impl {
    ServerOptions options;
    tls::Context tls;  // for Tls and WebSocketSecure
    int listen_fd = -1;
    std::uint16_t port = 0;
    std::atomic<bool> stopping{false};
    std::thread acceptor, housekeeper;

    std::mutex mutex;  // sessions, connections
    std::map<std::uint64_t, std::shared_ptr<Session>> sessions;
    struct Connection {
        std::thread thread;
        std::atomic<bool> done{false};
    };
    std::list<Connection> connections;
    std::deque<std::string> ended;  // the last sessions that ended, as the status report shows them
    std::mt19937_64 ids{std::random_device{}()};

    void accept_loop() {
        while (!stopping) {
            pollfd p{listen_fd, POLLIN, 0};
            if (::poll(&p, 1, 200) <= 0) continue;
            const int fd = ::accept4(listen_fd, nullptr, nullptr, SOCK_CLOEXEC | SOCK_NONBLOCK);
            if (fd < 0) continue;
            // A call's response is small and awaited; a peer gone without a word is found by keepalive, and its
            // session is then dropped, waiting for a resume.
            net::serve_connection(fd);
            std::lock_guard<std::mutex> lock(mutex);
            Connection& c = connections.emplace_back();
            c.thread = std::thread([this, fd, &c] {
                handle(fd);
                c.done = true;
            });
        }
    }

    // The connection's transport, its handshakes made; none when they failed.
    std::shared_ptr<Stream> stream_of(int fd) {
        const Transport t = options.transport;
        std::unique_ptr<Stream> stream;
        if (t == Transport::Tls || t == Transport::WebSocketSecure) {
            auto secure = std::make_unique<TlsStream>(fd, tls.get());
            if (!secure->handshake(stopping, kHandshakeIdle)) return nullptr;
            stream = std::move(secure);
        } else {
            stream = std::make_unique<SocketStream>(fd);
        }
        if (t == Transport::WebSocket || t == Transport::WebSocketSecure) {
            auto web = std::make_unique<WebSocketStream>(std::move(stream), options.limits.max_message);
            if (!web->handshake(stopping, kHandshakeIdle)) return nullptr;
            stream = std::move(web);
        }
        return stream;
    }

    // A new connection: a new session, or a resume of one.
    void handle(int fd) {
        Header h;
        std::string payload;
        std::shared_ptr<Session> session;
        std::shared_ptr<Stream> stream;
        try {
            stream = stream_of(fd);
            if (!stream || !read_message(*stream, options.limits.max_message, stopping, h, payload, kHandshakeIdle)) return;
            if (h.type == MessageType::NewSession) {
                session = open(*stream, payload_u32(payload, 0));
            } else if (h.type == MessageType::ResumeRequest) {
                session = find(h.session);
                if (!session)
                    stream->write_all(SessionState(h.session).first_frame(MessageType::ResumeStatus, u32s({kInvalidSession, kNoSequence})),
                                      std::chrono::milliseconds(1000));
                else if (!session->resume(stream, payload_u32(payload, 0)))  // it answered why
                    session.reset();
            } else {
                throw BadMessage(std::string("a ") + name(h.type) + " before a session");
            }
        } catch (BadMessage const& e) {
            std::fprintf(stderr, "fedpro: a connection closed: %s\n", e.what());
        } catch (std::exception const& e) {
            std::fprintf(stderr, "fedpro: a connection closed: %s\n", e.what());
        }
        if (session) session->serve(std::move(stream));
    }

    std::shared_ptr<Session> open(Stream& stream, std::uint32_t version) {
        std::uint64_t id = 0;
        {
            std::lock_guard<std::mutex> lock(mutex);
            while (id == 0 || sessions.count(id)) id = ids();
        }
        SessionState status_of(id);
        if (version != kProtocolVersion) {
            stream.write_all(SessionState(0).first_frame(MessageType::NewSessionStatus, u32s({kUnsupportedVersion})),
                             std::chrono::milliseconds(1000));
            return nullptr;
        }
        auto session = std::make_shared<Session>(id, options.limits);
        Session* raw = session.get();
        session->set_federate(
            make_federate(options.gateway, options.password, [raw](std::string_view callback) { raw->send_callback(callback); }));
        if (!stream.write_all(status_of.first_frame(MessageType::NewSessionStatus, u32s({kSessionOk})), std::chrono::milliseconds(1000)))
            return nullptr;
        std::lock_guard<std::mutex> lock(mutex);
        sessions[id] = session;
        return session;
    }

    std::shared_ptr<Session> find(std::uint64_t id) {
        std::lock_guard<std::mutex> lock(mutex);
        auto it = sessions.find(id);
        return it == sessions.end() ? nullptr : it->second;
    }

    // Ends the sessions dropped for too long and forgets those ended (keeping their last status), joins the
    // connections' finished threads.
    void housekeeping_loop() {
        while (!stopping) {
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
            const auto now = std::chrono::steady_clock::now();
            std::vector<std::shared_ptr<Session>> expired;
            std::list<Connection> finished;
            {
                std::lock_guard<std::mutex> lock(mutex);
                for (auto const& [id, session] : sessions)
                    if (session->expired(now)) expired.push_back(session);
                for (auto it = connections.begin(); it != connections.end();) {
                    auto here = it++;
                    if (here->done) finished.splice(finished.end(), connections, here);
                }
            }
            for (auto& s : expired) {
                if (!s->ended()) {
                    std::fprintf(stderr, "fedpro: session %llu not resumed in time: its federate resigns\n",
                                 (unsigned long long)s->id());
                    char why[64];
                    std::snprintf(why, sizeof why, "not resumed within %g s",
                                  std::chrono::duration<double>(options.limits.resume_timeout).count());
                    s->end(false, why);
                }
                std::lock_guard<std::mutex> lock(mutex);  // from open to ended at once, for the status report
                sessions.erase(s->id());
                ended.push_back(s->status_json(now));
                if (ended.size() > kEndedKept) ended.pop_front();
            }
            for (auto& c : finished) c.thread.join();
        }
    }
};

Server::Server(ServerOptions options) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.options = std::move(options);
    const ServerOptions& o = m.options;
    const bool secure = o.transport == Transport::Tls || o.transport == Transport::WebSocketSecure;
    if (!net::is_loopback(o.host) && !o.anyone_beyond_loopback) {
        if (o.password.empty())
            throw std::invalid_argument("the Federate Protocol's door on " + o.host + ", beyond this machine, needs the gateway's "
                                        "secret (--secret-file FILE: federates connect with it as HLAplainTextPassword "
                                        "credentials), or --no-secret to let in anyone who reaches the port");
        if (!secure)
            throw std::invalid_argument("the Federate Protocol's door on " + o.host + ", beyond this machine, takes the "
                                        "gateway's secret as a password: over tls:// or websocketsecure:// only, so that it "
                                        "does not cross the network in clear");
    }
    if (secure) {
        if (o.tls_cert.empty())
            throw std::invalid_argument(std::string("the Federate Protocol over ") + name(o.transport) +
                                        " needs the gateway's certificate: --tls-cert FILE --tls-key FILE");
        m.tls = tls::server_context(o.tls_cert, o.tls_key);  // std::runtime_error saying why not
    }
    if (o.gateway.empty()) throw std::invalid_argument("the Federate Protocol's server needs the gateway's address");
    const net::Listening listening = net::listen_tcp(m.options.host, m.options.port, SOCK_CLOEXEC);
    m.listen_fd = listening.fd;
    m.port = listening.port;
    m.acceptor = std::thread([&m] { m.accept_loop(); });
    m.housekeeper = std::thread([&m] { m.housekeeping_loop(); });
}

Server::~Server() { stop(); }

std::uint16_t Server::port() const { return impl_->port; }
Transport Server::transport() const { return impl_->options.transport; }

std::string Server::status_json() const {
    Impl& m = *impl_;
    const auto now = std::chrono::steady_clock::now();
    std::string json = "\"fedpro\":{\"address\":";
    json_string(json, address());
    json += std::string(",\"transport\":\"") + name(m.options.transport) + "\",\"sessions\":[";
    std::lock_guard<std::mutex> lock(m.mutex);
    bool first = true;
    for (auto const& entry : m.ended) {
        json += first ? "" : ",";
        json += entry;
        first = false;
    }
    for (auto const& [id, session] : m.sessions) {
        json += first ? "" : ",";
        json += session->status_json(now);
        first = false;
    }
    return json + "]}";
}
std::string Server::address() const { return impl_->options.host + ":" + std::to_string(impl_->port); }

void Server::stop() {
    Impl& m = *impl_;
    if (m.stopping.exchange(true)) return;
    if (m.acceptor.joinable()) m.acceptor.join();
    if (m.housekeeper.joinable()) m.housekeeper.join();
    std::map<std::uint64_t, std::shared_ptr<Session>> sessions;
    {
        std::lock_guard<std::mutex> lock(m.mutex);
        sessions.swap(m.sessions);
    }
    for (auto& [id, s] : sessions) s->end(true, "the gateway stopped");
    for (auto& c : m.connections) c.thread.join();  // each sees `stopping` or its session's end
    m.connections.clear();
    ::close(m.listen_fd);
}

}  // namespace hlacore::fedpro
