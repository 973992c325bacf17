#include "geometry/mesh/triangle_mesh_data.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geometry/mesh/mesh_index_problem.h"
#include "renderer/core/input_error.h"

namespace isotrace {
namespace {

std::string describe(const Vec3f& v) {
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

void check_attribute_count(const std::string& file, const char* field, std::size_t count, std::size_t positions) {
    if (count != 0 && count != positions) {
        throw InputError({file}, field,
                         std::to_string(count) + " values for " + std::to_string(positions) +
                             " positions (need none or one per position)");
    }
}

}  // namespace

void TriangleMeshData::validate(const std::string& file) const {
    if (triangles.empty()) throw InputError({file}, "", "mesh has no triangles");
    check_attribute_count(file, "normals", normals.size(), positions.size());
    check_attribute_count(file, "uvs", uvs.size(), positions.size());

    for (std::size_t i = 0; i < positions.size(); ++i) {
        const std::string field = "vertex " + std::to_string(i);
        if (!is_finite(positions[i])) throw InputError({file}, field, "position is not finite " + describe(positions[i]));
        if (!normals.empty() && !is_finite(normals[i])) {
            throw InputError({file}, field, "normal is not finite " + describe(normals[i]));
        }
        if (!uvs.empty() && !(std::isfinite(uvs[i][0]) && std::isfinite(uvs[i][1]))) {
            throw InputError({file}, field, "uv is not finite");
        }
    }
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (const std::uint32_t index : triangles[t]) {
            if (index >= positions.size()) {
                throw InputError({file}, "triangle " + std::to_string(t),
                                 index_out_of_range_problem("vertex", index, positions.size()));
            }
        }
    }
}

std::size_t TriangleMeshData::remove_degenerate_triangles() {
    // Double precision so that tiny but valid triangles do not underflow to zero area.
    const auto is_degenerate = [this](const std::array<std::uint32_t, 3>& t) {
        const Vec3d a(positions[t[0]]), b(positions[t[1]]), c(positions[t[2]]);
        return cross(b - a, c - a) == Vec3d{};
    };
    const std::size_t before = triangles.size();
    std::erase_if(triangles, is_degenerate);
    return before - triangles.size();
}

MeshBounds TriangleMeshData::bounds() const {
    constexpr float inf = std::numeric_limits<float>::infinity();
    MeshBounds box{{inf, inf, inf}, {-inf, -inf, -inf}};
    for (const Vec3f& p : positions) {
        box.min = min(box.min, p);
        box.max = max(box.max, p);
    }
    return box;
}

void TriangleMeshData::append_positions_and_triangles(const TriangleMeshData& part) {
    const auto base = std::uint32_t(positions.size());
    if (uvs.size() == positions.size() && part.uvs.size() == part.positions.size())
        uvs.insert(uvs.end(), part.uvs.begin(), part.uvs.end());
    else
        uvs.clear();
    positions.insert(positions.end(), part.positions.begin(), part.positions.end());
    for (const auto& t : part.triangles) triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

void TriangleMeshData::transform(const Transform& to_world) {
    for (Vec3f& p : positions) p = to_world.point(p);
    for (Vec3f& n : normals) n = to_world.normal(n);
    if (to_world.determinant() < 0)
        for (auto& triangle : triangles) std::swap(triangle[1], triangle[2]);
}

}  // namespace isotrace
