// The client's connection to a gateway: dialed (rti/net/dial.hpp), its session opened and its datagram path
// proven; each TLS read and write (one at a time: OpenSSL's session is not thread-safe), and closing.
#include "rti/client/client.hpp"

#include "rti/busy_poll.hpp"
#include "rti/net/dial.hpp"
#include "rti/net/wait.hpp"
#include "rti/unix_socket.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>

#include <openssl/err.h>
#include <openssl/x509_vfy.h>

#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

namespace hlacore {

Client::Client(const std::string& host, std::uint16_t port, ClientOptions options)
    : address_(net::address_of(host, port)),
      options_(options),
      timeout_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.timeout_s))) {
    if (!(options.timeout_s > 0) || options.timeout_s > 1e6)
        raise(ErrorCode::RTIinternalError, "the client's timeout must be between 0 and 1e6 seconds, not " +
                                               std::to_string(options.timeout_s));
    if (const std::string error = busy_poll_error(options.busy_poll_us); !error.empty())
        raise(ErrorCode::RTIinternalError, error);
    const bool local = unix_socket::is_unix(host);
    const auto deadline = Clock::now() + timeout_;
    net::Dialed link = net::dial(host, port, {timeout_, options_.tls, options_.tls_ca, options_.wait_host}, deadline);
    fd_ = link.fd;
    ssl_ = std::move(link.ssl);
    try {
        last_heard_ = Clock::now();
        open_session(deadline);
        if (datagram_token_) {
            if (options_.datagrams) open_datagram_path(deadline);
            else datagram_reason_ = "datagrams turned off on this side";
        } else if (local) {
            datagram_reason_ = "no datagrams over a Unix socket: best-effort messages go over it as a stream";
        } else {
            datagram_reason_ = ssl_ ? "the gateway offers no datagrams under TLS: best-effort messages go over the "
                                      "encrypted TCP stream"
                                    : "the gateway offers no datagrams";
        }
    } catch (...) {
        ssl_.reset();
        if (fd_ >= 0) ::close(fd_);
        if (datagram_fd_ >= 0) ::close(datagram_fd_);
        fd_ = datagram_fd_ = -1;
        throw;
    }
}

namespace {

// One SSL_read or SSL_write (`io`) under the session's lock: bytes moved, 0 when the socket would block,
// -1 with `error`.
template <class Io>
long tls_io(std::mutex& mu, SSL* ssl, Io io, std::string& error) {
    std::lock_guard<std::mutex> lock(mu);
    ERR_clear_error();
    errno = 0;
    const int n = io(ssl);
    if (n > 0) return n;
    switch (SSL_get_error(ssl, n)) {
        case SSL_ERROR_WANT_READ:
        case SSL_ERROR_WANT_WRITE: return 0;  // not after the handshake: no renegotiation
        case SSL_ERROR_ZERO_RETURN: error = "the gateway closed the connection"; return -1;
        case SSL_ERROR_SYSCALL: error = errno ? std::strerror(errno) : "the gateway closed the connection"; return -1;
        default: error = "TLS error: " + tls::errors("protocol error"); return -1;
    }
}

int clamped(std::size_t length) { return static_cast<int>(std::min<std::size_t>(length, INT_MAX)); }

}  // namespace

long Client::tls_write(const char* data, std::size_t length, std::string& error) {
    return tls_io(ssl_mu_, ssl_.get(), [&](SSL* ssl) { return SSL_write(ssl, data, clamped(length)); }, error);
}

long Client::tls_read(char* data, std::size_t length, std::string& error) {
    return tls_io(ssl_mu_, ssl_.get(), [&](SSL* ssl) { return SSL_read(ssl, data, clamped(length)); }, error);
}

bool Client::tls_pending() {
    std::lock_guard<std::mutex> lock(ssl_mu_);
    return SSL_has_pending(ssl_.get()) != 0;
}

bool Client::tls_readable() {
    std::lock_guard<std::mutex> lock(ssl_mu_);
    return SSL_pending(ssl_.get()) > 0;
}

Client::~Client() {
    if (writer_.joinable()) {  // it writes what is pending first (bounded by the timeout)
        {
            std::lock_guard<std::mutex> lock(send_mu_);
            writer_stop_ = true;
        }
        writer_work_.notify_all();
        writer_.join();
    }
    if (ssl_) {  // close_notify, if the socket takes it: the gateway sees a clean end
        std::lock_guard<std::mutex> lock(ssl_mu_);
        SSL_shutdown(ssl_.get());
        ERR_clear_error();
        ssl_.reset();
    }
    if (fd_ >= 0) ::close(fd_);
    if (datagram_fd_ >= 0) ::close(datagram_fd_);
}

// ---- plumbing ----
}  // namespace hlacore
