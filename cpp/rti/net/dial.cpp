// Connecting to a gateway (dial.hpp).
#include "rti/net/dial.hpp"

#include <cerrno>
#include <cstring>
#include <memory>
#include <stdexcept>

#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <openssl/err.h>
#include <openssl/x509_vfy.h>

#include "rti/exceptions.hpp"
#include "rti/unix_socket.hpp"

namespace hlacore::net {

namespace {

using Clock = std::chrono::steady_clock;

// Closes what dial() opened unless it succeeds.
struct Guard {
    Dialed& d;
    bool done = false;
    ~Guard() {
        if (done) return;
        d.ssl.reset();
        if (d.fd >= 0) ::close(d.fd);
        d.fd = -1;
    }
};

// d.fd connected to the gateway's Unix socket at `path`, or RTIinternalError saying why not. A connect to
// a Unix socket does not wait: it succeeds or fails at once (EAGAIN: the gateway's backlog is full).
void connect_local(Dialed& d, const std::string& address, const std::string& path) {
    sockaddr_un a{};
    try {
        a = unix_socket::address_of(path);
    } catch (const std::invalid_argument& e) {
        raise(ErrorCode::RTIinternalError, e.what());
    }
    d.fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (d.fd < 0 || ::connect(d.fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) < 0) {
        const int error = errno;
        raise(error == EAGAIN ? ErrorCode::GatewayNotResponding : ErrorCode::RTIinternalError,
              "cannot connect to rtig at " + address + ": " +
                  (error == EAGAIN ? std::string("it takes no more connections now") : std::strerror(error)));
    }
    unix_socket::size_send_buffer(d.fd);
}

void start_tls(Dialed& d, SSL_CTX* context, const std::string& host, const std::string& address, const DialOptions& options,
               Clock::time_point deadline) {
    try {
        d.ssl = tls::session(context, d.fd);  // the session holds its own reference to the context
    } catch (const std::exception& e) {
        raise(ErrorCode::AuthenticationFailed, e.what());
    }
    tls::expect_host(d.ssl.get(), host);
    SSL_set_connect_state(d.ssl.get());
    const std::string trusted = options.tls_ca.empty() ? "the system's CA store" : "the CA file '" + options.tls_ca + "'";
    for (;;) {
        ERR_clear_error();
        errno = 0;
        const int rc = SSL_do_handshake(d.ssl.get());
        if (rc == 1) return;
        const int error = SSL_get_error(d.ssl.get(), rc);
        const short events = error == SSL_ERROR_WANT_READ ? POLLIN : error == SSL_ERROR_WANT_WRITE ? POLLOUT : 0;
        if (!events) {
            const int saved_errno = errno;
            const long verify = SSL_get_verify_result(d.ssl.get());
            const unsigned long first = ERR_peek_error();
            const std::string errors = tls::errors();
            if (verify == X509_V_ERR_HOSTNAME_MISMATCH || verify == X509_V_ERR_IP_ADDRESS_MISMATCH)
                raise(ErrorCode::AuthenticationFailed,
                      "the gateway's certificate at " + address + " is not for '" + host + "' (" +
                          X509_verify_cert_error_string(verify) + "): connect by a name or address it names "
                          "(docs/networking.md)");
            if (verify != X509_V_OK)
                raise(ErrorCode::AuthenticationFailed, "the gateway's certificate is not trusted: " +
                                                           std::string(X509_verify_cert_error_string(verify)) + " (" +
                                                           address + ", checked against " + trusted + ")");
            const int reason = ERR_GET_REASON(first);
            if ((error == SSL_ERROR_SYSCALL || error == SSL_ERROR_ZERO_RETURN) && errors.empty())
                raise(ErrorCode::AuthenticationFailed,
                      "the gateway at " + address + " does not speak TLS: it closed the connection during the TLS "
                      "handshake (" + (saved_errno ? std::strerror(saved_errno) : "end of stream") +
                          "; an rtig without --tls-cert does so)");
            if (reason == SSL_R_WRONG_VERSION_NUMBER || reason == SSL_R_PACKET_LENGTH_TOO_LONG ||
                reason == SSL_R_RECORD_LENGTH_MISMATCH || reason == SSL_R_UNEXPECTED_EOF_WHILE_READING)
                raise(ErrorCode::AuthenticationFailed,
                      "the gateway at " + address + " does not speak TLS: " + errors);
            raise(ErrorCode::AuthenticationFailed, "the TLS handshake with the gateway at " + address +
                                                       " failed: " + (errors.empty() ? std::strerror(saved_errno) : errors));
        }
        if (poll_until(options.wait_host, d.fd, events, deadline) == 0)
            raise(ErrorCode::GatewayNotResponding, "no TLS handshake from " + address + " within " + seconds(options.timeout) +
                                                       ": the gateway is not responding (or does not speak TLS)");
    }
}

}  // namespace

std::string address_of(const std::string& host, std::uint16_t port) {
    return unix_socket::is_unix(host) ? host : host + ":" + std::to_string(port);
}

Dialed dial(const std::string& host, std::uint16_t port, const DialOptions& options, Clock::time_point deadline) {
    const std::string address = address_of(host, port);
    const bool local = unix_socket::is_unix(host);
    if (local && options.tls)
        raise(ErrorCode::RTIinternalError, "TLS is for TCP: a Unix socket (" + host + ") does not leave this host");
    Dialed d;
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_NUMERICSERV;
    addrinfo* found = nullptr;
    const std::string service = std::to_string(port);
    if (int rc = local ? 0 : getaddrinfo(host.c_str(), service.c_str(), &hints, &found); rc != 0)
        raise(ErrorCode::RTIinternalError, "cannot resolve rtig host '" + host + "': " + gai_strerror(rc));
    std::unique_ptr<addrinfo, decltype(&freeaddrinfo)> guard(found, freeaddrinfo);
    tls::Context tls_context;  // before connecting: a CA file that cannot be used fails without the network
    if (options.tls) {
        try {
            tls_context = tls::client_context(options.tls_ca);
        } catch (const std::exception& e) {
            raise(ErrorCode::AuthenticationFailed, e.what());
        }
    }
    std::string error = "no address";
    ErrorCode code = ErrorCode::RTIinternalError;
    Guard opened{d};
    if (local) connect_local(d, address, unix_socket::path_of(host));
    for (addrinfo* a = found; a && d.fd < 0; a = a->ai_next) {
        d.fd = ::socket(a->ai_family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
        if (d.fd < 0) continue;
        int rc = ::connect(d.fd, a->ai_addr, a->ai_addrlen);
        // A gateway host that drops packets leaves the connect pending: bounded by the timeout.
        if (rc < 0 && (errno == EINPROGRESS || errno == EINTR)) {
            if (poll_until(options.wait_host, d.fd, POLLOUT, deadline) == 0) {
                errno = ETIMEDOUT;
                code = ErrorCode::GatewayNotResponding;
            } else {
                int so_error = 0;
                socklen_t len = sizeof so_error;
                getsockopt(d.fd, SOL_SOCKET, SO_ERROR, &so_error, &len);
                errno = so_error;
                rc = so_error == 0 ? 0 : -1;
            }
        }
        if (rc == 0) break;
        error = std::strerror(errno);
        ::close(d.fd);
        d.fd = -1;
    }
    if (d.fd < 0) raise(code, "cannot connect to rtig at " + address + ": " + error);
    if (!local) {
        int one = 1;
        setsockopt(d.fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    }
    if (tls_context) start_tls(d, tls_context.get(), host, address, options, deadline);
    opened.done = true;
    return d;
}

}  // namespace hlacore::net
