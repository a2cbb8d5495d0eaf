// The gateway's stream I/O on a connection: plain TCP or a Unix socket, or TLS on either side of OpenSSL's
// non-blocking session; reads into the connection's buffer, writes from its queue.
#include "rti/server/gateway.hpp"
#include "rti/server/gateway_internal.hpp"

#include <cerrno>
#include <climits>
#include <cstring>

#include <sys/socket.h>

#include <openssl/err.h>
#include <openssl/ssl.h>

namespace hlacore {

std::string Gateway::read_plain(Connection& c, std::size_t budget, bool& peer_closed) {
    for (std::size_t got = 0; got < budget && !c.in.holds_large_frame();) {
        const std::size_t want = c.in.wanted(options_.max_frame_bytes);
        const ssize_t n = ::recv(c.fd, c.in.room(want), want, 0);
        if (n > 0) {
            if (c.in.empty()) c.partial_since = Clock::now();
            c.in.commit(static_cast<std::size_t>(n));
            got += static_cast<std::size_t>(n);
            if (static_cast<std::size_t>(n) < want) break;
            continue;
        }
        if (n == 0) {
            peer_closed = true;
            break;
        }
        if (errno == EINTR) continue;
        if (errno == EAGAIN || errno == EWOULDBLOCK) break;
        return std::string("read failed: ") + std::strerror(errno);
    }
    if (!c.greeted && tls::looks_like_record(c.in.unread()))
        return "it began a TLS handshake and this gateway has no TLS (rtig --tls-cert FILE --tls-key FILE)";
    return "";
}

// SSL_read until the session holds nothing more (SSL_has_pending) or wants more from the socket, so that no
// decrypted byte, nor a whole record, waits inside it while epoll reports nothing: what it may keep is the
// start of a record whose rest is still to come, which epoll will report.
std::string Gateway::read_tls(Connection& c, std::size_t budget, bool& peer_closed) {
    SSL* ssl = c.ssl.get();
    const bool waited_for_write = c.read_wants_write, write_waited = c.write_wants_read;
    c.read_wants_write = false;
    for (std::size_t got = 0; got < budget || SSL_has_pending(ssl);) {
        ERR_clear_error();
        errno = 0;
        const std::size_t want = std::min<std::size_t>(c.in.wanted(options_.max_frame_bytes), INT_MAX);
        const int n = SSL_read(ssl, c.in.room(want), static_cast<int>(want));
        if (n > 0) {
            if (c.in.empty()) c.partial_since = Clock::now();
            c.in.commit(static_cast<std::size_t>(n));
            got += static_cast<std::size_t>(n);
            if (!SSL_has_pending(ssl) && static_cast<std::size_t>(n) < want) break;
            continue;
        }
        const bool handshaking = !SSL_is_init_finished(ssl);
        switch (SSL_get_error(ssl, n)) {
            case SSL_ERROR_WANT_READ: break;
            case SSL_ERROR_WANT_WRITE:
                c.read_wants_write = true;
                break;
            case SSL_ERROR_ZERO_RETURN: peer_closed = true; break;
            case SSL_ERROR_SYSCALL:
                if (errno == 0 || errno == ECONNRESET) {
                    if (handshaking) return "connection closed during the TLS handshake";
                    peer_closed = true;
                    break;
                }
                return std::string("read failed: ") + std::strerror(errno);
            default: {
                if (!handshaking) return "TLS error: " + tls::errors("protocol error");
                // What the client sent besides is read and dropped, so that closing sends a FIN rather than a
                // reset that could overtake an alert: a client without TLS sees the connection closed (or
                // reads the alert, when OpenSSL sent one) and says what to do.
                char chunk[4096];
                for (int i = 0; i < 4 && ::recv(c.fd, chunk, sizeof chunk, MSG_DONTWAIT) > 0; ++i) {
                }
                // An alert from the client (OpenSSL's reasons from SSL_AD_REASON_OFFSET on): it refused the
                // certificate, most often; anything else at this stage is most often not TLS at all.
                const bool alert = ERR_GET_REASON(ERR_peek_error()) >= SSL_AD_REASON_OFFSET;
                return alert ? "TLS handshake failed: the client refused it (" + tls::errors() + ")"
                             : "TLS handshake failed (a client without TLS?): " + tls::errors("protocol error");
            }
        }
        break;
    }
    if (write_waited) {  // the write that waited for a read may go on
        c.write_wants_read = false;
        mark_dirty(c);
    }
    if (waited_for_write != c.read_wants_write || write_waited) update_events(c);
    return "";
}

long Gateway::write_some(Connection& c, std::string& error) {
    const std::size_t left = c.out.size() - c.out_offset;
    if (!c.ssl) {
        for (;;) {
            const ssize_t n = c.splices.empty() ? ::send(c.fd, c.out.data() + c.out_offset, left, MSG_NOSIGNAL)
                                                : c.write_queued();
            if (n > 0) return static_cast<long>(n);
            if (n < 0 && errno == EINTR) continue;
            if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return 0;
            error = std::string("write failed: ") + std::strerror(n < 0 ? errno : EPIPE);
            return -1;
        }
    }
    // Partial writes are on and the buffer may move: a retry after WANT_WRITE passes the same bytes from
    // c.out_offset on, with more behind them perhaps, as OpenSSL requires.
    ERR_clear_error();
    errno = 0;
    const int n = SSL_write(c.ssl.get(), c.out.data() + c.out_offset, static_cast<int>(std::min<std::size_t>(left, INT_MAX)));
    if (n > 0) return n;
    switch (SSL_get_error(c.ssl.get(), n)) {
        case SSL_ERROR_WANT_WRITE: return 0;
        case SSL_ERROR_WANT_READ:  // not after the handshake (no renegotiation); EPOLLIN brings it back
            c.write_wants_read = true;
            update_events(c);
            return 0;
        case SSL_ERROR_SYSCALL:
            error = std::string("write failed: ") + std::strerror(errno ? errno : EPIPE);
            return -1;
        default:
            error = "TLS error while writing: " + tls::errors("protocol error");
            return -1;
    }
}

}  // namespace hlacore
