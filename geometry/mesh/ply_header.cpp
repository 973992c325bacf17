#include "geometry/mesh/ply_header.h"

#include <algorithm>
#include <charconv>

#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

struct ScalarTypeName {
    std::string_view name;
    PlyScalarType type;
};

// The classic names come first so that ply_scalar_name() prints them.
constexpr ScalarTypeName scalar_type_names[] = {
    {"char", PlyScalarType::Int8},      {"uchar", PlyScalarType::UInt8},    {"short", PlyScalarType::Int16},
    {"ushort", PlyScalarType::UInt16},  {"int", PlyScalarType::Int32},      {"uint", PlyScalarType::UInt32},
    {"float", PlyScalarType::Float32},  {"double", PlyScalarType::Float64}, {"int8", PlyScalarType::Int8},
    {"uint8", PlyScalarType::UInt8},    {"int16", PlyScalarType::Int16},    {"uint16", PlyScalarType::UInt16},
    {"int32", PlyScalarType::Int32},    {"uint32", PlyScalarType::UInt32},  {"float32", PlyScalarType::Float32},
    {"float64", PlyScalarType::Float64},
};

class PlyHeaderParser {
public:
    PlyHeaderParser(std::string_view contents, const std::string& file) : contents_(contents), file_(file) {}

    PlyHeader parse() {
        if (!next_line() || words_.size() != 1 || words_[0] != "ply") {
            fail("not a PLY file (the first line must be 'ply')");
        }
        bool has_format = false;
        while (next_line()) {
            if (words_.empty() || words_[0] == "comment" || words_[0] == "obj_info") continue;
            const std::string_view keyword = words_[0];
            if (keyword == "format") {
                if (has_format) fail("second 'format' line");
                parse_format();
                has_format = true;
            } else if (keyword == "element") {
                parse_element();
            } else if (keyword == "property") {
                parse_property();
            } else if (keyword == "end_header") {
                if (words_.size() != 1) fail("unexpected text after 'end_header'");
                if (!has_format) fail("header has no 'format' line");
                check_last_element_has_properties();
                header_.body_offset = position_;
                header_.body_first_line = line_number_ + 1;
                return std::move(header_);
            } else {
                fail("unknown header keyword '" + std::string(keyword) + "'");
            }
        }
        fail("header has no 'end_header' line");
    }

private:
    // Splits the next line into words; false at the end of the contents.
    bool next_line() {
        if (position_ >= contents_.size()) return false;
        const std::size_t end = std::min(contents_.find('\n', position_), contents_.size());
        const std::string_view line = contents_.substr(position_, end - position_);
        position_ = std::min(end + 1, contents_.size());
        ++line_number_;
        words_.clear();
        std::size_t at = 0;
        while ((at = line.find_first_not_of(" \t\r", at)) != std::string_view::npos) {
            const std::size_t word_end = std::min(line.find_first_of(" \t\r", at), line.size());
            words_.push_back(line.substr(at, word_end - at));
            at = word_end;
        }
        return true;
    }

    void parse_format() {
        if (words_.size() != 3) fail("expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
        if (words_[1] == "ascii") {
            header_.format = PlyFormat::Ascii;
        } else if (words_[1] == "binary_little_endian") {
            header_.format = PlyFormat::BinaryLittleEndian;
        } else if (words_[1] == "binary_big_endian") {
            header_.format = PlyFormat::BinaryBigEndian;
        } else {
            fail("unknown format '" + std::string(words_[1]) +
                 "' (expected ascii, binary_little_endian or binary_big_endian)");
        }
        if (words_[2] != "1.0") fail("unsupported PLY version '" + std::string(words_[2]) + "' (expected 1.0)");
    }

    void parse_element() {
        if (words_.size() != 3) fail("expected 'element <name> <count>'");
        check_last_element_has_properties();
        PlyElement element;
        element.name = words_[1];
        element.line = line_number_;
        const std::string_view count = words_[2];
        const auto [end, error] = std::from_chars(count.data(), count.data() + count.size(), element.count);
        if (error != std::errc() || end != count.data() + count.size()) {
            fail("element count '" + std::string(count) + "' is not a non-negative integer");
        }
        for (const PlyElement& other : header_.elements) {
            if (other.name == element.name) fail("element '" + element.name + "' declared twice");
        }
        header_.elements.push_back(std::move(element));
    }

    void parse_property() {
        if (header_.elements.empty()) fail("property before any element");
        PlyElement& element = header_.elements.back();
        PlyProperty property;
        if (words_.size() == 5 && words_[1] == "list") {
            property.is_list = true;
            property.count_type = scalar_type(words_[2]);
            if (!ply_scalar_is_integer(property.count_type)) fail("list count type must be an integer type");
            property.type = scalar_type(words_[3]);
        } else if (words_.size() == 3 && words_[1] != "list") {
            property.type = scalar_type(words_[1]);
        } else {
            fail("expected 'property <type> <name>' or 'property list <count type> <item type> <name>'");
        }
        property.name = words_.back();
        if (element.find_property({property.name}) >= 0) {
            fail("property '" + property.name + "' declared twice in element '" + element.name + "'");
        }
        element.properties.push_back(std::move(property));
    }

    PlyScalarType scalar_type(std::string_view name) const {
        for (const ScalarTypeName& known : scalar_type_names) {
            if (known.name == name) return known.type;
        }
        fail("unknown property type '" + std::string(name) + "'");
    }

    // A record without properties would take no bytes, so its count could not be checked against the file size.
    void check_last_element_has_properties() const {
        if (!header_.elements.empty() && header_.elements.back().properties.empty()) {
            throw InputError({file_, header_.elements.back().line}, "",
                             "element '" + header_.elements.back().name + "' has no properties");
        }
    }

    [[noreturn]] void fail(const std::string& problem) const {
        throw InputError({file_, std::max(line_number_, 1)}, "", problem);
    }

    std::string_view contents_;
    const std::string& file_;
    std::size_t position_ = 0;
    int line_number_ = 0;
    std::vector<std::string_view> words_;
    PlyHeader header_;
};

}  // namespace

std::size_t ply_scalar_size(PlyScalarType type) {
    switch (type) {
        case PlyScalarType::Int8:
        case PlyScalarType::UInt8: return 1;
        case PlyScalarType::Int16:
        case PlyScalarType::UInt16: return 2;
        case PlyScalarType::Int32:
        case PlyScalarType::UInt32:
        case PlyScalarType::Float32: return 4;
        case PlyScalarType::Float64: return 8;
    }
    return 0;
}

bool ply_scalar_is_integer(PlyScalarType type) {
    return type != PlyScalarType::Float32 && type != PlyScalarType::Float64;
}

const char* ply_scalar_name(PlyScalarType type) {
    for (const ScalarTypeName& known : scalar_type_names) {
        if (known.type == type) return known.name.data();
    }
    return "?";
}

int PlyElement::find_property(std::initializer_list<std::string_view> names) const {
    for (std::size_t i = 0; i < properties.size(); ++i) {
        if (std::find(names.begin(), names.end(), properties[i].name) != names.end()) return int(i);
    }
    return -1;
}

PlyHeader parse_ply_header(std::string_view contents, const std::string& file) {
    return PlyHeaderParser(contents, file).parse();
}

}  // namespace isotrace
