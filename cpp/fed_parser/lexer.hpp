// Tokens of an HLA 1.3 `.fed` file: parentheses, bare words, quoted strings; `;;` comments are skipped.
// Private to the parser.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace hlacore::fom::detail {

enum class TokenKind : std::uint8_t { LParen, RParen, Word, String, End };

struct Token {
    TokenKind kind = TokenKind::End;
    std::string_view text;  // the word, or a string's contents without the quotes; empty otherwise
    std::size_t offset = 0; // byte offset of the token's first character (the quote for a string)
};

struct Position {
    int line = 1;
    int column = 1;
};

class Lexer {
public:
    Lexer(std::string_view text, std::string_view file_name);

    Token next();
    const Token& peek();

    std::size_t end_offset() const { return text_.size(); }

    // Line and column (1-based; the column counts UTF-8 characters). Computed on demand because
    // positions are only needed for messages.
    Position position(std::size_t offset) const;

    [[noreturn]] void fail(std::size_t offset, const std::string& message) const;

private:
    Token scan();

    std::string_view text_;
    std::string_view file_name_;
    std::size_t pos_ = 0;
    Token lookahead_;
    bool has_lookahead_ = false;
};

// Quoted for a message: printable ASCII and valid UTF-8 as is, other bytes as \xNN.
std::string quote_for_message(std::string_view text);

}  // namespace hlacore::fom::detail
