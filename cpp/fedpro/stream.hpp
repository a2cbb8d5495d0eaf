// A door connection's bytes, whatever carries them: the Federate Protocol's four transports are TCP, TLS on it,
// and WebSocket on either. A session reads its connection on one thread and writes to it from the threads that
// answer calls and deliver callbacks (one at a time: the session's lock), so a TLS stream keeps each SSL call under
// a lock of its own, never held while waiting, and a WebSocket stream's pong never cuts into a frame.
// Every wait polls in slices, so a stop is seen within 200 ms and no call blocks for good.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

#include "rti/tls.hpp"

namespace hlacore::fedpro {

class Stream {
public:
    virtual ~Stream() = default;
    // Exactly `n` bytes into `out`; false on the end of the stream, an error, `stop`, or nothing for `idle`
    // (when nonzero). BadMessage when the transport's own framing is broken.
    virtual bool read_exact(char* out, std::size_t n, std::atomic<bool> const& stop, std::chrono::milliseconds idle = {}) = 0;
    // All of `bytes` (for WebSocket: one frame); false on an error or a peer that takes nothing for `stall`.
    virtual bool write_all(std::string_view bytes, std::chrono::milliseconds stall) = 0;
    // Ends the connection both ways: its reader sees the end. The descriptor closes with the stream.
    virtual void shutdown() = 0;
};

// Plain TCP on a non-blocking socket, which it closes.
class SocketStream : public Stream {
public:
    explicit SocketStream(int fd) : fd_(fd) {}
    ~SocketStream() override;
    SocketStream(SocketStream const&) = delete;
    SocketStream& operator=(SocketStream const&) = delete;
    bool read_exact(char* out, std::size_t n, std::atomic<bool> const& stop, std::chrono::milliseconds idle = {}) override;
    bool write_all(std::string_view bytes, std::chrono::milliseconds stall) override;
    void shutdown() override;

protected:
    // One step each way: the bytes moved (> 0), 0 when it would block (`wait`: the poll event to wait for),
    // -1 at the end of the stream or on an error. Tried before any poll, so bytes a TLS session holds already
    // decrypted are never left waiting for the socket.
    virtual long receive_some(char* out, std::size_t n, short& wait);
    virtual long send_some(char const* in, std::size_t n, short& wait);
    int fd_;
};

// TLS (OpenSSL, rti/tls.hpp) on a SocketStream's socket, the server's side.
class TlsStream : public SocketStream {
public:
    TlsStream(int fd, SSL_CTX* context);
    // The handshake; false, saying why on stderr, when it fails, `stop` is set or the client is silent for `idle`.
    bool handshake(std::atomic<bool> const& stop, std::chrono::milliseconds idle);

protected:
    long receive_some(char* out, std::size_t n, short& wait) override;
    long send_some(char const* in, std::size_t n, short& wait) override;

private:
    long step(int n, short& wait);
    std::mutex ssl_mutex_;
    tls::Session ssl_;
};

// WebSocket (RFC 6455, fedpro/websocket.hpp), the server's side, on another stream it owns: the binary frames'
// payloads make the stream read; each write_all is one binary frame; pings are answered, a close frame ends it.
class WebSocketStream : public Stream {
public:
    WebSocketStream(std::unique_ptr<Stream> inner, std::uint64_t max_frame) : inner_(std::move(inner)), max_frame_(max_frame) {}
    // Reads the client's opening handshake and answers it; false when it is not one (refused with status 400 and
    // the reason, also said on stderr) or when the client is silent for `idle`.
    bool handshake(std::atomic<bool> const& stop, std::chrono::milliseconds idle);
    bool read_exact(char* out, std::size_t n, std::atomic<bool> const& stop, std::chrono::milliseconds idle = {}) override;
    bool write_all(std::string_view bytes, std::chrono::milliseconds stall) override;
    // A close frame first (going away), when it goes out at once: the client sees the end as a WebSocket's.
    void shutdown() override;

private:
    bool next_frame(std::atomic<bool> const& stop, std::chrono::milliseconds idle);
    bool write_frame(int opcode, std::string_view payload, std::chrono::milliseconds stall);
    std::unique_ptr<Stream> inner_;
    std::uint64_t max_frame_;
    std::mutex write_mutex_;
    std::uint64_t left_ = 0, offset_ = 0;  // of the data frame being read: its bytes still to come, those read
    std::array<std::uint8_t, 4> mask_{};
    bool in_message_ = false;  // a data frame without FIN was read: continuations follow
};

}  // namespace hlacore::fedpro
