#pragma once
// The blob march for groups of metaballs alone whose kernel is one polynomial piece on its whole support (Kim's,
// Wyvill's and Murakami's: the benchmark clouds and most scenes). The same pieces, bounds, Bernstein test and
// solving as the general march (field_march.h, march_piece.h), with the cell's candidates side by side in lanes of
// four (double4.h) instead of in a list of joined elements ordered by entry:
//   1. the float sphere test keeps the listed elements the stretch may come near; their exact nearest approaches
//      bound F from above (below T the stretch holds no crossing: nearly half the queries end here), and those
//      whose support's chord meets the stretch become the candidates, in ascending element order;
//   2. a metaball has one piece, its support's chord [t_enter, t_exit], so on any piece of the stretch its term of
//      the sum is one polynomial: a piece the bounds leave open composes the terms of the elements counting on it
//      directly in the piece's own u ∈ [0, 1], four lanes at a time (no shift of a sum to the piece);
//   3. pieces run between consecutive entries and exits: the next event is the least entry or exit beyond the
//      piece's start (a minimum over the lanes, no sort), and the elements that count on a piece are a mask of the
//      lanes (entered, not left), so each bound and sum is a masked sum over whole lanes: no branch per element,
//      where the general march's loops over 5–8 joined elements and its sort mispredicted (docs/decisions.md).
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
#include "geometry/implicit/metacube.h"
#include "geometry/implicit/sphere_prefilter.h"
#include "geometry/implicit/march_piece.h"
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

    // ∇(F + T) at a point of the crossing just reported, summed over the elements that count on its piece, in
    // ascending element order: the sum BlobGroup::gradient makes over the cell's list, hence the same bits (as
    // FieldMarch::gradient_at).
    Vec3d gradient_at(const Vec3d& point) const { return gradient<0>(point); }

    // F + T at a point, from `listed` (every element whose support may contain the point), four elements at a time:
    // an occlusion query asks it whether its ray started outside. BlobGroup::field sums the same terms one by one, so
    // the last bits may differ; the question allows 10⁻⁶ of T.
    double field_at(const Vec3d& point, std::span<const std::uint32_t> listed) const;

private:
    // What a report is given while march_pieces<kGroups> runs: the march, with its count of groups known.
    template <std::size_t kGroups>
    struct PiecesView {
        const MetaballMarch& march;
        Vec3d gradient_at(const Vec3d& point) const { return march.template gradient<kGroups>(point); }
    };
    template <std::size_t kGroups>
    Vec3d gradient(const Vec3d& point) const;
    // The centres, radii and weights of four listed elements (`listed[first…]`, the last one repeated past the end of
    // the list), each read in one load and transposed into lanes in registers, and the lanes that hold a listed one.
    struct ElementLanes {
        Double4 x, y, z, radius, weight;
        Mask4 in_list;
    };
    ElementLanes element_lanes(std::span<const std::uint32_t> listed, std::size_t first) const;

    static constexpr std::size_t kTermSize = 7;  // a cubic in x composed with the quadratic x(s): degree 6
    // The loops over groups of four lanes take their count as a template argument, 1 to kUnrolledGroups (nearly nine
    // queries in ten), so that they unroll and leave no loop exit to mispredict, and 0 for "read it from the query"
    // (the count varies from query to query, and a query runs some twenty such loops: ×1.04 on blobs_1k).
    static constexpr std::size_t kUnrolledGroups = 4;
    template <std::size_t kGroups>
    std::size_t groups() const { return kGroups != 0 ? kGroups : groups_; }

    // run once the near elements are known, with kNearGroups groups of them (0: as many as there are).
    template <std::size_t kNearGroups, class Query>
    void march_near(const MarchStretch& stretch, BlobQueryWork& work, Query& query);
    // The pieces of the stretch, in order, over kGroups groups of candidates (0: groups_).
    template <std::size_t kGroups, class Query>
    void march_pieces(const MarchStretch& stretch, BlobQueryWork& work, Query& query);

    // Loads the near elements into the lanes and returns an upper bound of Σ wᵢ·fᵢ on the stretch from each one's
    // nearest approach (as FieldMarch::gather), without the chords' square roots: nearly half the queries end at
    // this bound.
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
    const Vec3d& o = stretch.origin;
    const Vec3d& d = stretch.direction;
    const std::size_t n = near_.size();
    const std::size_t near_groups = kNearGroups != 0 ? kNearGroups : (n + 3) / 4;
    inverse_length2_ = 1 / dot(d, d);
    const double rounding = nearest_approach_rounding(stretch, centre_bound_);
    Double4 upper{};  // Σ wᵢ·max fᵢ on the stretch over elements of positive weight
    kept_lanes_ = 0;
    for (std::size_t g = 0; g < near_groups; ++g) {
        // Stored for the steps after. The lanes past the list repeat its last element; the exact test leaves them out.
        const auto [x, y, z, radius, weight, in_list] = element_lanes({near_.begin(), n}, 4 * g);
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
    for (std::size_t g = 0; g < (kNearGroups != 0 ? kNearGroups : (n + 3) / 4); ++g) {
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
template <std::size_t kGroups>
Vec3d MetaballMarch<Kernel>::gradient(const Vec3d& point) const {
    Vec3d sum(0, 0, 0);
    if constexpr (requires(Double4 x) { Kernel::unit_derivative_of(x); }) {
        // Each element's w·f'(r²)·2(P − C) four lanes at a time, with Metacube::field_gradient's operations in its
        // order (so its bits), 0 in the lanes that do not count, then summed in ascending element order as
        // BlobGroup::gradient sums them (adding the zeros changes no bit), with no branch on which lanes count.
        alignas(32) double gx[kMaxLanes], gy[kMaxLanes], gz[kMaxLanes];
        for (std::size_t g = 0; g < groups<kGroups>(); ++g) {
            const Mask4 counts = (Mask4{1, 2, 4, 8} & std::int64_t(counting_[g])) != 0;
            const Double4 ox = point.x - load4(x_ + 4 * g), oy = point.y - load4(y_ + 4 * g),
                          oz = point.z - load4(z_ + 4 * g);
            const Double4 inverse_radius2 = load4(inverse_radius2_ + 4 * g);
            const Double4 x = (ox * ox + oy * oy + oz * oz) * inverse_radius2;
            const Double4 slope =
                load4(weight_ + 4 * g) * select(x < 1.0, Kernel::unit_derivative_of(x) * inverse_radius2, Double4{});
            const Double4 twice = select(counts, 2 * slope, Double4{});
            store4(gx + 4 * g, ox * twice);
            store4(gy + 4 * g, oy * twice);
            store4(gz + 4 * g, oz * twice);
        }
        for (std::size_t lane = 0; lane < 4 * groups<kGroups>(); ++lane) sum += Vec3d(gx[lane], gy[lane], gz[lane]);
    } else {
        for (std::size_t g = 0; g < groups<kGroups>(); ++g)
            for (unsigned lanes = counting_[g]; lanes != 0; lanes &= lanes - 1)
                sum += elements_[index_[4 * g + std::size_t(std::countr_zero(lanes))]].field_gradient(kernel_, point);
    }
    return sum;
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
        march_pieces<kNearGroups>(stretch, work, query);
    else
        march_pieces<0>(stretch, work, query);
}

template <class Kernel>
template <std::size_t kGroups, class Query>
void MetaballMarch<Kernel>::march_pieces(const MarchStretch& stretch, BlobQueryWork& work, Query& query) {
    constexpr bool kPlaceNeeded = Query::kPlaceNeeded;
    using march_piece::sign_of;
    prepare_pieces<kGroups>(stretch);
    unsigned entered = 0;  // lanes that counted on some piece, for the statistics
    double t0 = stretch.t_begin;
    const auto witness = [&] {  // an element whose support contains the piece: the last counting one
        for (std::size_t g = groups<kGroups>(); g-- > 0;)
            if (counting_[g] != 0)
                return index_[4 * g + std::size_t(31 - std::countl_zero(counting_[g]))];
        return std::uint32_t(0);
    };
    const auto crossing = [&](double t, int before) {
        if (!(t > stretch.t_min && t < stretch.t_max)) return false;
        ++work.roots;
        return query.found(FieldCrossing{t, before < 0, witness()}, PiecesView<kGroups>{*this});
    };
    // Beyond the rounding of F at any point of the stretch: a few ulps of every candidate's term (inert lanes weigh 0).
    const auto rounding = [&] {
        return 1e-9 * (threshold_ + absolute_weights<kGroups>([](std::size_t) { return ~Mask4{}; }));
    };
    // The elements counting on the piece from t0, and F's sign before it; returns when the march must stop.
    const auto march = [&] {
        for (std::size_t g = 0; g < groups<kGroups>(); ++g) counting_[g] = mask_bits(counting(g, t0));
        const double at_start = value<kGroups>(t0);
        int previous_sign = sign_of(at_start);
        if (previous_sign > 0 && t0 > stretch.t_min &&
            march_piece::inside_beyond_rounding(
                at_start, threshold_, absolute_weights<kGroups>([&](std::size_t g) { return counting(g, t0); })) &&
            query.crossed_before())
            return;
        if constexpr (!kPlaceNeeded) {
            // Outside at the start and inside at the end, both beyond rounding: a crossing lies between, and no piece
            // need be examined. Tight cell boxes start many a shadow ray's stretch just outside a blob it then enters
            // (blobs_10k: 17,489 of 64,972 marched occlusion queries end here, pieces 148,471 → 66,455).
            const double margin = rounding();
            if (at_start < -margin && value<kGroups>(stretch.t_end) > margin &&
                crossing(0.5 * (t0 + stretch.t_end), previous_sign))
                return;
        }
        // A stretch from the ray's start (a ray leaving the surface), or any stretch of an occlusion query, that starts
        // outside: first the chords' bound over the whole stretch, every candidate counting. On blobs_1k it settles
        // 61 % of the first kind (bounce rays' marches of 4–5 pieces each, none holding a crossing) and 46 % of the
        // second; elsewhere nearly every stretch it is asked of holds a crossing.
        if (previous_sign < 0 && (!kPlaceNeeded || t0 == stretch.t_min) && convex_and_falling(unit_)) {
            Mask4 every[kMaxLanes / 4];
            for (std::size_t g = 0; g < groups<kGroups>(); ++g) every[g] = ~Mask4{};  // inert lanes weigh 0
            if (threshold_ - chord_upper_bound<kGroups>(t0 - t_ref_, stretch.t_end - t0, every) > rounding()) return;
        }
        Polynomial on_piece;  // F on the current piece in u ∈ [0, 1], for the pieces the bounds do not settle
        while (t0 < stretch.t_end) {
            // The piece [t0, t1] ends at the next entry or exit.
            double t1 = stretch.t_end;
            const double s0 = t0 - t_ref_;
            Double4 next = Double4{} + std::numeric_limits<double>::infinity();
            Mask4 counts[kMaxLanes / 4];
            for (std::size_t g = 0; g < groups<kGroups>(); ++g) {
                const Double4 t_enter = load4(t_enter_ + 4 * g), t_exit = load4(t_exit_ + 4 * g);
                const Double4 event = select(t_enter > t0, t_enter, t_exit);
                next = min4(next, select(event > t0, event, next));
                counts[g] = counting(g, t0);
                counting_[g] = mask_bits(counts[g]);
                entered |= counting_[g] << (4 * g);
            }
            t1 = std::min(t1, lane_min(next));
            ++work.pieces;
            const double s1 = t1 - t_ref_, width = t1 - t0;
            // First each element's own range: f is monotone in r², so its extremes on the piece are at the ends of
            // the element's r² range. Coming from outside, F is continuous, so it cannot be above T on the whole
            // piece: only its upper bound is needed.
            Double4 low{}, high{};
            for (std::size_t g = 0; g < groups<kGroups>(); ++g) {
                const Mask4 mask = counts[g];
                const auto [near, far] = distance2_range(g, s0, s1);
                const Double4 inverse_radius2 = load4(inverse_radius2_ + 4 * g), weight = load4(weight_ + 4 * g);
                if (previous_sign < 0) {
                    const Double4 x = select(weight > 0.0, near, far) * inverse_radius2;
                    high += select(mask, weight * unit_value(x, BoundMulAdd{}), Double4{});
                } else {
                    const Double4 w_near = weight * unit_value(near * inverse_radius2, BoundMulAdd{}),
                                  w_far = weight * unit_value(far * inverse_radius2, BoundMulAdd{});
                    low += select(mask, min4(w_near, w_far), Double4{});
                    high += select(mask, max4(w_near, w_far), Double4{});
                }
            }
            const double range_low = lane_sum(low), range_high = lane_sum(high);
            int start_sign = -1;
            bool settled;
            if (previous_sign < 0) {
                settled = march_piece::below_threshold(range_high, threshold_);
            } else {
                settled = march_piece::one_side_of_threshold(range_low, range_high, threshold_);
                start_sign = sign_of(range_low - threshold_);
            }
            if constexpr (!kPlaceNeeded) {
                if (!settled) {
                    // F beyond rounding on both sides of T at the piece's ends: an odd number of crossings inside.
                    // (Composing, testing and solving the piece was a third of a shadow ray's marched query.)
                    const double margin = rounding();
                    const double at_start = value<kGroups>(t0), at_end = value<kGroups>(t1);
                    if (std::abs(at_start) > margin && std::abs(at_end) > margin && (at_start < 0) != (at_end < 0) &&
                        crossing(0.5 * (t0 + t1), sign_of(at_start)))
                        return;
                }
            }
            // A piece from the ray's start (a ray leaving the surface), or any piece of an occlusion query, that the
            // ranges leave open: the chords' bound before the polynomial. It settles 86–92 % of them on blobs_1k (the
            // start of a ray leaving the surface is within a hair of T); elsewhere nearly every piece left open holds
            // a crossing.
            if (!settled && previous_sign < 0 && (!kPlaceNeeded || t0 == stretch.t_min) && convex_and_falling(unit_)) {
                const double upper = chord_upper_bound<kGroups>(s0, width, counts);
                // Beyond its rounding: a few ulps of the terms, which Σ |wᵢ| of the counting elements bounds.
                settled = threshold_ - upper >
                          1e-9 * (threshold_ + absolute_weights<kGroups>([&](std::size_t g) { return counts[g]; }));
            }
            BernsteinSigns signs;
            if (!settled) {
                const PiecePolynomial piece = piece_polynomial<kGroups>(s0, width, counts);
                int terms = 1;
                for (std::size_t g = 0; g < groups<kGroups>(); ++g) terms += std::popcount(counting_[g]);
                on_piece = Polynomial(std::span<const double>(piece.coefficients.data(), kTermSize));
                signs = march_piece::bernstein_signs_on_piece(on_piece, terms, piece.magnitude);
                start_sign = sign_of(on_piece[0]);
            }
            if (signs.variations == 0) {
                ++work.skipped_pieces;
                // A root on the boundary with the previous piece, which that piece ended on within rounding.
                if (start_sign != previous_sign && crossing(t0, previous_sign)) return;
                previous_sign = start_sign;
            } else if (march_piece::polynomial_piece_crossings(on_piece, signs, t0, width, previous_sign, work,
                                                               crossing)) {
                return;
            }
            t0 = t1;
        }
    };
    march();
    work.joined += std::uint64_t(std::popcount(entered));
}

}  // namespace isotrace
