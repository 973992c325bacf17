#include "geometry/expression/expression_lexer.h"

#include <cctype>
#include <charconv>

namespace isotrace {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool starts_name(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool continues_name(char c) { return starts_name(c) || is_digit(c); }

// digits [. digits] [e [+-] digits], or . digits [...]; `at` is on a digit or on a '.' before one.
std::size_t number_end(std::string_view text, std::size_t at) {
    std::size_t i = at;
    while (i < text.size() && is_digit(text[i])) ++i;
    if (i < text.size() && text[i] == '.') {
        ++i;
        while (i < text.size() && is_digit(text[i])) ++i;
    }
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        std::size_t j = i + 1;
        if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
        if (j >= text.size() || !is_digit(text[j]))
            throw ExpressionError{i, "the exponent of a number needs digits"};
        while (j < text.size() && is_digit(text[j])) ++j;
        i = j;
    }
    return i;
}

}  // namespace

std::vector<Token> tokenize(std::string_view text) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            ++i;
            continue;
        }
        if (is_digit(c) || (c == '.' && i + 1 < text.size() && is_digit(text[i + 1]))) {
            const std::size_t end = number_end(text, i);
            Token token{TokenKind::Number, i, text.substr(i, end - i)};
            const auto [rest, error] = std::from_chars(text.data() + i, text.data() + end, token.number);
            if (error != std::errc() || rest != text.data() + end)
                throw ExpressionError{i, "the number " + std::string(token.text) + " is out of range"};
            tokens.push_back(token);
            i = end;
            continue;
        }
        if (starts_name(c)) {
            std::size_t end = i;
            while (end < text.size() && continues_name(text[end])) ++end;
            tokens.push_back({TokenKind::Name, i, text.substr(i, end - i)});
            i = end;
            continue;
        }
        TokenKind kind;
        switch (c) {
            case '+': kind = TokenKind::Plus; break;
            case '-': kind = TokenKind::Minus; break;
            case '*': kind = TokenKind::Star; break;
            case '/': kind = TokenKind::Slash; break;
            case '^': kind = TokenKind::Caret; break;
            case '(': kind = TokenKind::Open; break;
            case ')': kind = TokenKind::Close; break;
            case ',': kind = TokenKind::Comma; break;
            case '.': kind = TokenKind::Dot; break;
            default: {
                const bool printable = static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f;
                throw ExpressionError{i, printable ? "unexpected character '" + std::string(1, c) + "'"
                                                   : "unexpected character"};
            }
        }
        tokens.push_back({kind, i, text.substr(i, 1)});
        ++i;
    }
    tokens.push_back({TokenKind::End, text.size(), {}});
    return tokens;
}

const char* token_description(TokenKind kind) {
    switch (kind) {
        case TokenKind::Number: return "a number";
        case TokenKind::Name: return "a name";
        case TokenKind::Plus: return "'+'";
        case TokenKind::Minus: return "'-'";
        case TokenKind::Star: return "'*'";
        case TokenKind::Slash: return "'/'";
        case TokenKind::Caret: return "'^'";
        case TokenKind::Open: return "'('";
        case TokenKind::Close: return "')'";
        case TokenKind::Comma: return "','";
        case TokenKind::Dot: return "'.'";
        case TokenKind::End: return "the end of the expression";
    }
    return "";
}

}  // namespace isotrace
