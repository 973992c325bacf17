#include "geometry/implicit/metacube_ray_slices.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geometry/polynomial/quadratic_roots.h"
#include "geometry/sphere/sphere_intersection.h"
#include "renderer/math/line_box_clip.h"

namespace isotrace {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The part of [begin, end] where the convex quadratic q is ≤ level, if any.
std::optional<std::pair<double, double>> where_at_most(const QuadraticAbout& q, double level, double begin,
                                                       double end) {
    double low = -kInfinity, high = kInfinity;  // roots of c2·s² + c1·s + c in s = t − t_ref
    if (q.c2 == 0) {
        // No axis that contributes to dist² moves along the ray (then c1 = 0 too): q is constant.
        if (q.c0 > level) return std::nullopt;
    } else {
        const QuadraticRoots roots = quadratic_roots(q.c2, q.c1, q.c0 - level);
        if (roots.count == 0) return std::nullopt;
        low = roots.roots[0];
        high = roots.roots[roots.count - 1];
    }
    const double from = std::max(begin, q.t_ref + low), to = std::min(end, q.t_ref + high);
    if (from > to) return std::nullopt;
    return std::pair{from, to};
}

}  // namespace

std::optional<MetacubeRaySlices> MetacubeRaySlices::slice(const Metacube& element, const Vec3d& origin,
                                                          const Vec3d& direction) {
    if (element.is_metaball()) {
        const auto roots = intersect_sphere(origin, direction, element.centre(), element.radius());
        if (!roots || !(roots->t0 < roots->t1)) return std::nullopt;
        return metaball(origin, direction, element.centre(), roots->t0, roots->t1);
    }
    const OrientedBox box = element.skeleton();
    MetacubeRaySlices slices;
    const Vec3d o = box.to_local(origin), v = box.to_local_vector(direction), d = box.half_size;
    slices.local_origin_ = o;
    slices.local_direction_ = v;
    slices.half_size_ = d;
    const double radius = element.radius();

    // The box grown by R contains the support: clip the line to it first.
    const Vec3d reach = d + Vec3d(radius, radius, radius);
    const auto clip = clip_line_to_box(-reach, reach, o, v, -kInfinity, kInfinity);
    if (!clip || !(clip->t_enter < clip->t_exit) || !std::isfinite(clip->t_enter) || !std::isfinite(clip->t_exit))
        return std::nullopt;
    const double t0 = clip->t_enter, t1 = clip->t_exit;

    // Breakpoints: crossings of the face planes pₖ = ±dₖ (an axis with dₖ = 0 has no slab, so no change of form).
    // At most eight cuts: inserting each in order keeps them sorted.
    std::array<double, 8> cuts{};
    int cut_count = 0;
    auto add_cut = [&](double t) {
        int i = cut_count++;
        for (; i > 0 && cuts[i - 1] > t; --i) cuts[i] = cuts[i - 1];
        cuts[i] = t;
    };
    add_cut(t0);
    add_cut(t1);
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0 || v[k] == 0) continue;
        for (const double plane : {-d[k], d[k]}) {
            const double t = (plane - o[k]) / v[k];
            if (t0 < t && t < t1) add_cut(t);
        }
    }

    // Regions between the cuts, then the exact support: the first and last t where dist² ≤ R² (one interval by
    // convexity, so the union of the per-piece solutions is its hull).
    double t_in = kInfinity, t_out = -kInfinity;
    for (int i = 0; i + 1 < cut_count; ++i) {
        RegionPiece piece{cuts[i], cuts[i + 1], {}};
        if (!(piece.t_begin < piece.t_end)) continue;
        piece.region = slices.region_at(0.5 * (piece.t_begin + piece.t_end));
        const auto inside =
            where_at_most(slices.distance_squared(piece, piece.t_begin), radius * radius, piece.t_begin, piece.t_end);
        if (inside) {
            t_in = std::min(t_in, inside->first);
            t_out = std::max(t_out, inside->second);
        }
        slices.pieces_[slices.count_++] = piece;
    }
    if (!(t_in < t_out)) return std::nullopt;

    int kept = 0;
    for (int i = 0; i < slices.count_; ++i) {
        RegionPiece piece = slices.pieces_[i];
        piece.t_begin = std::max(piece.t_begin, t_in);
        piece.t_end = std::min(piece.t_end, t_out);
        if (piece.t_begin < piece.t_end) slices.pieces_[kept++] = piece;
    }
    slices.count_ = kept;
    return slices;
}

// One piece between the support sphere's roots; distances need no rotation (the box has no extent).
MetacubeRaySlices MetacubeRaySlices::metaball(const Vec3d& origin, const Vec3d& direction, const Vec3d& centre,
                                              double t_in, double t_out) {
    MetacubeRaySlices slices;
    slices.local_origin_ = origin - centre;
    slices.local_direction_ = direction;
    slices.half_size_ = {0, 0, 0};
    slices.pieces_[0] = {t_in, t_out, {1, 1, 1}};
    slices.count_ = 1;
    return slices;
}

std::array<int, 3> MetacubeRaySlices::region_at(double t) const {
    std::array<int, 3> region{};
    for (int k = 0; k < 3; ++k) {
        const double p = local_origin_[k] + local_direction_[k] * t;
        if (half_size_[k] == 0 || p > half_size_[k]) region[k] = 1;
        else if (p < -half_size_[k]) region[k] = -1;
    }
    return region;
}

// On the piece, dist² = Σ over the axes with Uₖ ≠ 0 of (pₖ(t) − Uₖ·dₖ)², each term a square of a linear function
// of t; expanding it about t_ref keeps its offset aₖ small.
QuadraticAbout MetacubeRaySlices::distance_squared(const RegionPiece& piece, double t_ref) const {
    return squared_offsets(local_origin_, local_direction_, half_size_, piece.region, t_ref);
}

}  // namespace isotrace
