#include "geometry/abm_patch/loop_check.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace isotrace {
namespace {

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

void check_not_degenerate(const std::vector<PatchSide>& sides) {
    for (const PatchSide& side : sides) {
        double extent = 0;
        for (const Vec3d& p : side.curve->control_points()) extent = std::max(extent, max_component(abs(p)));
        if (!(side.curve->polyline_length(64) > 1e-12 * std::max(extent, 1e-300)))
            throw std::invalid_argument(side.name + " is degenerate: it has no length");
    }
}

}  // namespace isotrace
