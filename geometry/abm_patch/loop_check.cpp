#include "geometry/abm_patch/loop_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace isotrace {

std::string format_point(const Vec3d& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.x, p.y, p.z);
    return text;
}

std::string format_number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

namespace {

struct LoopPoint {
    Vec3d position;
    std::size_t side;
};

// The loop as a closed polyline: each side's samples without its end (the next side's start).
std::vector<LoopPoint> loop_polyline(const std::vector<PatchSide>& sides) {
    std::vector<LoopPoint> points;
    for (std::size_t i = 0; i < sides.size(); ++i) {
        const int count = std::clamp(4 * int(sides[i].curve->control_points().size()), kLoopSamplesPerCurve, 256);
        for (int k = 0; k < count; ++k) points.push_back({sides[i].point(double(k) / count), i});
    }
    return points;
}

// The direction to look along: the Newell normal (area vector) of the loop, or where its lobes cancel, the
// largest normal of the plane through the centroid and two points a quarter of the loop apart.
Vec3d viewing_normal(const std::vector<LoopPoint>& points, const Vec3d& centroid, double extent) {
    Vec3d newell{};
    for (std::size_t k = 0; k < points.size(); ++k)
        newell = newell + cross(points[k].position - centroid, points[(k + 1) % points.size()].position - centroid);
    if (length(newell) > 1e-6 * extent * extent) return newell;
    Vec3d widest{};
    for (std::size_t k = 0; k < points.size(); ++k) {
        const Vec3d n = cross(points[k].position - centroid, points[(k + points.size() / 4) % points.size()].position - centroid);
        if (length(n) > length(widest)) widest = n;
    }
    return widest;
}

}  // namespace

void check_closed_loop(const std::vector<PatchSide>& sides, double tolerance) {
    const std::size_t n = sides.size();
    for (std::size_t i = 0; i < n; ++i) {
        const PatchSide& a = sides[i];
        const PatchSide& b = sides[(i + 1) % n];
        const double gap = length(a.end() - b.start());
        if (gap <= tolerance) continue;
        std::string hint;
        if (length(a.start() - b.start()) <= tolerance || length(a.start() - b.end()) <= tolerance)
            hint = "; it closes with " + a.name + " reversed";
        else if (length(a.end() - b.end()) <= tolerance)
            hint = "; it closes with " + b.name + " reversed";
        throw std::invalid_argument("the boundary is not a closed loop: " + a.name + " ends at " + format_point(a.end()) +
                                    " but " + b.name + " starts at " + format_point(b.start()) + ", a gap of " +
                                    format_number(gap) + " (tolerance " + format_number(tolerance) + ")" + hint);
    }
}

void check_not_self_crossing(const std::vector<PatchSide>& sides) {
    const std::vector<LoopPoint> points = loop_polyline(sides);
    Vec3d centroid{};
    for (const LoopPoint& p : points) centroid = centroid + p.position;
    centroid = (1.0 / double(points.size())) * centroid;
    double extent = 0;
    for (const LoopPoint& p : points) extent = std::max(extent, length(p.position - centroid));
    const Vec3d normal = viewing_normal(points, centroid, extent);
    if (!(length(normal) > 1e-9 * extent * extent)) return;  // the loop lies on a line: nothing can cross
    // A basis of the plane seen along the normal.
    const Vec3d n = normalize(normal);
    const Vec3d e1 = normalize(std::abs(n.x) < 0.9 ? cross(n, Vec3d{1, 0, 0}) : cross(n, Vec3d{0, 1, 0}));
    const Vec3d e2 = cross(n, e1);
    std::vector<std::array<double, 2>> flat;
    for (const LoopPoint& p : points) flat.push_back({dot(p.position - centroid, e1), dot(p.position - centroid, e2)});
    // Orientations below this (in units of extent²) count as collinear.
    const double collinear = 1e-9 * extent * extent;
    auto orient = [&](std::size_t a, std::size_t b, std::size_t c) {
        const double v = (flat[b][0] - flat[a][0]) * (flat[c][1] - flat[a][1]) - (flat[b][1] - flat[a][1]) * (flat[c][0] - flat[a][0]);
        return v > collinear ? 1 : v < -collinear ? -1 : 0;
    };
    auto within_box = [&](std::size_t a, std::size_t b, std::size_t c) {  // c collinear with a, b: between them?
        return std::min(flat[a][0], flat[b][0]) <= flat[c][0] && flat[c][0] <= std::max(flat[a][0], flat[b][0]) &&
               std::min(flat[a][1], flat[b][1]) <= flat[c][1] && flat[c][1] <= std::max(flat[a][1], flat[b][1]);
    };
    // Segments that cross or touch (a loop through one point twice pinches the patch as much as a crossing).
    auto meet = [&](std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
        const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
        if (o1 * o2 < 0 && o3 * o4 < 0) return true;
        return (o1 == 0 && within_box(a, b, c)) || (o2 == 0 && within_box(a, b, d)) || (o3 == 0 && within_box(c, d, a)) ||
               (o4 == 0 && within_box(c, d, b));
    };
    const std::size_t m = flat.size();
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = i + 2; j < m; ++j) {
            if (i == 0 && j == m - 1) continue;  // neighbours across the loop's start
            if (meet(i, (i + 1) % m, j, (j + 1) % m))
                throw std::invalid_argument("the boundary loop crosses itself: " + sides[points[i].side].name + " crosses " +
                                            sides[points[j].side].name +
                                            " (seen along the loop's mean normal), so the patch would fold over; "
                                            "list the curves in the order they run around the patch");
        }
}

void check_not_degenerate(const std::vector<PatchSide>& sides) {
    for (const PatchSide& side : sides) {
        double extent = 0;
        for (const Vec3d& p : side.curve->control_points()) extent = std::max(extent, max_component(abs(p)));
        if (!(side.curve->polyline_length(64) > 1e-12 * std::max(extent, 1e-300)))
            throw std::invalid_argument(side.name + " is degenerate: it has no length");
    }
}

}  // namespace isotrace
