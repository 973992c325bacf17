#pragma once
// InputError: every problem caused by user input (scene files, meshes, images, command-line values).
// The CLI maps it to exit code 2 and prints what() verbatim, so the message must name the source.
#include <stdexcept>
#include <string>

namespace isotrace {

struct SourceLocation {
    std::string file;  // path as the user gave it (may be empty for command-line input)
    int line = 0;      // 1-based; 0 = unknown
    int column = 0;    // 1-based; 0 = unknown
};

class InputError : public std::runtime_error {
public:
    // `location` says where, `field` is the JSON path or field name ("objects[2].shape.radius"), may be empty.
    InputError(SourceLocation location, std::string field, const std::string& problem);

    const SourceLocation& location() const { return location_; }
    const std::string& field() const { return field_; }
    // The problem alone, without location and field (for re-throwing it at a better place).
    const std::string& problem() const { return problem_; }

private:
    SourceLocation location_;
    std::string field_;
    std::string problem_;
};

}  // namespace isotrace
