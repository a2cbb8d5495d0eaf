#include "rti/wire/json.hpp"

#include <charconv>
#include <cstdio>

namespace hlacore {

void json_string(std::string& out, std::string_view s) {
    out += '"';
    for (unsigned char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            out += escaped;
        } else {
            out += static_cast<char>(c);
        }
    }
    out += '"';
}

void json_number(std::string& out, double v) {
    if (!std::isfinite(v)) {
        out += "null";
        return;
    }
    char text[32];  // the shortest text that reads back as v
    out.append(text, std::to_chars(text, text + sizeof text, v).ptr);
}

void json_base64(std::string& out, std::string_view bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    out += '"';
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    std::size_t n = bytes.size(), i = 0;
    out.reserve(out.size() + (n + 2) / 3 * 4 + 1);
    for (; i + 3 <= n; i += 3) {
        const std::uint32_t v = p[i] << 16 | p[i + 1] << 8 | p[i + 2];
        const char quad[4] = {kDigits[v >> 18], kDigits[(v >> 12) & 63], kDigits[(v >> 6) & 63], kDigits[v & 63]};
        out.append(quad, 4);
    }
    if (n - i == 1) {
        const std::uint32_t v = p[i] << 16;
        const char quad[4] = {kDigits[v >> 18], kDigits[(v >> 12) & 63], '=', '='};
        out.append(quad, 4);
    } else if (n - i == 2) {
        const std::uint32_t v = p[i] << 16 | p[i + 1] << 8;
        const char quad[4] = {kDigits[v >> 18], kDigits[(v >> 12) & 63], kDigits[(v >> 6) & 63], '='};
        out.append(quad, 4);
    }
    out += '"';
}

namespace {
// Is `s` well-formed UTF-8 (no overlong forms, surrogates or code points above U+10FFFF)?
bool valid_utf8(std::string_view s) {
    const auto* p = reinterpret_cast<const unsigned char*>(s.data());
    const auto* end = p + s.size();
    while (p < end) {
        const unsigned char c = *p;
        std::size_t n;
        std::uint32_t cp;
        if (c < 0x80) {
            ++p;
            continue;
        } else if ((c & 0xE0) == 0xC0) {
            n = 1, cp = c & 0x1F;
        } else if ((c & 0xF0) == 0xE0) {
            n = 2, cp = c & 0x0F;
        } else if ((c & 0xF8) == 0xF0) {
            n = 3, cp = c & 0x07;
        } else {
            return false;
        }
        if (static_cast<std::size_t>(end - p) <= n) return false;
        for (std::size_t k = 1; k <= n; ++k) {
            if ((p[k] & 0xC0) != 0x80) return false;
            cp = cp << 6 | (p[k] & 0x3F);
        }
        static constexpr std::uint32_t kSmallest[] = {0, 0x80, 0x800, 0x10000};
        if (cp < kSmallest[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
        p += n + 1;
    }
    return true;
}
}  // namespace

void json_text(std::string& out, std::string_view text) {
    if (valid_utf8(text)) {
        json_string(out, text);
        return;
    }
    out += "{\"base64\":";
    json_base64(out, text);
    out += '}';
}

}  // namespace hlacore
