#include "geometry/polygonize/mesh_error.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "geometry/mesh/closest_triangle_point.h"
#include "renderer/core/parallel_for.h"

namespace isotrace {
namespace {

constexpr int kStepsPerLine = 256;

double first_order_distance(const ImplicitField& field, const Vec3d& p) {
    const double slope = length(field.gradient(p));
    const double f = std::abs(field.value(p));
    return slope > 0 ? f / slope : (f == 0 ? 0 : INFINITY);
}

// Surface points: sign changes along random lines through the bounds, bisected.
std::vector<Vec3d> surface_points(const ImplicitField& field, std::size_t wanted, std::uint64_t seed) {
    const FieldBox box = field.bounds();
    const std::size_t lines = std::max<std::size_t>(1, wanted / 4);
    std::vector<std::vector<Vec3d>> found(lines);
    parallel_for(std::size_t(0), lines, [&](std::size_t line) {
        std::mt19937_64 random(seed * 0x9E3779B97F4A7C15ull + line);
        std::uniform_real_distribution<double> u(0, 1);
        std::normal_distribution<double> g;
        // Through a random point of the box in a random direction, across the whole box.
        const Vec3d a = box.lower + box.extent() * Vec3d{u(random), u(random), u(random)};
        const Vec3d direction = normalize(Vec3d{g(random), g(random), g(random)});
        const double reach = length(box.extent());
        const Vec3d start = a - direction * reach, step = direction * (2 * reach / kStepsPerLine);
        double previous = field.value(start);
        for (int k = 1; k <= kStepsPerLine; ++k) {
            const Vec3d p = start + step * double(k);
            const double v = field.value(p);
            if ((v < 0) != (previous < 0)) {
                double lo = 0, hi = 1;  // along [p − step, p]
                for (int i = 0; i < 50; ++i) {
                    const double mid = (lo + hi) / 2;
                    ((field.value(p - step + step * mid) < 0) == (previous < 0) ? lo : hi) = mid;
                }
                found[line].push_back(p - step + step * ((lo + hi) / 2));
            }
            previous = v;
        }
    });
    std::vector<Vec3d> points;
    for (const auto& part : found) points.insert(points.end(), part.begin(), part.end());
    return points;
}

}  // namespace

MeshError measure_mesh_error(const ImplicitField& field, const TriangleMeshData& mesh, std::size_t samples,
                             std::uint64_t seed) {
    MeshError error;
    if (mesh.triangles.empty()) return error;
    std::vector<double> at_vertex(mesh.positions.size());
    parallel_for(std::size_t(0), mesh.positions.size(),
                 [&](std::size_t i) { at_vertex[i] = first_order_distance(field, Vec3d(mesh.positions[i])); });
    for (double e : at_vertex) {
        error.vertex_mean += e;
        error.vertex_max = std::max(error.vertex_max, e);
    }
    error.vertex_mean /= double(at_vertex.size());

    // Mesh → surface: points uniform by area.
    std::vector<double> cumulative(mesh.triangles.size());
    double total = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const Vec3d a(mesh.positions[tri[0]]), b(mesh.positions[tri[1]]), c(mesh.positions[tri[2]]);
        total += length(cross(b - a, c - a));
        cumulative[t] = total;
    }
    std::vector<double> to_surface(samples);
    parallel_for(std::size_t(0), samples, [&](std::size_t i) {
        std::mt19937_64 random(seed ^ (0xD1B54A32D192ED03ull * (i + 1)));
        std::uniform_real_distribution<double> u(0, 1);
        const std::size_t t = std::min<std::size_t>(
            std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), u(random) * total) - cumulative.begin()),
            cumulative.size() - 1);
        double s = u(random), r = u(random);
        if (s + r > 1) {
            s = 1 - s;
            r = 1 - r;
        }
        const auto& tri = mesh.triangles[t];
        const Vec3d a(mesh.positions[tri[0]]), b(mesh.positions[tri[1]]), c(mesh.positions[tri[2]]);
        to_surface[i] = first_order_distance(field, a + (b - a) * s + (c - a) * r);
    });
    for (double e : to_surface) error.mesh_to_surface = std::max(error.mesh_to_surface, e);

    // Surface → mesh.
    const std::vector<Vec3d> points = surface_points(field, samples, seed);
    error.surface_samples = points.size();
    const ClosestPointQuery query(mesh);
    std::vector<double> to_mesh(points.size());
    parallel_for(std::size_t(0), points.size(),
                 [&](std::size_t i) { to_mesh[i] = query.nearest(points[i], INFINITY).distance; });
    for (double e : to_mesh) error.surface_to_mesh = std::max(error.surface_to_mesh, e);
    return error;
}

}  // namespace isotrace
