#include "geometry/sweep/sweep_tessellation.h"

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include "geometry/sweep/sweep_surface.h"

namespace isotrace {

TriangleMeshData tessellate(const SweepSurface& sweep, const SweepTessellation& options) {
    const int n = options.theta_steps, k = options.t_steps;
    if (n < 3 || n > 4096) throw std::invalid_argument("theta_steps: must be in [3, 4096]");
    if (k < 1 || k > 4096) throw std::invalid_argument("t_steps: must be in [1, 4096]");
    TriangleMeshData mesh;
    for (int row = 0; row <= k; ++row)
        for (int i = 0; i < n; ++i) {
            mesh.positions.push_back(Vec3f(sweep.point(2 * std::numbers::pi * i / n, double(row) / k)));
            mesh.uvs.push_back({float(double(row) / k), float(double(i) / n)});
        }
    auto at = [n](int i, int row) { return std::uint32_t(row * n + (i % n)); };
    // ∂S/∂θ × ∂S/∂t points outwards (when the sections advance along N), so (θ, θ+1, next row) is the front.
    for (int row = 0; row < k; ++row)
        for (int i = 0; i < n; ++i) {
            mesh.triangles.push_back({at(i, row), at(i + 1, row), at(i + 1, row + 1)});
            mesh.triangles.push_back({at(i, row), at(i + 1, row + 1), at(i, row + 1)});
        }
    if (options.caps) {
        const auto start = std::uint32_t(mesh.positions.size());
        mesh.positions.push_back(Vec3f(sweep.centre(0)));
        mesh.positions.push_back(Vec3f(sweep.centre(1)));
        mesh.uvs.push_back({0.0f, 0.5f});  // a cap's uvs lie on a line: no parametrisation
        mesh.uvs.push_back({1.0f, 0.5f});
        for (int i = 0; i < n; ++i) {
            mesh.triangles.push_back({start, at(i + 1, 0), at(i, 0)});
            mesh.triangles.push_back({start + 1, at(i, k), at(i + 1, k)});
        }
    }
    return mesh;
}

void unwrap_tube_seams(TriangleMeshData& tubes) {
    if (tubes.uvs.size() != tubes.positions.size()) return;
    const std::size_t original = tubes.positions.size();
    std::vector<std::uint32_t> copy_of(original, 0);  // 0: none yet (a copy is never vertex 0)
    for (auto& triangle : tubes.triangles) {
        float low = 1, high = 0;
        for (const std::uint32_t corner : triangle) {
            low = std::min(low, tubes.uvs[corner][1]);
            high = std::max(high, tubes.uvs[corner][1]);
        }
        if (!(high - low > 0.5f)) continue;
        for (std::uint32_t& corner : triangle) {
            if (corner >= original || !(tubes.uvs[corner][1] < 0.5f)) continue;
            if (copy_of[corner] == 0) {
                copy_of[corner] = std::uint32_t(tubes.positions.size());
                tubes.positions.push_back(tubes.positions[corner]);
                if (!tubes.normals.empty()) tubes.normals.push_back(tubes.normals[corner]);
                tubes.uvs.push_back({tubes.uvs[corner][0], tubes.uvs[corner][1] + 1});
            }
            corner = copy_of[corner];
        }
    }
}

}  // namespace isotrace
