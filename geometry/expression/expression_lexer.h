#pragma once
// The tokens of the expression language: numbers, names, operators and punctuation, each with its offset in the
// text (for error messages).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace isotrace {

enum class TokenKind { Number, Name, Plus, Minus, Star, Slash, Caret, Open, Close, Comma, Dot, End };

struct Token {
    TokenKind kind;
    std::size_t offset;  // of its first character
    std::string_view text;
    double number = 0;  // Number
};

// A problem in the expression text, at an offset; compile_expression turns it into an InputError at the character.
struct ExpressionError {
    std::size_t offset;
    std::string problem;
};

// The tokens of `text`, ending with End. Throws ExpressionError for a character that starts no token or a
// malformed number.
std::vector<Token> tokenize(std::string_view text);

// How a token kind is named in messages ("')'", "a number", "the end of the expression").
const char* token_description(TokenKind kind);

}  // namespace isotrace
