#include "geometry/sweep/sweep_tessellation.h"

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
        for (int i = 0; i < n; ++i)
            mesh.positions.push_back(Vec3f(sweep.point(2 * std::numbers::pi * i / n, double(row) / k)));
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
        for (int i = 0; i < n; ++i) {
            mesh.triangles.push_back({start, at(i + 1, 0), at(i, 0)});
            mesh.triangles.push_back({start + 1, at(i, k), at(i + 1, k)});
        }
    }
    return mesh;
}

}  // namespace isotrace
