#include "geometry/mesh/obj_loader.h"

#include <tiny_obj_loader.h>

#include <cstdint>
#include <functional>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "geometry/mesh/fan_triangulation.h"
#include "geometry/mesh/file_contents.h"
#include "geometry/mesh/mesh_index_problem.h"
#include "geometry/mesh/obj_syntax_check.h"
#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

// tinyobjloader reports the line only inside its message text, as "... line 12 ...".
int line_in_parser_message(std::string_view message) {
    const std::size_t at = message.find("line ");
    if (at == std::string_view::npos) return 0;
    int line = 0;
    for (std::size_t i = at + 5; i < message.size() && message[i] >= '0' && message[i] <= '9'; ++i) {
        line = line * 10 + (message[i] - '0');
        if (line > 100'000'000) return 0;  // not a line number we can trust
    }
    return line;
}

std::string trimmed(std::string_view text) {
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    return std::string(text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1));
}

// A face corner after tinyobjloader made its indices 0-based; -1 means "absent".
struct Corner {
    int position = -1;
    int normal = -1;
    int uv = -1;
    bool operator==(const Corner&) const = default;
};

struct CornerHash {
    std::size_t operator()(const Corner& c) const {
        const std::hash<int> h;
        return h(c.position) ^ (h(c.normal) * 0x9e3779b97f4a7c15ULL) ^ (h(c.uv) * 0xc2b2ae3d27d4eb4fULL);
    }
};

// Builds the mesh from tinyobjloader's output, checking every index (tinyobjloader only warns about them).
class ObjMeshBuilder {
public:
    ObjMeshBuilder(const std::string& path, const tinyobj::attrib_t& attrib,
                   const std::vector<tinyobj::shape_t>& shapes)
        : path_(path),
          attrib_(attrib),
          shapes_(shapes),
          keep_normals_(every_corner_has(shapes, &tinyobj::index_t::normal_index)),
          keep_uvs_(every_corner_has(shapes, &tinyobj::index_t::texcoord_index)) {}

    TriangleMeshData build() {
        std::vector<std::uint32_t> polygon;
        for (const tinyobj::shape_t& shape : shapes_) {
            check_corner_counts(shape.mesh);
            std::size_t next = 0;
            for (const unsigned char corner_count : shape.mesh.num_face_vertices) {
                ++face_number_;
                polygon.clear();
                for (std::size_t k = 0; k < corner_count; ++k) polygon.push_back(vertex_for(shape.mesh.indices[next + k]));
                next += corner_count;
                append_fan_triangles(polygon, mesh_.triangles);
            }
        }
        return std::move(mesh_);
    }

private:
    std::uint32_t vertex_for(const tinyobj::index_t& index) {
        const Corner corner{checked(index.vertex_index, attrib_.vertices.size() / 3, "vertex"),
                            keep_normals_ ? checked(index.normal_index, attrib_.normals.size() / 3, "normal") : -1,
                            keep_uvs_ ? checked(index.texcoord_index, attrib_.texcoords.size() / 2, "texture coordinate")
                                      : -1};
        const auto [slot, inserted] = vertex_of_corner_.try_emplace(corner, std::uint32_t(mesh_.positions.size()));
        if (inserted) add_vertex(corner);
        return slot->second;
    }

    void add_vertex(const Corner& corner) {
        const auto vec3_at = [](const std::vector<tinyobj::real_t>& values, int i) {
            return Vec3f(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
        };
        mesh_.positions.push_back(vec3_at(attrib_.vertices, corner.position));
        if (keep_normals_) mesh_.normals.push_back(vec3_at(attrib_.normals, corner.normal));
        if (keep_uvs_) mesh_.uvs.push_back({attrib_.texcoords[2 * corner.uv], attrib_.texcoords[2 * corner.uv + 1]});
    }

    int checked(int index, std::size_t count, const char* what) const {
        if (index < 0 || std::size_t(index) >= count) {
            // OBJ numbers from 1; show the index as written (relative indices show resolved).
            throw InputError({path_}, "face " + std::to_string(face_number_),
                             index_out_of_range_problem(what, index + 1LL, count));
        }
        return index;
    }

    // tinyobjloader stores corner counts as bytes, so a bigger polygon leaves counts and corners out of step.
    void check_corner_counts(const tinyobj::mesh_t& mesh) const {
        std::size_t corners = 0;
        for (const unsigned char count : mesh.num_face_vertices) corners += count;
        if (corners != mesh.indices.size()) {
            throw InputError({path_}, "", "a polygon has more than 255 corners (tinyobjloader's limit)");
        }
    }

    static bool every_corner_has(const std::vector<tinyobj::shape_t>& shapes, int tinyobj::index_t::*attribute) {
        for (const tinyobj::shape_t& shape : shapes) {
            for (const tinyobj::index_t& index : shape.mesh.indices) {
                if (index.*attribute < 0) return false;
            }
        }
        return true;
    }

    const std::string& path_;
    const tinyobj::attrib_t& attrib_;
    const std::vector<tinyobj::shape_t>& shapes_;
    const bool keep_normals_;
    const bool keep_uvs_;
    long long face_number_ = 0;  // 1-based across the file, like OBJ indices
    std::unordered_map<Corner, std::uint32_t, CornerHash> vertex_of_corner_;
    TriangleMeshData mesh_;
};

}  // namespace

TriangleMeshData load_obj(const std::string& path) {
    tinyobj::ObjReaderConfig config;
    // We triangulate ourselves: tinyobjloader's triangulation silently skips faces with bad indices.
    config.triangulate = false;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // Parsing from memory keeps tinyobjloader from looking for .mtl files we do not use.
    const std::string text = read_file_contents(path);
    check_obj_syntax(text, path);
    if (!reader.ParseFromString(text, "", config)) {
        throw InputError({path, line_in_parser_message(reader.Error())}, "", trimmed(reader.Error()));
    }
    TriangleMeshData mesh = ObjMeshBuilder(path, reader.GetAttrib(), reader.GetShapes()).build();
    mesh.validate(path);
    return mesh;
}

}  // namespace isotrace
