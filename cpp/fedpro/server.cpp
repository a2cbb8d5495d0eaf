#include "fedpro/server.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <cstdio>
#include <list>
#include <map>
#include <mutex>
#include <random>
#include <stdexcept>
#include <thread>

#include "fedpro/federate.hpp"
#include "rti/net/listen.hpp"

namespace hlacore::fedpro {

namespace {

constexpr std::chrono::milliseconds kHandshakeIdle{10000};  // a connection that says nothing for this long is closed

}  // namespace

void parse_listen_address(std::string const& text, ServerOptions& options) {
    const auto colon = text.rfind(':');
    std::string host = colon == std::string::npos ? text : text.substr(0, colon);
    if (!host.empty()) options.host = host;
    if (colon == std::string::npos) return;
    const std::string port = text.substr(colon + 1);
    char* end = nullptr;
    const long n = std::strtol(port.c_str(), &end, 10);
    if (port.empty() || *end != '\0' || n < 0 || n > 65535)
        throw std::invalid_argument("'" + text + "' is not HOST:PORT (the Federate Protocol's address)");
    options.port = std::uint16_t(n);
}

std::unique_ptr<Server> open_door(std::string const& listen, std::string const& gateway, std::string const& secret_file,
                                  double resume_timeout_s) {
    ServerOptions options;
    parse_listen_address(listen, options);
    options.limits.resume_timeout = std::chrono::milliseconds(static_cast<long long>(resume_timeout_s * 1000));
    options.gateway = "address=" + gateway + (secret_file.empty() ? "" : "\nsecret_file=" + secret_file);
    return std::make_unique<Server>(options);
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
    std::mt19937_64 ids{std::random_device{}()};

    void accept_loop() {
        while (!stopping) {
            pollfd p{listen_fd, POLLIN, 0};
            if (::poll(&p, 1, 200) <= 0) continue;
            const int fd = ::accept4(listen_fd, nullptr, nullptr, SOCK_CLOEXEC);
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

    // A new connection: a new session, or a resume of one.
    void handle(int fd) {
        Header h;
        std::string payload;
        std::shared_ptr<Session> session;
        try {
            if (!read_message(fd, options.limits.max_message, stopping, h, payload, kHandshakeIdle)) {
                ::close(fd);
                return;
            }
            if (h.type == MessageType::NewSession) {
                session = open(fd, payload_u32(payload, 0));
            } else if (h.type == MessageType::ResumeRequest) {
                session = find(h.session);
                if (!session)
                    write_all(fd, SessionState(h.session).first_frame(MessageType::ResumeStatus, u32s({kInvalidSession, kNoSequence})),
                              std::chrono::milliseconds(1000));
                else if (!session->resume(fd, payload_u32(payload, 0)))  // it answered why
                    session.reset();
            } else {
                throw BadMessage(std::string("a ") + name(h.type) + " before a session");
            }
        } catch (BadMessage const& e) {
            std::fprintf(stderr, "fedpro: a connection closed: %s\n", e.what());
        } catch (std::exception const& e) {
            std::fprintf(stderr, "fedpro: a connection closed: %s\n", e.what());
        }
        if (session)
            session->serve(fd);
        else
            ::close(fd);
    }

    std::shared_ptr<Session> open(int fd, std::uint32_t version) {
        std::uint64_t id = 0;
        {
            std::lock_guard<std::mutex> lock(mutex);
            while (id == 0 || sessions.count(id)) id = ids();
        }
        SessionState status_of(id);
        if (version != kProtocolVersion) {
            write_all(fd, SessionState(0).first_frame(MessageType::NewSessionStatus, u32s({kUnsupportedVersion})),
                      std::chrono::milliseconds(1000));
            return nullptr;
        }
        auto session = std::make_shared<Session>(id, options.limits);
        Session* raw = session.get();
        session->set_federate(make_federate(options.gateway, [raw](std::string_view callback) { raw->send_callback(callback); }));
        if (!write_all(fd, status_of.first_frame(MessageType::NewSessionStatus, u32s({kSessionOk})), std::chrono::milliseconds(1000)))
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

    // Ends the sessions dropped for too long, joins the connections' finished threads.
    void housekeeping_loop() {
        while (!stopping) {
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
            const auto now = std::chrono::steady_clock::now();
            std::vector<std::shared_ptr<Session>> expired;
            std::list<Connection> finished;
            {
                std::lock_guard<std::mutex> lock(mutex);
                for (auto it = sessions.begin(); it != sessions.end();) {
                    if (it->second->expired(now)) {
                        expired.push_back(it->second);
                        it = sessions.erase(it);
                    } else {
                        ++it;
                    }
                }
                for (auto it = connections.begin(); it != connections.end();) {
                    auto here = it++;
                    if (here->done) finished.splice(finished.end(), connections, here);
                }
            }
            for (auto& s : expired) {
                if (!s->ended())
                    std::fprintf(stderr, "fedpro: session %llu not resumed in time: its federate resigns\n",
                                 (unsigned long long)s->id());
                s->end(false);
            }
            for (auto& c : finished) c.thread.join();
        }
    }
};

Server::Server(ServerOptions options) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.options = std::move(options);
    if (!net::is_loopback(m.options.host))
        throw std::invalid_argument("the Federate Protocol listens on loopback only for now (" + m.options.host +
                                    " asked): federates beyond this host need credentials, which are not checked yet");
    if (m.options.gateway.empty()) throw std::invalid_argument("the Federate Protocol's server needs the gateway's address");
    const net::Listening listening = net::listen_tcp(m.options.host, m.options.port, SOCK_CLOEXEC);
    m.listen_fd = listening.fd;
    m.port = listening.port;
    m.acceptor = std::thread([&m] { m.accept_loop(); });
    m.housekeeper = std::thread([&m] { m.housekeeping_loop(); });
}

Server::~Server() { stop(); }

std::uint16_t Server::port() const { return impl_->port; }
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
    for (auto& [id, s] : sessions) s->end(true);
    for (auto& c : m.connections) c.thread.join();  // each sees `stopping` or its session's end
    m.connections.clear();
    ::close(m.listen_fd);
}

}  // namespace hlacore::fedpro
