// rtig --status's query (status_query.hpp).
#include "rti/net/status_query.hpp"

#include <cerrno>
#include <climits>
#include <cstring>
#include <string_view>

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <openssl/err.h>

#include "rti/exceptions.hpp"
#include "rti/net/dial.hpp"
#include "rti/net/session.hpp"
#include "rti/wire/codec.hpp"

namespace hlacore::net {

namespace {

using Clock = std::chrono::steady_clock;

// One blocking exchange after another on a dialed link, each bounded by the query's deadline.
class Exchange {
public:
    Exchange(Dialed& link, std::string address, Clock::time_point deadline)
        : link_(link), address_(std::move(address)), deadline_(deadline) {}

    template <class M>
    void send(const M& m) {
        std::string out;
        wire::encode(out, m);
        for (std::string_view left = out; !left.empty();) left.remove_prefix(move_bytes(POLLOUT, const_cast<char*>(left.data()), left.size()));
    }

    std::uint32_t max_frame_bytes = wire::kMaxFrameBytes;  // the Welcome's, once it came
    bool welcomed = false;

    // The next message from the gateway.
    wire::Message receive() {
        for (;;) {
            wire::Frame frame;
            if (const std::size_t used = wire::next_frame(in_, frame, max_frame_bytes)) {
                wire::Message m = wire::decode(frame);
                in_.erase(0, used);
                return m;
            }
            char chunk[1 << 16];
            in_.append(chunk, move_bytes(POLLIN, chunk, sizeof chunk));
            if (!link_.ssl && !welcomed && tls::looks_like_record(in_))
                raise(ErrorCode::AuthenticationFailed, "the gateway at " + address_ + " answered with TLS: " + kTlsAdvice);
        }
    }

private:
    // One read (POLLIN) or write (POLLOUT) of at least one byte, waiting for the socket as it must.
    std::size_t move_bytes(short direction, char* data, std::size_t size) {
        const int length = static_cast<int>(std::min<std::size_t>(size, INT_MAX));
        for (;;) {
            short wait = direction;
            long n;
            if (link_.ssl) {
                ERR_clear_error();
                errno = 0;
                n = direction == POLLIN ? SSL_read(link_.ssl.get(), data, length) : SSL_write(link_.ssl.get(), data, length);
                if (n <= 0) {
                    const int error = SSL_get_error(link_.ssl.get(), static_cast<int>(n));
                    if (error == SSL_ERROR_WANT_READ) wait = POLLIN;
                    else if (error == SSL_ERROR_WANT_WRITE) wait = POLLOUT;
                    else if (error == SSL_ERROR_ZERO_RETURN || (error == SSL_ERROR_SYSCALL && errno == 0)) closed();
                    else raise(ErrorCode::RTIinternalError, "the connection to " + address_ + " failed: " +
                                                                tls::errors(std::strerror(errno)));
                    n = 0;
                }
            } else {
                n = direction == POLLIN ? ::recv(link_.fd, data, size, 0) : ::send(link_.fd, data, size, MSG_NOSIGNAL);
                if (n == 0 && direction == POLLIN) closed();
                if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
                    raise(ErrorCode::RTIinternalError, "the connection to " + address_ + " failed: " + std::strerror(errno));
                if (n < 0) n = 0;
            }
            if (n > 0) return static_cast<std::size_t>(n);
            if (poll_until(nullptr, link_.fd, wait, deadline_) == 0)
                raise(ErrorCode::GatewayNotResponding, "no status report from " + address_ + " in time: the gateway is not responding");
        }
    }
    [[noreturn]] void closed() const {
        if (!link_.ssl && !welcomed)
            raise(ErrorCode::RTIinternalError, "the gateway at " + address_ + " closed the connection before its "
                                               "Welcome, as a gateway with TLS does to a client without it: " + kTlsAdvice);
        raise(ErrorCode::RTIinternalError, "the gateway at " + address_ + " closed the connection");
    }
    static constexpr const char* kTlsAdvice =
        "give --tls or --tls-ca FILE (or $HLACORE_TLS) for a gateway with TLS (rtig --tls-cert; docs/networking.md)";

    Dialed& link_;
    std::string address_;
    Clock::time_point deadline_;
    std::string in_;
};

}  // namespace

std::string query_status(const std::string& host, std::uint16_t port, const StatusQueryOptions& options) {
    const auto deadline = Clock::now() + options.timeout;
    const std::string address = address_of(host, port);
    Dialed link = dial(host, port, {options.timeout, options.tls, options.tls_ca, nullptr}, deadline);
    struct Closer {
        Dialed& link;
        ~Closer() {
            link.ssl.reset();
            ::close(link.fd);
        }
    } closer{link};
    Exchange exchange(link, address, deadline);
    exchange.send(wire::Hello{});
    for (;;) {
        wire::Message m = exchange.receive();
        if (const auto* welcome = std::get_if<wire::Welcome>(&m)) {
            exchange.max_frame_bytes = welcome->max_frame_bytes;
            exchange.welcomed = true;
            if (!welcome->challenge.empty()) exchange.send(answer_challenge(address, options.secret, welcome->challenge));
            exchange.send(wire::QueryStatus{1, 0, true});
        } else if (const auto* verdict = std::get_if<wire::Authenticated>(&m)) {
            check_authenticated(address, *verdict);
        } else if (const auto* reply = std::get_if<wire::Reply>(&m); reply && reply->error != 0) {
            raise(error_code(reply->error), reply->message);
        } else if (auto* report = std::get_if<wire::StatusReport>(&m)) {
            return std::move(report->json);
        }
    }
}

}  // namespace hlacore::net
