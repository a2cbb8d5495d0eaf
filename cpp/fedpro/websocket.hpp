// WebSocket (RFC 6455), the server's side, as pure functions: the opening handshake a client sends and our
// answer, and the frame headers. The Federate Protocol over WebSocket carries its messages as the payload of
// binary frames, a byte stream the session reads as it reads TCP (a message may span frames, a frame hold
// several). No sockets here (stream.hpp has them), so the decoders are fuzzed on their own
// (cpp/fuzz/fuzz_websocket.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fedpro/session_protocol.hpp"  // BadMessage

namespace hlacore::fedpro::websocket {

enum class Opcode : std::uint8_t { Continuation = 0, Text = 1, Binary = 2, Close = 8, Ping = 9, Pong = 10 };

constexpr std::size_t kMaxRequest = 8192;   // an opening handshake longer than this is refused
constexpr std::size_t kMaxControl = 125;    // a control frame's payload, at most

struct FrameHeader {
    bool fin = true;
    Opcode opcode = Opcode::Binary;
    bool masked = false;
    std::uint64_t length = 0;
    std::array<std::uint8_t, 4> mask{};
    std::size_t size = 0;  // the header's bytes
};

// How many bytes the frame header starting with `first_two` takes (2 to 14).
std::size_t header_size(std::string_view first_two);
// The whole header in `bytes` (header_size of them). BadMessage for reserved bits set, an unknown opcode, a
// control frame fragmented or longer than kMaxControl, a payload over `max_length`, or an unmasked frame (a
// client masks every frame).
FrameHeader decode_header(std::string_view bytes, std::uint64_t max_length);
// A server's frame header (final, unmasked) for a payload of `length` bytes.
std::string encode_header(Opcode opcode, std::uint64_t length);
// XORs `n` bytes of a payload with its mask, `offset` being where they start in the payload.
void unmask(char* data, std::size_t n, std::array<std::uint8_t, 4> const& mask, std::uint64_t offset);

// The client's opening handshake, up to and including the blank line: a GET of HTTP/1.1 or later asking to
// upgrade to websocket, version 13, with its key. BadMessage saying what is wrong.
struct Upgrade {
    std::string path;
    std::string key;
};
Upgrade parse_upgrade(std::string_view request);
// Our 101 answer to `key`, and a refusal (status 400) saying why.
std::string accept_response(std::string_view key);
std::string refusal(std::string_view why);
// base64(SHA-1(key + the protocol's GUID)): Sec-WebSocket-Accept.
std::string accept_key(std::string_view key);

}  // namespace hlacore::fedpro::websocket
