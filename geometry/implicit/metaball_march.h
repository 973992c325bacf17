#pragma once
// The blob march for groups of metaballs alone whose kernel is one polynomial piece on its whole support (Kim's,
// Wyvill's and Murakami's: the benchmark clouds and most scenes). The same pieces, bounds, Bernstein test and
// solving as the general march (field_march.h, march_piece.h), with the cell's candidates side by side in lanes of
// four (double4.h) instead of in a list of joined elements ordered by entry:
//   1. the float sphere test keeps the listed elements the stretch may come near; their exact nearest approaches
//      bound F from above (below T the stretch holds no crossing, and many queries end here), and those
//      whose support's chord meets the stretch become the candidates, in ascending element order;
//   2. a metaball has one piece, its support's chord [t_enter, t_exit], so on any piece of the stretch its term of
//      the sum is one polynomial: a piece the bounds leave open composes the terms of the elements counting on it
//      directly in the piece's own u ∈ [0, 1], four lanes at a time (no shift of a sum to the piece);
//   3. pieces run between consecutive entries and exits: the next event is the least entry or exit beyond the
//      piece's start (a minimum over the lanes, no sort), and the elements that count on a piece are a mask of the
//      lanes (entered, not left), so each bound and sum is a masked sum over whole lanes: no branch per element,
//      where the general march's loops over its joined elements and its sort mispredict (docs/decisions.md).
// It takes at most kMaxLanes near elements (nearly every query of the benchmark clouds): run returns false for more,
// having done nothing, and the general march takes the query. Its sums run in lane order rather than in order of
// entry, so its crossings agree with the general march's to rounding, not bit for bit.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>

#include "geometry/implicit/field_function.h"
#include "geometry/implicit/march_piece.h"
#include "geometry/implicit/metacube.h"
#include "geometry/implicit/piece_march.h"
#include "geometry/implicit/sphere_prefilter.h"
#include "geometry/implicit/unit_piece_lanes.h"
#include "renderer/core/inline_vector.h"
#include "renderer/math/double4.h"
#include "renderer/math/fused_bounds.h"

namespace isotrace {

template <class Kernel>
class MetaballMarch {
public:
    static constexpr std::size_t kMaxLanes = 32;  // lane sets are bits of an unsigned

    // Whether a group of `elements` with this kernel may be marched here: metaballs only, and a kernel that is one
    // polynomial piece of degree ≤ 3 in r²/R² on the whole support.
    static bool applies(const Kernel& kernel, std::span<const Metacube> elements) {
        const auto pieces = kernel.unit_pieces();
        if (pieces.size() != 1 || !pieces[0].is_polynomial || pieces[0].degree > 3) return false;
        for (const Metacube& element : elements)
            if (!element.is_metaball()) return false;
        return true;
    }

    // centre_bound ≥ the largest |centre| of the spheres.
    MetaballMarch(const Kernel& kernel, double threshold, std::span<const Metacube> elements,
                  std::span<const BoundingSphere> spheres, double centre_bound)
        : kernel_(kernel), threshold_(threshold), elements_(elements), spheres_(spheres),
          centre_bound_(centre_bound), unit_(kernel.unit_pieces()[0]) {}

    // As FieldMarch::run: marches `stretch` over the field of the `listed` elements (every element whose support
    // may reach the stretch is among them), calling query.found(crossing, march) for each crossing in increasing t
    // (true: stop) and query.crossed_before() when the stretch starts inside after t_min (true: stop). Returns false,
    // having done nothing, when more than kMaxLanes listed elements may come near the stretch. Without
    // Query::kPlaceNeeded (occlusion) a crossing may be reported at any t of the piece it lies on: F beyond rounding on
    // both sides of T at a piece's ends proves one there, with no polynomial composed or solved.
    template <class Query>
    bool run(std::span<const std::uint32_t> listed, const MarchStretch& stretch, BlobQueryWork& work, Query& query);

    // F + T at a point, from `listed` (every element whose support may contain the point), four elements at a time:
    // an occlusion query asks it whether its ray started outside. BlobGroup::field sums the same terms one by one, so
    // the last bits may differ; the question allows 10⁻⁶ of T.
    double field_at(const Vec3d& point, std::span<const std::uint32_t> listed) const;

private:
    // The lanes as the piece march (piece_march.h) reads them, over kGroups groups of candidates (0: groups_).
    template <std::size_t kGroups>
    class Pieces;
    // The centres, radii and weights of four listed elements (`listed[first…]`, the last one repeated past the end of
    // the list), each read in one load and transposed into lanes in registers, and the lanes that hold a listed one.
    struct ElementLanes {
        Double4 x, y, z, radius, weight;
        Mask4 in_list;
    };
    ElementLanes element_lanes(std::span<const std::uint32_t> listed, std::size_t first) const;

    static constexpr std::size_t kTermSize = 7;  // a cubic in x composed with the quadratic x(s): degree 6
    // The loops over groups of four lanes take their count as a template argument, 1 to kUnrolledGroups (most
    // queries), so that they unroll and leave no loop exit to mispredict, and 0 for "read it from the query" (the
    // count varies from query to query, and a query runs some twenty such loops).
    static constexpr std::size_t kUnrolledGroups = 4;
    template <std::size_t kGroups>
    std::size_t groups() const { return kGroups != 0 ? kGroups : groups_; }
    template <std::size_t kNearGroups>
    std::size_t near_groups() const { return kNearGroups != 0 ? kNearGroups : (near_.size() + 3) / 4; }

    // run once the near elements are known, with kNearGroups groups of them (0: as many as there are).
    template <std::size_t kNearGroups, class Query>
    void march_near(const MarchStretch& stretch, BlobQueryWork& work, Query& query);
    // The piece march over kGroups groups of candidates (0: groups_).
    template <std::size_t kGroups, class Query>
    void march_lanes(const MarchStretch& stretch, BlobQueryWork& work, Query& query);

    // Loads the near elements into the lanes and returns an upper bound of Σ wᵢ·fᵢ on the stretch from each one's
    // nearest approach (as FieldMarch::gather), without the chords' square roots: many queries end at this bound.
    template <std::size_t kNearGroups>
    double near_bound(const MarchStretch& stretch);
    // Leaves in the lanes, compacted, the candidates (their support's chord meets the stretch) with their chords.
    template <std::size_t kNearGroups>
    void make_candidates(const MarchStretch& stretch);
    // The candidates' dist² quadratics about the stretch's start and their 1/R².
    template <std::size_t kGroups>
    void prepare_pieces(const MarchStretch& stretch);
    // F − T on the piece [s0, s0 + width] as a polynomial in u ∈ [0, 1], summed over the lanes in `counts`, and a bound
    // on the magnitude of every value its composition rounds (for the Bernstein test's rounding).
    struct PiecePolynomial {
        std::array<double, 8> coefficients;  // two lanes of four: kTermSize coefficients, then a 0
        double magnitude;
    };
    template <std::size_t kGroups>
    PiecePolynomial piece_polynomial(double s0, double width, const Mask4* counts) const;
    // The kernel on x = r²/R² per lane (unit_piece_lanes.h).
    template <class MulAdd = RoundedMulAdd>
    Double4 unit_value(Double4 x, MulAdd mul_add = {}) const {
        return unit_piece_value(unit_.coefficients, x, mul_add);
    }
    // dist² per lane of group g at s (about the stretch's start; a number or one per lane).
    template <class S, class MulAdd = RoundedMulAdd>
    Double4 distance2(std::size_t g, S s, MulAdd mul_add = {}) const {
        return mul_add(s, mul_add(s, c2_, load4(q1_ + 4 * g)), load4(q0_ + 4 * g));
    }
    // d(dist²)/ds per lane of group g at s: where a piece's x(u) and a chord's rise start.
    Double4 distance2_slope(std::size_t g, double s) const { return load4(q1_ + 4 * g) + 2 * c2_ * s; }
    // The smallest and largest dist² per lane of group g on [s0, s1] (branch free: which end is nearer is data), for
    // the piece's bounds.
    std::pair<Double4, Double4> distance2_range(std::size_t g, double s0, double s1) const {
        const Double4 at_s0 = distance2(g, s0, BoundMulAdd{}), at_s1 = distance2(g, s1, BoundMulAdd{});
        const Double4 nearest = min4(max4(load4(vertex_ + 4 * g), Double4{} + s0), Double4{} + s1);
        const Double4 at_nearest = distance2(g, nearest, BoundMulAdd{});
        return {max4(min4(min4(at_s0, at_s1), at_nearest), Double4{}), max4(at_s0, at_s1)};
    }
    // The elements counting on the piece that starts at t0, per group of four lanes (entered, not left).
    Mask4 counting(std::size_t g, double t0) const {
        return (load4(t_enter_ + 4 * g) <= t0) & (load4(t_exit_ + 4 * g) > t0);
    }
    template <std::size_t kGroups>
    double value(double t) const;
    // Σ |wᵢ| over the lanes(g) of each group (elements counting at some t, or every candidate): F + T cannot exceed
    // it where only those count (f ≤ 1), so it scales the rounding of value().
    template <std::size_t kGroups, class Lanes>
    double absolute_weights(Lanes&& lanes) const;

    // Whether the kernel's polynomial f(x) on [0, 1] is convex and non-increasing (f'' ≥ 0 at both ends, as it is
    // linear; f' ≤ 0 at 1) and meets 0 at x = 1, so that f(min(x, 1)) is convex on x ≥ 0: Kim's, Wyvill's and
    // Murakami's kernels are.
    static bool convex_and_falling(const FieldPiece& unit) {
        const auto& b = unit.coefficients;
        const double at_one = b[0] + b[1] + b[2] + b[3];
        return 2 * b[2] >= 0 && 2 * b[2] + 6 * b[3] >= 0 && b[1] + 2 * b[2] + 3 * b[3] <= 0 &&
               std::abs(at_one) <= 1e-12 * (std::abs(b[0]) + std::abs(b[1]) + std::abs(b[2]) + std::abs(b[3]));
    }
    // An upper bound of Σ wᵢ·fᵢ on [s0, s0 + width] (s about t_ref_, the lanes in `counts`: those counting on a piece,
    // or every candidate over several pieces) for a convex kernel, tighter than the elements' own ranges: there an
    // element's x = r²/R² stays within [x_near, x_far], where f(min(x, 1)) lies below its chord (beyond x = 1, outside
    // the support, f is 0), a line in x and so a quadratic in s; the sum of the chords (concave: they fall) peaks at
    // its vertex or an end. The ranges are loose where some elements rise while others fall, as at the start of a
    // ray leaving the surface, where F is within a hair of T.
    template <std::size_t kGroups>
    double chord_upper_bound(double s0, double width, const Mask4* counts) const;

    const Kernel& kernel_;
    double threshold_;
    std::span<const Metacube> elements_;
    std::span<const BoundingSphere> spheres_;
    double centre_bound_;
    const FieldPiece& unit_;

    InlineVector<std::uint32_t, 64> near_;  // the elements the float test kept
    unsigned kept_lanes_ = 0;               // of those, the ones the exact test kept
    double inverse_length2_ = 0;            // 1/|d|²
    // The lanes hold the near elements, then the candidates, lanes [0, count_); the lanes up to the end of their
    // group are inert (they never count).
    std::size_t count_ = 0, groups_ = 0;
    double t_ref_ = 0, c2_ = 0;  // dist² = q0 + q1·s + c2·s² with s = t − t_ref_ (c2 = |d|² for every lane)
    alignas(32) double x_[kMaxLanes], y_[kMaxLanes], z_[kMaxLanes];
    alignas(32) double radius_[kMaxLanes], inverse_radius2_[kMaxLanes], weight_[kMaxLanes];
    alignas(32) double middle_[kMaxLanes];  // where the line passes nearest the centre
    alignas(32) double t_enter_[kMaxLanes], t_exit_[kMaxLanes];
    alignas(32) double q0_[kMaxLanes], q1_[kMaxLanes], vertex_[kMaxLanes];  // vertex: where dist² is least, in s
    std::uint32_t index_[kMaxLanes];
    std::array<unsigned, kMaxLanes / 4> counting_{};  // per group, the lanes counting on the current piece
};

template <class Kernel>
typename MetaballMarch<Kernel>::ElementLanes MetaballMarch<Kernel>::element_lanes(std::span<const std::uint32_t> listed,
                                                                                  std::size_t first) const {
    const std::size_t n = listed.size();
    const double* e[4];
    for (std::size_t k = 0; k < 4; ++k) e[k] = elements_[listed[std::min(first + k, n - 1)]].centre_radius_weight();
    const Double4 a = load4(e[0]), b = load4(e[1]), c = load4(e[2]), f = load4(e[3]);
    const Double4 ab_even = __builtin_shufflevector(a, b, 0, 4, 2, 6);
    const Double4 ab_odd = __builtin_shufflevector(a, b, 1, 5, 3, 7);
    const Double4 cf_even = __builtin_shufflevector(c, f, 0, 4, 2, 6);
    const Double4 cf_odd = __builtin_shufflevector(c, f, 1, 5, 3, 7);
    const std::int64_t lane = std::int64_t(first);
    return {__builtin_shufflevector(ab_even, cf_even, 0, 1, 4, 5), __builtin_shufflevector(ab_odd, cf_odd, 0, 1, 4, 5),
            __builtin_shufflevector(ab_even, cf_even, 2, 3, 6, 7), __builtin_shufflevector(ab_odd, cf_odd, 2, 3, 6, 7),
            Double4{e[0][4], e[1][4], e[2][4], e[3][4]},
            Mask4{lane, lane + 1, lane + 2, lane + 3} < std::int64_t(n)};
}

template <class Kernel>
double MetaballMarch<Kernel>::field_at(const Vec3d& point, std::span<const std::uint32_t> listed) const {
    InlineVector<std::uint32_t, 64> near;
    append_near(listed, spheres_, PointNearSpheres(point, centre_bound_), near);
    const std::span<const std::uint32_t> ids(near.begin(), near.size());
    Double4 sum{};
    for (std::size_t first = 0; first < ids.size(); first += 4) {
        const auto [x, y, z, radius, weight, in_list] = element_lanes(ids, first);
        const Double4 dx = point.x - x, dy = point.y - y, dz = point.z - z;
        sum += select(in_list, weight * unit_value((dx * dx + dy * dy + dz * dz) / (radius * radius)), Double4{});
    }
    return lane_sum(sum);
}

template <class Kernel>
template <std::size_t kNearGroups>
double MetaballMarch<Kernel>::near_bound(const MarchStretch& stretch) {
    inverse_length2_ = 1 / dot(stretch.direction, stretch.direction);
    const Vec3d& o = stretch.origin;
    const Vec3d& d = stretch.direction;
    const double rounding = nearest_approach_rounding(stretch, centre_bound_);
    Double4 upper{};  // Σ wᵢ·max fᵢ on the stretch over elements of positive weight
    kept_lanes_ = 0;
    for (std::size_t g = 0; g < near_groups<kNearGroups>(); ++g) {
        // Stored for the steps after. The lanes past the list repeat its last element; the exact test leaves them out.
        const auto [x, y, z, radius, weight, in_list] = element_lanes({near_.begin(), near_.size()}, 4 * g);
        store4(x_ + 4 * g, x);
        store4(y_ + 4 * g, y);
        store4(z_ + 4 * g, z);
        store4(radius_ + 4 * g, radius);
        store4(weight_ + 4 * g, weight);
        const Double4 middle = ((x - o.x) * d.x + (y - o.y) * d.y + (z - o.z) * d.z) * inverse_length2_;
        store4(middle_ + 4 * g, middle);
        // The stretch's point nearest the centre: the element's field there bounds it on the whole stretch.
        const Double4 nearest = min4(max4(middle, Double4{} + stretch.t_begin), Double4{} + stretch.t_end);
        const Double4 gx = (o.x + d.x * nearest) - x, gy = (o.y + d.y * nearest) - y, gz = (o.z + d.z * nearest) - z;
        const Double4 gap2 = gx * gx + gy * gy + gz * gz;
        const Double4 keep = radius * (1 + 1e-9) + rounding;
        const Mask4 kept = in_list & (gap2 <= keep * keep);
        kept_lanes_ |= mask_bits(kept) << (4 * g);
        const Double4 bound = weight * unit_value(gap2 / (radius * radius), BoundMulAdd{});
        upper += select(kept & (weight > 0.0), bound, Double4{});
    }
    return lane_sum(upper);
}

template <class Kernel>
template <std::size_t kNearGroups>
void MetaballMarch<Kernel>::make_candidates(const MarchStretch& stretch) {
    const Vec3d& o = stretch.origin;
    const Vec3d& d = stretch.direction;
    const std::size_t n = near_.size();
    unsigned candidates = 0;
    for (std::size_t g = 0; g < near_groups<kNearGroups>(); ++g) {
        // The chord through the support: the centre's projection on the line ± the half chord.
        const Double4 middle = load4(middle_ + 4 * g), radius = load4(radius_ + 4 * g);
        const Double4 lx = (o.x + d.x * middle) - load4(x_ + 4 * g), ly = (o.y + d.y * middle) - load4(y_ + 4 * g),
                      lz = (o.z + d.z * middle) - load4(z_ + 4 * g);
        const Double4 half_chord2 = (radius * radius - (lx * lx + ly * ly + lz * lz)) * inverse_length2_;
        const Double4 half_chord = sqrt4(max4(half_chord2, Double4{}));
        const Double4 t_enter = middle - half_chord, t_exit = middle + half_chord;
        store4(t_enter_ + 4 * g, t_enter);
        store4(t_exit_ + 4 * g, t_exit);
        const Mask4 meets = (half_chord2 >= 0.0) & (t_exit > stretch.t_begin) & (t_enter < stretch.t_end);
        candidates |= mask_bits(meets) << (4 * g);
    }
    candidates &= kept_lanes_;
    std::size_t k = 0;
    if (candidates == unsigned((std::uint64_t(1) << n) - 1)) {
        // Every near element is a candidate, in its lane already.
        for (; k < n; ++k) index_[k] = near_[k];
    } else {
        // Compacted in place (lane k ≤ i), without a branch per lane; ascending element order is kept.
        for (std::size_t i = 0; i < n; ++i) {
            x_[k] = x_[i];
            y_[k] = y_[i];
            z_[k] = z_[i];
            radius_[k] = radius_[i];
            weight_[k] = weight_[i];
            t_enter_[k] = t_enter_[i];
            t_exit_[k] = t_exit_[i];
            index_[k] = near_[i];
            k += (candidates >> i) & 1u;
        }
    }
    count_ = k;
    groups_ = (k + 3) / 4;
    t_ref_ = stretch.t_begin;
    c2_ = d.x * d.x + d.y * d.y + d.z * d.z;
    if (groups_ == 0) return;
    // The lanes after the last candidate, up to the end of its group, are inert: never entered, weight 0 (their
    // index is never read). Masked in one pass over the group rather than lane by lane.
    const std::size_t last = 4 * (groups_ - 1);
    const Mask4 inert = Mask4{0, 1, 2, 3} >= std::int64_t(k - last);
    const Double4 never = Double4{} + std::numeric_limits<double>::infinity();
    for (double* lanes : {x_, y_, z_, weight_}) store4(lanes + last, select(inert, Double4{}, load4(lanes + last)));
    store4(radius_ + last, select(inert, Double4{} + 1, load4(radius_ + last)));
    store4(t_enter_ + last, select(inert, never, load4(t_enter_ + last)));
    store4(t_exit_ + last, select(inert, never, load4(t_exit_ + last)));
}

template <class Kernel>
template <std::size_t kGroups>
void MetaballMarch<Kernel>::prepare_pieces(const MarchStretch& stretch) {
    const Vec3d& o = stretch.origin;
    const Vec3d& d = stretch.direction;
    // dist² about the stretch's start, as MetacubeRaySlices::metaball_distance_squared writes it.
    for (std::size_t g = 0; g < groups<kGroups>(); ++g) {
        const Double4 ax = (o.x - load4(x_ + 4 * g)) + d.x * t_ref_, ay = (o.y - load4(y_ + 4 * g)) + d.y * t_ref_,
                      az = (o.z - load4(z_ + 4 * g)) + d.z * t_ref_;
        const Double4 q1 = 2 * ax * d.x + 2 * ay * d.y + 2 * az * d.z;
        store4(q0_ + 4 * g, ax * ax + ay * ay + az * az);
        store4(q1_ + 4 * g, q1);
        store4(vertex_ + 4 * g, -q1 / (2 * c2_));
        const Double4 radius = load4(radius_ + 4 * g);
        store4(inverse_radius2_ + 4 * g, 1 / (radius * radius));
    }
}

template <class Kernel>
template <std::size_t kGroups>
typename MetaballMarch<Kernel>::PiecePolynomial MetaballMarch<Kernel>::piece_polynomial(double s0, double width,
                                                                                        const Mask4* counts) const {
    // Each counting element's w·Σₖ βₖ·xᵏ with x(u) = dist²(s0 + u·width)/R² = x0 + x1·u + x2·u², by Horner on
    // polynomials: each step multiplies by x(u) (every new coefficient from the old ones, cᵢ ← cᵢ₋₂·x2 + cᵢ₋₁·x1 +
    // cᵢ·x0) and adds w·βₖ. Composed on the piece itself, not about the stretch's start and then shifted to the piece
    // (a degree-6 shift on the critical path of every hit, and its rounding). Four lanes at a time; the loops have
    // constant bounds and unroll, so the coefficients stay in registers.
    const auto& b = unit_.coefficients;
    const double reach = std::abs(s0) + width;  // |s| on the piece is at most this
    Double4 total[kTermSize] = {}, magnitude{};
    for (std::size_t g = 0; g < groups<kGroups>(); ++g) {
        const Double4 weight = load4(weight_ + 4 * g), inverse_radius2 = load4(inverse_radius2_ + 4 * g);
        const Double4 x0 = distance2(g, s0) * inverse_radius2, x1 = (distance2_slope(g, s0) * width) * inverse_radius2,
                      x2 = (c2_ * (width * width)) * inverse_radius2;
        Double4 c[kTermSize] = {};
        c[0] = weight * b[3];
#pragma GCC unroll 4
        for (int k = 2; k >= 0; --k) {
            const std::size_t degree = std::size_t(2 * (2 - k));  // of c before this step
            Double4 next[kTermSize] = {};
#pragma GCC unroll 8
            for (std::size_t i = 0; i <= degree + 2; ++i) {
                Double4 sum{};
                if (i >= 2) sum = c[i - 2] * x2;
                if (i >= 1 && i - 1 <= degree) sum = i >= 2 ? sum + c[i - 1] * x1 : c[i - 1] * x1;
                if (i <= degree) sum = i >= 1 ? sum + c[i] * x0 : c[i] * x0;
                next[i] = sum;
            }
            next[0] = next[0] + weight * b[std::size_t(k)];
            for (std::size_t i = 0; i < kTermSize; ++i) c[i] = next[i];
        }
        const Mask4 mask = counts[g];
#pragma GCC unroll 7
        for (std::size_t i = 0; i < kTermSize; ++i) total[i] += select(mask, c[i], Double4{});
        // |w|·Σ|βₖ|·Xᵏ with X = (|q0| + |q1|·reach + c2·reach²)/R² ≥ |x| and every product the composition forms, the
        // dist² quadratic's own included.
        const Double4 x_bound =
            (abs4(load4(q0_ + 4 * g)) + abs4(load4(q1_ + 4 * g)) * reach + c2_ * (reach * reach)) * inverse_radius2;
        const Double4 term_bound =
            abs4(weight) *
            (std::abs(b[0]) + x_bound * (std::abs(b[1]) + x_bound * (std::abs(b[2]) + x_bound * std::abs(b[3]))));
        magnitude += select(mask, term_bound, Double4{});
    }
    static_assert(kTermSize == 7, "two lanes of four coefficients");
    PiecePolynomial piece;
    store4(piece.coefficients.data(), lane_sums(total[0], total[1], total[2], total[3]));
    store4(piece.coefficients.data() + 4, lane_sums(total[4], total[5], total[6], Double4{}));
    piece.coefficients[0] -= threshold_;
    piece.magnitude = lane_sum(magnitude) + threshold_;
    return piece;
}

template <class Kernel>
template <std::size_t kGroups>
double MetaballMarch<Kernel>::value(double t) const {
    const double s = t - t_ref_;
    Double4 sum{};
    for (std::size_t g = 0; g < groups<kGroups>(); ++g) {
        const Double4 x = max4(distance2(g, s), Double4{}) * load4(inverse_radius2_ + 4 * g);
        sum += select(counting(g, t), load4(weight_ + 4 * g) * unit_value(x), Double4{});
    }
    return lane_sum(sum) - threshold_;
}

template <class Kernel>
template <std::size_t kGroups, class Lanes>
double MetaballMarch<Kernel>::absolute_weights(Lanes&& lanes) const {
    Double4 sum{};
    for (std::size_t g = 0; g < groups<kGroups>(); ++g) {
        const Double4 weight = load4(weight_ + 4 * g);
        sum += select(lanes(g), abs4(weight), Double4{});
    }
    return lane_sum(sum);
}

template <class Kernel>
template <std::size_t kGroups>
double MetaballMarch<Kernel>::chord_upper_bound(double s0, double width, const Mask4* counts) const {
    Double4 a{}, b{}, c{};  // the chords' sum as a + b·σ + c·σ², σ = s − s0 ∈ [0, width]
    for (std::size_t g = 0; g < groups<kGroups>(); ++g) {
        const auto [near, far] = distance2_range(g, s0, s0 + width);
        const Double4 inverse_radius2 = load4(inverse_radius2_ + 4 * g), weight = load4(weight_ + 4 * g);
        const Double4 x_near = near * inverse_radius2, x_far = far * inverse_radius2;
        const Double4 f_near = unit_value(x_near, BoundMulAdd{}), f_far = unit_value(x_far, BoundMulAdd{});
        // The chord's slope in x (≤ 0); its rounding moves the chord by a rounding of f over [x_near, x_far].
        const Mask4 spread = x_far > x_near;
        const Double4 slope =
            select(spread, (f_far - f_near) / select(spread, x_far - x_near, Double4{} + 1), Double4{});
        // dist²(s0 + σ) − near = (dist²(s0) − near) + (q1 + 2·c2·s0)·σ + c2·σ²
        const Double4 per_distance2 = weight * slope * inverse_radius2;
        const Double4 rise = distance2_slope(g, s0);
        const Mask4 positive = weight > 0.0;
        // An element of negative weight adds at most w·f(x_far).
        a += select(counts[g],
                    select(positive, weight * f_near + per_distance2 * (distance2(g, s0) - near), weight * f_far),
                    Double4{});
        b += select(counts[g] & positive, per_distance2 * rise, Double4{});
        c += select(counts[g] & positive, per_distance2 * c2_, Double4{});
    }
    const double a0 = lane_sum(a), b0 = lane_sum(b), c0 = lane_sum(c);
    double peak = std::max(a0, a0 + width * (b0 + width * c0));
    if (c0 < 0) {
        const double vertex = -b0 / (2 * c0);
        if (vertex > 0 && vertex < width) peak = std::max(peak, a0 + vertex * (b0 + vertex * c0));
    }
    return peak;
}

template <class Kernel>
template <class Query>
bool MetaballMarch<Kernel>::run(std::span<const std::uint32_t> listed, const MarchStretch& stretch,
                                BlobQueryWork& work, Query& query) {
    near_.clear();
    append_near(listed, spheres_, near_stretch_test(stretch, centre_bound_), near_);
    if (near_.size() > kMaxLanes) return false;
    ++work.queries;
    const auto with_near_groups = [&]<std::size_t kNearGroups>() {
        march_near<kNearGroups>(stretch, work, query);
    };
    static_assert(kUnrolledGroups == 4, "one case per unrolled count");
    switch ((near_.size() + 3) / 4) {
        case 1: with_near_groups.template operator()<1>(); break;
        case 2: with_near_groups.template operator()<2>(); break;
        case 3: with_near_groups.template operator()<3>(); break;
        case 4: with_near_groups.template operator()<4>(); break;
        default: with_near_groups.template operator()<0>(); break;
    }
    return true;
}

template <class Kernel>
template <std::size_t kNearGroups, class Query>
void MetaballMarch<Kernel>::march_near(const MarchStretch& stretch, BlobQueryWork& work, Query& query) {
    if (stretch_below_threshold(near_bound<kNearGroups>(stretch), threshold_)) {
        ++work.queries_bounded;
        work.candidates += std::uint64_t(std::popcount(kept_lanes_));
        return;
    }
    make_candidates<kNearGroups>(stretch);
    work.candidates += count_;
    // Nearly every near element is a candidate: the count of groups stays.
    if (kNearGroups != 0 && groups_ == kNearGroups)
        march_lanes<kNearGroups>(stretch, work, query);
    else
        march_lanes<0>(stretch, work, query);
}

template <class Kernel>
template <std::size_t kGroups, class Query>
void MetaballMarch<Kernel>::march_lanes(const MarchStretch& stretch, BlobQueryWork& work, Query& query) {
    prepare_pieces<kGroups>(stretch);
    Pieces<kGroups> pieces(*this);
    PieceMarch(pieces, stretch, work, query).run();
    work.joined += std::uint64_t(std::popcount(pieces.entered()));
}

// The piece march's Elements (piece_march.h): the pieces run between consecutive entries and exits of the lanes,
// the elements counting on a piece are a mask, and every bound and sum is a masked sum over whole lanes.
template <class Kernel>
template <std::size_t kGroups>
class MetaballMarch<Kernel>::Pieces {
public:
    static constexpr bool kAllPolynomial = true;  // no piece needs search_piece

    explicit Pieces(MetaballMarch& lanes) : m_(lanes) {}

    double threshold() const { return m_.threshold_; }
    unsigned entered() const { return entered_; }  // the lanes that counted on some piece

    double start(double t0) {
        for (std::size_t g = 0; g < groups(); ++g) m_.counting_[g] = mask_bits(m_.counting(g, t0));
        return m_.template value<kGroups>(t0);
    }
    double counting_weights(double t0) const {
        return m_.template absolute_weights<kGroups>([&](std::size_t g) { return m_.counting(g, t0); });
    }

    // Before any piece, for a stretch that starts outside: two proofs over the whole stretch.
    template <class March>
    bool settles_stretch(double t0, double at_start, int previous_sign, March& march) const {
        const MarchStretch& stretch = march.stretch();
        if constexpr (!March::kPlaceNeeded) {
            // Outside at the start and inside at the end, both beyond rounding: a crossing lies between, and no piece
            // need be examined. Tight cell boxes start many a shadow ray's stretch just outside a blob it then enters.
            const double margin = rounding();
            if (at_start < -margin && m_.template value<kGroups>(stretch.t_end) > margin &&
                march.crossing(0.5 * (t0 + stretch.t_end), previous_sign))
                return true;
        }
        // A stretch from the ray's start (a ray leaving the surface), or any stretch of an occlusion query, that
        // starts outside: the chords' bound over the whole stretch, every candidate counting, often settles it where
        // the ranges cannot (the start of a ray leaving the surface is within a hair of T); elsewhere nearly every
        // stretch it would be asked of holds a crossing.
        if (previous_sign < 0 && (!March::kPlaceNeeded || t0 == stretch.t_min) && convex_and_falling(m_.unit_)) {
            Mask4 every[kMaxLanes / 4];
            for (std::size_t g = 0; g < groups(); ++g) every[g] = ~Mask4{};  // inert lanes weigh 0
            return m_.threshold_ - m_.template chord_upper_bound<kGroups>(t0 - m_.t_ref_, stretch.t_end - t0, every) >
                   rounding();
        }
        return false;
    }

    // The next entry or exit after t0 (a minimum over the lanes, no sort); the lanes counting from t0 become current.
    double next_event(double t0, double t_end) {
        Double4 next = Double4{} + std::numeric_limits<double>::infinity();
        for (std::size_t g = 0; g < groups(); ++g) {
            const Double4 t_enter = load4(m_.t_enter_ + 4 * g), t_exit = load4(m_.t_exit_ + 4 * g);
            const Double4 event = select(t_enter > t0, t_enter, t_exit);
            next = min4(next, select(event > t0, event, next));
            counts_[g] = m_.counting(g, t0);
            m_.counting_[g] = mask_bits(counts_[g]);
            entered_ |= m_.counting_[g] << (4 * g);
        }
        return std::min(t_end, lane_min(next));
    }

    template <class March>
    PieceBound bound_piece(double t0, double t1, int previous_sign, March& march) const {
        PieceBound bound;
        const auto [low, high] = ranges(t0 - m_.t_ref_, t1 - m_.t_ref_, previous_sign);
        if (previous_sign < 0) {
            bound.settled = march_piece::below_threshold(high, m_.threshold_);
        } else {
            bound.settled = march_piece::one_side_of_threshold(low, high, m_.threshold_);
            bound.start_sign = march_piece::sign_of(low - m_.threshold_);
        }
        if constexpr (!March::kPlaceNeeded) {
            // F beyond rounding on both sides of T at the piece's ends: an odd number of crossings inside, proven
            // without composing, testing or solving the piece.
            if (!bound.settled) {
                const double margin = rounding();
                const double at_start = m_.template value<kGroups>(t0), at_end = m_.template value<kGroups>(t1);
                if (std::abs(at_start) > margin && std::abs(at_end) > margin && (at_start < 0) != (at_end < 0) &&
                    march.crossing(0.5 * (t0 + t1), march_piece::sign_of(at_start)))
                    return {true, false, -1};
            }
        }
        // A piece from the ray's start (a ray leaving the surface), or any piece of an occlusion query, that the
        // ranges leave open: the chords' bound before the polynomial, as over the whole stretch.
        const bool leaving = previous_sign < 0 && (!March::kPlaceNeeded || t0 == march.stretch().t_min);
        if (!bound.settled && leaving && convex_and_falling(m_.unit_)) {
            const double upper = m_.template chord_upper_bound<kGroups>(t0 - m_.t_ref_, t1 - t0, counts_);
            // Beyond its rounding: a few ulps of the terms, which Σ |wᵢ| of the counting elements bounds.
            bound.settled = m_.threshold_ - upper >
                            1e-9 * (m_.threshold_ +
                                    m_.template absolute_weights<kGroups>([&](std::size_t g) { return counts_[g]; }));
        }
        return bound;
    }

    // The counting terms composed directly in the piece's own u ∈ [0, 1] (MetaballMarch::piece_polynomial).
    PieceTest test_piece(double t0, double t1) {
        const PiecePolynomial piece = m_.template piece_polynomial<kGroups>(t0 - m_.t_ref_, t1 - t0, counts_);
        int terms = 1;
        for (std::size_t g = 0; g < groups(); ++g) terms += std::popcount(m_.counting_[g]);
        on_piece_ = Polynomial(std::span<const double>(piece.coefficients.data(), kTermSize));
        PieceTest test;
        test.signs = march_piece::bernstein_signs_on_piece(on_piece_, terms, piece.magnitude);
        test.start_sign = march_piece::sign_of(on_piece_[0]);
        test.open = test.signs.variations != 0;
        test.polynomial = &on_piece_;
        return test;
    }

    // Every lane's next event is found afresh on each piece, and no element steps at the stretch's end.
    void advance(double) {}
    template <class March>
    void at_end(double, int, March&) {}

    // An element whose support contains the piece: the last counting one.
    std::uint32_t witness() const {
        for (std::size_t g = groups(); g-- > 0;)
            if (m_.counting_[g] != 0) return m_.index_[4 * g + std::size_t(31 - std::countl_zero(m_.counting_[g]))];
        return 0;
    }

    // ∇(F + T) at a point of the crossing just reported, summed over the elements that count on its piece, in
    // ascending element order: the sum BlobGroup::gradient makes over the cell's list, hence the same bits.
    Vec3d gradient_at(const Vec3d& point) const;

private:
    std::size_t groups() const { return m_.template groups<kGroups>(); }
    // Beyond the rounding of F at any point of the stretch: a few ulps of every candidate's term (inert lanes weigh 0).
    double rounding() const {
        return 1e-9 * (m_.threshold_ + m_.template absolute_weights<kGroups>([](std::size_t) { return ~Mask4{}; }));
    }
    // Bounds of Σ wᵢ·fᵢ on [s0, s1] from each counting element's own range: f is monotone in r², so its extremes on
    // the piece are at the ends of the element's r² range. Coming from outside (F is continuous), F cannot be above T
    // on the whole piece: only the upper bound is formed.
    std::pair<double, double> ranges(double s0, double s1, int previous_sign) const {
        Double4 low{}, high{};
        for (std::size_t g = 0; g < groups(); ++g) {
            const Mask4 mask = counts_[g];
            const auto [near, far] = m_.distance2_range(g, s0, s1);
            const Double4 inverse_radius2 = load4(m_.inverse_radius2_ + 4 * g), weight = load4(m_.weight_ + 4 * g);
            if (previous_sign < 0) {
                const Double4 x = select(weight > 0.0, near, far) * inverse_radius2;
                high += select(mask, weight * m_.unit_value(x, BoundMulAdd{}), Double4{});
            } else {
                const Double4 w_near = weight * m_.unit_value(near * inverse_radius2, BoundMulAdd{}),
                              w_far = weight * m_.unit_value(far * inverse_radius2, BoundMulAdd{});
                low += select(mask, min4(w_near, w_far), Double4{});
                high += select(mask, max4(w_near, w_far), Double4{});
            }
        }
        return {lane_sum(low), lane_sum(high)};
    }

    MetaballMarch& m_;
    Mask4 counts_[kMaxLanes / 4];  // per group, the lanes counting on the current piece
    unsigned entered_ = 0;
    Polynomial on_piece_;  // F on the current piece in u ∈ [0, 1], for the pieces the bounds leave open
};

template <class Kernel>
template <std::size_t kGroups>
Vec3d MetaballMarch<Kernel>::Pieces<kGroups>::gradient_at(const Vec3d& point) const {
    Vec3d sum(0, 0, 0);
    if constexpr (requires(Double4 x) { Kernel::unit_derivative_of(x); }) {
        // Each element's w·f'(r²)·2(P − C) four lanes at a time, with Metacube::field_gradient's operations in its
        // order (so its bits), 0 in the lanes that do not count, then summed in ascending element order as
        // BlobGroup::gradient sums them (adding the zeros changes no bit), with no branch on which lanes count.
        alignas(32) double gx[kMaxLanes], gy[kMaxLanes], gz[kMaxLanes];
        for (std::size_t g = 0; g < groups(); ++g) {
            const Mask4 counts = (Mask4{1, 2, 4, 8} & std::int64_t(m_.counting_[g])) != 0;
            const Double4 ox = point.x - load4(m_.x_ + 4 * g), oy = point.y - load4(m_.y_ + 4 * g),
                          oz = point.z - load4(m_.z_ + 4 * g);
            const Double4 inverse_radius2 = load4(m_.inverse_radius2_ + 4 * g);
            const Double4 x = (ox * ox + oy * oy + oz * oz) * inverse_radius2;
            const Double4 slope = load4(m_.weight_ + 4 * g) *
                                  select(x < 1.0, Kernel::unit_derivative_of(x) * inverse_radius2, Double4{});
            const Double4 twice = select(counts, 2 * slope, Double4{});
            store4(gx + 4 * g, ox * twice);
            store4(gy + 4 * g, oy * twice);
            store4(gz + 4 * g, oz * twice);
        }
        for (std::size_t lane = 0; lane < 4 * groups(); ++lane) sum += Vec3d(gx[lane], gy[lane], gz[lane]);
    } else {
        for (std::size_t g = 0; g < groups(); ++g)
            for (unsigned lanes = m_.counting_[g]; lanes != 0; lanes &= lanes - 1)
                sum += m_.elements_[m_.index_[4 * g + std::size_t(std::countr_zero(lanes))]].field_gradient(m_.kernel_,
                                                                                                             point);
    }
    return sum;
}

}  // namespace isotrace
