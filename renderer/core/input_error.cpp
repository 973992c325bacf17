#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

// Control characters from the input (a NUL in a JSON key, say) are spelled out: a NUL would end what() early,
// and the others garble a terminal. Line breaks and tabs stay.
std::string printable(const std::string& text) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if ((byte < 0x20 && c != '\n' && c != '\t') || byte == 0x7f) {
            out += "\\x";
            out += kHex[byte >> 4];
            out += kHex[byte & 15];
        } else {
            out += c;
        }
    }
    return out;
}

std::string format_message(const SourceLocation& where, const std::string& field, const std::string& problem) {
    std::string message;
    if (!where.file.empty()) {
        message += printable(where.file);
        if (where.line > 0) message += ":" + std::to_string(where.line);
        if (where.column > 0) message += ":" + std::to_string(where.column);
        message += ": ";
    }
    if (!field.empty()) message += printable(field) + ": ";
    return message + printable(problem);
}

}  // namespace

InputError::InputError(SourceLocation location, std::string field, const std::string& problem)
    : std::runtime_error(format_message(location, field, problem)),
      location_(std::move(location)),
      field_(std::move(field)),
      problem_(problem) {}

}  // namespace isotrace
