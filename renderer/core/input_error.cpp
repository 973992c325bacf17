#include "renderer/core/input_error.h"

#include "renderer/core/printable.h"

namespace isotrace {
namespace {

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
