#pragma once
// Reads the values of a PLY body one at a time, hiding whether it is ASCII or binary (either byte order), and
// reports problems with the file, the line (ASCII only) and the record being read. Never reads past the data.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "geometry/mesh/ply_header.h"

namespace isotrace {

class PlyValueReader {
public:
    virtual ~PlyValueReader() = default;

    // Brackets record `index` of `element`; ASCII records are lines, so end_record() checks nothing is left over.
    virtual void begin_record(const std::string& element, std::uint64_t index) = 0;
    virtual void end_record() = 0;
    // Fails unless only what may trail a body is left.
    virtual void expect_end() = 0;

    // The next value, declared in the header with `type`; `property` names it in messages.
    virtual double read(PlyScalarType type, std::string_view property) = 0;
    // The next value, which must be a whole number (list counts, vertex indices).
    std::int64_t read_integer(PlyScalarType type, std::string_view property);

    std::size_t remaining_bytes() const { return body_.size() - position_; }

    // Throws InputError for the current record: "file:line: vertex 3: problem".
    [[noreturn]] void fail(const std::string& problem) const;

protected:
    PlyValueReader(std::string_view body, const std::string& file, int line) : body_(body), file_(file), line_(line) {}

    std::string_view body_;
    std::size_t position_ = 0;
    const std::string& file_;
    int line_;  // of the current record; 0 for binary bodies
    const std::string* element_ = nullptr;
    std::uint64_t record_ = 0;
};

// `contents` is the whole file; the reader starts where `header` says the body does.
std::unique_ptr<PlyValueReader> make_ply_value_reader(const PlyHeader& header, std::string_view contents,
                                                      const std::string& file);

}  // namespace isotrace
