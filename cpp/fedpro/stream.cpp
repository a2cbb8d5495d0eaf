#include "fedpro/stream.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <openssl/err.h>

#include <cerrno>
#include <cstdio>

#include "fedpro/websocket.hpp"

namespace hlacore::fedpro {

namespace {

constexpr std::chrono::milliseconds kPollSlice{200};

// Waits up to a slice for `events` on `fd`; adds the slice to `waited` when nothing came.
void wait_for(int fd, short events, std::chrono::milliseconds& waited) {
    pollfd p{fd, events, 0};
    if (::poll(&p, 1, int(kPollSlice.count())) == 0) waited += kPollSlice;
}

}  // namespace

SocketStream::~SocketStream() { ::close(fd_); }

void SocketStream::shutdown() { ::shutdown(fd_, SHUT_RDWR); }

long SocketStream::receive_some(char* out, std::size_t n, short& wait) {
    const ssize_t got = ::recv(fd_, out, n, 0);
    if (got > 0) return got;
    if (got < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) {
        wait = POLLIN;
        return 0;
    }
    return -1;
}

long SocketStream::send_some(char const* in, std::size_t n, short& wait) {
    const ssize_t put = ::send(fd_, in, n, MSG_NOSIGNAL);
    if (put >= 0) return put > 0 ? put : (wait = POLLOUT, 0);
    if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) {
        wait = POLLOUT;
        return 0;
    }
    return -1;
}

bool SocketStream::read_exact(char* out, std::size_t n, std::atomic<bool> const& stop, std::chrono::milliseconds idle) {
    std::chrono::milliseconds quiet{0};
    while (n > 0) {
        if (stop) return false;
        short wait = POLLIN;
        const long got = receive_some(out, n, wait);
        if (got < 0) return false;
        if (got > 0) {
            out += got;
            n -= std::size_t(got);
            quiet = {};
            continue;
        }
        if (idle.count() && quiet >= idle) return false;
        wait_for(fd_, wait, quiet);
    }
    return true;
}

bool SocketStream::write_all(std::string_view bytes, std::chrono::milliseconds stall) {
    std::chrono::milliseconds waited{0};
    while (!bytes.empty()) {
        short wait = POLLOUT;
        const long put = send_some(bytes.data(), bytes.size(), wait);
        if (put < 0) return false;
        if (put > 0) {
            bytes.remove_prefix(std::size_t(put));
            waited = {};
            continue;
        }
        if (waited >= stall) return false;
        wait_for(fd_, wait, waited);
    }
    return true;
}

TlsStream::TlsStream(int fd, SSL_CTX* context) : SocketStream(fd), ssl_(tls::session(context, fd)) {
    SSL_set_accept_state(ssl_.get());
}

long TlsStream::step(int n, short& wait) {
    if (n > 0) return n;
    switch (SSL_get_error(ssl_.get(), n)) {
        case SSL_ERROR_WANT_READ: wait = POLLIN; return 0;
        case SSL_ERROR_WANT_WRITE: wait = POLLOUT; return 0;
        default: ERR_clear_error(); return -1;  // the end of the stream, or a broken one: the connection drops
    }
}

long TlsStream::receive_some(char* out, std::size_t n, short& wait) {
    std::lock_guard<std::mutex> lock(ssl_mutex_);
    ERR_clear_error();
    return step(SSL_read(ssl_.get(), out, int(std::min<std::size_t>(n, 1 << 30))), wait);
}

long TlsStream::send_some(char const* in, std::size_t n, short& wait) {
    std::lock_guard<std::mutex> lock(ssl_mutex_);
    ERR_clear_error();
    return step(SSL_write(ssl_.get(), in, int(std::min<std::size_t>(n, 1 << 30))), wait);
}

bool TlsStream::handshake(std::atomic<bool> const& stop, std::chrono::milliseconds idle) {
    std::chrono::milliseconds quiet{0};
    while (!stop && quiet < idle) {
        short wait = POLLIN;
        std::string why;
        {
            std::lock_guard<std::mutex> lock(ssl_mutex_);
            ERR_clear_error();
            const int r = SSL_do_handshake(ssl_.get());
            if (r == 1) return true;
            const int e = SSL_get_error(ssl_.get(), r);
            if (e == SSL_ERROR_WANT_READ) wait = POLLIN;
            else if (e == SSL_ERROR_WANT_WRITE) wait = POLLOUT;
            else why = tls::errors("the connection closed");
        }
        if (!why.empty()) {
            std::fprintf(stderr, "fedpro: a connection closed in its TLS handshake: %s\n", why.c_str());
            return false;
        }
        wait_for(fd_, wait, quiet);
    }
    return false;
}

bool WebSocketStream::handshake(std::atomic<bool> const& stop, std::chrono::milliseconds idle) {
    // Byte by byte up to the blank line, so that nothing of the first frame is taken; within `idle` in all.
    const auto deadline = std::chrono::steady_clock::now() + idle;
    std::string request;
    while (request.size() < 4 || request.compare(request.size() - 4, 4, "\r\n\r\n") != 0) {
        if (request.size() >= websocket::kMaxRequest) {
            inner_->write_all(websocket::refusal("an opening handshake over 8 KiB"), std::chrono::milliseconds(1000));
            std::fprintf(stderr, "fedpro: a WebSocket connection refused: its opening handshake is over 8 KiB\n");
            return false;
        }
        if (std::chrono::steady_clock::now() > deadline) return false;
        char c;
        if (!inner_->read_exact(&c, 1, stop, idle)) return false;
        request += c;
    }
    try {
        const websocket::Upgrade upgrade = websocket::parse_upgrade(request);
        return inner_->write_all(websocket::accept_response(upgrade.key), std::chrono::milliseconds(1000));
    } catch (BadMessage const& e) {
        inner_->write_all(websocket::refusal(e.what()), std::chrono::milliseconds(1000));
        std::fprintf(stderr, "fedpro: a WebSocket connection refused: %s\n", e.what());
        return false;
    }
}

bool WebSocketStream::next_frame(std::atomic<bool> const& stop, std::chrono::milliseconds idle) {
    using websocket::Opcode;
    for (;;) {
        char head[14];
        if (!inner_->read_exact(head, 2, stop, idle)) return false;
        const std::size_t size = websocket::header_size({head, 2});
        if (!inner_->read_exact(head + 2, size - 2, stop, idle)) return false;
        const websocket::FrameHeader h = websocket::decode_header({head, size}, max_frame_);
        if (h.opcode >= Opcode::Close) {
            char payload[websocket::kMaxControl];
            if (!inner_->read_exact(payload, std::size_t(h.length), stop, idle)) return false;
            websocket::unmask(payload, std::size_t(h.length), h.mask, 0);
            const std::string_view body(payload, std::size_t(h.length));
            if (h.opcode == Opcode::Ping) write_frame(int(Opcode::Pong), body, std::chrono::milliseconds(1000));
            if (h.opcode == Opcode::Close) {
                write_frame(int(Opcode::Close), body.substr(0, 2), std::chrono::milliseconds(1000));
                return false;
            }
            continue;
        }
        if (h.opcode == Opcode::Text) throw BadMessage("a WebSocket text frame: the Federate Protocol travels in binary frames");
        if ((h.opcode == Opcode::Continuation) != in_message_)
            throw BadMessage(in_message_ ? "a WebSocket message begun within another" : "a WebSocket continuation of no message");
        in_message_ = !h.fin;
        left_ = h.length;
        offset_ = 0;
        mask_ = h.mask;
        if (left_ > 0) return true;
    }
}

bool WebSocketStream::read_exact(char* out, std::size_t n, std::atomic<bool> const& stop, std::chrono::milliseconds idle) {
    while (n > 0) {
        if (left_ == 0 && !next_frame(stop, idle)) return false;
        const std::size_t take = std::size_t(std::min<std::uint64_t>(n, left_));
        if (!inner_->read_exact(out, take, stop, idle)) return false;
        websocket::unmask(out, take, mask_, offset_);
        offset_ += take;
        left_ -= take;
        out += take;
        n -= take;
    }
    return true;
}

bool WebSocketStream::write_frame(int opcode, std::string_view payload, std::chrono::milliseconds stall) {
    const std::string header = websocket::encode_header(websocket::Opcode(opcode), payload.size());
    std::lock_guard<std::mutex> lock(write_mutex_);
    if (payload.size() <= 4096) return inner_->write_all(header + std::string(payload), stall);
    return inner_->write_all(header, stall) && inner_->write_all(payload, stall);
}

void WebSocketStream::shutdown() {
    std::unique_lock<std::mutex> lock(write_mutex_, std::try_to_lock);  // not while a frame is half written
    if (lock.owns_lock()) inner_->write_all(websocket::encode_header(websocket::Opcode::Close, 2) + "\x03\xe9", {});
    inner_->shutdown();
}

bool WebSocketStream::write_all(std::string_view bytes, std::chrono::milliseconds stall) {
    return write_frame(int(websocket::Opcode::Binary), bytes, stall);
}

}  // namespace hlacore::fedpro
