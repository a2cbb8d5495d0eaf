#include "fedpro/websocket.hpp"

#include <openssl/evp.h>
#include <openssl/sha.h>

#include <algorithm>
#include <cctype>

namespace hlacore::fedpro::websocket {

namespace {

constexpr std::string_view kGuid = "258EAFA5-E914-47DA-95CA-C5AB0DC85B11";

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return out;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// Whether the comma-separated `list` holds `token` (case-insensitive): "keep-alive, Upgrade" holds "upgrade".
bool has_token(std::string_view list, std::string_view token) {
    while (!list.empty()) {
        const auto comma = list.find(',');
        if (lower(trim(list.substr(0, comma))) == token) return true;
        if (comma == std::string_view::npos) break;
        list.remove_prefix(comma + 1);
    }
    return false;
}

}  // namespace

std::size_t header_size(std::string_view first_two) {
    const auto b1 = std::uint8_t(first_two.at(1));
    const std::size_t extended = (b1 & 0x7F) == 126 ? 2 : (b1 & 0x7F) == 127 ? 8 : 0;
    return 2 + extended + ((b1 & 0x80) ? 4 : 0);
}

FrameHeader decode_header(std::string_view bytes, std::uint64_t max_length) {
    if (bytes.size() < 2 || bytes.size() < header_size(bytes)) throw BadMessage("a WebSocket frame header cut short");
    const auto b0 = std::uint8_t(bytes[0]), b1 = std::uint8_t(bytes[1]);
    FrameHeader h;
    h.fin = b0 & 0x80;
    if (b0 & 0x70) throw BadMessage("a WebSocket frame with reserved bits set (no extension was agreed)");
    const unsigned op = b0 & 0x0F;
    if (op > 2 && (op < 8 || op > 10)) throw BadMessage("a WebSocket frame of unknown opcode " + std::to_string(op));
    h.opcode = Opcode(op);
    h.masked = b1 & 0x80;
    std::size_t at = 2;
    h.length = b1 & 0x7F;
    if (h.length >= 126) {
        const std::size_t n = h.length == 126 ? 2 : 8;
        h.length = 0;
        for (std::size_t i = 0; i < n; ++i) h.length = (h.length << 8) | std::uint8_t(bytes[at++]);
    }
    if (op >= 8 && (!h.fin || h.length > kMaxControl))
        throw BadMessage("a WebSocket control frame fragmented or longer than 125 bytes");
    if (h.length > max_length)
        throw BadMessage("a WebSocket frame of " + std::to_string(h.length) + " bytes, over the limit of " + std::to_string(max_length));
    if (!h.masked) throw BadMessage("an unmasked WebSocket frame from a client");
    for (auto& m : h.mask) m = std::uint8_t(bytes[at++]);
    h.size = at;
    return h;
}

std::string encode_header(Opcode opcode, std::uint64_t length) {
    std::string out(1, char(0x80 | std::uint8_t(opcode)));
    if (length < 126) {
        out += char(length);
    } else if (length <= 0xFFFF) {
        out += char(126);
        out += char(length >> 8);
        out += char(length);
    } else {
        out += char(127);
        for (int shift = 56; shift >= 0; shift -= 8) out += char(length >> shift);
    }
    return out;
}

void unmask(char* data, std::size_t n, std::array<std::uint8_t, 4> const& mask, std::uint64_t offset) {
    for (std::size_t i = 0; i < n; ++i) data[i] = char(std::uint8_t(data[i]) ^ mask[(offset + i) & 3]);
}

Upgrade parse_upgrade(std::string_view request) {
    const auto line_end = request.find("\r\n");
    if (line_end == std::string_view::npos) throw BadMessage("not an HTTP request");
    const std::string_view line = request.substr(0, line_end);
    const auto sp1 = line.find(' '), sp2 = line.rfind(' ');
    if (sp1 == std::string_view::npos || sp1 == sp2 || line.substr(0, sp1) != "GET" ||
        line.substr(sp2 + 1).substr(0, 5) != "HTTP/" || line.substr(sp2 + 1) < "HTTP/1.1")
        throw BadMessage("not a GET of HTTP/1.1: '" + std::string(line.substr(0, 80)) + "'");
    Upgrade u;
    u.path = std::string(line.substr(sp1 + 1, sp2 - sp1 - 1));
    bool upgrade = false, connection = false, version = false;
    for (std::string_view rest = request.substr(line_end + 2); !rest.empty();) {
        const auto end = rest.find("\r\n");
        const std::string_view field = rest.substr(0, end);
        rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 2);
        const auto colon = field.find(':');
        if (field.empty() || colon == std::string_view::npos) continue;
        const std::string name = lower(trim(field.substr(0, colon)));
        const std::string_view value = trim(field.substr(colon + 1));
        if (name == "upgrade") upgrade = has_token(value, "websocket");
        else if (name == "connection") connection = has_token(value, "upgrade");
        else if (name == "sec-websocket-version") version = value == "13";
        else if (name == "sec-websocket-key") u.key = std::string(value);
    }
    if (!upgrade || !connection) throw BadMessage("an HTTP request that does not ask to upgrade to websocket");
    if (!version) throw BadMessage("a WebSocket version other than 13");
    if (u.key.size() != 24) throw BadMessage("a Sec-WebSocket-Key that is not 16 bytes in base64");
    return u;
}

std::string accept_key(std::string_view key) {
    const std::string text = std::string(key) + std::string(kGuid);
    unsigned char digest[SHA_DIGEST_LENGTH];
    SHA1(reinterpret_cast<const unsigned char*>(text.data()), text.size(), digest);
    unsigned char out[4 * ((SHA_DIGEST_LENGTH + 2) / 3) + 1];
    const int n = EVP_EncodeBlock(out, digest, SHA_DIGEST_LENGTH);
    return std::string(reinterpret_cast<char*>(out), std::size_t(n));
}

std::string accept_response(std::string_view key) {
    return "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept: " +
           accept_key(key) + "\r\n\r\n";
}

std::string refusal(std::string_view why) {
    const std::string body = "This is the HLA 4 Federate Protocol over WebSocket: " + std::string(why) + "\n";
    return "HTTP/1.1 400 Bad Request\r\nSec-WebSocket-Version: 13\r\nContent-Type: text/plain\r\nContent-Length: " +
           std::to_string(body.size()) + "\r\nConnection: close\r\n\r\n" + body;
}

}  // namespace hlacore::fedpro::websocket
