#include "fed_parser/lexer.hpp"

#include <array>

#include "fed_parser/fom.hpp"

namespace hlacore::fom::detail {
namespace {

enum CharClass : std::uint8_t { Other, Space, WordChar };

constexpr std::array<std::uint8_t, 256> make_classes() {
    std::array<std::uint8_t, 256> c{};
    for (unsigned char ch : {' ', '\t', '\r', '\n', '\f', '\v'}) c[ch] = Space;
    for (int ch = 'a'; ch <= 'z'; ++ch) c[ch] = WordChar;
    for (int ch = 'A'; ch <= 'Z'; ++ch) c[ch] = WordChar;
    for (int ch = '0'; ch <= '9'; ++ch) c[ch] = WordChar;
    // Words are scanned wider than identifiers (a FEDversion such as "1.3" starts with a digit);
    // the parser checks the identifier rule where a name is expected.
    c[static_cast<unsigned char>('_')] = WordChar;
    c[static_cast<unsigned char>('-')] = WordChar;
    c[static_cast<unsigned char>('.')] = WordChar;
    return c;
}

constexpr std::array<std::uint8_t, 256> kClass = make_classes();

inline std::uint8_t class_of(char ch) { return kClass[static_cast<unsigned char>(ch)]; }

// Length of the valid UTF-8 sequence starting at text[i], 0 if invalid.
std::size_t utf8_length(std::string_view text, std::size_t i) {
    const auto b = static_cast<unsigned char>(text[i]);
    std::size_t n = 0;
    if (b >= 0xC2 && b <= 0xDF) n = 2;
    else if (b >= 0xE0 && b <= 0xEF) n = 3;
    else if (b >= 0xF0 && b <= 0xF4) n = 4;
    else return 0;
    if (i + n > text.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return 0;
    }
    return n;
}

}  // namespace

std::string quote_for_message(std::string_view text) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto b = static_cast<unsigned char>(text[i]);
        if (b >= 0x20 && b < 0x7F) {
            out += text[i++];
        } else if (std::size_t n = utf8_length(text, i)) {
            out.append(text.substr(i, n));
            i += n;
        } else {
            out += "\\x";
            out += kHex[b >> 4];
            out += kHex[b & 0xF];
            ++i;
        }
    }
    return out;
}

Lexer::Lexer(std::string_view text, std::string_view file_name) : text_(text), file_name_(file_name) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;  // UTF-8 byte order mark left by some editors
}

const Token& Lexer::peek() {
    if (!has_lookahead_) {
        lookahead_ = scan();
        has_lookahead_ = true;
    }
    return lookahead_;
}

Token Lexer::next() {
    if (has_lookahead_) {
        has_lookahead_ = false;
        return lookahead_;
    }
    return scan();
}

Token Lexer::scan() {
    const std::size_t n = text_.size();
    for (;;) {
        while (pos_ < n && class_of(text_[pos_]) == Space) ++pos_;
        if (pos_ >= n) return Token{TokenKind::End, {}, n};
        if (text_[pos_] != ';') break;
        if (pos_ + 1 < n && text_[pos_ + 1] == ';') {
            const std::size_t eol = text_.find('\n', pos_);
            pos_ = eol == std::string_view::npos ? n : eol + 1;
            continue;
        }
        fail(pos_, "invalid character ';' (comments start with ';;')");
    }

    const std::size_t start = pos_;
    const char ch = text_[pos_];
    if (ch == '(') {
        ++pos_;
        return Token{TokenKind::LParen, {}, start};
    }
    if (ch == ')') {
        ++pos_;
        return Token{TokenKind::RParen, {}, start};
    }
    if (ch == '"') {
        std::size_t i = start + 1;
        while (i < n && text_[i] != '"' && text_[i] != '\n') ++i;
        if (i >= n || text_[i] != '"') fail(start, "unterminated string (a string ends with '\"' on the same line)");
        pos_ = i + 1;
        return Token{TokenKind::String, text_.substr(start + 1, i - start - 1), start};
    }
    if (class_of(ch) == WordChar) {
        std::size_t i = start + 1;
        while (i < n && class_of(text_[i]) == WordChar) ++i;
        pos_ = i;
        return Token{TokenKind::Word, text_.substr(start, i - start), start};
    }
    const std::size_t len = utf8_length(text_, start);
    fail(start, "invalid character '" + quote_for_message(text_.substr(start, len ? len : 1)) + "'");
}

Position Lexer::position(std::size_t offset) const {
    if (offset > text_.size()) offset = text_.size();
    Position p;
    std::size_t line_start = 0;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text_[i] == '\n') {
            ++p.line;
            line_start = i + 1;
        }
    }
    if (line_start == 0 && text_.substr(0, 3) == "\xEF\xBB\xBF" && offset >= 3) line_start = 3;
    for (std::size_t i = line_start; i < offset; ++i) {
        if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++p.column;
    }
    return p;
}

void Lexer::fail(std::size_t offset, const std::string& message) const {
    const Position p = position(offset);
    throw FedError(std::string(file_name_), p.line, p.column, message);
}

}  // namespace hlacore::fom::detail
