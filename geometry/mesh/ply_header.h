#pragma once
// The header of a PLY file: its encoding and the elements (with their properties) that the body holds, in order.
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace isotrace {

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

enum class PlyScalarType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::size_t ply_scalar_size(PlyScalarType type);
bool ply_scalar_is_integer(PlyScalarType type);
const char* ply_scalar_name(PlyScalarType type);

struct PlyProperty {
    std::string name;
    PlyScalarType type = PlyScalarType::Float32;  // of the value, or of each list item
    bool is_list = false;
    PlyScalarType count_type = PlyScalarType::UInt8;  // lists only
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
    int line = 0;  // header line that declares it, for messages

    // Position of the property with one of `names`, or -1.
    int find_property(std::initializer_list<std::string_view> names) const;
};

struct PlyHeader {
    PlyFormat format = PlyFormat::Ascii;
    std::vector<PlyElement> elements;
    std::size_t body_offset = 0;  // first byte after "end_header\n"
    int body_first_line = 0;      // line number of that byte, for ASCII bodies
};

// Throws InputError with `file` and the header line for anything malformed or unsupported.
PlyHeader parse_ply_header(std::string_view contents, const std::string& file);

}  // namespace isotrace
