#include "geometry/mesh/mesh_closedness.h"

#include <array>
#include <map>
#include <unordered_map>
#include <vector>

namespace isotrace {
namespace {

// One index per distinct position: the first vertex index at that position.
std::vector<std::uint32_t> weld_by_position(const TriangleMeshData& mesh) {
    std::map<std::array<float, 3>, std::uint32_t> first_at;
    std::vector<std::uint32_t> welded(mesh.positions.size());
    for (std::uint32_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3f& p = mesh.positions[i];
        welded[i] = first_at.emplace(std::array<float, 3>{p.x, p.y, p.z}, i).first->second;
    }
    return welded;
}

std::uint64_t edge_key(std::uint32_t from, std::uint32_t to) { return std::uint64_t(from) << 32 | to; }

// Problem edges of one kind: how many, and the smallest one as an example.
struct EdgeTally {
    std::size_t count = 0;
    std::uint64_t example = ~std::uint64_t(0);

    void add(std::uint64_t key) {
        ++count;
        example = std::min(example, key);
    }
    std::string describe(const std::string& what) const {
        if (count == 0) return "";
        return std::to_string(count) + " " + what + " (e.g. " + std::to_string(example >> 32) + "–" +
               std::to_string(example & 0xffffffffu) + ")";
    }
};

double signed_volume(const TriangleMeshData& mesh) {
    double volume = 0;
    for (const auto& t : mesh.triangles) {
        const Vec3d a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        volume += dot(a, cross(b, c)) / 6;
    }
    return volume;
}

}  // namespace

std::string closed_mesh_problem(const TriangleMeshData& mesh) {
    const std::vector<std::uint32_t> welded = weld_by_position(mesh);
    std::unordered_map<std::uint64_t, int> directed;  // how many triangles run along each directed edge
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t from = welded[t[std::size_t(k)]], to = welded[t[std::size_t((k + 1) % 3)]];
            if (from != to) ++directed[edge_key(from, to)];
        }
    EdgeTally boundary, same_direction, crowded;
    for (const auto& [key, forward] : directed) {
        const std::uint32_t from = std::uint32_t(key >> 32), to = std::uint32_t(key);
        const auto reverse_entry = directed.find(edge_key(to, from));
        const int reverse = reverse_entry == directed.end() ? 0 : reverse_entry->second;
        if (reverse > 0 && from > to) continue;  // the undirected edge is visited from its smaller end
        const std::uint64_t undirected = edge_key(std::min(from, to), std::max(from, to));
        if (forward == 1 && reverse == 1) continue;
        if (forward + reverse == 1) {
            boundary.add(undirected);
        } else if (forward + reverse == 2) {
            same_direction.add(undirected);
        } else {
            crowded.add(undirected);
        }
    }
    std::string problem;
    for (const std::string& part : {boundary.describe("boundary edges"),
                                    same_direction.describe("edges whose two triangles disagree in orientation"),
                                    crowded.describe("edges shared by more than two triangles")})
        if (!part.empty()) problem += (problem.empty() ? "has " : ", ") + part;
    if (!problem.empty()) return problem;
    if (const double volume = signed_volume(mesh); !(volume > 0))
        return "has its triangles facing inwards (signed volume " + std::to_string(volume) +
               "); reverse their corner order";
    return "";
}

}  // namespace isotrace
