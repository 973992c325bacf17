#include "geometry/mesh/ply_value_reader.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

std::string quoted(std::string_view text) { return "'" + std::string(text) + "'"; }

// Smallest and largest value each integer type can hold, for range checks on ASCII input.
std::array<double, 2> integer_range(PlyScalarType type) {
    switch (type) {
        case PlyScalarType::Int8: return {-128.0, 127.0};
        case PlyScalarType::UInt8: return {0.0, 255.0};
        case PlyScalarType::Int16: return {-32768.0, 32767.0};
        case PlyScalarType::UInt16: return {0.0, 65535.0};
        case PlyScalarType::Int32: return {-2147483648.0, 2147483647.0};
        case PlyScalarType::UInt32: return {0.0, 4294967295.0};
        case PlyScalarType::Float32:
        case PlyScalarType::Float64: break;
    }
    return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
}

// Records are lines; values are separated by spaces or tabs.
class AsciiPlyValueReader final : public PlyValueReader {
public:
    AsciiPlyValueReader(std::string_view body, const std::string& file, int first_line)
        : PlyValueReader(body, file, first_line), cursor_line_(first_line) {}

    void begin_record(const std::string& element, std::uint64_t index) override {
        element_ = &element;
        record_ = index;
        while (true) {
            line_ = cursor_line_;
            if (position_ >= body_.size()) fail("file ends before this record");
            line_end_ = std::min(body_.find('\n', position_), body_.size());
            skip_blanks();
            if (position_ < line_end_) return;
            next_line();
        }
    }

    void end_record() override {
        skip_blanks();
        if (position_ < line_end_) {
            fail("unexpected extra value " + quoted(next_token()) + " (the header declares fewer properties)");
        }
        next_line();
    }

    void expect_end() override {
        const std::size_t rest = body_.find_first_not_of(" \t\r\n", position_);
        if (rest == std::string_view::npos) return;
        element_ = nullptr;
        line_ = cursor_line_ + int(std::count(body_.begin() + position_, body_.begin() + rest, '\n'));
        fail("unexpected data after the last element declared in the header");
    }

    double read(PlyScalarType type, std::string_view property) override {
        skip_blanks();
        if (position_ >= line_end_) fail("missing value for property " + quoted(property));
        const std::string_view token = next_token();
        double value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc() || end != token.data() + token.size()) {
            fail("value " + quoted(token) + " of property " + quoted(property) + " is not a number");
        }
        if (ply_scalar_is_integer(type)) {
            const auto [lowest, highest] = integer_range(type);
            if (value != std::floor(value) || value < lowest || value > highest) {
                fail("value " + quoted(token) + " of property " + quoted(property) + " is not a valid " +
                     ply_scalar_name(type));
            }
        }
        return value;
    }

private:
    void skip_blanks() {
        while (position_ < line_end_ && (body_[position_] == ' ' || body_[position_] == '\t' || body_[position_] == '\r')) {
            ++position_;
        }
    }

    std::string_view next_token() {
        const std::size_t start = position_;
        while (position_ < line_end_ && body_[position_] != ' ' && body_[position_] != '\t' && body_[position_] != '\r') {
            ++position_;
        }
        return body_.substr(start, position_ - start);
    }

    void next_line() {
        position_ = std::min(line_end_ + 1, body_.size());
        ++cursor_line_;
    }

    std::size_t line_end_ = 0;
    int cursor_line_;  // line at position_; line_ stays on the record being read, for messages
};

// Fixed-size values in the file's byte order.
class BinaryPlyValueReader final : public PlyValueReader {
public:
    BinaryPlyValueReader(std::string_view body, const std::string& file, std::endian byte_order)
        : PlyValueReader(body, file, 0), swap_bytes_(byte_order != std::endian::native) {}

    void begin_record(const std::string& element, std::uint64_t index) override {
        element_ = &element;
        record_ = index;
    }

    void end_record() override {}

    // Trailing bytes are tolerated: some writers pad or end the file with a newline.
    void expect_end() override {}

    double read(PlyScalarType type, std::string_view property) override {
        const std::size_t size = ply_scalar_size(type);
        if (remaining_bytes() < size) {
            fail("file ends while reading property " + quoted(property) + " (binary data truncated at byte " +
                 std::to_string(position_) + " of the body)");
        }
        std::array<unsigned char, 8> bytes{};
        std::memcpy(bytes.data(), body_.data() + position_, size);
        position_ += size;
        if (swap_bytes_) std::reverse(bytes.begin(), bytes.begin() + size);
        switch (type) {
            case PlyScalarType::Int8: return decode<std::int8_t>(bytes);
            case PlyScalarType::UInt8: return decode<std::uint8_t>(bytes);
            case PlyScalarType::Int16: return decode<std::int16_t>(bytes);
            case PlyScalarType::UInt16: return decode<std::uint16_t>(bytes);
            case PlyScalarType::Int32: return decode<std::int32_t>(bytes);
            case PlyScalarType::UInt32: return decode<std::uint32_t>(bytes);
            case PlyScalarType::Float32: return decode<float>(bytes);
            case PlyScalarType::Float64: return decode<double>(bytes);
        }
        return 0;
    }

private:
    template <class T>
    static double decode(const std::array<unsigned char, 8>& bytes) {
        T value;
        std::memcpy(&value, bytes.data(), sizeof(T));
        return double(value);
    }

    bool swap_bytes_;
};

}  // namespace

std::int64_t PlyValueReader::read_integer(PlyScalarType type, std::string_view property) {
    const double value = read(type, property);
    // Only float-typed values can fail here; 2^53 keeps the conversion exact.
    if (value != std::floor(value) || std::abs(value) > 9007199254740992.0) {
        fail("value " + std::to_string(value) + " of property " + quoted(property) + " is not a whole number");
    }
    return std::int64_t(value);
}

void PlyValueReader::fail(const std::string& problem) const {
    const std::string field = element_ ? *element_ + " " + std::to_string(record_) : std::string();
    throw InputError({file_, line_}, field, problem);
}

std::unique_ptr<PlyValueReader> make_ply_value_reader(const PlyHeader& header, std::string_view contents,
                                                      const std::string& file) {
    const std::string_view body = contents.substr(header.body_offset);
    switch (header.format) {
        case PlyFormat::Ascii: return std::make_unique<AsciiPlyValueReader>(body, file, header.body_first_line);
        case PlyFormat::BinaryLittleEndian: return std::make_unique<BinaryPlyValueReader>(body, file, std::endian::little);
        case PlyFormat::BinaryBigEndian: return std::make_unique<BinaryPlyValueReader>(body, file, std::endian::big);
    }
    return nullptr;
}

}  // namespace isotrace
