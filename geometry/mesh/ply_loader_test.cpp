#include "geometry/mesh/ply_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstring>
#include <limits>
#include <random>

#include "geometry/mesh/mesh_test_support.h"
#include "geometry/mesh/ply_header.h"

namespace isotrace {
namespace {

using mesh_test::expect_unit_cube;
using mesh_test::input_error_message;
using mesh_test::ScratchDirectory;

const char* format_name(PlyFormat format) {
    switch (format) {
        case PlyFormat::Ascii: return "ascii";
        case PlyFormat::BinaryLittleEndian: return "binary_little_endian";
        case PlyFormat::BinaryBigEndian: return "binary_big_endian";
    }
    return "";
}

// Encodes a PLY body value by value, in any of the three formats.
class PlyBodyWriter {
public:
    explicit PlyBodyWriter(PlyFormat format) : format_(format) {}

    template <class T>
    PlyBodyWriter& operator<<(T value) {
        if (format_ == PlyFormat::Ascii) {
            char text[64];
            // Unary + prints 8-bit integers as numbers, not characters.
            const auto result = std::to_chars(text, text + sizeof text, +value);
            body_ += separator_;
            body_.append(text, result.ptr);
            separator_ = " ";
        } else {
            char bytes[sizeof(T)];
            std::memcpy(bytes, &value, sizeof(T));
            if ((format_ == PlyFormat::BinaryBigEndian) != (std::endian::native == std::endian::big)) {
                std::reverse(bytes, bytes + sizeof(T));
            }
            body_.append(bytes, sizeof(T));
        }
        return *this;
    }

    void end_record() {
        if (format_ == PlyFormat::Ascii) body_ += "\n";
        separator_ = "";
    }

    const std::string& body() const { return body_; }

private:
    PlyFormat format_;
    std::string body_;
    const char* separator_ = "";
};

constexpr float cube_corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
// Counter-clockwise seen from outside.
constexpr int cube_quads[6][4] = {{0, 3, 2, 1}, {0, 1, 5, 4}, {0, 4, 7, 3}, {4, 5, 6, 7}, {3, 7, 6, 2}, {1, 2, 6, 5}};

struct CubePly {
    PlyFormat format = PlyFormat::Ascii;
    bool double_coordinates = false;
    bool int_list_types = false;  // "list int uint" instead of "list uchar int"
    bool extras = false;          // unknown elements, and unknown scalar and list properties between known ones
};

std::string cube_ply(const CubePly& options) {
    const char* coordinate = options.double_coordinates ? "double" : "float32";
    std::string header = std::string("ply\nformat ") + format_name(options.format) + " 1.0\ncomment unit cube\n";
    if (options.extras) header += "element material 2\nproperty uchar red\nproperty list uint8 float weights\n";
    header += "element vertex 8\n";
    header += std::string("property ") + coordinate + " x\n";
    if (options.extras) header += "property uchar flags\n";
    header += std::string("property ") + coordinate + " y\n";
    if (options.extras) header += "property list int int16 neighbours\n";
    header += std::string("property ") + coordinate + " z\n";
    if (options.extras) header += "property double confidence\n";
    header += "element face 6\n";
    if (options.extras) header += "property short material_index\n";
    header += options.int_list_types ? "property list int uint vertex_indices\n"
                                     : "property list uchar int vertex_indices\n";
    if (options.extras) header += "property list uchar float texcoord\nelement edge 1\nproperty list ushort int ends\n";
    header += "end_header\n";

    PlyBodyWriter body(options.format);
    if (options.extras) {
        for (std::uint8_t m = 0; m < 2; ++m) {
            body << std::uint8_t(200 + m) << std::uint8_t(2) << 0.25f << 0.75f;
            body.end_record();
        }
    }
    for (const auto& p : cube_corners) {
        const auto coordinate_value = [&](float value) {
            if (options.double_coordinates) {
                body << double(value);
            } else {
                body << value;
            }
        };
        coordinate_value(p[0]);
        if (options.extras) body << std::uint8_t(7);
        coordinate_value(p[1]);
        if (options.extras) body << std::int32_t(3) << std::int16_t(-1) << std::int16_t(2) << std::int16_t(5);
        coordinate_value(p[2]);
        if (options.extras) body << 0.5;
        body.end_record();
    }
    for (const auto& quad : cube_quads) {
        if (options.extras) body << std::int16_t(1);
        if (options.int_list_types) {
            body << std::int32_t(4);
            for (const int v : quad) body << std::uint32_t(v);
        } else {
            body << std::uint8_t(4);
            for (const int v : quad) body << std::int32_t(v);
        }
        if (options.extras) body << std::uint8_t(2) << 0.0f << 1.0f;
        body.end_record();
    }
    if (options.extras) {
        body << std::uint16_t(2) << std::int32_t(0) << std::int32_t(1);
        body.end_record();
    }
    return header + body.body();
}

std::vector<CubePly> all_cube_variants() {
    std::vector<CubePly> variants;
    for (const PlyFormat format : {PlyFormat::Ascii, PlyFormat::BinaryLittleEndian, PlyFormat::BinaryBigEndian}) {
        for (const bool double_coordinates : {false, true}) {
            for (const bool int_list_types : {false, true}) {
                for (const bool extras : {false, true}) {
                    variants.push_back({format, double_coordinates, int_list_types, extras});
                }
            }
        }
    }
    return variants;
}

TEST(PlyLoader, CubeIsIdenticalInEveryFormatAndLayout) {
    ScratchDirectory scratch;
    const TriangleMeshData reference = load_ply(scratch.write("reference.ply", cube_ply({})));
    EXPECT_EQ(reference.positions.size(), 8u);
    EXPECT_TRUE(reference.normals.empty());
    EXPECT_TRUE(reference.uvs.empty());
    expect_unit_cube(reference);

    for (const CubePly& variant : all_cube_variants()) {
        SCOPED_TRACE(std::string(format_name(variant.format)) + (variant.double_coordinates ? " double" : " float") +
                     (variant.int_list_types ? " int-lists" : " uchar-lists") + (variant.extras ? " extras" : ""));
        const TriangleMeshData mesh = load_ply(scratch.write("cube.ply", cube_ply(variant)));
        EXPECT_EQ(mesh.positions, reference.positions);
        EXPECT_EQ(mesh.normals, reference.normals);
        EXPECT_EQ(mesh.uvs, reference.uvs);
        EXPECT_EQ(mesh.triangles, reference.triangles);
    }
}

TEST(PlyLoader, ReadsNormalsAndTextureCoordinates) {
    ScratchDirectory scratch;
    const std::string text = R"(ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
property float nx
property float ny
property float nz
property float s
property float t
element face 1
property list uchar uint vertex_index
end_header
0 0 0  0 0 1  0 0
1 0 0  0 0.6 0.8  1 0
0 1 0  0 0 1  0 1
3 0 1 2
)";
    const TriangleMeshData mesh = load_ply(scratch.write("triangle.ply", text));
    ASSERT_EQ(mesh.normals.size(), 3u);
    ASSERT_EQ(mesh.uvs.size(), 3u);
    EXPECT_EQ(mesh.normals[1], Vec3f(0, 0.6f, 0.8f));
    EXPECT_EQ(mesh.uvs[1], (std::array<float, 2>{1, 0}));
    EXPECT_EQ(mesh.uvs[2], (std::array<float, 2>{0, 1}));
}

// Hand-encoded bytes, so that the byte order is checked independently of PlyBodyWriter.
TEST(PlyLoader, DecodesBothByteOrders) {
    ScratchDirectory scratch;
    const std::string header_end = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                   "element face 1\nproperty list uchar ushort vertex_indices\nend_header\n";
    const std::string one_big("\x3f\x80\x00\x00", 4), one_little("\x00\x00\x80\x3f", 4), zero(4, '\0');
    const std::string big = "ply\nformat binary_big_endian 1.0\n" + header_end + zero + zero + zero + one_big + zero +
                            zero + zero + one_big + zero + std::string("\x03\x00\x00\x00\x01\x00\x02", 7);
    const std::string little = "ply\nformat binary_little_endian 1.0\n" + header_end + zero + zero + zero +
                               one_little + zero + zero + zero + one_little + zero +
                               std::string("\x03\x00\x00\x01\x00\x02\x00", 7);
    for (const std::string& contents : {big, little}) {
        const TriangleMeshData mesh = load_ply(scratch.write("triangle.ply", contents));
        EXPECT_EQ(mesh.positions, (std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
        EXPECT_EQ(mesh.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}}));
    }
}

constexpr const char* ascii_triangle_header = R"(ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
element face 2
property list uchar int vertex_indices
end_header
)";

std::string ascii_triangles(const std::string& vertex_lines, const std::string& face_lines) {
    return ascii_triangle_header + vertex_lines + face_lines;
}

const std::string good_vertices = "0 0 0\n1 0 0\n0 1 0\n";

TEST(PlyLoader, IndexOutOfRangeNamesFileLineAndFace) {
    ScratchDirectory scratch;
    const std::string path = scratch.write("bad.ply", ascii_triangles(good_vertices, "3 0 1 2\n\n3 0 1 99\n"));
    EXPECT_EQ(input_error_message([&] { load_ply(path); }),
              path + ":15: face 1: vertex index 99 out of range (vertex count 3)");
}

TEST(PlyLoader, BinaryIndexOutOfRangeNamesFace) {
    ScratchDirectory scratch;
    std::string contents = cube_ply({PlyFormat::BinaryLittleEndian});
    contents[contents.size() - 1] = 9;  // the last face's last index, high byte
    const std::string path = scratch.write("bad.ply", contents);
    EXPECT_EQ(input_error_message([&] { load_ply(path); }),
              path + ": face 5: vertex index 150994949 out of range (vertex count 8)");
}

TEST(PlyLoader, MalformedHeadersNameTheLine) {
    ScratchDirectory scratch;
    const struct {
        std::string contents;
        std::string expected;
    } cases[] = {
        {"", ":1: not a PLY file"},
        {"solid cube\n", ":1: not a PLY file"},
        {"ply\nformat ascii 2.0\n", ":2: unsupported PLY version '2.0'"},
        {"ply\nformat text 1.0\n", ":2: unknown format 'text'"},
        {"ply\nformat ascii 1.0\nelement vertex 3\nproperty flaot x\n", ":4: unknown property type 'flaot'"},
        {"ply\nformat ascii 1.0\nproperty float x\n", ":3: property before any element"},
        {"ply\nformat ascii 1.0\nelement vertex -3\n", ":3: element count '-3' is not a non-negative integer"},
        {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n", ":4: header has no 'end_header' line"},
        {"ply\nelement vertex 0\nproperty float x\nend_header\n", ":4: header has no 'format' line"},
        {"ply\nformat ascii 1.0\nelement vertex 0\nend_header\n", ":3: element 'vertex' has no properties"},
        {"ply\nformat ascii 1.0\nelement vertex 0\nproperty list float int x\n", ":4: list count type must be"},
        {"ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float x\n", ":5: property 'x' declared twice"},
        {"ply\nformat ascii 1.0\nelment vertex 0\n", ":3: unknown header keyword 'elment'"},
        {"ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nend_header\n", ":3: element vertex: missing property 'y'"},
        {"ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
         "property float nx\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n",
         ":3: element vertex: needs all or none of nx, ny, nz"},
        {"ply\nformat ascii 1.0\nelement face 0\nproperty int vertex_indices\nend_header\n",
         ":3: element face: 'vertex_indices' must be a list"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.contents);
        const std::string path = scratch.write("header.ply", c.contents);
        const std::string message = input_error_message([&] { load_ply(path); });
        EXPECT_EQ(message.rfind(path + c.expected, 0), 0u) << message;
    }
}

TEST(PlyLoader, MalformedAsciiBodiesNameTheLine) {
    ScratchDirectory scratch;
    const struct {
        std::string vertices;
        std::string faces;
        std::string expected;
    } cases[] = {
        {"0 0 0\n1 0\n0 1 0\n", "", ":11: vertex 1: missing value for property 'z'"},
        {"0 0 0\n1 0 0 5\n0 1 0\n", "", ":11: vertex 1: unexpected extra value '5'"},
        {"0 0 0\n1 zero 0\n0 1 0\n", "", ":11: vertex 1: value 'zero' of property 'y' is not a number"},
        {good_vertices, "3 0 1 2\n3 0 1.5 2\n", ":14: face 1: value '1.5' of property 'vertex_indices' is not a valid int"},
        {good_vertices, "3 0 1 2\n300 0 1 2\n", ":14: face 1: value '300' of property 'vertex_indices' is not a valid uchar"},
        {good_vertices, "3 0 1 2\n3 0 -1 2\n", ":14: face 1: vertex index -1 out of range (vertex count 3)"},
        {good_vertices, "3 0 1 2\n", ":14: face 1: file ends before this record"},
        {good_vertices, "3 0 1 2\n3 0 1 2\n\n0 0 0\n", ":16: unexpected data after the last element"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.vertices + c.faces);
        const std::string path = scratch.write("body.ply", ascii_triangles(c.vertices, c.faces));
        const std::string message = input_error_message([&] { load_ply(path); });
        EXPECT_EQ(message.rfind(path + c.expected, 0), 0u) << message;
    }
}

TEST(PlyLoader, NegativeListCountIsAnError) {
    ScratchDirectory scratch;
    std::string contents = cube_ply({.int_list_types = true});
    contents.replace(contents.find("\n4 0 3 2 1\n"), 11, "\n-4 0 3 2 1\n");
    const std::string bad = scratch.write("bad.ply", contents);
    EXPECT_EQ(input_error_message([&] { load_ply(bad); }),
              bad + ":19: face 0: negative item count -4 in list 'vertex_indices'");
}

TEST(PlyLoader, NanCoordinateIsAnError) {
    ScratchDirectory scratch;
    const std::string ascii = scratch.write("nan.ply", ascii_triangles("0 0 0\n1 nan 0\n0 1 0\n", "3 0 1 2\n3 0 1 2\n"));
    const std::string message = input_error_message([&] { load_ply(ascii); });
    EXPECT_EQ(message.rfind(ascii + ": vertex 1: position is not finite", 0), 0u) << message;

    PlyBodyWriter body(PlyFormat::BinaryLittleEndian);
    body << 0.0f << 0.0f << 0.0f << 1.0f << std::numeric_limits<float>::quiet_NaN() << 0.0f << 0.0f << 1.0f << 0.0f;
    body << std::uint8_t(3) << 0 << 1 << 2;
    std::string header = ascii_triangle_header;
    header.replace(header.find("ascii"), 5, "binary_little_endian");
    header.replace(header.find("face 2"), 6, "face 1");
    const std::string binary = scratch.write("nan_binary.ply", header + body.body());
    const std::string binary_message = input_error_message([&] { load_ply(binary); });
    EXPECT_EQ(binary_message.rfind(binary + ": vertex 1: position is not finite", 0), 0u) << binary_message;
}

// Byte order does not change where values end, so one order covers every cut.
TEST(PlyLoader, EveryTruncationOfABinaryFileIsAnInputError) {
    ScratchDirectory scratch;
    const std::string contents = cube_ply({.format = PlyFormat::BinaryLittleEndian, .extras = true});
    const std::size_t body_start = contents.find("end_header\n") + 11;
    for (std::size_t size = body_start; size < contents.size(); ++size) {
        const std::string path = scratch.write("truncated.ply", contents.substr(0, size));
        const std::string message = input_error_message([&] { load_ply(path); });
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        EXPECT_NE(message.find("binary data truncated"), std::string::npos) << message;
    }
}

// Corrupted bytes must give a mesh or an InputError; anything else (a crash, another exception) fails.
TEST(PlyLoader, CorruptedBinaryFilesNeverEscapeInputError) {
    ScratchDirectory scratch;
    const std::string original = cube_ply({.format = PlyFormat::BinaryBigEndian, .extras = true});
    const std::size_t body_start = original.find("end_header\n") + 11;
    std::mt19937 random(12345);
    std::uniform_int_distribution<std::size_t> position(body_start, original.size() - 1);
    std::uniform_int_distribution<int> byte(0, 255);
    for (int trial = 0; trial < 200; ++trial) {
        std::string contents = original;
        for (int k = 0; k < 3; ++k) contents[position(random)] = char(byte(random));
        const std::string path = scratch.write("corrupt.ply", contents);
        try {
            load_ply(path);
        } catch (const InputError&) {
        }
    }
}

TEST(PlyLoader, MissingFileNamesIt) {
    ScratchDirectory scratch;
    const std::string path = scratch.path_of("absent.ply");
    EXPECT_EQ(input_error_message([&] { load_ply(path); }), path + ": file not found");
}

}  // namespace
}  // namespace isotrace
