#include "geometry/polygonize/mesh_error.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "geometry/field/crossing_search.h"
#include "geometry/mesh/closest_triangle_point.h"
#include "geometry/polygonize/neighbour_directions.h"
#include "renderer/core/parallel_for.h"

namespace isotrace {
namespace {

constexpr int kStepsPerLine = 256;
// The line search resolves crossings to this fraction of the line (closer pairs count as grazing).
constexpr double kLineResolution = 1.0 / 256;

// The distance from p to the nearest crossing of the surface along `line` (a unit vector; both ways, out to
// `reach`), found by the guaranteed crossing search the ray tracer uses for implicit surfaces (crossing_search.h)
// with the field's interval bounds; infinite when there is none.
double distance_along(const ImplicitField& field, const Vec3d& p, double f, const Vec3d& line, double reach) {
    double nearest = INFINITY;
    // Towards the surface first (against the gradient outside, along it inside): the nearer crossing found there
    // shortens the search the other way.
    const double towards = f > 0 ? -1.0 : 1.0;
    for (const double sense : {towards, -towards}) {
        const Vec3d d = line * sense;
        const auto at = [&](double t) { return p + d * t; };
        const auto value = [&](double t) { return field.value(at(t)); };
        const auto segment = [&](double a, double b) {
            IntervalBox box = IntervalBox::point(at(a));
            box.extend(at(b));
            return box;
        };
        const double end = std::min(reach, nearest);
        CrossingSearchWork work;
        search_crossings(
            0.0, end, f, value(end), reach * kLineResolution, false, value,
            [&](double a, double b) { return field.value_range(segment(a, b)); },
            [&](double a, double b) { return field.slope_range(segment(a, b), d); }, work,
            [&](const Crossing& crossing) {
                nearest = std::min(nearest, crossing.t);
                return false;
            });
    }
    return nearest;
}

// The distance from p to the surface along the gradient's line: an upper bound of the distance to the surface
// and, near it, the distance itself (the nearest surface point lies along the normal). Unlike |f|/|∇f| it holds
// where the gradient is zero or the field is no distance (a blob's flat outer field, a hard cube's step). Where
// the gradient is zero or its line meets no surface within `reach` (a point just off a box's corner, say), the
// nearest crossing along the 26 directions of neighbour_directions.h.
double distance_to_surface(const ImplicitField& field, const Vec3d& p, double reach) {
    const double f = field.value(p);
    if (f == 0) return 0;
    const Vec3d g = field.gradient(p);
    const double slope = length(g);
    // Mesh points lie near the surface: a short line first (a field without interval bounds is searched cell by
    // cell of the resolution), the whole reach only when it holds no crossing.
    for (const double length_of_line : {reach / 64, reach}) {
        double nearest = slope > 0 && std::isfinite(slope) ? distance_along(field, p, f, g / slope, length_of_line)
                                                           : INFINITY;
        if (std::isfinite(nearest)) return nearest;
        for (const Vec3d& direction : neighbour_directions())  // each line twice, both ways: simple, and rare
            nearest = std::min(nearest, distance_along(field, p, f, direction, length_of_line));
        if (std::isfinite(nearest)) return nearest;
    }
    return INFINITY;
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
    const double reach = length(field.bounds().extent());
    // At most kVertexSamples vertices, evenly spread over the numbering.
    const std::size_t stride =
        std::max<std::size_t>(1, (mesh.positions.size() + kVertexSamples - 1) / kVertexSamples);
    std::vector<double> at_vertex((mesh.positions.size() + stride - 1) / stride);
    parallel_for(std::size_t(0), at_vertex.size(), [&](std::size_t i) {
        at_vertex[i] = distance_to_surface(field, Vec3d(mesh.positions[i * stride]), reach);
    });
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
        to_surface[i] = distance_to_surface(field, a + (b - a) * s + (c - a) * r, reach);
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
