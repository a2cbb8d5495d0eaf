// hlacore-rtia's loop: the federate's requests answered in order, its ticks served one callback at a time.
#include "certi/rtia.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <system_error>

#include "fed_parser/omt.hpp"

namespace hlacore::certi {

namespace {

// How often a wait for the gateway looks whether the federate hung up meanwhile.
constexpr auto kFederateCheck = std::chrono::milliseconds(100);

void read_exactly(int fd, char* at, std::size_t n, bool& eof) {
    std::size_t got = 0;
    while (got < n) {
        const ssize_t r = ::read(fd, at + got, n - got);
        if (r > 0) {
            got += static_cast<std::size_t>(r);
        } else if (r == 0) {
            if (got != 0) throw ProtocolError("the federate closed the connection within a frame");
            eof = true;
            return;
        } else if (errno != EINTR) {
            throw std::system_error(errno, std::generic_category(), "reading from the federate");
        }
    }
}

// The answer to a request that failed: CERTI's exception of the same name, the reason kept.
Message refused(Type type, Exception code, const std::string& reason) {
    Message a(type);
    a.exception = code;
    a.reason = reason;
    return a;
}

Message refusal(Type type) {
    try {
        throw;
    } catch (const RtiError& e) {
        const char* name = error_name(e.code());
        const Exception code = exception_named(name);
        // hlacore's own (GatewayNotResponding, ...) are RTIinternalError in CERTI's list, named in the reason.
        return refused(type, code, code == Exception::RTIinternalError && std::string(name) != "RTIinternalError"
                                       ? std::string(name) + ": " + e.what()
                                       : std::string(e.what()));
    } catch (const std::bad_alloc&) {
        return refused(type, Exception::MemoryExhausted, "out of memory");
    } catch (const std::exception& e) {
        return refused(type, Exception::RTIinternalError, e.what());
    }
}

}  // namespace

FederateLink::~FederateLink() { ::close(fd_); }

std::optional<Message> FederateLink::receive() {
    std::string frame(kFrameHeader, '\0');
    bool eof = false;
    read_exactly(fd_, frame.data(), kFrameHeader, eof);
    if (eof) return std::nullopt;
    const std::uint32_t length = frame_length(frame);
    frame.resize(length);
    read_exactly(fd_, frame.data() + kFrameHeader, length - kFrameHeader, eof);
    if (eof) throw ProtocolError("the federate closed the connection within a frame");
    Message m = decode(frame, &big_endian_);
    ++received_[static_cast<std::size_t>(m.type)];
    if (trace_ == Trace::Messages) std::cerr << "hlacore-rtia: <- " << type_name(m.type) << "\n";
    return m;
}

void FederateLink::send(const Message& m) {
    if (trace_ == Trace::Messages)
        std::cerr << "hlacore-rtia: -> " << type_name(m.type)
                  << (m.exception != Exception::None ? std::string(" ") + exception_name(m.exception) + ": " + m.reason : "")
                  << "\n";
    const std::string frame = encode(m, big_endian_);
    std::size_t sent = 0;
    while (sent < frame.size()) {
        const ssize_t w = ::send(fd_, frame.data() + sent, frame.size() - sent, MSG_NOSIGNAL);
        if (w >= 0) sent += static_cast<std::size_t>(w);
        else if (errno != EINTR) throw std::system_error(errno, std::generic_category(), "writing to the federate");
    }
}

void FederateLink::print_counts() const {
    if (trace_ != Trace::Counts) return;
    std::ostringstream line;
    line << "hlacore-rtia: received";
    for (std::size_t t = 1; t < received_.size(); ++t)
        if (received_[t]) line << " " << type_name(static_cast<Type>(t)) << " " << received_[t];
    std::cerr << line.str() << "\n";
}

bool FederateLink::gone() const {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, 0) <= 0) return false;
    if (p.revents & (POLLHUP | POLLERR)) return true;
    char byte;
    return ::recv(fd_, &byte, 1, MSG_PEEK | MSG_DONTWAIT) == 0;
}

Client& Rtia::client() {
    if (!client_) raise(ErrorCode::RTIinternalError, "no OPEN_CONNEXION yet: the federate must open the connection first");
    return *client_;
}

Message Rtia::answer(const Message& request) {
    try {
        return serve(request);
    } catch (...) {
        return refusal(request.type);
    }
}

int Rtia::run() {
    const int status = serve_federate();
    link_.print_counts();
    return status;
}

int Rtia::serve_federate() {
    try {
        for (;;) {
            std::optional<Message> request = link_.receive();
            if (!request) {
                if (joined_) std::cerr << "hlacore-rtia: the federate hung up while joined; it leaves as a dead federate\n";
                return joined_ ? 1 : 0;
            }
            if (request->type == Type::TICK_REQUEST) tick(*request);
            else link_.send(answer(*request));
            if (closed_) return 0;
        }
    } catch (const std::exception& e) {
        std::cerr << "hlacore-rtia: " << e.what() << (joined_ ? "; the federate leaves as a dead federate" : "") << "\n";
        return 1;
    }
}

void Rtia::tick(const Message& request) {
    if (in_callback_) {
        link_.send(refused(Type::TICK_REQUEST, Exception::ConcurrentAccessAttempted, "tick called from a callback"));
        return;
    }
    Message done(Type::TICK_REQUEST);
    try {
        Client& c = client();
        using Seconds = std::chrono::duration<double>;
        const auto start = Client::Clock::now();
        const auto after = [&](double s) {
            return s >= 1e9 ? Client::Clock::time_point::max()
                            : start + std::chrono::duration_cast<Client::Clock::duration>(Seconds(s));
        };
        // CERTI's tick: up to min_tick seconds for the first callback (none when negative), then more while
        // `multiple` and within max_tick, each one acknowledged by the federate before the next.
        c.poll_now();
        const auto first = after(request.min_tick);
        while (!c.has_callbacks() && Client::Clock::now() < first) {
            c.wait_for_callback(std::min(first, Client::Clock::now() + kFederateCheck));
            if (link_.gone()) throw ProtocolError("the federate hung up during its tick");
        }
        const auto deadline = after(request.max_tick);
        bool more = false;
        while (auto callback = c.pop_callback()) {
            link_.send(message_of(*callback));
            const bool stop = await_acknowledgement();
            c.poll_now();
            more = c.has_callbacks();
            if (stop || !request.flag || !more || Client::Clock::now() >= deadline) break;
        }
        done.flag = more;
    } catch (const ProtocolError&) {
        throw;
    } catch (...) {
        done = refusal(Type::TICK_REQUEST);
    }
    link_.send(done);
}

bool Rtia::await_acknowledgement() {
    in_callback_ = true;
    for (;;) {
        std::optional<Message> m = link_.receive();
        if (!m) throw ProtocolError("the federate hung up within a callback");
        if (m->type == Type::TICK_REQUEST_NEXT || m->type == Type::TICK_REQUEST_STOP) {
            in_callback_ = false;
            return m->type == Type::TICK_REQUEST_STOP;
        }
        if (m->type == Type::TICK_REQUEST) tick(*m);  // refused: not from a callback
        else link_.send(answer(*m));
    }
}

std::string find_file(const std::string& fed, std::string& path_found) {
    std::vector<std::string> candidates{fed};
    if (fed.find('/') != 0) {
        if (const char* dirs = std::getenv("CERTI_FOM_PATH")) {
            std::istringstream list(dirs);
            for (std::string dir; std::getline(list, dir, ':');)
                if (!dir.empty()) candidates.push_back(dir + "/" + fed);
        }
        if (const char* home = std::getenv("CERTI_HOME")) candidates.push_back(std::string(home) + "/share/federations/" + fed);
    }
    for (const std::string& path : candidates) {
        std::ifstream file(path, std::ios::binary);
        if (!file) continue;
        std::ostringstream text;
        text << file.rdbuf();
        path_found = path;
        return text.str();
    }
    return {};
}

std::string find_fed(const std::string& fed, std::string& path_found) {
    std::string text = find_file(fed, path_found);
    if (path_found.empty()) return text;
    try {
        fom::parse_fom(text, path_found);  // its FILE:LINE:COL here, at the federate's call
    } catch (const fom::FedError& e) {
        raise(ErrorCode::ErrorReadingFED, e.what());
    }
    return text;
}

}  // namespace hlacore::certi
