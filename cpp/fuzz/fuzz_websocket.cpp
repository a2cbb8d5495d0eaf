// libFuzzer target for the Federate Protocol's WebSocket decoders (cpp/fedpro/websocket.hpp): arbitrary bytes as
// what a client sends, first as an opening handshake (up to the blank line), then as frame headers one after
// another, each payload skipped.
//
// The only exception allowed out is BadMessage. An accepted handshake has a 24-character key; a decoded header
// takes the bytes header_size says, its payload is within the limit, a control frame's within 125 bytes and
// final; our own header for that length decodes (with a mask added) to the same length.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fedpro/websocket.hpp"

using namespace hlacore::fedpro;

namespace {
void check(bool ok) {
    if (!ok) std::abort();
}
constexpr std::uint64_t kLimit = 1u << 16;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view in(reinterpret_cast<const char*>(data), size);
    const auto blank = in.find("\r\n\r\n");
    try {
        const websocket::Upgrade u = websocket::parse_upgrade(in.substr(0, blank == std::string_view::npos ? in.size() : blank + 4));
        check(u.key.size() == 24 && websocket::accept_key(u.key).size() == 28);
    } catch (BadMessage const&) {
    }
    if (blank != std::string_view::npos) in.remove_prefix(blank + 4);
    try {
        while (in.size() >= 2) {
            const std::size_t n = websocket::header_size(in);
            check(n >= 2 && n <= 14);
            if (in.size() < n) break;
            const websocket::FrameHeader h = websocket::decode_header(in.substr(0, n), kLimit);
            check(h.size == n && h.masked && h.length <= kLimit);
            if (h.opcode >= websocket::Opcode::Close) check(h.fin && h.length <= websocket::kMaxControl);
            std::string ours = websocket::encode_header(h.opcode, h.length);
            ours[1] = char(std::uint8_t(ours[1]) | 0x80);
            ours.append(4, '\0');
            check(websocket::header_size(ours) == ours.size() && websocket::decode_header(ours, kLimit).length == h.length);
            in.remove_prefix(n);
            in.remove_prefix(std::min<std::size_t>(in.size(), std::size_t(h.length)));
        }
    } catch (BadMessage const&) {
    }
    return 0;
}
